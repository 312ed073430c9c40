// shadow.esm: exponential shadow maps.
#include "core/registry.hpp"
#include "shaders/shadow/esm_depth_frag.h"
#include "shaders/shadow/esm_frag.h"
#include "shaders/shadow/log_box_filter_comp.h"
#include "../shaders/shadow_filtering.h"
#include "esm_params.h"
#include "../common/prefilter_params.hpp"
#include "../common/shadow_technique.hpp"

#include <fmt/format.h>

#include <cmath>

namespace canopy {
namespace {

class ExponentialShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "shadow.esm"; }
    std::string summary() const override { return "exponential shadow maps: prefiltered exp(c z), linear or log space"; }
    std::string paper() const override { return "Salvi 2008; Annen et al. 2008; Gumbau 2011 Table 7.1 'Exponential'"; }

    std::vector<ParamSpec> params() const override { return shader::EsmParams::specs(); }

    // Linear storage of exp(c z) overflows past esm_max_exponent: the stored value becomes inf, is
    // read as FLT_MAX, and every shadow vanishes without a sign. Refused rather than clamped, so
    // a result never silently uses another exponent than the config says.
    std::optional<ParamConflict> conflict(const ParamSet& params) const override {
        if (params.boolean("log_space")) return std::nullopt;
        const bool half = half_precision(params);
        const double c = params.real("exponent");
        const double limit = shader::esm_max_exponent(half);
        if (c <= limit) return std::nullopt;
        const std::string format = half ? "fp16" : "fp32";
        ParamConflict conflict;
        conflict.params = {"exponent", "precision", "log_space"};
        conflict.message = fmt::format(
            "exponent {} overflows {} storage: exp(c z) reaches e^{} at the far plane, beyond the largest {} value "
            "({}), and every shadow would vanish",
            c, format, c, format, half ? "65504 = e^11.09" : "3.4e38 = e^88.7, less the prefilter's sums");
        conflict.hint = half ? "with precision = \"fp16\" use exponent in [1, 11], or set log_space = true "
                               "(stores c z: no overflow), or precision = \"fp32\" (exponent up to 84)"
                             : "with precision = \"fp32\" use exponent in [1, 84], or set log_space = true "
                               "(stores c z: no overflow)";
        return conflict;
    }


    ShadowPlan plan(const ParamSet& params) const override {
        const shader::EsmParams block = shader::EsmParams::from(params);
        const float c = block.exponent;
        const bool log_space = block.log_space != 0;
        ShadowPlan plan;
        // The clear value is the statistic of depth 1 (no caster): exp(c), finite since conflict()
        // refuses exponents linear storage cannot hold.
        const float far_value = log_space ? c : std::exp(c);
        plan.moment_map = moment_map_needs(params, 1, esm_depth_frag, {far_value, 0.0f, 0.0f, 1.0f},
                                           log_space ? std::span<const uint32_t>(log_box_filter_comp)
                                                     : std::span<const uint32_t>());
        plan.forward_fragment_spirv = esm_frag;
        plan.shader_params.set_block(block);
        return plan;
    }
};

RegisterTechnique<ExponentialShadows> registered;

}  // namespace
}  // namespace canopy
