// The GPU cull of the first grass population's copies (shaders/grass_cull.glsl), shared by
// grass.geometry (culling = "gpu") and grass.lod's near band: at load the copies and the cull block
// are uploaded; every frame a compute pass keeps the copies whose box may be seen (and lies within
// the technique's distance) and writes an indirect draw of them.
#pragma once

#include "graph/frame_graph.hpp"
#include "graph/pass_context.hpp"

#include <cstdint>
#include <span>

namespace canopy::grass {

namespace cull_names {
inline constexpr const char* kCull = "cull";                // GrassCull
inline constexpr const char* kCopies = "cull_copies";       // PopulationInstance per copy of the first grass population
inline constexpr const char* kSurvivors = "survivors";      // the copies the cull keeps, packed
inline constexpr const char* kArguments = "draw_arguments"; // VkDrawIndexedIndirectCommand
}  // namespace cull_names

// The cull's buffers, its load-phase upload (`cull_setup`) and its frame pass (`cull`), which runs
// `cull_spirv` (a compute shader including grass_cull.glsl) one invocation per copy.
void declare_grass_cull(FrameGraph& g, std::span<const uint32_t> cull_spirv);

// The uses a pass drawing the survivors adds (vertex copies, indirect arguments).
void use_cull_survivors(PassDecl& pass);

// Draws every population with the bound pipeline: the first grass population's survivors
// indirectly, the others whole.
void draw_populations_culled(PassContext& pc);

}  // namespace canopy::grass
