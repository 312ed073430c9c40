// What grass.slices declares, apart from the technique, so another technique (grass.lod's middle
// band) can declare the same bake and slices: Boulanger's axis-aligned BTF slices (2008, §4.2.3):
// n vertical slices along x and n along z and one horizontal slice per cell, each baked at load
// under five light directions from both sides it can be seen from.
#pragma once

#include "graph/frame_graph.hpp"
#include "graph/raster_state.hpp"

#include "../common/mip_passes.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace canopy::grass {

// A shadowed bake's depth bias, in texels of its light views, so that the blade a texel shows does
// not shadow itself.
inline constexpr float kBakeShadowBias = 1.0f;
// And its normal offset (bake_shadows.h), in the same texels.
inline constexpr float kBakeShadowNormalOffset = 1.5f;
// A tiled light view's margin around the cell across the light, in its texels: room for the
// offsets and the 2 x 2 compare of a lookup at the cell's edge.
inline constexpr float kBakeShadowMargin = 4.0f;

struct SlicesSettings {
    uint32_t slices = 8;              // vertical slices per direction
    uint32_t resolution = 256;        // texels across the patch (and each way of the horizontal slice)
    uint32_t height_resolution = 64;  // texels up a vertical slice
    float slice_height = 0.1f;        // the horizontal slice's height, a fraction of the tallest blade
    bool neighbours = true;           // bake the patch with its 8 neighbours, cut to the cell
    // Above 0: bake the blades' shadows into the rows (bake_shadows.h), from one depth layer per
    // baked light this many texels a side, looked up with a bias of kBakeShadowBias texels.
    uint32_t shadow_resolution = 0;
    std::string prefix;               // before every resource and pass name ("" for grass.slices)
    // The frame pass draws the copies the cull of this prefix kept (grass_cull.hpp), not all.
    std::optional<std::string> culled_by;
    SliceFiltering filtering;         // how the slices are filtered when drawn
};

// The vertices the frame pass draws per cell: 2n vertical quads and the horizontal one; on a
// terrain each vertical quad is cut in two where the ground's diagonal crosses it.
inline uint32_t slices_cell_vertices(const SlicesSettings& s) { return 6 * (2 * s.slices + 1); }
inline uint32_t slices_cell_vertices_on_terrain(const SlicesSettings& s) { return 6 * (4 * s.slices + 1); }

// The slices' images, the quads that show them and the load-phase passes that bake them: one pass
// per vertical slice and side (front: seen from +axis; back: from -axis) and one for the
// horizontal slice, each writing the slice's albedo and density threshold (the ambient row of
// Figure 4.6, and Figure 4.9's threshold texture) and its five lit rows (btf_interpolation.h).
// With a shadow_resolution, first one depth pass per baked light direction (bake_light_<direction>).
void declare_slices_bake(FrameGraph& g, const SlicesSettings& s);

// The frame pass: with `ground`, the scene's objects first (grass::ground_state); then the 2n + 1
// quads of every cell, drawn with `per_cell` (shaders/grass_slices_vertex.glsl and
// grass_slices_fragment.glsl). `attachments`: the colour and depth it renders into.
PassDecl slices_frame_pass(const SlicesSettings& s, const RasterState& per_cell, bool ground,
                           std::vector<ResourceUse> attachments);

// Layer names and layout: the vertical slices' albedo array holds, for axis a (0: x, 1: z),
// slice k and side v (0: front, 1: back), layer (a n + k) 2 + v; their lit array holds that
// layer's five rows at 5 layer + row (btf_light_direction's order).
inline uint32_t slice_side_layer(uint32_t axis, uint32_t slice, uint32_t side, uint32_t n) {
    return (axis * n + slice) * 2 + side;
}
std::string slices_albedo_name(const std::string& prefix);
std::string slices_lit_name(const std::string& prefix);
std::string top_albedo_name(const std::string& prefix);
std::string top_lit_name(const std::string& prefix);

}  // namespace canopy::grass
