// shadow.pcss: percentage-closer soft shadows.
#include "core/registry.hpp"
#include "shaders/pcss_frag.h"
#include "../common/shadow_map_params.hpp"
#include "../common/shadow_family.hpp"

namespace canopy {
namespace {

class PercentageCloserSoftShadows final : public Technique {
public:
    std::string name() const override { return "shadow.pcss"; }
    std::string summary() const override { return "percentage-closer soft shadows: blocker search, eq 6.1 penumbra, PCF"; }
    std::string paper() const override { return "Fernando 2005; Gumbau 2011 eq 6.1, Table 6.1 'PCSS Bs5+PCF5/11/23'"; }

    std::vector<ParamSpec> params() const override {
        auto specs = shadow_map_params();
        specs.push_back(ParamSpec::integer("blocker_search", 5, 1, 16, "blocker-search grid width Bs: Bs x Bs samples"));
        specs.push_back(ParamSpec::integer("kernel", 5, 1, 31, "PCF grid width K: K x K samples spread over the penumbra"));
        specs.push_back(ParamSpec::real("max_radius", 64.0, 1.0, 512.0,
                                        "cap on the search and filter radius in texels (huge lights)"));
        return specs;
    }

    ErrorColumns error_columns() const override { return kShadowErrorColumns; }

    FramePlan plan(const ParamSet& params) const override {
        FramePlan plan;
        plan.shadow_map = shadow_map_needs(params);
        plan.needs_area_light = true;
        plan.forward_fragment_spirv = pcss_frag;
        write_bias_params(params, plan.shader_params);
        plan.shader_params.values[2] = float(params.integer("blocker_search"));
        plan.shader_params.values[3] = float(params.integer("kernel"));
        plan.shader_params.values[4] = float(params.real("max_radius"));
        return plan;
    }
};

RegisterTechnique<PercentageCloserSoftShadows> registered;

}  // namespace
}  // namespace canopy
