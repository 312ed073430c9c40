// shadow.gauss-cdf: Gaussian-CDF shadow filtering (Gumbau 2011, section 7.2.1).
#include "core/registry.hpp"
#include "shaders/shadow/gauss_cdf_frag.h"
#include "shaders/shadow/two_moments_frag.h"
#include "gauss_cdf_params.h"
#include "../common/prefilter_params.hpp"
#include "../common/shadow_technique.hpp"

namespace canopy {
namespace {

class GaussianCdfShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "shadow.gauss-cdf"; }
    std::string summary() const override { return "Gaussian CDF of prefiltered depth moments, Winitzki's erf"; }
    std::string paper() const override { return "Gumbau 2011 eq 7.1-7.4, Table 7.1 'Gaussian CDF'"; }

    std::vector<ParamSpec> params() const override { return shader::GaussCdfParams::specs(); }


    ShadowPlan plan(const ParamSet& params) const override {
        ShadowPlan plan;
        plan.moment_map = moment_map_needs(params, 2, two_moments_frag, {1.0f, 1.0f, 0.0f, 1.0f});
        plan.forward_fragment_spirv = gauss_cdf_frag;
        plan.shader_params.set_block(shader::GaussCdfParams::from(params));
        return plan;
    }
};

RegisterTechnique<GaussianCdfShadows> registered;

}  // namespace
}  // namespace canopy
