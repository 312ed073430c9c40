// The GPU cull of the first grass population's copies (shaders/grass_cull.comp), shared by
// grass.geometry (culling = "gpu") and grass.lod's three bands: at load the copies and one block
// per cull are uploaded; every frame a compute pass per cull keeps the copies whose box may be
// seen within that cull's distances and writes an indirect draw of them.
#pragma once

#include "graph/frame_graph.hpp"
#include "graph/pass_context.hpp"
#include "graph/raster_state.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace canopy::grass {

// One cull: what it keeps, and what draws its survivors.
struct CullBand {
    std::string prefix;         // of its names (CullNames); "" for a technique's only cull
    float min_distance = 0.0f;  // a box whose farthest point is nearer is dropped
    float max_distance = 0.0f;  // a box whose nearest point is farther is dropped (0: none)
    // 0: the survivors are drawn as the population's prototype (draw_population_indirect); else
    // they carry geometry a technique draws over each copy, this many vertices
    // (draw_over_population_indirect).
    uint32_t vertex_count = 0;
    // The vertices when the population stands on a terrain, where they differ (grass.slices' quads
    // cut at the ground's diagonal); 0: vertex_count.
    uint32_t vertex_count_on_terrain = 0;
};

// A cull's resources and its frame pass: <prefix>cull (its GrassCull block, and the pass),
// <prefix>survivors (the copies kept, packed), <prefix>draw_arguments (the indirect record).
struct CullNames {
    explicit CullNames(const std::string& prefix)
        : block(prefix + "cull"), pass(prefix + "cull"), survivors(prefix + "survivors"),
          arguments(prefix + "draw_arguments") {}
    std::string block, pass, survivors, arguments;
};
inline constexpr const char* kCullCopies = "cull_copies";  // every copy of the first grass population, shared

// The copies' buffer, each cull's block, survivors and arguments, the load-phase upload
// (`cull_setup`) and one frame pass per cull, one invocation per copy.
void declare_grass_cull(FrameGraph& g, const std::vector<CullBand>& bands);

// The uses a pass drawing a cull's survivors adds (vertex copies, indirect arguments).
void use_cull_survivors(PassDecl& pass, const std::string& prefix = "");

// Draws every population with the bound pipeline: the first grass population's survivors of the
// cull `prefix` indirectly, the others whole.
void draw_populations_culled(PassContext& pc, const std::string& prefix = "");

// record_copies (grass_passes.hpp), the first grass population's copies being those the cull
// `culled_by` kept (the others whole); without a cull, record_copies itself.
void record_copies_culled(PassContext& pc, const RasterState& over, const std::string& vertex_buffer,
                          uint32_t vertex_count, const std::optional<std::string>& culled_by);

}  // namespace canopy::grass
