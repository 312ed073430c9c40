// What grass.image declares, apart from the technique, so grass.lod's far band declares the same
// bake and quads: the top view baked at load (Lemme §5.3) and the frame pass that shows it on one
// horizontal quad per cell or macro-cell.
#pragma once

#include "graph/frame_graph.hpp"
#include "graph/raster_state.hpp"

#include "../common/macro_passes.hpp"
#include "../common/mip_passes.hpp"
#include "../common/quadtree_passes.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace canopy::grass {

struct ImageSettings {
    uint32_t resolution = 256;   // texels across the bake
    float slice_height = 0.1f;   // a fraction of the patch's tallest blade
    uint32_t macro_cells = 0;    // 0: a quad per cell; k: per k x k macro-cell
    std::string prefix;          // before every resource and pass name ("" for grass.image)
    // The frame pass draws the copies the cull of this prefix kept (grass_cull.hpp), not all
    // (per-cell quads only).
    std::optional<std::string> culled_by;
    // The frame pass draws the macro-cells this band of a quadtree selects each frame
    // (quadtree_passes.hpp), with the tiled bake; its shaders are the macro bodies
    // (shaders/grass_image_macro_*.glsl), given as `per_cell` to image_frame_pass.
    std::optional<QuadtreeBandDecl> selected_by;
    // How macro-cells follow a terrain (grass.image's own; not a quadtree's): each quad's corners
    // on the field's grid heights, uneven macro-cells split (macro_passes.hpp). The setup and the
    // frame pass share its count, so both passes are declared from the same settings.
    MacroTerrain macro_terrain{.max_unplanarity = 0.05f};
    SliceFiltering filtering;    // how the bake is filtered when drawn
};

// The vertices the frame pass draws per cell (a cull drawing them needs it).
inline constexpr uint32_t kImageCellVertices = 6;

// The bake's images and buffers and the load-phase passes that fill them.
void declare_image_bake(FrameGraph& g, const ImageSettings& s);

// The frame pass: with `ground`, the scene's objects first; then one quad per cell (drawn with
// `per_cell`, shaders of the image's bodies, shaders/grass_image_vertex.glsl and
// grass_image_fragment.glsl) or per macro-cell. `attachments`: colour and depth, cleared or loaded.
// Under a quadtree (`selected_by`), `per_cell_on_terrain` are the macro shaders for a field on a terrain.
PassDecl image_frame_pass(const ImageSettings& s, const RasterState& per_cell, bool ground,
                          std::vector<ResourceUse> attachments,
                          const std::optional<RasterState>& per_cell_on_terrain = std::nullopt);

}  // namespace canopy::grass
