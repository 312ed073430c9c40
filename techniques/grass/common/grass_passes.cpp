#include "grass_passes.hpp"

#include "patch_bake.hpp"

#include "shaders/grass/grass_ground_frag.h"
#include "shaders/grass/patch_bake_vert.h"
#include "shaders/harness/scene_vert.h"

#include <array>
#include <fmt/format.h>
#include <cstddef>

namespace canopy::grass {

std::optional<ParamConflict> blade_samples_conflict(const ParamSet& params) {
    const long long samples = params.integer("samples");
    if (samples != 1 && samples != 4)
        return ParamConflict{{"samples"}, fmt::format("{} MSAA samples: lavapipe offers 1 and 4 only", samples),
                             "samples = 1 or samples = 4"};
    if (samples == 1 && params.choice("coverage") == "alpha_to_coverage")
        return ParamConflict{{"coverage", "samples"},
                             "alpha-to-coverage with one sample per pixel is an alpha test with wider blades",
                             "coverage = \"alpha_test\" for samples = 1, or samples = 4"};
    return std::nullopt;
}

PassDecl clear_camera_depth_pass() {
    PassDecl depth{.name = "clear_depth", .kind = PassKind::raster};
    depth.uses = {cleared(graph_names::kDepth, Use::depth_attachment, kFarDepth)};
    depth.settings = "clear";
    depth.record = [](PassContext&) {};
    return depth;
}

RasterState ground_state() {
    RasterState s;
    s.vertex_spirv = scene_vert;
    s.fragment_spirv = grass_ground_frag;
    return s;
}

VertexLayout without_locations(VertexLayout layout, uint32_t first, uint32_t last) {
    std::erase_if(layout.attributes,
                  [&](const VertexLayout::Attribute& a) { return a.location >= first && a.location <= last; });
    return layout;
}

RasterState bake_state(std::span<const uint32_t> fragment_spirv) {
    RasterState s;
    s.vertex_spirv = patch_bake_vert;
    s.fragment_spirv = fragment_spirv;
    s.vertices = without_locations(VertexLayout::population(), 2, 9);
    return s;
}

void record_prototype_bake(PassContext& pc, const RasterState& bake, bool tiled) {
    const GeneratedPopulation* grass = first_grass(pc.populations());
    if (!grass) return;
    pc.bind(pc.raster_pipeline(bake));
    if (tiled)
        pc.draw_prototype(grass->name, 9);
    else
        pc.draw_population(grass->name, 1);
}

void record_ground(PassContext& pc, const RasterState& ground) {
    pc.bind(pc.raster_pipeline(ground));
    pc.draw_scene(SceneFilter::all);
}

void record_ground_and_copies(PassContext& pc, const RasterState& ground, const RasterState& over,
                              const std::string& vertex_buffer, uint32_t vertex_count) {
    record_ground(pc, ground);
    record_copies(pc, over, vertex_buffer, vertex_count);
}

void record_copies(PassContext& pc, const RasterState& over, const std::string& vertex_buffer, uint32_t vertex_count) {
    pc.bind(pc.raster_pipeline(over));
    const std::array<std::string, 1> buffers{vertex_buffer};
    for (const GeneratedPopulation& population : pc.populations())
        pc.draw_over_population(population.name, buffers, vertex_count);
}

VertexLayout quad_layout() {
    VertexLayout layout;
    layout.bindings = {{uint32_t(sizeof(QuadVertex)), false}};
    layout.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(offsetof(QuadVertex, position))},
                         {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(offsetof(QuadVertex, uv))}};
    layout.population_copies();
    return layout;
}

}  // namespace canopy::grass
