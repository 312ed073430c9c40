#include "volume_graph.hpp"

#include "graph/pass_context.hpp"
#include "render/frame_uniforms.hpp"

#include "../common/grass_cull.hpp"
#include "../common/grass_passes.hpp"
#include "../common/grass_population.hpp"
#include "../common/macro_passes.hpp"
#include "../common/patch_bake.hpp"
#include "../shaders/volume_walk.h"

#include "shaders/grass/grass_volume_macro_frag.h"
#include "shaders/grass/grass_volume_macro_terrain_frag.h"
#include "shaders/grass/grass_volume_macro_terrain_vert.h"
#include "shaders/grass/grass_volume_macro_vert.h"
#include "shaders/grass/volume_bake_frag.h"

#include <fmt/format.h>

#include <array>
#include <optional>
#include <stdexcept>

namespace canopy::grass {
namespace {

// Resource names under the settings' prefix.
struct Names {
    std::string albedo;      // RGBA32F x 2n layers: albedo, covered (blade_texels.h)
    std::string normal;      // RGBA16F x 2n layers: patch-space normal
    std::string blades;      // RGBA32F x 2n layers: the blade map (blade_texels.h)
    std::string bake_depth;
    std::string cuboid;      // 36 QuadVertex: corner (q space), face plane
    std::string box;         // VolumeBox
    explicit Names(const std::string& p)
        : albedo(p + "slices_albedo"), normal(p + "slices_normal"), blades(p + "slices_blades"),
          bake_depth(p + "bake_depth"), cuboid(p + "cuboid"),
          box(p + "volume_box") {}
};

constexpr uint32_t kCuboidVertices = kVolumeCellVertices;

// Layers 0 .. n-1 hold the slices along x (planes x = const, baked looking along x), layers
// n .. 2n-1 those along z: what grass_volume_fragment.glsl reads.
struct SliceBake {
    BakeView view;
    uint32_t section;  // k along the slice's axis
    uint32_t layer;
    std::string camera;  // its PatchBake's buffer
};

std::vector<SliceBake> slice_bakes(uint32_t n, const std::string& prefix) {
    std::vector<SliceBake> bakes;
    for (uint32_t axis = 0; axis < 2; ++axis)
        for (uint32_t k = 0; k < n; ++k)
            bakes.push_back({axis == 0 ? BakeView::along_x : BakeView::along_z, k, axis * n + k,
                             fmt::format("{}bake_{}{}", prefix, axis == 0 ? 'x' : 'z', k)});
    return bakes;
}

// The camera of one slice: the bake's frame seen along the slice's axis, keeping section k of n.
shader::PatchBake slice_camera(const Bounds& bounds, const SliceBake& slice, uint32_t n, bool tiled) {
    const Bounds f = baked_frame(bounds, tiled);
    shader::PatchBake bake = ortho_bake(bounds, slice.view, tiled);
    const int axis = slice.view == BakeView::along_x ? 0 : 2;
    bake.section.x = bake_section_start(f, axis, slice.section, n, tiled);
    bake.section.y = bake_section_start(f, axis, slice.section + 1, n, tiled);
    return bake;
}

// The unit cube's six faces as two triangles each, with each face's outward plane.
std::array<QuadVertex, kCuboidVertices> cuboid() {
    std::array<QuadVertex, kCuboidVertices> vertices;
    size_t v = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
            glm::vec4 plane(0.0f);
            plane[axis] = side == 0 ? -1.0f : 1.0f;
            plane.w = side == 0 ? 0.0f : 1.0f;
            for (const glm::vec2 c : kQuadCorners) {
                glm::vec4 corner(0.0f, 0.0f, 0.0f, 1.0f);
                corner[axis] = float(side);
                corner[u_axis] = c.x;
                corner[v_axis] = c.y;
                vertices[v++] = {corner, plane};
            }
        }
    return vertices;
}

}  // namespace

std::string volume_albedo_name(const std::string& prefix) { return Names(prefix).albedo; }

void declare_volume_bake(FrameGraph& g, const VolumeSettings& s) {
    const Names names(s.prefix);
    const uint32_t n = s.slices;
    const bool tiled = s.macro_cells > 0 || s.selected_by.has_value();
    const ImageExtent extent = bake_extent(s.resolution, s.height_resolution, s.filtering);
    const std::vector<SliceBake> bakes = slice_bakes(n, s.prefix);
    const uint32_t mips = mip_levels(s.resolution, s.height_resolution, s.filtering);
    g.images.push_back({.name = names.albedo, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .extent = extent,
                        .layers = 2 * n, .mips = mips, .persistent = true});
    g.images.push_back({.name = names.normal, .format = VK_FORMAT_R16G16B16A16_SFLOAT, .extent = extent,
                        .layers = 2 * n, .mips = mips, .persistent = true});
    g.images.push_back({.name = names.blades, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .extent = extent,
                        .layers = 2 * n, .mips = mips, .persistent = true});
    g.images.push_back({.name = names.bake_depth, .format = VK_FORMAT_D32_SFLOAT, .extent = extent});
    g.buffers.push_back({.name = names.cuboid, .bytes = sizeof(QuadVertex) * kCuboidVertices, .usage = kVertexBuffer,
                         .persistent = true});
    // One cell's cuboid is the bake's frame; macro-cells place theirs from the field (macro_field).
    if (!tiled)
        g.buffers.push_back({.name = names.box, .bytes = sizeof(shader::VolumeBox), .usage = kUniformBuffer,
                             .persistent = true});
    for (const SliceBake& b : bakes)
        g.buffers.push_back({.name = b.camera, .bytes = sizeof(shader::PatchBake), .usage = kUniformBuffer});
    if (s.macro_cells > 0) {  // a quadtree's bands share the field records it declares
        declare_macro_buffers(g, s.macro_terrain);
        g.passes.push_back(macro_setup_pass(s.macro_cells, s.macro_terrain));
    }

    PassDecl setup{.name = s.prefix + "bake_setup", .kind = PassKind::copy, .phase = Phase::load};
    setup.uses = {use(names.cuboid, Use::transfer_write)};
    if (!tiled) setup.uses.push_back(use(names.box, Use::transfer_write));
    for (const SliceBake& b : bakes) setup.uses.push_back(use(b.camera, Use::transfer_write));
    setup.settings = fmt::format("slices={} tiled={}", n, tiled);
    setup.record = [bakes, n, tiled, names](PassContext& pc) {
        const Bounds bounds = prototype_bounds(first_grass(pc.populations()));
        const Bounds f = baked_frame(bounds, tiled);
        const auto vertices = cuboid();
        const shader::VolumeBox box{glm::vec4(f.min, 0.0f), glm::vec4(f.max - f.min, 0.0f)};
        pc.upload(names.cuboid, vertices.data(), sizeof(vertices));
        if (!tiled) pc.upload(names.box, &box, sizeof(box));
        for (const SliceBake& b : bakes) {
            const shader::PatchBake camera = slice_camera(bounds, b, n, tiled);
            pc.upload(b.camera, &camera, sizeof(camera));
        }
    };
    g.passes.push_back(std::move(setup));

    const RasterState bake = bake_state(volume_bake_frag);
    for (const SliceBake& b : bakes) {
        PassDecl p{.name = fmt::format("{}bake_slice_{}{}", s.prefix, b.view == BakeView::along_x ? 'x' : 'z', b.section),
                   .kind = PassKind::raster,
                   .phase = Phase::load};
        p.push_constant_bytes = sizeof(DrawConstants);
        p.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(b.camera, Use::uniform, 1),
                  cleared(names.albedo, Use::color_attachment, {0.0f, 0.0f, 0.0f, 0.0f}, true, b.layer),
                  cleared(names.normal, Use::color_attachment, {0.0f, 1.0f, 0.0f, 0.0f}, true, b.layer),
                  cleared(names.blades, Use::color_attachment, kBladeMapEmpty, true, b.layer),
                  cleared(names.bake_depth, Use::depth_attachment, kFarDepth, false)};
        p.settings = fmt::format("layer={}{}", b.layer, tiled ? " tiled" : "");
        p.record = [bake, tiled](PassContext& pc) { record_prototype_bake(pc, bake, tiled); };
        g.passes.push_back(std::move(p));
    }
    declare_mip_passes(g, {.colour = names.albedo, .blades = names.blades, .companion = names.normal, .width = s.resolution,
                           .height = s.height_resolution, .layers = 2 * n, .filtering = s.filtering,
                           .pass_prefix = s.prefix + "slices_"});
}

PassDecl volume_frame_pass(const VolumeSettings& s, const RasterState& per_cell, bool ground,
                           std::vector<ResourceUse> attachments,
                           const std::optional<RasterState>& per_cell_on_terrain) {
    const Names names(s.prefix);
    const uint32_t macro = s.macro_cells;
    PassDecl frame{.name = s.prefix + "volumes", .kind = PassKind::raster};
    frame.push_constant_bytes = sizeof(DrawConstants);
    frame.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), sampled_slices(names.albedo, 1, s.filtering),
                  sampled_slices(names.normal, 2, s.filtering), sampled_slices(names.blades, 8, s.filtering),
                  use(names.cuboid, Use::vertex)};
    frame.uses.insert(frame.uses.end(), attachments.begin(), attachments.end());
    const std::optional<RasterState> objects = ground ? std::optional<RasterState>(ground_state()) : std::nullopt;
    if (s.selected_by) {
        if (!per_cell_on_terrain) throw std::logic_error("volume_frame_pass: a quadtree's band needs its shaders on a terrain");
        declare_macro_band_pass(frame, *s.selected_by, objects, per_cell, *per_cell_on_terrain, names.cuboid);
        frame.settings = fmt::format("one cuboid per cell or macro-cell (at most {} a side) the quadtree's {} band keeps, "
                                     "its exit faces drawn",
                                     s.selected_by->max_macro, s.selected_by->name);
    } else if (macro > 0) {
        if (!objects) throw std::logic_error("volume_frame_pass: macro-cells draw the ground in their pass");
        if (s.culled_by) throw std::logic_error("volume_frame_pass: macro-cells are not culled");
        use_macro_buffers(frame, s.macro_terrain);
        RasterState flat;
        flat.vertex_spirv = grass_volume_macro_vert;
        flat.fragment_spirv = grass_volume_macro_frag;
        flat.vertices = macro_layout();
        RasterState on_terrain = flat;
        on_terrain.vertex_spirv = grass_volume_macro_terrain_vert;
        on_terrain.fragment_spirv = grass_volume_macro_terrain_frag;
        frame.settings = fmt::format("one cuboid per {} x {} macro-cell, its exit faces drawn", macro, macro);
        frame.record = [objects, flat, on_terrain, cuboid = names.cuboid, terrain = s.macro_terrain](PassContext& pc) {
            record_ground_and_macros(pc, *objects, flat, on_terrain, cuboid, kCuboidVertices, terrain);
        };
    } else {
        frame.uses.insert(frame.uses.begin() + 3, use(names.box, Use::uniform, 3));
        RasterState volume = per_cell;
        volume.vertices = quad_layout();
        frame.settings = s.culled_by ? "one cuboid per cell the cull keeps, its exit faces drawn"
                                     : "one cuboid per cell, its exit faces drawn";
        if (s.culled_by) use_cull_survivors(frame, *s.culled_by);
        frame.record = [objects, volume, cuboid = names.cuboid, culled_by = s.culled_by](PassContext& pc) {
            if (objects) record_ground(pc, *objects);
            record_copies_culled(pc, volume, cuboid, kCuboidVertices, culled_by);
        };
    }
    return frame;
}

}  // namespace canopy::grass
