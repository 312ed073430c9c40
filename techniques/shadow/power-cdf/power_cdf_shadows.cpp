// shadow.power-cdf: power-function CDF reconstruction (Gumbau 2011, section 7.2.2).
#include "core/registry.hpp"
#include "shaders/shadow/min_max_mean_filter_comp.h"
#include "shaders/shadow/power_cdf_depth_frag.h"
#include "shaders/shadow/power_cdf_frag.h"
#include "power_cdf_params.h"
#include "../common/prefilter_params.hpp"
#include "../common/shadow_technique.hpp"

namespace canopy {
namespace {

class PowerCdfShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "shadow.power-cdf"; }
    std::string summary() const override { return "CDF reconstructed as t^beta from prefiltered min, max and mean depth"; }
    std::string paper() const override { return "Gumbau 2011 eq 7.5-7.7, Table 7.1 'CDF recons. 32/16 bits'"; }
    std::vector<ParamSpec> params() const override { return shader::PowerCdfParams::specs(); }


    ShadowPlan plan(const ParamSet& params) const override {
        ShadowPlan plan;
        plan.moment_map = moment_map_needs(params, 4, power_cdf_depth_frag, {1.0f, 1.0f, 1.0f, 1.0f},
                                           min_max_mean_filter_comp);
        plan.forward_fragment_spirv = power_cdf_frag;
        shader::PowerCdfParams block = shader::PowerCdfParams::from(params);
        // Two units of roundoff of the stored depths: 2^-10 for fp16 (10-bit mantissa), 2^-23 for fp32.
        block.depth_roundoff = half_precision(params) ? 0x1p-10f : 0x1p-23f;
        plan.shader_params.set_block(block);
        return plan;
    }
};

RegisterTechnique<PowerCdfShadows> registered;

}  // namespace
}  // namespace canopy
