// The shadow family's frame graph, built from a ShadowPlan: a depth map or a moment map rendered
// from the shadow light, their compute prefilters, an optional screen-space pass with its
// filters, and the lit pass. Every shadow technique runs on it.
#pragma once

#include "graph/frame_graph.hpp"
#include "shadow_plan.hpp"

#include <string>

namespace canopy {

FrameGraph shadow_graph(const ShadowPlan& plan);

// What a filter chain's shaders may read besides their source (separable_filter.glsl).
struct FilterChainInputs {
    bool frame_uniforms = false;  // binding 2
    std::string shadow_depth;     // binding 3, NEAREST
    std::string aux;              // binding 4, NEAREST
};

// Adds to `graph` a chain of compute FilterPasses over image `source` (width x height texels, or
// the camera target's size when `screen_sized`): pass 0 reads the source, each later pass the
// previous output. Same-size outputs ping-pong between two images named `prefix`_a/_b (or between
// _a and the source, when `write_back` lets later passes overwrite it); a chain with a
// downsampling pass gets one image per pass, `prefix`_<i>, of ceil(input / downsample) texels.
// Returns the name of the image the last pass writes.
std::string add_filter_chain(FrameGraph& graph, const std::string& prefix, const std::string& source, bool write_back,
                             uint32_t width, uint32_t height, VkFormat format, const std::vector<FilterPass>& passes,
                             const FilterChainInputs& inputs, bool screen_sized);

// Names of the images shadow_graph declares, for tests that read them back.
namespace shadow_images {
inline constexpr const char* kDepthMap = "shadow_depth";
inline constexpr const char* kMomentMap = "moment_map";
// The image each chain's last filter writes (filters ping-pong, so it depends on the plan).
std::string coarse_map(const ShadowPlan& plan);     // needs shadow_map->coarse_filters
std::string screen_shadow(const ShadowPlan& plan);  // needs screen_shadow
std::string moment_result(const ShadowPlan& plan);  // needs moment_map
}  // namespace shadow_images

}  // namespace canopy
