// grass.billboard: the classic image-based baseline. At load, the patch is rendered into two
// images by orthographic cameras along z and along x; every frame, each cell shows them on two
// crossed quads (or one quad turned to the camera), cut where the baked blade's density
// threshold exceeds the cell's density.
#include "core/registry.hpp"
#include "graph/pass_context.hpp"
#include "render/frame_uniforms.hpp"

#include "grass_billboard_params.h"
#include "../common/grass_family.hpp"
#include "../common/grass_passes.hpp"
#include "../common/mip_passes.hpp"
#include "../common/patch_bake.hpp"
#include "../common/grass_population.hpp"

#include "shaders/grass/billboard_bake_frag.h"
#include "shaders/grass/grass_billboards_frag.h"
#include "shaders/grass/grass_billboards_vert.h"

#include <fmt/format.h>

#include <array>

namespace canopy {
namespace {

namespace names {
constexpr const char* kImage = "billboard";      // RGBA32F x 2 layers: radiance, covered (blade_texels.h)
constexpr const char* kBlades = "billboard_blades";  // RGBA32F x 2 layers: the blade map (blade_texels.h)
constexpr const char* kBakeDepth = "bake_depth";
constexpr const char* kQuads = "quads";          // 24 QuadVertex: the xy quad's two halves, then the zy quad's
constexpr const char* kFront = "bake_front";     // PatchBake of layer 0
constexpr const char* kSide = "bake_side";       // PatchBake of layer 1
}  // namespace names

constexpr uint32_t kQuadVertices = 24;

using grass::cleared;
using grass::kFarDepth;
using grass::use;

// The quads for a prototype with these bounds (patch space) over its bake_frame: the xy quad at
// the patch's z centre (layer 0, in position.w), the zy quad at its x centre (layer 1). Each is
// cut in two at the cell's centre: on a terrain its foot follows the ground, whose two triangles
// meet along a diagonal through that centre (grass_terrain.h), so each half's ground is a line.
std::array<grass::QuadVertex, kQuadVertices> billboard_quads(const Bounds& bounds) {
    const Bounds f = grass::bake_frame(bounds);
    std::array<grass::QuadVertex, kQuadVertices> quads;
    const auto half = [&](size_t first, int axis, float from, float to) {
        const float low = axis == 0 ? f.min.x : f.min.z, high = axis == 0 ? f.max.x : f.max.z;
        for (size_t i = 0; i < 6; ++i) {
            const glm::vec2 c = grass::kQuadCorners[i];
            const float along = from + c.x * (to - from);  // patch x (or z)
            const glm::vec4 uv((along - low) / (high - low), 1.0f - c.y, 0.0f, 0.0f);
            quads[first + i] = {axis == 0 ? glm::vec4(along, c.y * f.max.y, 0.5f, 0.0f)
                                          : glm::vec4(0.5f, c.y * f.max.y, along, 1.0f),
                                uv};
        }
    };
    half(0, 0, f.min.x, 0.5f);
    half(6, 0, 0.5f, f.max.x);
    half(12, 1, f.min.z, 0.5f);
    half(18, 1, 0.5f, f.max.z);
    return quads;
}

class GrassBillboard final : public Technique {
public:
    std::string name() const override { return "grass.billboard"; }
    std::string summary() const override {
        return "grass as billboards: the patch baked at load into two images, shown on crossed or camera-facing quads";
    }
    std::string paper() const override { return "the classic baseline of Lemme 2012 ch. 2 and Boulanger 2008 §2"; }
    std::vector<ParamSpec> params() const override { return shader::GrassBillboardParams::specs(); }
    ErrorColumns error_columns() const override { return grass::kGrassErrorColumns; }
    std::vector<std::string> pareto_errors() const override { return grass::pareto_errors(); }

    std::optional<ParamConflict> conflict(const ParamSet& params) const override {
        return grass::slice_filtering_conflict(params);
    }

    FrameGraph graph(const ParamSet& params) const override {
        const uint32_t resolution = uint32_t(params.integer("resolution"));
        const auto block = shader::GrassBillboardParams::from(params);
        const bool crossed = block.orientation == shader::GRASS_BILLBOARD_CROSSED;
        FrameGraph g;
        g.needs.populations = {grass::kGrassPopulationKind};
        g.needs.populations_on_terrain = true;  // each quad's foot on the ground (grass_billboards.vert)
        g.shader_params.set_block(block);
        g.report["orientation"] = crossed ? "crossed" : "camera-facing";
        const grass::SliceFiltering filtering = grass::slice_filtering(params);
        const uint32_t mips = grass::mip_levels(resolution, resolution, filtering);
        const ImageExtent extent = grass::bake_extent(resolution, resolution, filtering);
        for (const char* image : {names::kImage, names::kBlades})
            g.images.push_back({.name = image, .format = VK_FORMAT_R32G32B32A32_SFLOAT, .extent = extent, .layers = 2,
                                .mips = mips, .persistent = true});
        g.images.push_back({.name = names::kBakeDepth, .format = VK_FORMAT_D32_SFLOAT, .extent = extent});
        g.buffers.push_back({.name = names::kQuads, .bytes = sizeof(grass::QuadVertex) * kQuadVertices,
                             .usage = kVertexBuffer, .persistent = true});
        for (const char* camera : {names::kFront, names::kSide})
            g.buffers.push_back({.name = camera, .bytes = sizeof(shader::PatchBake), .usage = kUniformBuffer});

        PassDecl setup{.name = "bake_setup", .kind = PassKind::copy, .phase = Phase::load};
        setup.uses = {use(names::kQuads, Use::transfer_write), use(names::kFront, Use::transfer_write),
                      use(names::kSide, Use::transfer_write)};
        setup.settings = "bounds of the first grass population's prototype";
        setup.record = [](PassContext& pc) {
            const Bounds bounds = grass::prototype_bounds(grass::first_grass(pc.populations()));
            const auto quads = billboard_quads(bounds);
            const shader::PatchBake front = grass::ortho_bake(bounds, grass::BakeView::along_z);
            const shader::PatchBake side = grass::ortho_bake(bounds, grass::BakeView::along_x);
            pc.upload(names::kQuads, quads.data(), sizeof(quads));
            pc.upload(names::kFront, &front, sizeof(front));
            pc.upload(names::kSide, &side, sizeof(side));
        };
        g.passes.push_back(std::move(setup));

        const RasterState bake = grass::bake_state(billboard_bake_frag);
        const std::array<const char*, 2> cameras{names::kFront, names::kSide};
        for (uint32_t layer = 0; layer < 2; ++layer) {
            PassDecl p{.name = layer == 0 ? "bake_front" : "bake_side", .kind = PassKind::raster, .phase = Phase::load};
            p.push_constant_bytes = sizeof(DrawConstants);
            p.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(cameras[layer], Use::uniform, 1),
                      cleared(names::kImage, Use::color_attachment, {0.0f, 0.0f, 0.0f, 0.0f}, true, layer),
                      cleared(names::kBlades, Use::color_attachment, grass::kBladeMapEmpty, true, layer),
                      cleared(names::kBakeDepth, Use::depth_attachment, kFarDepth, false)};
            p.settings = fmt::format("layer={}", layer);
            p.record = [bake](PassContext& pc) { grass::record_prototype_bake(pc, bake); };
            g.passes.push_back(std::move(p));
        }
        grass::declare_mip_passes(g, {.colour = names::kImage, .blades = names::kBlades, .width = resolution,
                                      .height = resolution, .layers = 2, .filtering = filtering});

        PassDecl frame{.name = "billboards", .kind = PassKind::raster};
        frame.push_constant_bytes = sizeof(DrawConstants);
        frame.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), grass::sampled_slices(names::kImage, 1, filtering),
                      grass::sampled_slices(names::kBlades, 8, filtering), use(names::kQuads, Use::vertex),
                      cleared(graph_names::kColor, Use::color_attachment, grass::kUncoveredClear),
                      cleared(graph_names::kDepth, Use::depth_attachment, kFarDepth)};
        const RasterState ground = grass::ground_state();
        RasterState quads;
        quads.vertex_spirv = grass_billboards_vert;
        quads.fragment_spirv = grass_billboards_frag;
        // The copies' normal matrix (locations 6-8) carries no normal here, only the terrain's
        // corner heights in its w (grass_terrain.h).
        quads.vertices = grass::quad_layout();
        const uint32_t vertices = crossed ? kQuadVertices : kQuadVertices / 2;
        frame.settings = fmt::format("orientation={}", g.report["orientation"]);
        frame.record = [ground, quads, vertices](PassContext& pc) {
            grass::record_ground_and_copies(pc, ground, quads, names::kQuads, vertices);
        };
        g.passes.push_back(std::move(frame));
        return g;
    }
};

RegisterTechnique<GrassBillboard> registered;

}  // namespace
}  // namespace canopy
