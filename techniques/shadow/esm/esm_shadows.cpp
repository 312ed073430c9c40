// shadow.esm: exponential shadow maps.
#include "core/registry.hpp"
#include "shaders/esm_depth_frag.h"
#include "shaders/esm_frag.h"
#include "shaders/log_box_filter_comp.h"
#include "../common/prefilter_params.hpp"

#include <cmath>

namespace canopy {
namespace {

class ExponentialShadows final : public Technique {
public:
    std::string name() const override { return "shadow.esm"; }
    std::string summary() const override { return "exponential shadow maps: prefiltered exp(c z), linear or log space"; }
    std::string paper() const override { return "Salvi 2008; Annen et al. 2008; Gumbau 2011 Table 7.1 'Exponential'"; }

    std::vector<ParamSpec> params() const override {
        auto specs = prefilter_params();
        specs.push_back(ParamSpec::real("exponent", 80.0, 1.0, 200.0,
                                        "c in exp(c z); exp(c) overflows fp16 above c = 11 and fp32 above c = 88 unless log_space"));
        specs.push_back(ParamSpec::boolean("log_space", false,
                                           "store c z and filter in log space (log-sum-exp), so no exponent overflows"));
        return specs;
    }

    FramePlan plan(const ParamSet& params) const override {
        const float c = float(params.real("exponent"));
        const bool log_space = params.boolean("log_space");
        FramePlan plan;
        // The clear value is the statistic of depth 1 (no caster); exp(c) may be +inf, as the
        // rendered texels would be: that is the overflow the exponent parameter documents.
        const float far_value = log_space ? c : std::exp(c);
        plan.moment_map = moment_map_needs(params, 1, esm_depth_frag, {far_value, 0.0f, 0.0f, 1.0f},
                                           log_space ? std::span<const uint32_t>(log_box_filter_comp)
                                                     : std::span<const uint32_t>());
        plan.forward_fragment_spirv = esm_frag;
        plan.shader_params.values[0] = c;
        plan.shader_params.values[1] = log_space ? 1.0f : 0.0f;
        return plan;
    }
};

RegisterTechnique<ExponentialShadows> registered;

}  // namespace
}  // namespace canopy
