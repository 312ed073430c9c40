#include "slices_graph.hpp"

#include "graph/pass_context.hpp"
#include "render/frame_uniforms.hpp"

#include "../common/grass_cull.hpp"
#include "../common/grass_passes.hpp"
#include "../common/grass_population.hpp"
#include "../common/patch_bake.hpp"
#include "../shaders/btf_interpolation.h"

#include "../shaders/bake_shadows.h"

#include "shaders/grass/slices_bake_frag.h"
#include "shaders/grass/slices_bake_shadowed_frag.h"
#include "shaders/grass/slices_light_depth_frag.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace canopy::grass {
namespace {

struct Names {
    std::string albedo;      // RGBA32F x 4n layers: albedo (the ambient row), covered (blade_texels.h)
    std::string lit;         // RGBA16F x 20n layers: the five lit rows of each slice and side
    std::string blades;      // RGBA32F x 4n layers: the blade map (blade_texels.h)
    std::string top_albedo;  // RGBA32F, arrayed: the horizontal slice's albedo, covered
    std::string top_lit;     // RGBA16F x 5 layers
    std::string top_blades;  // RGBA32F, arrayed: its blade map
    std::string bake_depth, top_depth;
    std::string quads;       // (2n + 1) x 6 QuadVertex, (4n + 1) x 6 on a terrain
    std::string light_depth;  // D32 x 5 layers: a shadowed bake's light views
    std::string shadows;      // BakeShadows
    explicit Names(const std::string& p)
        : albedo(p + "slices_albedo"), lit(p + "slices_lit"), blades(p + "slices_blades"), top_albedo(p + "top_albedo"),
          top_lit(p + "top_lit"), top_blades(p + "top_blades"),
          bake_depth(p + "bake_depth"), top_depth(p + "top_bake_depth"), quads(p + "slice_quads"),
          light_depth(p + "bake_light_depth"), shadows(p + "bake_shadows") {}
};

// One bake pass: a vertical slice's side, or (axis 2) the horizontal slice seen from above.
struct SliceBake {
    uint32_t axis;     // 0: planes x = const, 1: z = const, 2: the horizontal slice
    uint32_t section;  // k of n along the axis
    uint32_t side;     // 0: front (seen from +axis), 1: back
    uint32_t layer;    // in the albedo array (0 for the horizontal slice)
    std::string camera;
    std::string name;
};

const char* const kLightNames[] = {"y+", "x+", "z+", "x-", "z-"};  // btf_light_direction's order
static_assert(shader::BAKE_SHADOW_LIGHTS == shader::BTF_LIGHTS, "a shadowed bake looks up each baked light");

std::string light_camera_name(const std::string& prefix, uint32_t row) {
    return prefix + "bake_light_camera_" + kLightNames[row];
}

std::vector<SliceBake> slice_bakes(uint32_t n, const std::string& prefix) {
    std::vector<SliceBake> bakes;
    for (uint32_t axis = 0; axis < 2; ++axis)
        for (uint32_t k = 0; k < n; ++k)
            for (uint32_t side = 0; side < 2; ++side) {
                const std::string id = fmt::format("{}{}_{}", axis == 0 ? 'x' : 'z', k, side == 0 ? "front" : "back");
                bakes.push_back({axis, k, side, slice_side_layer(axis, k, side, n), prefix + "bake_camera_" + id,
                                 prefix + "bake_slice_" + id});
            }
    bakes.push_back({2, 0, 0, 0, prefix + "bake_camera_top", prefix + "bake_top"});
    return bakes;
}

// The camera of one bake: looking along -axis for the front side, along +axis for the back (the
// same image coordinates, depth reversed), keeping the slice's section.
shader::PatchBake slice_camera(const Bounds& bounds, const SliceBake& b, uint32_t n, bool tiled) {
    if (b.axis == 2) return ortho_bake(bounds, BakeView::down, tiled);
    const Bounds f = baked_frame(bounds, tiled);
    const int axis = b.axis == 0 ? 0 : 2;
    shader::PatchBake bake = ortho_bake(bounds, b.axis == 0 ? BakeView::along_x : BakeView::along_z, tiled);
    const float lo = bake_section_start(f, axis, b.section, n, tiled), hi = bake_section_start(f, axis, b.section + 1, n, tiled);
    bake.section = glm::vec4(lo, hi, 0.0f, 0.0f);
    if (b.side == 1) {
        reverse_bake_depth(bake, axis);
        bake.section = glm::vec4(-hi, -lo, 0.0f, 0.0f);  // along = -coordinate
    }
    return bake;
}

// The 2n vertical quads, each at the middle of its section, spanning the frame and the blades'
// height, and the horizontal one. position.w: 0; uv: (u, v) in the slice's bake, z: the axis
// (0 x, 1 z, 2 horizontal), w: the slice (the horizontal quad: the frame's width in x).
//
// For a field on a terrain (`on_terrain`) each vertical quad is cut in two where the cell's
// ground diagonal crosses it, which depends on the cell's mirror and so is placed by the vertex
// shader (grass_diagonal_crossing): a crossing vertex has position.w = 1 and carries the frame's
// extent along its quad instead of a place, its start in position and its end in u.
std::vector<QuadVertex> slice_quads(const Bounds& bounds, uint32_t n, float slice_height, bool tiled, bool on_terrain) {
    const Bounds f = baked_frame(bounds, tiled);
    const float top = f.max.y;
    std::vector<QuadVertex> quads;
    for (uint32_t a = 0; a < 2; ++a) {
        const int axis = a == 0 ? 0 : 2, across = a == 0 ? 2 : 0;
        for (uint32_t k = 0; k < n; ++k) {
            const float plane = f.min[axis] + (f.max[axis] - f.min[axis]) * (float(k) + 0.5f) / float(n);
            // Corner c.x of a quad along the slice: 0 the frame's start, 1 its end, 0.5 the crossing.
            const auto vertex = [&](glm::vec2 c) {
                glm::vec4 p(0.0f, c.y * top, 0.0f, 0.0f);
                p[axis] = plane;
                if (c.x == 0.5f) {
                    p[across] = f.min[across];
                    p.w = 1.0f;
                    return QuadVertex{p, glm::vec4(f.max[across], 1.0f - c.y, float(a), float(k))};
                }
                p[across] = f.min[across] + c.x * (f.max[across] - f.min[across]);
                return QuadVertex{p, glm::vec4(c.x, 1.0f - c.y, float(a), float(k))};
            };
            if (!on_terrain) {
                for (const glm::vec2 c : kQuadCorners) quads.push_back(vertex(c));
                continue;
            }
            for (const glm::vec2 c : kQuadCorners) quads.push_back(vertex({0.5f * c.x, c.y}));         // start to cut
            for (const glm::vec2 c : kQuadCorners) quads.push_back(vertex({0.5f + 0.5f * c.x, c.y}));  // cut to end
        }
    }
    for (const glm::vec2 c : kQuadCorners)
        quads.push_back({glm::vec4(f.min.x + c.x * (f.max.x - f.min.x), slice_height * top,
                                   f.min.z + c.y * (f.max.z - f.min.z), 0.0f),
                         glm::vec4(c.x, c.y, 2.0f, f.max.x - f.min.x)});
    return quads;
}

}  // namespace

std::string slices_albedo_name(const std::string& prefix) { return Names(prefix).albedo; }
std::string slices_lit_name(const std::string& prefix) { return Names(prefix).lit; }
std::string top_albedo_name(const std::string& prefix) { return Names(prefix).top_albedo; }
std::string top_lit_name(const std::string& prefix) { return Names(prefix).top_lit; }

void declare_slices_bake(FrameGraph& g, const SlicesSettings& s) {
    const Names names(s.prefix);
    const uint32_t n = s.slices, lights = uint32_t(shader::BTF_LIGHTS);
    const bool tiled = s.neighbours;
    const float slice_height = s.slice_height;
    const ImageExtent side = bake_extent(s.resolution, s.height_resolution, s.filtering);
    const ImageExtent top = bake_extent(s.resolution, s.resolution, s.filtering);
    const uint32_t side_mips = mip_levels(s.resolution, s.height_resolution, s.filtering);
    const uint32_t top_mips = mip_levels(s.resolution, s.resolution, s.filtering);
    g.images.push_back({.name = names.albedo, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .extent = side,
                        .layers = 4 * n, .mips = side_mips, .persistent = true});
    g.images.push_back({.name = names.lit, .format = VK_FORMAT_R16G16B16A16_SFLOAT, .extent = side,
                        .layers = 4 * n * lights, .mips = side_mips, .persistent = true});
    g.images.push_back({.name = names.blades, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .extent = side,
                        .layers = 4 * n, .mips = side_mips, .persistent = true});
    g.images.push_back({.name = names.top_albedo, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .extent = top,
                        .mips = top_mips, .persistent = true, .arrayed = true});
    g.images.push_back({.name = names.top_lit, .format = VK_FORMAT_R16G16B16A16_SFLOAT, .extent = top,
                        .layers = lights, .mips = top_mips, .persistent = true});
    g.images.push_back({.name = names.top_blades, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .extent = top,
                        .mips = top_mips, .persistent = true, .arrayed = true});
    g.images.push_back({.name = names.bake_depth, .format = VK_FORMAT_D32_SFLOAT, .extent = side});
    g.images.push_back({.name = names.top_depth, .format = VK_FORMAT_D32_SFLOAT, .extent = top});
    // Room for the quads on a terrain; a flat field fills and draws the first slices_cell_vertices.
    g.buffers.push_back({.name = names.quads, .bytes = sizeof(QuadVertex) * slices_cell_vertices_on_terrain(s),
                         .usage = kVertexBuffer, .persistent = true});
    const std::vector<SliceBake> bakes = slice_bakes(n, s.prefix);
    for (const SliceBake& b : bakes)
        g.buffers.push_back({.name = b.camera, .bytes = sizeof(shader::PatchBake), .usage = kUniformBuffer});
    const uint32_t shadow_resolution = s.shadow_resolution;
    const bool shadowed = shadow_resolution > 0;
    if (shadowed) {
        g.images.push_back({.name = names.light_depth, .format = VK_FORMAT_D32_SFLOAT,
                            .extent = ImageExtent::square(shadow_resolution), .layers = lights});
        for (uint32_t row = 0; row < lights; ++row)
            g.buffers.push_back({.name = light_camera_name(s.prefix, row), .bytes = sizeof(shader::PatchBake),
                                 .usage = kUniformBuffer});
        g.buffers.push_back({.name = names.shadows, .bytes = sizeof(shader::BakeShadows), .usage = kUniformBuffer});
    }

    PassDecl setup{.name = s.prefix + "bake_setup", .kind = PassKind::copy, .phase = Phase::load};
    setup.uses = {use(names.quads, Use::transfer_write)};
    for (const SliceBake& b : bakes) setup.uses.push_back(use(b.camera, Use::transfer_write));
    if (shadowed) {
        for (uint32_t row = 0; row < lights; ++row)
            setup.uses.push_back(use(light_camera_name(s.prefix, row), Use::transfer_write));
        setup.uses.push_back(use(names.shadows, Use::transfer_write));
    }
    setup.settings = fmt::format("slices={} slice_height={} neighbours={}", n, slice_height, tiled);
    if (shadowed)
        setup.settings += fmt::format(" shadows: {} texels, bias {} texels, normal offset {} texels", shadow_resolution,
                                      kBakeShadowBias, kBakeShadowNormalOffset);
    setup.record = [bakes, n, slice_height, tiled, names, shadowed, shadow_resolution, prefix = s.prefix](PassContext& pc) {
        const Bounds bounds = prototype_bounds(first_grass(pc.populations()));
        const std::vector<QuadVertex> quads = slice_quads(bounds, n, slice_height, tiled, grass_on_terrain(pc.populations()));
        pc.upload(names.quads, quads.data(), quads.size() * sizeof(QuadVertex));
        for (const SliceBake& b : bakes) {
            const shader::PatchBake camera = slice_camera(bounds, b, n, tiled);
            pc.upload(b.camera, &camera, sizeof(camera));
        }
        if (!shadowed) return;
        // The offsets in patch units: texels across the coarsest light view (the extents across the
        // light; along it a view may reach over the neighbours).
        const float margin = kBakeShadowMargin / float(shadow_resolution);
        float texel = 0.0f;
        for (uint32_t row = 0; row < uint32_t(shader::BTF_LIGHTS); ++row) {
            const Bounds frame = light_frame(bounds, row, tiled, margin);
            for (int axis = 0; axis < 3; ++axis)
                if (axis != light_axis(row))
                    texel = std::max(texel, (frame.max[axis] - frame.min[axis]) / float(shadow_resolution));
        }
        shader::BakeShadows block{};
        for (uint32_t row = 0; row < uint32_t(shader::BTF_LIGHTS); ++row) {
            const shader::PatchBake camera = light_bake(bounds, row, tiled, margin);
            pc.upload(light_camera_name(prefix, row), &camera, sizeof(camera));
            block.lookup[row] = light_lookup(bounds, row, tiled, margin, kBakeShadowBias * texel);
        }
        block.offsets = glm::vec4(kBakeShadowNormalOffset * texel, 0.0f, 0.0f, 0.0f);
        pc.upload(names.shadows, &block, sizeof(block));
    };
    g.passes.push_back(std::move(setup));

    // A shadowed bake's light views: the blades' depth seen from each baked light direction.
    if (shadowed) {
        const RasterState light_view = bake_state(slices_light_depth_frag);
        for (uint32_t row = 0; row < lights; ++row) {
            PassDecl p{.name = s.prefix + "bake_light_" + kLightNames[row], .kind = PassKind::raster, .phase = Phase::load};
            p.push_constant_bytes = sizeof(DrawConstants);
            p.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(light_camera_name(s.prefix, row), Use::uniform, 1),
                      cleared(names.light_depth, Use::depth_attachment, kFarDepth, true, row)};
            p.settings = fmt::format("{} {}x{}{}", kLightNames[row], shadow_resolution, shadow_resolution,
                                     tiled ? " tiled" : "");
            p.record = [light_view, tiled](PassContext& pc) { record_prototype_bake(pc, light_view, tiled); };
            g.passes.push_back(std::move(p));
        }
    }

    // Each bake writes the slice side's albedo and threshold and its five lit rows at once: one
    // drawing of the blades between the slice's clipping planes, shaded under every baked light.
    const RasterState bake = shadowed ? bake_state(slices_bake_shadowed_frag) : bake_state(slices_bake_frag);
    for (const SliceBake& b : bakes) {
        const bool horizontal = b.axis == 2;
        PassDecl p{.name = b.name, .kind = PassKind::raster, .phase = Phase::load};
        p.push_constant_bytes = sizeof(DrawConstants);
        p.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(b.camera, Use::uniform, 1),
                  cleared(horizontal ? names.top_albedo : names.albedo, Use::color_attachment, {0.0f, 0.0f, 0.0f, 0.0f},
                          true, b.layer)};
        if (shadowed) {
            ResourceUse depth = use(names.light_depth, Use::sampled, 2);
            depth.sampler = SamplerKind::compare_linear;
            p.uses.push_back(depth);
            p.uses.push_back(use(names.shadows, Use::uniform, 3));
        }
        for (uint32_t row = 0; row < lights; ++row)
            p.uses.push_back(cleared(horizontal ? names.top_lit : names.lit, Use::color_attachment, {0.0f, 0.0f, 0.0f, 0.0f},
                                     true, horizontal ? row : b.layer * lights + row));
        p.uses.push_back(cleared(horizontal ? names.top_blades : names.blades, Use::color_attachment, kBladeMapEmpty, true,
                                 b.layer));
        p.uses.push_back(cleared(horizontal ? names.top_depth : names.bake_depth, Use::depth_attachment, kFarDepth, false));
        p.settings = horizontal ? fmt::format("down{}", tiled ? ", tiled" : "")
                                : fmt::format("layer={}{}", b.layer, tiled ? " tiled" : "");
        if (shadowed) p.settings += ", shadowed";
        p.record = [bake, tiled](PassContext& pc) { record_prototype_bake(pc, bake, tiled); };
        g.passes.push_back(std::move(p));
    }
    // The lit rows filter with their slice side's coverage (five to a layer).
    declare_mip_passes(g, {.colour = names.albedo, .blades = names.blades, .companion = names.lit, .companions = lights,
                           .width = s.resolution, .height = s.height_resolution, .layers = 4 * n,
                           .filtering = s.filtering, .pass_prefix = s.prefix + "slices_"});
    declare_mip_passes(g, {.colour = names.top_albedo, .blades = names.top_blades, .companion = names.top_lit,
                           .companions = lights, .width = s.resolution, .height = s.resolution, .layers = 1,
                           .filtering = s.filtering, .pass_prefix = s.prefix + "top_"});
}

PassDecl slices_frame_pass(const SlicesSettings& s, const RasterState& per_cell, bool ground,
                           std::vector<ResourceUse> attachments) {
    const Names names(s.prefix);
    PassDecl frame{.name = s.prefix + "btf_slices", .kind = PassKind::raster};
    frame.push_constant_bytes = sizeof(DrawConstants);
    const SliceFiltering& f = s.filtering;
    frame.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), sampled_slices(names.albedo, 1, f),
                  sampled_slices(names.lit, 2, f),          sampled_slices(names.top_albedo, 3, f),
                  sampled_slices(names.top_lit, 4, f),      sampled_slices(names.blades, 8, f),
                  sampled_slices(names.top_blades, 9, f),   use(names.quads, Use::vertex)};
    frame.uses.insert(frame.uses.end(), attachments.begin(), attachments.end());
    const std::optional<RasterState> objects = ground ? std::optional<RasterState>(ground_state()) : std::nullopt;
    RasterState slices = per_cell;
    slices.vertices = quad_layout();
    const uint32_t flat_vertices = slices_cell_vertices(s), terrain_vertices = slices_cell_vertices_on_terrain(s);
    frame.settings = fmt::format("{} vertical and 1 horizontal quads per cell{}", 2 * s.slices,
                                 s.culled_by ? " the cull keeps" : "");
    if (s.culled_by) use_cull_survivors(frame, *s.culled_by);
    frame.record = [objects, slices, flat_vertices, terrain_vertices, quads = names.quads,
                    culled_by = s.culled_by](PassContext& pc) {
        if (objects) record_ground(pc, *objects);
        const uint32_t vertices = grass_on_terrain(pc.populations()) ? terrain_vertices : flat_vertices;
        record_copies_culled(pc, slices, quads, vertices, culled_by);
    };
    return frame;
}

}  // namespace canopy::grass
