#include "image_graph.hpp"

#include "graph/pass_context.hpp"
#include "render/frame_uniforms.hpp"

#include "../common/grass_cull.hpp"
#include "../common/grass_passes.hpp"
#include "../common/grass_population.hpp"
#include "../common/macro_passes.hpp"
#include "../common/mip_passes.hpp"
#include "../common/patch_bake.hpp"

#include "shaders/grass/grass_image_macro_frag.h"
#include "shaders/grass/grass_image_macro_terrain_vert.h"
#include "shaders/grass/grass_image_macro_vert.h"
#include "shaders/grass/image_bake_frag.h"

#include <fmt/format.h>

#include <array>
#include <optional>
#include <stdexcept>

namespace canopy::grass {
namespace {

struct Names {
    std::string albedo;  // RGBA32F: albedo, covered (blade_texels.h)
    std::string normal;  // RGBA16F: patch-space normal
    std::string blades;  // RGBA32F: the blade map (blade_texels.h)
    std::string bake_depth;
    std::string quad;    // 6 QuadVertex
    std::string camera;  // PatchBake, looking down
    explicit Names(const std::string& p)
        : albedo(p + "slice_albedo"), normal(p + "slice_normal"), blades(p + "slice_blades"),
          bake_depth(p + "bake_depth"), quad(p + "quad"), camera(p + "bake_camera") {}
};

// The quad over the bake's frame in x and z at `height` above the ground, its coordinates those
// of the top-view bake (BakeView::down: u = x, v = z), then the frame's width in x and z (a cell
// on a terrain reflects its quad across the frame: grass_image_vertex.glsl). Tiled, the frame is
// the cell, and the macro-cells' vertex shader reads x and z as the corner of the macro-cell.
std::array<QuadVertex, 6> slice_quad(const Bounds& bounds, float height, bool tiled) {
    const Bounds f = baked_frame(bounds, tiled);
    std::array<QuadVertex, 6> quad;
    for (size_t i = 0; i < 6; ++i) {
        const glm::vec2 c = kQuadCorners[i];
        quad[i] = {glm::vec4(f.min.x + c.x * (f.max.x - f.min.x), height, f.min.z + c.y * (f.max.z - f.min.z), 1.0f),
                   glm::vec4(c.x, c.y, f.max.x - f.min.x, f.max.z - f.min.z)};
    }
    return quad;
}

}  // namespace

void declare_image_bake(FrameGraph& g, const ImageSettings& s) {
    const Names names(s.prefix);
    const bool tiled = s.macro_cells > 0 || s.selected_by.has_value();
    const float slice_height = s.slice_height;
    const uint32_t mips = mip_levels(s.resolution, s.resolution, s.filtering);
    const ImageExtent extent = bake_extent(s.resolution, s.resolution, s.filtering);
    g.images.push_back({.name = names.albedo, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .extent = extent, .mips = mips,
                        .persistent = true, .arrayed = true});
    g.images.push_back({.name = names.normal, .format = VK_FORMAT_R16G16B16A16_SFLOAT, .extent = extent, .mips = mips,
                        .persistent = true, .arrayed = true});
    g.images.push_back({.name = names.blades, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .extent = extent, .mips = mips,
                        .persistent = true, .arrayed = true});
    g.images.push_back({.name = names.bake_depth, .format = VK_FORMAT_D32_SFLOAT, .extent = extent});
    g.buffers.push_back({.name = names.quad, .bytes = sizeof(QuadVertex) * 6, .usage = kVertexBuffer, .persistent = true});
    g.buffers.push_back({.name = names.camera, .bytes = sizeof(shader::PatchBake), .usage = kUniformBuffer});
    if (s.macro_cells > 0) {  // a quadtree's bands share the field records it declares
        declare_macro_buffers(g, s.macro_terrain);
        g.passes.push_back(macro_setup_pass(s.macro_cells, s.macro_terrain));
    }

    PassDecl setup{.name = s.prefix + "bake_setup", .kind = PassKind::copy, .phase = Phase::load};
    setup.uses = {use(names.quad, Use::transfer_write), use(names.camera, Use::transfer_write)};
    setup.settings = fmt::format("slice_height={} tiled={}", slice_height, tiled);
    setup.record = [slice_height, tiled, names](PassContext& pc) {
        const Bounds bounds = prototype_bounds(first_grass(pc.populations()));
        const auto quad = slice_quad(bounds, slice_height * bounds.max.y, tiled);
        const shader::PatchBake camera = ortho_bake(bounds, BakeView::down, tiled);
        pc.upload(names.quad, quad.data(), sizeof(quad));
        pc.upload(names.camera, &camera, sizeof(camera));
    };
    g.passes.push_back(std::move(setup));

    const RasterState bake = bake_state(image_bake_frag);
    PassDecl top{.name = s.prefix + "bake_top", .kind = PassKind::raster, .phase = Phase::load};
    top.push_constant_bytes = sizeof(DrawConstants);
    top.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(names.camera, Use::uniform, 1),
                cleared(names.albedo, Use::color_attachment, {0.0f, 0.0f, 0.0f, 0.0f}),
                cleared(names.normal, Use::color_attachment, {0.0f, 1.0f, 0.0f, 0.0f}),
                cleared(names.blades, Use::color_attachment, kBladeMapEmpty),
                cleared(names.bake_depth, Use::depth_attachment, kFarDepth, false)};
    top.settings = tiled ? "down, tiled" : "down";
    top.record = [bake, tiled](PassContext& pc) { record_prototype_bake(pc, bake, tiled); };
    g.passes.push_back(std::move(top));
    declare_mip_passes(g, {.colour = names.albedo, .blades = names.blades, .companion = names.normal, .width = s.resolution,
                           .height = s.resolution, .layers = 1, .filtering = s.filtering, .pass_prefix = s.prefix + "top_"});
}

PassDecl image_frame_pass(const ImageSettings& s, const RasterState& per_cell, bool ground,
                          std::vector<ResourceUse> attachments,
                           const std::optional<RasterState>& per_cell_on_terrain) {
    const Names names(s.prefix);
    const uint32_t macro = s.macro_cells;
    PassDecl frame{.name = s.prefix + "slices", .kind = PassKind::raster};
    frame.push_constant_bytes = sizeof(DrawConstants);
    frame.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), sampled_slices(names.albedo, 1, s.filtering),
                  sampled_slices(names.normal, 2, s.filtering), sampled_slices(names.blades, 8, s.filtering),
                  use(names.quad, Use::vertex)};
    frame.uses.insert(frame.uses.end(), attachments.begin(), attachments.end());
    const std::optional<RasterState> objects = ground ? std::optional<RasterState>(ground_state()) : std::nullopt;
    if (s.selected_by) {
        if (!per_cell_on_terrain) throw std::logic_error("image_frame_pass: a quadtree's band needs its shaders on a terrain");
        declare_macro_band_pass(frame, *s.selected_by, objects, per_cell, *per_cell_on_terrain, names.quad);
        frame.settings = fmt::format("one quad per cell or macro-cell (at most {} a side) the quadtree's {} band keeps",
                                     s.selected_by->max_macro, s.selected_by->name);
    } else if (macro > 0) {
        if (!objects) throw std::logic_error("image_frame_pass: macro-cells draw the ground in their pass");
        if (s.culled_by) throw std::logic_error("image_frame_pass: macro-cells are not culled");
        use_macro_buffers(frame, s.macro_terrain);
        RasterState flat;
        flat.vertex_spirv = grass_image_macro_vert;
        flat.fragment_spirv = grass_image_macro_frag;
        flat.vertices = macro_layout();
        RasterState on_terrain = flat;
        on_terrain.vertex_spirv = grass_image_macro_terrain_vert;
        frame.settings = fmt::format("one quad per {} x {} macro-cell", macro, macro);
        frame.record = [objects, flat, on_terrain, quad = names.quad, terrain = s.macro_terrain](PassContext& pc) {
            record_ground_and_macros(pc, *objects, flat, on_terrain, quad, kImageCellVertices, terrain);
        };
    } else {
        RasterState slice = per_cell;
        slice.vertices = quad_layout();
        frame.settings = s.culled_by ? "one quad per cell the cull keeps" : "one quad per cell";
        if (s.culled_by) use_cull_survivors(frame, *s.culled_by);
        frame.record = [objects, slice, quad = names.quad, culled_by = s.culled_by](PassContext& pc) {
            if (objects) record_ground(pc, *objects);
            record_copies_culled(pc, slice, quad, kImageCellVertices, culled_by);
        };
    }
    return frame;
}

}  // namespace canopy::grass
