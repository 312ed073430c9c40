// What grass.volume declares, apart from the technique, so grass.lod's middle band declares the
// same bake and cuboids: the slice images and their load-phase bakes (Lemme §4.2.1), the cuboid,
// and the frame pass that ray-casts one cuboid per cell or macro-cell.
#pragma once

#include "graph/frame_graph.hpp"
#include "graph/raster_state.hpp"

#include "../common/macro_passes.hpp"
#include "../common/mip_passes.hpp"
#include "../common/quadtree_passes.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace canopy::grass {

struct VolumeSettings {
    uint32_t slices = 8;              // per direction
    uint32_t resolution = 256;        // texels across the patch
    uint32_t height_resolution = 64;  // texels up its height
    uint32_t macro_cells = 0;         // 0: a cuboid per cell; k: per k x k macro-cell
    std::string prefix;               // before every resource and pass name ("" for grass.volume)
    // The frame pass draws the copies the cull of this prefix kept (grass_cull.hpp), not all
    // (per-cell cuboids only).
    std::optional<std::string> culled_by;
    // The frame pass draws the macro-cells this band of a quadtree selects each frame
    // (quadtree_passes.hpp), with the tiled bake; its shaders are the macro bodies
    // (shaders/grass_volume_macro_*.glsl), given as `per_cell` to volume_frame_pass.
    std::optional<QuadtreeBandDecl> selected_by;
    // How macro-cells follow a terrain (grass.volume's own; not a quadtree's): each cuboid over
    // its ground's height range, each hit's lookup shifted by the ground under it; never split
    // (macro_passes.hpp). The setup and the frame pass share its count.
    MacroTerrain macro_terrain{.height_ranges = true};
    SliceFiltering filtering;         // how the slices are filtered when drawn
};

// The vertices the frame pass draws per cell: a cuboid's 12 triangles.
inline constexpr uint32_t kVolumeCellVertices = 36;

// The slices' images and buffers and the load-phase passes that bake them.
void declare_volume_bake(FrameGraph& g, const VolumeSettings& s);

// The frame pass: with `ground`, the scene's objects first (grass::ground_state); then one cuboid
// per cell (drawn with `per_cell`, a vertex and fragment shader of the volume's bodies,
// shaders/grass_volume_vertex.glsl and grass_volume_fragment.glsl) or per macro-cell.
// `attachments`: the colour and depth the pass renders into, cleared or loaded. Under a quadtree
// (`selected_by`), `per_cell_on_terrain` are the macro shaders for a field on a terrain.
PassDecl volume_frame_pass(const VolumeSettings& s, const RasterState& per_cell, bool ground,
                           std::vector<ResourceUse> attachments,
                           const std::optional<RasterState>& per_cell_on_terrain = std::nullopt);

// The name of the slices' albedo-and-threshold array (RGBA32F, 2n layers) under `prefix`.
std::string volume_albedo_name(const std::string& prefix);

}  // namespace canopy::grass
