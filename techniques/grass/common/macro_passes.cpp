#include "macro_passes.hpp"

#include "grass_passes.hpp"
#include "grass_population.hpp"
#include "macro_cells.hpp"
#include "patch_bake.hpp"

#include <fmt/format.h>

#include <array>
#include <cstddef>

namespace canopy::grass {

namespace {

// The first grass population's field's placement (its density, which the copies carry, is not
// made again: no map is read or generated inside the load pass); a 0 x 0 field without one.
GrassField field_of(const GeneratedPopulation* population) {
    if (!population) return GrassField{.cells = {0, 0}};
    return grass_field_placement(population->params);
}

// Its cells alone, read from the parameters (every frame: no density map is made).
glm::uvec2 cells_of(const GeneratedPopulation* population) {
    if (!population) return {0, 0};
    return {uint32_t(population->params.integer("cells_x")), uint32_t(population->params.integer("cells_z"))};
}

}  // namespace

void declare_macro_buffers(FrameGraph& g) {
    g.buffers.push_back({.name = macro_names::kCells, .bytes_per_copy = sizeof(shader::GrassCell),
                         .usage = kStorageBuffer, .persistent = true});
    g.buffers.push_back({.name = macro_names::kMacros, .bytes_per_copy = sizeof(MacroInstance), .usage = kVertexBuffer,
                         .persistent = true});
    g.buffers.push_back({.name = macro_names::kField, .bytes = sizeof(shader::GrassMacroField),
                         .usage = kUniformBuffer, .persistent = true});
}

PassDecl macro_setup_pass(uint32_t k) {
    PassDecl p{.name = "macro_setup", .kind = PassKind::copy, .phase = Phase::load};
    p.uses = {use(macro_names::kCells, Use::transfer_write), use(macro_names::kMacros, Use::transfer_write),
              use(macro_names::kField, Use::transfer_write)};
    p.settings = fmt::format("macro_cells={}", k);
    p.record = [k](PassContext& pc) {
        const GeneratedPopulation* grass = first_grass(pc.populations());
        if (!grass || grass->instances.empty()) return;
        const GrassField field = field_of(grass);
        const std::vector<shader::GrassCell> cells = grass_cells(field, grass->instances);
        const std::vector<MacroInstance> macros = macro_instances(field.cells, k);
        const shader::GrassMacroField placement = macro_field(field, k, cell_frame(prototype_bounds(grass)).max.y, grass->transmission);
        pc.upload(macro_names::kCells, cells.data(), cells.size() * sizeof(shader::GrassCell));
        pc.upload(macro_names::kMacros, macros.data(), macros.size() * sizeof(MacroInstance));
        pc.upload(macro_names::kField, &placement, sizeof(placement));
    };
    return p;
}

VertexLayout macro_layout() {
    VertexLayout layout;
    layout.bindings = {{uint32_t(sizeof(QuadVertex)), false}, {uint32_t(sizeof(MacroInstance)), true}};
    layout.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(offsetof(QuadVertex, position))},
                         {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(offsetof(QuadVertex, uv))},
                         {2, 1, VK_FORMAT_R16G16B16A16_UINT, 0}};
    return layout;
}

void record_ground_and_macros(PassContext& pc, const RasterState& ground, const RasterState& over,
                              const std::string& vertex_buffer, uint32_t vertex_count, uint32_t k) {
    pc.bind(pc.raster_pipeline(ground));
    pc.draw_scene(SceneFilter::all);
    const GeneratedPopulation* grass = first_grass(pc.populations());
    if (!grass || grass->instances.empty()) return;
    const uint32_t macros = macro_count(cells_of(grass), k);
    pc.bind(pc.raster_pipeline(over));
    const std::array<std::string, 2> buffers{vertex_buffer, macro_names::kMacros};
    pc.draw(buffers, vertex_count, macros);
}

}  // namespace canopy::grass
