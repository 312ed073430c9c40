// shadow.msm: moment shadow mapping, 4 moments, Hamburger reconstruction.
#include "core/registry.hpp"
#include "shaders/msm_depth_frag.h"
#include "shaders/msm_frag.h"
#include "shadow_filtering.h"
#include "../common/prefilter_params.hpp"
#include "../common/shadow_family.hpp"

namespace canopy {
namespace {

class MomentShadows final : public Technique {
public:
    std::string name() const override { return "shadow.msm"; }
    std::string summary() const override { return "moment shadow maps: 4 moments, Hamburger reconstruction"; }
    std::string paper() const override { return "Peters & Klein 2015 (beyond the papers)"; }

    std::vector<ParamSpec> params() const override {
        auto specs = prefilter_params();
        // Peters & Klein store the quantised moments in 16-bit unorm; rgba16f is offered too.
        for (ParamSpec& spec : specs)
            if (spec.name == "precision") {
                spec.choices = {"fp32", "fp16", "unorm16"};
                spec.doc = "moment storage: 32-bit float, 16-bit float, or 16-bit unorm (the paper's)";
            }
        specs.push_back(ParamSpec::real("moment_bias", 3e-5, 0.0, 0.01,
                                        "blend towards well-conditioned target moments (3e-5 for fp32, 6e-5 suits 16 bits)"));
        return specs;
    }

    ErrorColumns error_columns() const override { return kShadowErrorColumns; }

    FramePlan plan(const ParamSet& params) const override {
        const glm::vec4 far_moments = shader::msm_encode(1.0f);
        FramePlan plan;
        plan.moment_map = moment_map_needs(params, 4, msm_depth_frag,
                                           {far_moments.x, far_moments.y, far_moments.z, far_moments.w});
        if (params.choice("precision") == "unorm16") plan.moment_map->format = MomentFormat::rgba16unorm;
        plan.forward_fragment_spirv = msm_frag;
        plan.shader_params.values[0] = float(params.real("moment_bias"));
        return plan;
    }
};

RegisterTechnique<MomentShadows> registered;

}  // namespace
}  // namespace canopy
