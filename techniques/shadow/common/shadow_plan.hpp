// The shadow family's plans: which maps a technique renders from the shadow light, how it
// prefilters them and which fragment shader lights the scene with them. Pure data; shadow_graph()
// turns a plan into the frame graph the harness runs.
#pragma once

#include "core/shader_params.hpp"

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace canopy {

enum class DepthFormat { d16, d32f };
const char* to_string(DepthFormat format);

// Storage of a moment map's texels: one, two or four channels of 16 or 32-bit float, or four
// 16-bit unsigned normalised channels (moment shadow maps' quantised moments).
enum class MomentFormat { r16f, r32f, rg16f, rg32f, rgba16f, rgba32f, rgba16unorm };
const char* to_string(MomentFormat format);
uint32_t bytes_per_texel(MomentFormat format);
VkFormat vk_format(MomentFormat format);
VkFormat vk_format(DepthFormat format);

// One 1D pass of a separable prefilter over the moment map: a compute shader reading the
// previous result (`src`, sampler2D, NEAREST) and writing the next (`dst`, image2D); see
// techniques/shadow/shaders/separable_filter.glsl for its interface. Filters with parameters read them
// from the technique's parameter block (frame.technique; FilterExtras gives them the frame).
struct FilterPass {
    std::string name;                          // timing label, e.g. "blur_x"
    std::span<const uint32_t> compute_spirv;
    int radius = 1;                            // texels on each side of the centre
    bool horizontal = true;
    int downsample = 1;                        // output is ceil(input / downsample) in both axes
};

// A depth-only shadow map rendered from the scene's shadow light. It stores linear depth
// (distance along the light's axis, normalised to the light's [near, far]) so that every
// technique can compare and filter depths in the same, well-conditioned units.
struct ShadowMapNeeds {
    uint32_t resolution = 1024;
    DepthFormat format = DepthFormat::d32f;
    // Bind a depth-compare sampler with LINEAR filtering (hardware 2x2 PCF). The Vulkan spec
    // allows LINEAR with compareEnable even where the format lacks FILTER_LINEAR; the harness
    // requires SAMPLED_IMAGE_DEPTH_COMPARISON instead and reports which sampler was used.
    bool compare_sampler = false;
    // Separable passes that turn the depth map into a "coarse" R32F map the lit or screen pass
    // samples at binding 4 (e.g. the min-filtered map of screen-space soft shadows). Pass 0
    // reads the depth map itself; every pass may read the frame uniforms (binding 2).
    std::vector<FilterPass> coarse_filters;
};



// A colour shadow map holding per-texel statistics of the casters' depth (moments,
// exponentials, min/max/mean), rendered from the shadow light, then prefiltered by the
// passes in order. The lit pass samples the result with LINEAR filtering (binding 3).
struct MomentMapNeeds {
    uint32_t resolution = 1024;
    MomentFormat format = MomentFormat::rg32f;
    // Writes the statistics of the fragment's normalised linear light depth
    // (include techniques/shadow/shaders/moment_output.glsl).
    std::span<const uint32_t> fragment_spirv;
    std::array<float, 4> clear_value{1.0f, 1.0f, 1.0f, 1.0f};  // the statistics of depth 1 (no caster)
    std::vector<FilterPass> prefilter;
};

// Screen-space shadowing (Gumbau 2011 ch. 6): after the shadow map, a camera pass renders the
// scene into two buffers — rgba32f per-pixel shadow data and rgba16f world normals — then
// separable compute passes filter the first in screen space (they may read the frame
// uniforms, the depth map and the normals; see FilterExtras), and the lit pass reads the
// result at its own pixel (binding 5).
struct ScreenShadowNeeds {
    std::span<const uint32_t> fragment_spirv;  // writes both buffers (include screen_shadow_output.glsl)
    std::vector<FilterPass> filters;
};

// What one shadow technique, with one set of parameter values, needs for a frame: the family's
// mould, turned into a FrameGraph by shadow_graph() (shadow_graph.hpp).
struct ShadowPlan {
    std::optional<ShadowMapNeeds> shadow_map;
    std::optional<MomentMapNeeds> moment_map;
    std::optional<ScreenShadowNeeds> screen_shadow;  // needs shadow_map
    bool needs_area_light = false;                 // refuses scenes whose shadow light has no size
    std::span<const uint32_t> forward_fragment_spirv;  // the lit pass's fragment shader
    ShaderParams shader_params;
};

}  // namespace canopy
