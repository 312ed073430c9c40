// grass.geometry: the field's blades drawn as geometry (Lemme ch. 4, Boulanger §4.2): every
// cell's mirrored copy of the blade patch in one instanced draw, thinned in the vertex shader,
// the outline cut by an alpha test or alpha-to-coverage with MSAA.
#include "core/registry.hpp"
#include "graph/pass_context.hpp"
#include "render/frame_uniforms.hpp"

#include "grass_geometry_params.h"
#include "../common/grass_cull.hpp"
#include "../common/grass_family.hpp"
#include "../common/grass_passes.hpp"
#include "../common/grass_population.hpp"

#include "shaders/grass/grass_blades_frag.h"
#include "shaders/grass/grass_blades_vert.h"

#include <fmt/format.h>


namespace canopy {
namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;  // as the camera target

using grass::cleared;
using grass::kFarDepth;
using grass::use;

class GrassGeometry final : public Technique {
public:
    std::string name() const override { return "grass.geometry"; }
    std::string summary() const override {
        return "grass as blades: instanced patches per cell, alpha test or alpha-to-coverage with MSAA, optionally GPU-culled";
    }
    std::string paper() const override { return "Lemme 2012 ch. 4 and 6; Boulanger 2008 §4.2"; }
    std::vector<ParamSpec> params() const override { return shader::GrassGeometryParams::specs(); }
    ErrorColumns error_columns() const override { return grass::kGrassErrorColumns; }
    std::vector<std::string> pareto_errors() const override { return grass::pareto_errors(); }

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
        g.needs.populations_on_terrain = true;  // grass_blades_vertex.glsl lifts each blade (grass_terrain.h)
        g.shader_params.set_block(block);
        g.report["coverage"] = to_coverage ? "alpha-to-coverage" : "alpha-test";
        g.report["samples"] = std::to_string(samples);
        g.report["culling"] = culled ? (max_distance > 0.0f ? fmt::format("gpu, within {}", max_distance) : "gpu") : "none";
        // Read only by the cull: without it, the report (and the pass's settings) say the value was unused.
        if (!culled && max_distance > 0.0f) g.report["culling"] = fmt::format("none (max_distance {} unused)", max_distance);
        if (culled) grass::declare_grass_cull(g, {{.max_distance = max_distance}});

        const std::array<float, 4> background = grass::kUncoveredClear;
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
        if (culled) grass::use_cull_survivors(blades);
        blades.record = [ground, field, culled](PassContext& pc) {
            pc.bind(pc.raster_pipeline(ground));
            pc.draw_scene(SceneFilter::all);
            pc.bind(pc.raster_pipeline(field));
            if (culled)
                grass::draw_populations_culled(pc);
            else
                for (const GeneratedPopulation& population : pc.populations()) pc.draw_population(population.name);
        };
        g.passes.push_back(std::move(blades));
        if (samples > 1) g.passes.push_back(grass::clear_camera_depth_pass());
        return g;
    }
};

RegisterTechnique<GrassGeometry> registered;

}  // namespace
}  // namespace canopy
