// shadow.evsm: exponential variance shadow maps, 2 or 4 components.
#include "core/registry.hpp"
#include "shaders/evsm_depth_frag.h"
#include "shaders/evsm_frag.h"
#include "shadow_filtering.h"
#include "../common/prefilter_params.hpp"
#include "../common/shadow_family.hpp"

#include <algorithm>

namespace canopy {
namespace {

class ExponentialVarianceShadows final : public Technique {
public:
    std::string name() const override { return "shadow.evsm"; }
    std::string summary() const override { return "exponential variance shadow maps: Chebyshev on exp-warped depth"; }
    std::string paper() const override { return "Lauritzen & McCool 2008 (beyond the papers)"; }

    std::vector<ParamSpec> params() const override {
        auto specs = prefilter_params();
        specs.push_back(ParamSpec::choice("components", "4", {"2", "4"}, "positive warp only (2) or positive and negative (4)"));
        specs.push_back(ParamSpec::real("positive_exponent", 40.0, 0.0, 100.0,
                                        "c+ of exp(c+ z'), clamped to what the precision can store"));
        specs.push_back(ParamSpec::real("negative_exponent", 5.0, 0.0, 100.0,
                                        "c- of -exp(-c- z'), clamped to what the precision can store"));
        specs.push_back(ParamSpec::real("min_variance", 1e-5, 0.0, 0.01,
                                        "variance floor in depth units (z^2, as shadow.vsm), mapped through each warp's slope"));
        specs.push_back(ParamSpec::real("bleeding_reduction", 0.0, 0.0, 0.95, "as in shadow.vsm"));
        return specs;
    }

    ErrorColumns error_columns() const override { return kShadowErrorColumns; }

    FramePlan plan(const ParamSet& params) const override {
        const float limit = shader::evsm_max_exponent(half_precision(params));
        const float c_pos = std::min(float(params.real("positive_exponent")), limit);
        const float c_neg = std::min(float(params.real("negative_exponent")), limit);
        const bool four = params.choice("components") == "4";
        const glm::vec4 far_moments = shader::evsm_moments(1.0f, c_pos, c_neg);
        FramePlan plan;
        plan.moment_map = moment_map_needs(params, four ? 4 : 2, evsm_depth_frag,
                                           {far_moments.x, far_moments.y, far_moments.z, far_moments.w});
        plan.forward_fragment_spirv = evsm_frag;
        plan.shader_params.values[0] = c_pos;
        plan.shader_params.values[1] = c_neg;
        plan.shader_params.values[2] = four ? 4.0f : 2.0f;
        plan.shader_params.values[3] = float(params.real("min_variance"));
        plan.shader_params.values[4] = float(params.real("bleeding_reduction"));
        return plan;
    }
};

RegisterTechnique<ExponentialVarianceShadows> registered;

}  // namespace
}  // namespace canopy
