// grass.volume: Lemme's volume-based representation (§4.2.1, §5.2). At load, the patch is cut by
// pairs of clipping planes into n sections along x and n along z, and each section is baked by an
// orthographic camera along its axis into one layer of a texture array (colour, threshold,
// normal). Every frame, each cell draws its carrier cuboid, and each of its pixels casts a ray
// through the slices (shaders/volume_walk.h), stopping at the first blade the cell's density
// keeps.
#include "core/registry.hpp"
#include "graph/pass_context.hpp"
#include "render/frame_uniforms.hpp"

#include "grass_volume_params.h"
#include "../common/grass_passes.hpp"
#include "../common/grass_population.hpp"
#include "../common/macro_passes.hpp"
#include "../common/patch_bake.hpp"
#include "../shaders/volume_walk.h"

#include "shaders/grass/grass_volume_frag.h"
#include "shaders/grass/grass_volume_macro_frag.h"
#include "shaders/grass/grass_volume_macro_vert.h"
#include "shaders/grass/grass_volume_vert.h"
#include "shaders/grass/volume_bake_frag.h"

#include <fmt/format.h>

#include <array>
#include <string>
#include <vector>

namespace canopy {
namespace {

using grass::cleared;
using grass::kFarDepth;
using grass::use;

namespace names {
constexpr const char* kAlbedo = "slices_albedo";  // RGBA32F x 2n layers: albedo, threshold
constexpr const char* kNormal = "slices_normal";  // RGBA16F x 2n layers: patch-space normal
constexpr const char* kBakeDepth = "bake_depth";
constexpr const char* kCuboid = "cuboid";         // 36 QuadVertex: corner (q space), face plane
constexpr const char* kBox = "volume_box";        // VolumeBox
}  // namespace names

constexpr uint32_t kCuboidVertices = 36;

// Layers 0 .. n-1 hold the slices along x (planes x = const, baked looking along x), layers
// n .. 2n-1 those along z: what grass_volume.frag reads.
struct SliceBake {
    grass::BakeView view;
    uint32_t section;  // k along the slice's axis
    uint32_t layer;
    std::string camera;  // its PatchBake's buffer
};

std::vector<SliceBake> slice_bakes(uint32_t n) {
    std::vector<SliceBake> bakes;
    for (uint32_t axis = 0; axis < 2; ++axis)
        for (uint32_t k = 0; k < n; ++k)
            bakes.push_back({axis == 0 ? grass::BakeView::along_x : grass::BakeView::along_z, k, axis * n + k,
                             fmt::format("bake_{}{}", axis == 0 ? 'x' : 'z', k)});
    return bakes;
}

// The camera of one slice: the bake's frame seen along the slice's axis, keeping section k of n.
shader::PatchBake slice_camera(const Bounds& bounds, const SliceBake& slice, uint32_t n, bool tiled) {
    const Bounds f = grass::baked_frame(bounds, tiled);
    shader::PatchBake bake = grass::ortho_bake(bounds, slice.view, tiled);
    const int axis = slice.view == grass::BakeView::along_x ? 0 : 2;
    const float width = (f.max[axis] - f.min[axis]) / float(n);
    // The outer sections reach past the frame, so a blade on its edge belongs to one of them.
    bake.section.x = slice.section == 0 ? -1e30f : f.min[axis] + width * float(slice.section);
    bake.section.y = slice.section + 1 == n ? 1e30f : f.min[axis] + width * float(slice.section + 1);
    return bake;
}

// The unit cube's six faces as two triangles each, with each face's outward plane.
std::array<grass::QuadVertex, kCuboidVertices> cuboid() {
    std::array<grass::QuadVertex, kCuboidVertices> vertices;
    size_t v = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
            glm::vec4 plane(0.0f);
            plane[axis] = side == 0 ? -1.0f : 1.0f;
            plane.w = side == 0 ? 0.0f : 1.0f;
            for (const glm::vec2 c : grass::kQuadCorners) {
                glm::vec4 corner(0.0f, 0.0f, 0.0f, 1.0f);
                corner[axis] = float(side);
                corner[u_axis] = c.x;
                corner[v_axis] = c.y;
                vertices[v++] = {corner, plane};
            }
        }
    return vertices;
}

class GrassVolume final : public Technique {
public:
    std::string name() const override { return "grass.volume"; }
    std::string summary() const override {
        return "grass as a ray-cast volume: n vertical slices per direction baked at load, walked per pixel in a cuboid per cell or macro-cell";
    }
    std::string paper() const override { return "Lemme 2012 §4.2.1 and §5.2 (eq 5.2-5.21), after Habel et al. 2007"; }
    std::vector<ParamSpec> params() const override { return shader::GrassVolumeParams::specs(); }
    ErrorColumns error_columns() const override { return {}; }

    FrameGraph graph(const ParamSet& params) const override {
        const auto block = shader::GrassVolumeParams::from(params);
        const uint32_t n = uint32_t(block.slices);
        const ImageExtent extent =
            ImageExtent::texels(uint32_t(params.integer("resolution")), uint32_t(params.integer("height_resolution")));
        const std::vector<SliceBake> bakes = slice_bakes(n);
        const uint32_t macro = uint32_t(params.integer("macro_cells"));
        const bool tiled = macro > 0;
        FrameGraph g;
        g.needs.populations = {grass::kGrassPopulationKind};
        g.shader_params.set_block(block);
        g.report["slices"] = fmt::format("{} per direction", n);
        g.images.push_back({.name = names::kAlbedo, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .extent = extent,
                            .layers = 2 * n, .persistent = true});
        g.images.push_back({.name = names::kNormal, .format = VK_FORMAT_R16G16B16A16_SFLOAT, .extent = extent,
                            .layers = 2 * n, .persistent = true});
        g.images.push_back({.name = names::kBakeDepth, .format = VK_FORMAT_D32_SFLOAT, .extent = extent});
        g.buffers.push_back({.name = names::kCuboid, .bytes = sizeof(grass::QuadVertex) * kCuboidVertices,
                             .usage = kVertexBuffer, .persistent = true});
        // One cell's cuboid is the bake's frame; macro-cells place theirs from the field (macro_field).
        if (!tiled)
            g.buffers.push_back({.name = names::kBox, .bytes = sizeof(shader::VolumeBox), .usage = kUniformBuffer,
                                 .persistent = true});
        for (const SliceBake& b : bakes)
            g.buffers.push_back({.name = b.camera, .bytes = sizeof(shader::PatchBake), .usage = kUniformBuffer});
        if (tiled) {
            g.report["macro_cells"] = fmt::format("{} x {}", macro, macro);
            grass::declare_macro_buffers(g);
            g.passes.push_back(grass::macro_setup_pass(macro));
        }

        PassDecl setup{.name = "bake_setup", .kind = PassKind::copy, .phase = Phase::load};
        setup.uses = {use(names::kCuboid, Use::transfer_write)};
        if (!tiled) setup.uses.push_back(use(names::kBox, Use::transfer_write));
        for (const SliceBake& b : bakes) setup.uses.push_back(use(b.camera, Use::transfer_write));
        setup.settings = fmt::format("slices={} tiled={}", n, tiled);
        setup.record = [bakes, n, tiled](PassContext& pc) {
            const Bounds bounds = grass::prototype_bounds(grass::first_grass(pc.populations()));
            const Bounds f = grass::baked_frame(bounds, tiled);
            const auto vertices = cuboid();
            const shader::VolumeBox box{glm::vec4(f.min, 0.0f), glm::vec4(f.max - f.min, 0.0f)};
            pc.upload(names::kCuboid, vertices.data(), sizeof(vertices));
            if (!tiled) pc.upload(names::kBox, &box, sizeof(box));
            for (const SliceBake& b : bakes) {
                const shader::PatchBake camera = slice_camera(bounds, b, n, tiled);
                pc.upload(b.camera, &camera, sizeof(camera));
            }
        };
        g.passes.push_back(std::move(setup));

        const RasterState bake = grass::bake_state(volume_bake_frag);
        for (const SliceBake& b : bakes) {
            PassDecl p{.name = fmt::format("bake_slice_{}{}", b.view == grass::BakeView::along_x ? 'x' : 'z', b.section),
                       .kind = PassKind::raster,
                       .phase = Phase::load};
            p.push_constant_bytes = sizeof(DrawConstants);
            p.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(b.camera, Use::uniform, 1),
                      cleared(names::kAlbedo, Use::color_attachment, {0.0f, 0.0f, 0.0f, shader::PATCH_BAKE_EMPTY}, true,
                              b.layer),
                      cleared(names::kNormal, Use::color_attachment, {0.0f, 1.0f, 0.0f, 0.0f}, true, b.layer),
                      cleared(names::kBakeDepth, Use::depth_attachment, kFarDepth, false)};
            p.settings = fmt::format("layer={}{}", b.layer, tiled ? " tiled" : "");
            p.record = [bake, tiled](PassContext& pc) { grass::record_prototype_bake(pc, bake, tiled); };
            g.passes.push_back(std::move(p));
        }

        PassDecl frame{.name = "volumes", .kind = PassKind::raster};
        frame.push_constant_bytes = sizeof(DrawConstants);
        frame.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(names::kAlbedo, Use::sampled, 1),
                      use(names::kNormal, Use::sampled, 2), use(names::kCuboid, Use::vertex),
                      cleared(graph_names::kColor, Use::color_attachment, {0.0f, 0.0f, 0.0f, 1.0f}),
                      cleared(graph_names::kDepth, Use::depth_attachment, kFarDepth)};
        const RasterState ground = grass::ground_state();
        RasterState volume;
        if (tiled) {
            frame.uses.push_back(use(grass::macro_names::kField, Use::uniform, 3));
            frame.uses.push_back(use(grass::macro_names::kCells, Use::storage_read, 4));
            frame.uses.push_back(use(grass::macro_names::kMacros, Use::vertex));
            volume.vertex_spirv = grass_volume_macro_vert;
            volume.fragment_spirv = grass_volume_macro_frag;
            volume.vertices = grass::macro_layout();
            frame.settings = fmt::format("one cuboid per {} x {} macro-cell, its exit faces drawn", macro, macro);
            frame.record = [ground, volume, macro](PassContext& pc) {
                grass::record_ground_and_macros(pc, ground, volume, names::kCuboid, kCuboidVertices, macro);
            };
        } else {
            frame.uses.insert(frame.uses.begin() + 3, use(names::kBox, Use::uniform, 3));
            volume.vertex_spirv = grass_volume_vert;
            volume.fragment_spirv = grass_volume_frag;
            volume.vertices = grass::quad_layout();
            frame.settings = "one cuboid per cell, its exit faces drawn";
            frame.record = [ground, volume](PassContext& pc) {
                grass::record_ground_and_copies(pc, ground, volume, names::kCuboid, kCuboidVertices);
            };
        }
        g.passes.push_back(std::move(frame));
        return g;
    }
};

RegisterTechnique<GrassVolume> registered;

}  // namespace
}  // namespace canopy
