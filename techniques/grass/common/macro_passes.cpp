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

void declare_macro_buffers(FrameGraph& g, bool terrain) {
    g.buffers.push_back({.name = macro_names::kCells, .bytes_per_copy = sizeof(shader::GrassCell),
                         .usage = kStorageBuffer, .persistent = true});
    g.buffers.push_back({.name = macro_names::kMacros, .bytes_per_copy = sizeof(MacroInstance), .usage = kVertexBuffer,
                         .persistent = true});
    g.buffers.push_back({.name = macro_names::kField, .bytes = sizeof(shader::GrassMacroField),
                         .usage = kUniformBuffer, .persistent = true});
    // (cells.x + 1)(cells.z + 1) floats: one a copy, plus the far row and column of a field of at
    // most kMaxFieldSide cells a side.
    if (terrain)
        g.buffers.push_back({.name = macro_names::kHeights, .bytes = sizeof(float) * (2 * kMaxFieldSide + 1),
                             .bytes_per_copy = sizeof(float), .usage = kStorageBuffer, .persistent = true});
}

PassDecl macro_setup_pass(uint32_t k, const std::optional<MacroTerrain>& terrain) {
    PassDecl p{.name = "macro_setup", .kind = PassKind::copy, .phase = Phase::load};
    p.uses = {use(macro_names::kCells, Use::transfer_write), use(macro_names::kMacros, Use::transfer_write),
              use(macro_names::kField, Use::transfer_write)};
    if (terrain) p.uses.push_back(use(macro_names::kHeights, Use::transfer_write));
    p.settings = fmt::format("macro_cells={}{}", k,
                             terrain ? fmt::format(", split above {} unplanarity", terrain->max_unplanarity) : "");
    p.record = [k, terrain](PassContext& pc) {
        const GeneratedPopulation* grass = first_grass(pc.populations());
        if (!grass || grass->instances.empty()) return;
        const GrassField field = field_of(grass);
        const std::vector<shader::GrassCell> cells = grass_cells(field, grass->instances);
        std::vector<MacroInstance> macros;
        if (terrain) {
            const std::vector<float> heights = grid_heights(field, grass->instances);
            macros = macro_instances_on_terrain(field.cells, k, heights, terrain->max_unplanarity);
            *terrain->count = uint32_t(macros.size());
            pc.upload(macro_names::kHeights, heights.data(), heights.size() * sizeof(float));
        } else {
            macros = macro_instances(field.cells, k);
        }
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
                              const std::string& vertex_buffer, uint32_t vertex_count, uint32_t k,
                              const std::optional<MacroTerrain>& terrain) {
    pc.bind(pc.raster_pipeline(ground));
    pc.draw_scene(SceneFilter::all);
    const GeneratedPopulation* grass = first_grass(pc.populations());
    if (!grass || grass->instances.empty()) return;
    const uint32_t macros = terrain ? *terrain->count : macro_count(cells_of(grass), k);
    pc.bind(pc.raster_pipeline(over));
    const std::array<std::string, 2> buffers{vertex_buffer, macro_names::kMacros};
    pc.draw(buffers, vertex_count, macros);
}

}  // namespace canopy::grass
