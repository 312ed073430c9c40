// shadow.msm: moment shadow mapping, 4 moments, Hamburger reconstruction.
#include "core/registry.hpp"
#include "shaders/shadow/msm_depth_frag.h"
#include "shaders/shadow/msm_frag.h"
#include "../shaders/shadow_filtering.h"
#include "msm_params.h"
#include "../common/prefilter_params.hpp"
#include "../common/shadow_technique.hpp"

namespace canopy {
namespace {

class MomentShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "shadow.msm"; }
    std::string summary() const override { return "moment shadow maps: 4 moments, Hamburger reconstruction"; }
    std::string paper() const override { return "Peters & Klein 2015 (beyond the papers)"; }

    std::vector<ParamSpec> params() const override { return shader::MsmParams::specs(); }


    ShadowPlan plan(const ParamSet& params) const override {
        const glm::vec4 far_moments = shader::msm_encode(1.0f);
        ShadowPlan plan;
        plan.moment_map = moment_map_needs(params, 4, msm_depth_frag,
                                           {far_moments.x, far_moments.y, far_moments.z, far_moments.w});
        if (params.choice("precision") == "unorm16") plan.moment_map->format = MomentFormat::rgba16unorm;
        plan.forward_fragment_spirv = msm_frag;
        plan.shader_params.set_block(shader::MsmParams::from(params));
        return plan;
    }
};

RegisterTechnique<MomentShadows> registered;

}  // namespace
}  // namespace canopy
