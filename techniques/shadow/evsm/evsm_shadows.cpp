// shadow.evsm: exponential variance shadow maps, 2 or 4 components.
#include "core/registry.hpp"
#include "shaders/shadow/evsm_depth_frag.h"
#include "shaders/shadow/evsm_frag.h"
#include "../shaders/shadow_filtering.h"
#include "evsm_params.h"
#include "../common/prefilter_params.hpp"
#include "../common/shadow_technique.hpp"

#include <algorithm>

namespace canopy {
namespace {

class ExponentialVarianceShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "shadow.evsm"; }
    std::string summary() const override { return "exponential variance shadow maps: Chebyshev on exp-warped depth"; }
    std::string paper() const override { return "Lauritzen & McCool 2008 (beyond the papers)"; }

    std::vector<ParamSpec> params() const override { return shader::EvsmParams::specs(); }


    ShadowPlan plan(const ParamSet& params) const override {
        shader::EvsmParams block = shader::EvsmParams::from(params);
        const float limit = shader::evsm_max_exponent(half_precision(params));
        block.c_pos = std::min(float(params.real("positive_exponent")), limit);
        block.c_neg = std::min(float(params.real("negative_exponent")), limit);
        const bool four = block.components == EVSM_COMPONENTS_4;
        const glm::vec4 far_moments = shader::evsm_moments(1.0f, block.c_pos, block.c_neg);
        ShadowPlan plan;
        plan.moment_map = moment_map_needs(params, four ? 4 : 2, evsm_depth_frag,
                                           {far_moments.x, far_moments.y, far_moments.z, far_moments.w});
        plan.forward_fragment_spirv = evsm_frag;
        plan.shader_params.set_block(block);
        return plan;
    }
};

RegisterTechnique<ExponentialVarianceShadows> registered;

}  // namespace
}  // namespace canopy
