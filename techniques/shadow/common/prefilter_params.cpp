#include "prefilter_params.hpp"

#include "shaders/shadow/box_filter_comp.h"

namespace canopy {

bool half_precision(const ParamSet& params) { return params.choice("precision") == "fp16"; }

MomentMapNeeds moment_map_needs(const ParamSet& params, int channels, std::span<const uint32_t> fragment_spirv,
                                std::array<float, 4> clear_value, std::span<const uint32_t> filter_shader) {
    const bool half = half_precision(params);
    MomentMapNeeds needs;
    needs.resolution = uint32_t(params.integer("resolution"));
    needs.format = channels == 1   ? (half ? MomentFormat::r16f : MomentFormat::r32f)
                   : channels == 2 ? (half ? MomentFormat::rg16f : MomentFormat::rg32f)
                                   : (half ? MomentFormat::rgba16f : MomentFormat::rgba32f);
    needs.fragment_spirv = fragment_spirv;
    needs.clear_value = clear_value;
    const int radius = int(params.integer("filter")) / 2;
    if (radius > 0) {
        const std::span<const uint32_t> shader = filter_shader.empty() ? std::span<const uint32_t>(box_filter_comp) : filter_shader;
        needs.prefilter.push_back({"prefilter_x", shader, radius, true});
        needs.prefilter.push_back({"prefilter_y", shader, radius, false});
    }
    return needs;
}

}  // namespace canopy
