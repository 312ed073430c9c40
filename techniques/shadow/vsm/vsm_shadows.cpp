// shadow.vsm: variance shadow maps.
#include "core/registry.hpp"
#include "shaders/shadow/two_moments_frag.h"
#include "shaders/shadow/vsm_frag.h"
#include "vsm_params.h"
#include "../common/prefilter_params.hpp"
#include "../common/shadow_technique.hpp"

namespace canopy {
namespace {

class VarianceShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "shadow.vsm"; }
    std::string summary() const override { return "variance shadow maps: Chebyshev bound on prefiltered depth moments"; }
    std::string paper() const override { return "Donnelly & Lauritzen 2006; Gumbau 2011 eq 2.1-2.2, Table 7.1 'Chebyshev'"; }

    std::vector<ParamSpec> params() const override { return shader::VsmParams::specs(); }


    ShadowPlan plan(const ParamSet& params) const override {
        ShadowPlan plan;
        plan.moment_map = moment_map_needs(params, 2, two_moments_frag, {1.0f, 1.0f, 0.0f, 1.0f});
        plan.forward_fragment_spirv = vsm_frag;
        plan.shader_params.set_block(shader::VsmParams::from(params));
        return plan;
    }
};

RegisterTechnique<VarianceShadows> registered;

}  // namespace
}  // namespace canopy
