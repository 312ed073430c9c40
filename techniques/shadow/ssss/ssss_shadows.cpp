// shadow.ssss: screen-space soft shadows (Gumbau 2011, chapter 6).
#include "core/registry.hpp"
#include "shaders/block_min_comp.h"
#include "shaders/ssss_blur_comp.h"
#include "shaders/ssss_dilate_comp.h"
#include "shaders/ssss_frag.h"
#include "shaders/ssss_screen_frag.h"
#include "../common/shadow_map_params.hpp"
#include "../common/shadow_family.hpp"

namespace canopy {
namespace {

class ScreenSpaceSoftShadows final : public Technique {
public:
    std::string name() const override { return "shadow.ssss"; }
    std::string summary() const override {
        return "screen-space soft shadows: hard shadows blurred by a separable anisotropic Gaussian of eq 6.2 width";
    }
    std::string paper() const override { return "Gumbau 2011 ch. 6, eq 6.2, Table 6.1 'SSSS K5/K11/K23'"; }

    std::vector<ParamSpec> params() const override {
        auto specs = shadow_map_params();
        specs.push_back(ParamSpec::integer("kernel", 11, 1, 63, "Gaussian taps K per axis (the paper's K5, K11, K23)"));
        specs.push_back(ParamSpec::integer("coarse_block", 4, 1, 16,
                                           "shadow-map texels per coarse-map texel in each axis (block minimum)"));
        specs.push_back(ParamSpec::real("occluder_distance", 1.0, 0.0, 1.0,
                                        "the paper's dilation factor (6.2.1): the largest distance from a caster to the "
                                        "receiver of its penumbra, as a fraction of the light's depth range"));
        specs.push_back(ParamSpec::real("depth_error", 0.05, 0.0, 1.0,
                                        "a tap whose distance to the observer differs by more than this fraction from "
                                        "where its ray meets the centre pixel's tangent plane is another surface"));
        specs.push_back(ParamSpec::boolean("lazy", true,
                                           "lazy shadowing (6.3.2): shadow-test hidden taps on the tangent plane instead of dropping them"));
        return specs;
    }

    ErrorColumns error_columns() const override { return kShadowErrorColumns; }

    FramePlan plan(const ParamSet& params) const override {
        const int block = int(params.integer("coarse_block"));
        const std::array<float, 4> dilate{float(block), float(params.real("occluder_distance")), 0.0f, 0.0f};
        const std::array<float, 4> blur{float(params.integer("kernel")), float(params.real("depth_error")),
                                        params.boolean("lazy") ? 1.0f : 0.0f, 0.0f};
        FramePlan plan;
        plan.shadow_map = shadow_map_needs(params);
        // The coarse map (6.2.1): block minima of the depth map, then a separable min filter whose
        // reach follows the light's size (ssss_dilate.comp), up to kMaxDilation coarse texels.
        plan.shadow_map->coarse_filters = {{"coarse_block", block_min_comp, 0, true, {}, block},
                                           {"coarse_x", ssss_dilate_comp, kMaxDilation, true, dilate},
                                           {"coarse_y", ssss_dilate_comp, kMaxDilation, false, dilate}};
        plan.screen_shadow = ScreenShadowNeeds{ssss_screen_frag,
                                               {{"blur_x", ssss_blur_comp, 0, true, blur},
                                                {"blur_y", ssss_blur_comp, 0, false, blur}}};
        plan.needs_area_light = true;
        plan.forward_fragment_spirv = ssss_frag;
        write_bias_params(params, plan.shader_params);
        plan.shader_params.values[2] = float(block);  // the screen pass finds a texel's coarse block
        return plan;
    }

    // The dilation's cost cap: coarse texels each way (a reach beyond it is cut there).
    static constexpr int kMaxDilation = 64;
};

RegisterTechnique<ScreenSpaceSoftShadows> registered;

}  // namespace
}  // namespace canopy
