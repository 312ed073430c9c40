// grass.geometry: the field's blades drawn as geometry (Lemme ch. 4, Boulanger §4.2): every
// cell's mirrored copy of the blade patch in one instanced draw, thinned in the vertex shader,
// the outline cut by an alpha test or alpha-to-coverage with MSAA.
#include "core/registry.hpp"
#include "graph/pass_context.hpp"
#include "render/frame_uniforms.hpp"

#include "grass_geometry_params.h"
#include "../common/grass_passes.hpp"
#include "../common/grass_population.hpp"
#include "../common/patch_bake.hpp"
#include "../shaders/grass_culling.h"

#include "shaders/grass/grass_blades_frag.h"
#include "shaders/grass/grass_blades_vert.h"
#include "shaders/grass/grass_cull_comp.h"

#include <fmt/format.h>

#include <algorithm>

namespace canopy {
namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;  // as the camera target

using grass::cleared;
using grass::kFarDepth;
using grass::use;

namespace names {
constexpr const char* kCull = "cull";                // GrassCull
constexpr const char* kCopies = "cull_copies";       // PopulationInstance per copy of the first grass population
constexpr const char* kSurvivors = "survivors";      // the copies the cull keeps, packed
constexpr const char* kArguments = "draw_arguments"; // VkDrawIndexedIndirectCommand
}  // namespace names

// The culled draw's declarations: the copies and the cull block uploaded at load, the cull pass
// (compute) every frame before the blades.
void declare_cull(FrameGraph& g) {
    g.buffers.push_back({.name = names::kCull, .bytes = sizeof(shader::GrassCull), .usage = kUniformBuffer, .persistent = true});
    g.buffers.push_back({.name = names::kCopies, .bytes_per_copy = sizeof(PopulationInstance), .usage = kStorageBuffer,
                         .persistent = true});
    g.buffers.push_back({.name = names::kSurvivors, .bytes_per_copy = sizeof(PopulationInstance),
                         .usage = kStorageBuffer | kVertexBuffer});
    g.buffers.push_back({.name = names::kArguments, .bytes = sizeof(VkDrawIndexedIndirectCommand),
                         .usage = kStorageBuffer | kIndirectBuffer});

    PassDecl setup{.name = "cull_setup", .kind = PassKind::copy, .phase = Phase::load};
    setup.uses = {use(names::kCull, Use::transfer_write), use(names::kCopies, Use::transfer_write)};
    setup.settings = "the first grass population's copies";
    setup.record = [](PassContext& pc) {
        const GeneratedPopulation* grass = grass::first_grass(pc.populations());
        shader::GrassCull cull{};
        if (grass && !grass->instances.empty()) {
            const Bounds bounds = grass::prototype_bounds(grass);
            const VkDrawIndexedIndirectCommand draw = pc.population_draw_arguments(grass->name);
            cull.box_min = glm::vec4(bounds.min, 0.0f);
            cull.box_max = glm::vec4(bounds.max, 0.0f);
            cull.draw = glm::uvec4(draw.indexCount, draw.firstIndex, uint32_t(draw.vertexOffset), draw.instanceCount);
            pc.upload(names::kCopies, grass->instances.data(), grass->instances.size() * sizeof(PopulationInstance));
        }
        pc.upload(names::kCull, &cull, sizeof(cull));
    };
    g.passes.push_back(std::move(setup));

    PassDecl cull{.name = "cull", .kind = PassKind::compute};
    cull.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(names::kCull, Use::uniform, 1),
                 use(names::kCopies, Use::storage_read, 2), use(names::kSurvivors, Use::storage_write, 3),
                 use(names::kArguments, Use::storage_write, 4)};
    cull.settings = "frustum and max_distance, one invocation per copy";
    cull.record = [](PassContext& pc) {
        const GeneratedPopulation* grass = grass::first_grass(pc.populations());
        // The count restarts at 0 by a fill before the dispatch, not by a barrier inside a workgroup.
        pc.fill(names::kArguments, 0);
        const uint32_t copies = grass ? uint32_t(grass->instances.size()) : 0;
        pc.dispatch(pc.compute_pipeline(grass_cull_comp), std::max(1u, (copies + 63) / 64), 1, 1);
    };
    g.passes.push_back(std::move(cull));
}

class GrassGeometry final : public Technique {
public:
    std::string name() const override { return "grass.geometry"; }
    std::string summary() const override {
        return "grass as blades: instanced patches per cell, alpha test or alpha-to-coverage with MSAA, optionally GPU-culled";
    }
    std::string paper() const override { return "Lemme 2012 ch. 4 and 6; Boulanger 2008 §4.2"; }
    std::vector<ParamSpec> params() const override { return shader::GrassGeometryParams::specs(); }
    ErrorColumns error_columns() const override { return {}; }  // image errors only: no lit pass of canopy's

    std::optional<ParamConflict> conflict(const ParamSet& params) const override {
        return grass::blade_samples_conflict(params);
    }

    FrameGraph graph(const ParamSet& params) const override {
        const uint32_t samples = uint32_t(params.integer("samples"));
        const auto block = shader::GrassGeometryParams::from(params);
        const bool to_coverage = block.coverage == shader::GRASS_COVERAGE_ALPHA_TO_COVERAGE;
        const bool culled = params.choice("culling") == "gpu";
        const float max_distance = float(params.real("max_distance"));
        FrameGraph g;
        g.needs.populations = {grass::kGrassPopulationKind};
        g.shader_params.set_block(block);
        g.report["coverage"] = to_coverage ? "alpha-to-coverage" : "alpha-test";
        g.report["samples"] = std::to_string(samples);
        g.report["culling"] = culled ? (max_distance > 0.0f ? fmt::format("gpu, within {}", max_distance) : "gpu") : "none";
        if (culled) declare_cull(g);

        const std::array<float, 4> background{0.0f, 0.0f, 0.0f, 1.0f};
        PassDecl blades{.name = "blades", .kind = PassKind::raster};
        blades.push_constant_bytes = sizeof(DrawConstants);
        blades.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0)};
        if (samples > 1) {
            g.images.push_back({.name = "msaa_color", .format = kColorFormat, .extent = ImageExtent::screen(),
                                .samples = samples});
            g.images.push_back({.name = "msaa_depth", .format = VK_FORMAT_D32_SFLOAT, .extent = ImageExtent::screen(),
                                .samples = samples});
            blades.uses.push_back(cleared("msaa_color", Use::color_attachment, background));
            blades.uses.push_back(cleared("msaa_depth", Use::depth_attachment, kFarDepth, false));
            blades.uses.push_back(use(graph_names::kColor, Use::resolve_target));
        } else {
            blades.uses.push_back(cleared(graph_names::kColor, Use::color_attachment, background));
            blades.uses.push_back(cleared(graph_names::kDepth, Use::depth_attachment, kFarDepth));
        }
        const RasterState ground = grass::ground_state();
        RasterState field;
        field.vertex_spirv = grass_blades_vert;
        field.fragment_spirv = grass_blades_frag;
        field.vertices = VertexLayout::population();
        field.alpha_to_coverage = to_coverage && samples > 1;
        blades.settings = fmt::format("samples={} coverage={} culling={}", samples, g.report["coverage"], g.report["culling"]);
        if (culled) {
            blades.uses.push_back(use(names::kSurvivors, Use::vertex));
            blades.uses.push_back(use(names::kArguments, Use::indirect));
        }
        blades.record = [ground, field, culled](PassContext& pc) {
            pc.bind(pc.raster_pipeline(ground));
            pc.draw_scene(SceneFilter::all);
            pc.bind(pc.raster_pipeline(field));
            const GeneratedPopulation* first = grass::first_grass(pc.populations());
            for (const GeneratedPopulation& population : pc.populations()) {
                // The cull covers the first grass population; others are drawn whole.
                if (culled && &population == first)
                    pc.draw_population_indirect(population.name, names::kSurvivors, names::kArguments);
                else
                    pc.draw_population(population.name);
            }
        };
        g.passes.push_back(std::move(blades));
        if (samples > 1) g.passes.push_back(grass::clear_camera_depth_pass());
        return g;
    }
};

RegisterTechnique<GrassGeometry> registered;

}  // namespace
}  // namespace canopy
