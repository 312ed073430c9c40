// What every grass technique's frame graph declares alike: resource uses written briefly, the
// pipeline that draws the scene's own objects (the ground) with the family's shading, and what
// the image-based techniques share: the load-phase bake of the prototype and the quads that show
// it once per cell.
#pragma once

#include "graph/frame_graph.hpp"
#include "graph/pass_context.hpp"
#include "graph/raster_state.hpp"
#include "core/technique.hpp"

#include "../shaders/blade_texels.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace canopy::grass {

inline ResourceUse use(const std::string& resource, Use how, int binding = -1) { return {resource, how, binding}; }
inline ResourceUse use(const std::string& resource, Use how, int binding, SamplerKind sampler) {
    return {resource, how, binding, sampler};
}

// What a blade map is cleared to: no blade.
inline constexpr std::array<float, 4> kBladeMapEmpty = {shader::BLADE_MAP_EMPTY.x, shader::BLADE_MAP_EMPTY.y,
                                                        shader::BLADE_MAP_EMPTY.z, shader::BLADE_MAP_EMPTY.w};

// An attachment cleared at the pass's start, its level 0 (an image with mips has them made from it
// after); `layer`: one layer of a layered image (else all).
inline ResourceUse cleared(const std::string& image, Use how, std::array<float, 4> clear, bool store = true,
                           uint32_t layer = ~0u) {
    ResourceUse u{image, how};
    u.clear = clear;
    u.store = store;
    u.range = Subresource{0, 1, 0, ~0u};
    if (layer != ~0u) u.range = Subresource{0, 1, layer, 1};
    return u;
}

inline constexpr std::array<float, 4> kFarDepth{1.0f, 0.0f, 0.0f, 0.0f};

// The blades' `samples` and `coverage` (grass.geometry, grass.lod): lavapipe's 1 or 4 samples,
// and alpha-to-coverage only with 4.
std::optional<ParamConflict> blade_samples_conflict(const ParamSet& params);

// After a multisampled frame: the camera depth, not resolved from the multisampled passes, cleared
// (far) so that nothing reads undefined memory. Image errors do not use it.
PassDecl clear_camera_depth_pass();

// scene.vert and grass_ground.frag: the scene's objects shaded as the blades are.
RasterState ground_state();

// `layout` without the attributes at locations [first, last]; their bindings stay, so the
// buffers a draw binds keep their slots.
VertexLayout without_locations(VertexLayout layout, uint32_t first, uint32_t last);

// A bake of the prototype: shaders/patch_bake.vert (its camera at binding 1) and `fragment_spirv`,
// with the population's layout less the copies' attributes (locations 2-9): the prototype is
// drawn in patch space.
RasterState bake_state(std::span<const uint32_t> fragment_spirv);
// Records that bake: the first grass population's prototype, drawn once, or `tiled` nine times
// (PatchBake::tiles); nothing without one.
void record_prototype_bake(PassContext& pc, const RasterState& bake, bool tiled = false);

// One vertex of the quads that show a bake, patch space (w: whatever the technique's shader
// reads there, e.g. the image layer), and its coordinates in the baked image.
struct QuadVertex {
    glm::vec4 position;
    glm::vec4 uv;
};
// The corners of a quad's two triangles, (0, 0) to (1, 1).
inline constexpr std::array<glm::vec2, 6> kQuadCorners{glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1),
                                                       glm::vec2(0, 0), glm::vec2(1, 1), glm::vec2(0, 1)};
// QuadVertex at locations 0-1 (binding 0), then the copies (VertexLayout::population_copies).
VertexLayout quad_layout();

// What the image-based techniques' frame pass records: the scene's objects with `ground`
// (record_ground), then `vertex_count` vertices of `vertex_buffer` drawn with `over` once per copy
// of every population (record_copies).
void record_ground(PassContext& pc, const RasterState& ground);
void record_copies(PassContext& pc, const RasterState& over, const std::string& vertex_buffer, uint32_t vertex_count);
void record_ground_and_copies(PassContext& pc, const RasterState& ground, const RasterState& over,
                              const std::string& vertex_buffer, uint32_t vertex_count);

}  // namespace canopy::grass
