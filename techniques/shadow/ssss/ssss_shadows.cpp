// shadow.ssss: screen-space soft shadows (Gumbau 2011, chapter 6).
#include "core/registry.hpp"
#include "shaders/block_min_comp.h"
#include "shaders/min_filter_comp.h"
#include "shaders/ssss_blur_comp.h"
#include "shaders/ssss_frag.h"
#include "shaders/ssss_screen_frag.h"
#include "../common/shadow_map_params.hpp"

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
        specs.push_back(ParamSpec::integer("dilation", 2, 0, 32,
                                           "min-filter radius of the coarse map in coarse texels: the paper's user "
                                           "factor, large enough to reach outer penumbrae"));
        specs.push_back(ParamSpec::real("depth_error", 0.05, 0.0, 1.0,
                                        "relative difference in distance to the observer that marks another surface"));
        specs.push_back(ParamSpec::boolean("lazy", true,
                                           "lazy shadowing (6.3.2): shadow-test hidden taps on the tangent plane instead of dropping them"));
        return specs;
    }

    FramePlan plan(const ParamSet& params) const override {
        const int block = int(params.integer("coarse_block"));
        const int dilation = int(params.integer("dilation"));
        const std::array<float, 4> blur{float(params.integer("kernel")), float(params.real("depth_error")),
                                        params.boolean("lazy") ? 1.0f : 0.0f, 0.0f};
        FramePlan plan;
        plan.shadow_map = shadow_map_needs(params);
        // The coarse map (6.2.1): block minima of the depth map, then a separable min filter.
        plan.shadow_map->coarse_filters = {{"coarse_block", block_min_comp, 0, true, {}, block}};
        if (dilation > 0) {
            plan.shadow_map->coarse_filters.push_back({"coarse_x", min_filter_comp, dilation, true, {}});
            plan.shadow_map->coarse_filters.push_back({"coarse_y", min_filter_comp, dilation, false, {}});
        }
        plan.screen_shadow = ScreenShadowNeeds{ssss_screen_frag,
                                               {{"blur_x", ssss_blur_comp, 0, true, blur},
                                                {"blur_y", ssss_blur_comp, 0, false, blur}}};
        plan.needs_area_light = true;
        plan.forward_fragment_spirv = ssss_frag;
        write_bias_params(params, plan.shader_params);
        return plan;
    }
};

RegisterTechnique<ScreenSpaceSoftShadows> registered;

}  // namespace
}  // namespace canopy
