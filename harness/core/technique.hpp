// The technique plug-in contract. A technique registers by name, declares typed parameters,
// and, for chosen parameter values, returns a FramePlan: the passes and resources it needs.
// The harness builds only what the plan asks for (Falcor-style: passes declare their inputs).
#pragma once

#include "core/param.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace canopy {

enum class DepthFormat { d16, d32f };
const char* to_string(DepthFormat format);

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
};

// Parameters a technique hands to its shaders: 16 floats in the frame uniform block
// (`technique_params[4]` in GLSL) plus an optional table of up to 128 vec2 sample offsets.
struct ShaderParams {
    std::array<float, 16> values{};
    std::vector<std::array<float, 2>> offsets;  // e.g. a Poisson disk; size() <= kMaxOffsets
    static constexpr size_t kMaxOffsets = 128;
};

// What one technique, with one set of parameter values, needs for a frame.
struct FramePlan {
    std::optional<ShadowMapNeeds> shadow_map;
    bool needs_area_light = false;                 // refuses scenes whose shadow light has no size
    std::span<const uint32_t> forward_fragment_spirv;  // the lit pass's fragment shader
    ShaderParams shader_params;
};

class Technique {
public:
    virtual ~Technique() = default;
    virtual std::string name() const = 0;         // "shadow.pcf"
    virtual std::string summary() const = 0;      // one line for `canopy list`
    virtual std::string paper() const = 0;        // where it comes from
    virtual std::vector<ParamSpec> params() const = 0;
    virtual FramePlan plan(const ParamSet& params) const = 0;
};

}  // namespace canopy
