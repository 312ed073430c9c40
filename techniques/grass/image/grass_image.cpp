// grass.image: Lemme's far representation (§4.2, §5.3): the patch seen from above, baked at load
// into its colour, density threshold and normal, shown on one horizontal quad per cell a little
// above the ground, cut by the cell's density and lit per pixel.
#include "core/registry.hpp"
#include "graph/pass_context.hpp"
#include "render/frame_uniforms.hpp"

#include "grass_image_params.h"
#include "../common/grass_passes.hpp"
#include "../common/grass_population.hpp"
#include "../common/macro_passes.hpp"
#include "../common/patch_bake.hpp"

#include "shaders/grass/grass_image_frag.h"
#include "shaders/grass/grass_image_macro_frag.h"
#include "shaders/grass/grass_image_macro_vert.h"
#include "shaders/grass/grass_image_vert.h"
#include "shaders/grass/image_bake_frag.h"

#include <fmt/format.h>

#include <array>

namespace canopy {
namespace {

using grass::cleared;
using grass::kFarDepth;
using grass::use;

namespace names {
constexpr const char* kAlbedo = "slice_albedo";  // RGBA32F: albedo, threshold
constexpr const char* kNormal = "slice_normal";  // RGBA16F: patch-space normal
constexpr const char* kBakeDepth = "bake_depth";
constexpr const char* kQuad = "quad";            // 6 QuadVertex
constexpr const char* kCamera = "bake_camera";   // PatchBake, looking down
}  // namespace names

// The quad over the bake's frame in x and z at `height` above the ground, its coordinates those
// of the top-view bake (grass::BakeView::down: u = x, v = z). Tiled, the frame is the cell, and
// the macro-cells' vertex shader reads x and z as the corner of the macro-cell.
std::array<grass::QuadVertex, 6> slice_quad(const Bounds& bounds, float height, bool tiled) {
    const Bounds f = grass::baked_frame(bounds, tiled);
    std::array<grass::QuadVertex, 6> quad;
    for (size_t i = 0; i < 6; ++i) {
        const glm::vec2 c = grass::kQuadCorners[i];
        quad[i] = {glm::vec4(f.min.x + c.x * (f.max.x - f.min.x), height, f.min.z + c.y * (f.max.z - f.min.z), 1.0f),
                   glm::vec4(c.x, c.y, 0.0f, 0.0f)};
    }
    return quad;
}

class GrassImage final : public Technique {
public:
    std::string name() const override { return "grass.image"; }
    std::string summary() const override {
        return "grass as one horizontal slice per cell or macro-cell: the patch's top view baked at load, lit per pixel";
    }
    std::string paper() const override { return "Lemme 2012 §4.2 and §5.3; Boulanger 2008 §4.2 (the far slice)"; }
    std::vector<ParamSpec> params() const override { return shader::GrassImageParams::specs(); }
    ErrorColumns error_columns() const override { return {}; }

    FrameGraph graph(const ParamSet& params) const override {
        const uint32_t resolution = uint32_t(params.integer("resolution"));
        const float slice_height = float(params.real("slice_height"));
        const uint32_t macro = uint32_t(params.integer("macro_cells"));
        const bool tiled = macro > 0;
        FrameGraph g;
        g.needs.populations = {grass::kGrassPopulationKind};
        g.shader_params.set_block(shader::GrassImageParams::from(params));
        g.images.push_back({.name = names::kAlbedo, .format = VK_FORMAT_R32G32B32A32_SFLOAT,
                            .extent = ImageExtent::square(resolution), .persistent = true});
        g.images.push_back({.name = names::kNormal, .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                            .extent = ImageExtent::square(resolution), .persistent = true});
        g.images.push_back({.name = names::kBakeDepth, .format = VK_FORMAT_D32_SFLOAT,
                            .extent = ImageExtent::square(resolution)});
        g.buffers.push_back({.name = names::kQuad, .bytes = sizeof(grass::QuadVertex) * 6, .usage = kVertexBuffer,
                             .persistent = true});
        g.buffers.push_back({.name = names::kCamera, .bytes = sizeof(shader::PatchBake), .usage = kUniformBuffer});
        if (tiled) {
            g.report["macro_cells"] = fmt::format("{} x {}", macro, macro);
            grass::declare_macro_buffers(g);
            g.passes.push_back(grass::macro_setup_pass(macro));
        }

        PassDecl setup{.name = "bake_setup", .kind = PassKind::copy, .phase = Phase::load};
        setup.uses = {use(names::kQuad, Use::transfer_write), use(names::kCamera, Use::transfer_write)};
        setup.settings = fmt::format("slice_height={} tiled={}", slice_height, tiled);
        setup.record = [slice_height, tiled](PassContext& pc) {
            const Bounds bounds = grass::prototype_bounds(grass::first_grass(pc.populations()));
            const auto quad = slice_quad(bounds, slice_height * bounds.max.y, tiled);
            const shader::PatchBake camera = grass::ortho_bake(bounds, grass::BakeView::down, tiled);
            pc.upload(names::kQuad, quad.data(), sizeof(quad));
            pc.upload(names::kCamera, &camera, sizeof(camera));
        };
        g.passes.push_back(std::move(setup));

        const RasterState bake = grass::bake_state(image_bake_frag);
        PassDecl top{.name = "bake_top", .kind = PassKind::raster, .phase = Phase::load};
        top.push_constant_bytes = sizeof(DrawConstants);
        top.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(names::kCamera, Use::uniform, 1),
                    cleared(names::kAlbedo, Use::color_attachment, {0.0f, 0.0f, 0.0f, shader::PATCH_BAKE_EMPTY}),
                    cleared(names::kNormal, Use::color_attachment, {0.0f, 1.0f, 0.0f, 0.0f}),
                    cleared(names::kBakeDepth, Use::depth_attachment, kFarDepth, false)};
        top.settings = tiled ? "down, tiled" : "down";
        top.record = [bake, tiled](PassContext& pc) { grass::record_prototype_bake(pc, bake, tiled); };
        g.passes.push_back(std::move(top));

        PassDecl frame{.name = "slices", .kind = PassKind::raster};
        frame.push_constant_bytes = sizeof(DrawConstants);
        frame.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(names::kAlbedo, Use::sampled, 1),
                      use(names::kNormal, Use::sampled, 2), use(names::kQuad, Use::vertex),
                      cleared(graph_names::kColor, Use::color_attachment, {0.0f, 0.0f, 0.0f, 1.0f}),
                      cleared(graph_names::kDepth, Use::depth_attachment, kFarDepth)};
        const RasterState ground = grass::ground_state();
        RasterState slice;
        if (tiled) {
            frame.uses.push_back(use(grass::macro_names::kField, Use::uniform, 3));
            frame.uses.push_back(use(grass::macro_names::kCells, Use::storage_read, 4));
            frame.uses.push_back(use(grass::macro_names::kMacros, Use::vertex));
            slice.vertex_spirv = grass_image_macro_vert;
            slice.fragment_spirv = grass_image_macro_frag;
            slice.vertices = grass::macro_layout();
            frame.settings = fmt::format("one quad per {} x {} macro-cell", macro, macro);
            frame.record = [ground, slice, macro](PassContext& pc) {
                grass::record_ground_and_macros(pc, ground, slice, names::kQuad, 6, macro);
            };
        } else {
            slice.vertex_spirv = grass_image_vert;
            slice.fragment_spirv = grass_image_frag;
            slice.vertices = grass::quad_layout();
            frame.settings = "one quad per cell";
            frame.record = [ground, slice](PassContext& pc) {
                grass::record_ground_and_copies(pc, ground, slice, names::kQuad, 6);
            };
        }
        g.passes.push_back(std::move(frame));
        return g;
    }
};

RegisterTechnique<GrassImage> registered;

}  // namespace
}  // namespace canopy
