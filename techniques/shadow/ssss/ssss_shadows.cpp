// shadow.ssss: screen-space soft shadows (Gumbau 2011, chapter 6).
#include "core/registry.hpp"
#include "shaders/shadow/block_min_comp.h"
#include "shaders/shadow/ssss_blur_comp.h"
#include "shaders/shadow/ssss_dilate_comp.h"
#include "shaders/shadow/ssss_frag.h"
#include "shaders/shadow/ssss_screen_frag.h"
#include "ssss_params.h"
#include "../common/shadow_map_params.hpp"
#include "../common/shadow_technique.hpp"

namespace canopy {
namespace {

class ScreenSpaceSoftShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "shadow.ssss"; }
    std::string summary() const override {
        return "screen-space soft shadows: hard shadows blurred by a separable anisotropic Gaussian of eq 6.2 width";
    }
    std::string paper() const override { return "Gumbau 2011 ch. 6, eq 6.2, Table 6.1 'SSSS K5/K11/K23'"; }

    std::vector<ParamSpec> params() const override { return shader::SsssParams::specs(); }


    ShadowPlan plan(const ParamSet& params) const override {
        const shader::SsssParams block = shader::SsssParams::from(params);
        ShadowPlan plan;
        plan.shadow_map = shadow_map_needs(params);
        // The coarse map (6.2.1): block minima of the depth map, then a separable min filter whose
        // reach follows the light's size (ssss_dilate.comp), up to kMaxDilation coarse texels.
        plan.shadow_map->coarse_filters = {{"coarse_block", block_min_comp, 0, true, block.coarse_block},
                                           {"coarse_x", ssss_dilate_comp, kMaxDilation, true},
                                           {"coarse_y", ssss_dilate_comp, kMaxDilation, false}};
        plan.screen_shadow = ScreenShadowNeeds{ssss_screen_frag,
                                               {{"blur_x", ssss_blur_comp, 0, true},
                                                {"blur_y", ssss_blur_comp, 0, false}}};
        plan.needs_area_light = true;
        plan.forward_fragment_spirv = ssss_frag;
        plan.shader_params.set_block(block);
        return plan;
    }

    // The dilation's cost cap: coarse texels each way (a reach beyond it is cut there).
    static constexpr int kMaxDilation = 64;
};

RegisterTechnique<ScreenSpaceSoftShadows> registered;

}  // namespace
}  // namespace canopy
