#include "grass_passes.hpp"

#include "patch_bake.hpp"

#include "shaders/grass/grass_ground_frag.h"
#include "shaders/grass/patch_bake_vert.h"
#include "shaders/harness/scene_vert.h"

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

void record_prototype_bake(PassContext& pc, const RasterState& bake) {
    const GeneratedPopulation* grass = first_grass(pc.populations());
    if (!grass) return;
    pc.bind(pc.raster_pipeline(bake));
    pc.draw_population(grass->name, 1);
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
