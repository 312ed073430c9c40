// The technique plug-in contract. A technique registers by name, declares typed parameters,
// and, for chosen parameter values, returns a FramePlan: the passes and resources it needs.
// The harness builds only what the plan asks for (Falcor-style: passes declare their inputs).
#pragma once

#include "core/error_columns.hpp"
#include "core/param.hpp"
#include "core/param_block.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace canopy {

enum class DepthFormat { d16, d32f };
const char* to_string(DepthFormat format);

// Storage of a moment map's texels: one, two or four channels of 16 or 32-bit float, or four
// 16-bit unsigned normalised channels (moment shadow maps' quantised moments).
enum class MomentFormat { r16f, r32f, rg16f, rg32f, rgba16f, rgba32f, rgba16unorm };
const char* to_string(MomentFormat format);
uint32_t bytes_per_texel(MomentFormat format);

// One 1D pass of a separable prefilter over the moment map: a compute shader reading the
// previous result (`src`, sampler2D, NEAREST) and writing the next (`dst`, image2D); see
// harness/shaders/separable_filter.glsl for its interface. Filters with parameters read them
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
    // (include harness/shaders/moment_output.glsl).
    std::span<const uint32_t> fragment_spirv;
    std::array<float, 4> clear_value{1.0f, 1.0f, 1.0f, 1.0f};  // the statistics of depth 1 (no caster)
    std::vector<FilterPass> prefilter;
};

// Parameters a technique hands to its shaders: its parameter struct (declared once with
// CANOPY_PARAM_BLOCK, harness/shaders/param_block.h), uploaded as `frame.technique` at the end of
// the frame uniform block, plus an optional table of up to 128 vec2 sample offsets.
struct ShaderParams {
    std::array<std::byte, kMaxParamBlockBytes> block{};  // the struct's bytes (std140 = C++ layout)
    std::vector<ParamBlockMember> layout;                 // its members; empty: no block
    std::vector<std::array<float, 2>> offsets;  // e.g. a Poisson disk; size() <= kMaxOffsets
    static constexpr size_t kMaxOffsets = 128;

    template <class Block>
    void set_block(const Block& values) {
        static_assert(sizeof(Block) <= kMaxParamBlockBytes && std::is_trivially_copyable_v<Block>);
        block.fill(std::byte{0});
        std::memcpy(block.data(), &values, sizeof(Block));
        layout = Block::layout();
    }
    // The block as `Block` (tests read what a plan hands its shaders).
    template <class Block>
    Block get_block() const {
        static_assert(sizeof(Block) <= kMaxParamBlockBytes && std::is_trivially_copyable_v<Block>);
        Block values;
        std::memcpy(&values, block.data(), sizeof(Block));
        return values;
    }
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

// What one technique, with one set of parameter values, needs for a frame.
struct FramePlan {
    std::optional<ShadowMapNeeds> shadow_map;
    std::optional<MomentMapNeeds> moment_map;
    std::optional<ScreenShadowNeeds> screen_shadow;  // needs shadow_map
    bool needs_area_light = false;                 // refuses scenes whose shadow light has no size
    std::span<const uint32_t> forward_fragment_spirv;  // the lit pass's fragment shader
    ShaderParams shader_params;
};

// A combination of parameter values, each valid on its own, that a technique refuses because it
// would render something meaningless (e.g. a stored exponential that overflows its format).
struct ParamConflict {
    std::vector<std::string> params;  // the parameters involved, the one to change first
    std::string message;              // what would go wrong
    std::string hint;                 // the safe range, what to change
};

class Technique {
public:
    virtual ~Technique() = default;
    virtual std::string name() const = 0;         // "shadow.pcf"
    virtual std::string summary() const = 0;      // one line for `canopy list`
    virtual std::string paper() const = 0;        // where it comes from
    virtual std::vector<ParamSpec> params() const = 0;
    virtual FramePlan plan(const ParamSet& params) const = 0;
    // Which error columns mean something for this technique: its family's declaration
    // (core/error_columns.hpp); reports show the others as "n/a".
    virtual ErrorColumns error_columns() const = 0;
    // A refused combination of `params`, or nullopt. Checked by resolve_params when a config's
    // cases are expanded, before anything runs or is written.
    virtual std::optional<ParamConflict> conflict(const ParamSet& params) const;
};

// ParamSet::resolve with `technique`'s specs (`specs`: technique.params(), built once by a caller
// resolving many cases), then its conflict check: a refused combination throws ConfigError at the
// line of the first conflicting parameter the config gives (else at `where`), with the
// technique's hint.
ParamSet resolve_params(const Technique& technique, const std::vector<ParamSpec>& specs,
                        const std::map<std::string, ParamValue>& given, const std::map<std::string, int>& given_lines,
                        const SourceLocation& where);

}  // namespace canopy
