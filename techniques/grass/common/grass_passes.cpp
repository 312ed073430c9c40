#include "grass_passes.hpp"

#include "patch_bake.hpp"

#include "shaders/grass/grass_ground_frag.h"
#include "shaders/grass/patch_bake_vert.h"
#include "shaders/harness/scene_vert.h"

#include <array>
#include <cstddef>

namespace canopy::grass {

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

void record_ground_and_copies(PassContext& pc, const RasterState& ground, const RasterState& over,
                              const std::string& vertex_buffer, uint32_t vertex_count) {
    pc.bind(pc.raster_pipeline(ground));
    pc.draw_scene(SceneFilter::all);
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
