// shadow.pcss: percentage-closer soft shadows.
#include "core/registry.hpp"
#include "shaders/shadow/pcss_frag.h"
#include "pcss_params.h"
#include "../common/shadow_map_params.hpp"
#include "../common/shadow_technique.hpp"

namespace canopy {
namespace {

class PercentageCloserSoftShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "shadow.pcss"; }
    std::string summary() const override { return "percentage-closer soft shadows: blocker search, eq 6.1 penumbra, PCF"; }
    std::string paper() const override { return "Fernando 2005; Gumbau 2011 eq 6.1, Table 6.1 'PCSS Bs5+PCF5/11/23'"; }

    std::vector<ParamSpec> params() const override { return shader::PcssParams::specs(); }


    ShadowPlan plan(const ParamSet& params) const override {
        ShadowPlan plan;
        plan.shadow_map = shadow_map_needs(params);
        plan.needs_area_light = true;
        plan.forward_fragment_spirv = pcss_frag;
        plan.shader_params.set_block(shader::PcssParams::from(params));
        return plan;
    }
};

RegisterTechnique<PercentageCloserSoftShadows> registered;

}  // namespace
}  // namespace canopy
