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

}  // namespace

bool macros_on_terrain(std::span<const GeneratedPopulation> populations) {
    const GeneratedPopulation* grass = first_grass(populations);
    return grass && grass->on_terrain;
}

BufferDecl grid_heights_buffer(bool host_visible) {
    // (cells.x + 1)(cells.z + 1) floats: one a copy, plus the far row and column of a field of at
    // most kMaxFieldSide cells a side.
    return {.name = macro_names::kHeights, .bytes = sizeof(float) * (2 * kMaxFieldSide + 1),
            .bytes_per_copy = sizeof(float), .usage = kStorageBuffer, .persistent = true,
            .host_visible = host_visible, .only_on_terrain = true};
}

std::vector<float> upload_grid_heights(PassContext& pc, const GrassField& field, const GeneratedPopulation& grass) {
    std::vector<float> heights = grid_heights(field, grass.instances);
    pc.upload(macro_names::kHeights, heights.data(), heights.size() * sizeof(float));
    return heights;
}

void declare_macro_buffers(FrameGraph& g, const MacroTerrain& terrain) {
    g.buffers.push_back({.name = macro_names::kCells, .bytes_per_copy = sizeof(shader::GrassCell),
                         .usage = kStorageBuffer, .persistent = true});
    g.buffers.push_back({.name = macro_names::kMacros, .bytes_per_copy = sizeof(MacroInstance), .usage = kVertexBuffer,
                         .persistent = true});
    g.buffers.push_back({.name = macro_names::kField, .bytes = sizeof(shader::GrassMacroField),
                         .usage = kUniformBuffer, .persistent = true});
    g.buffers.push_back(grid_heights_buffer(false));
    // At most one macro-cell a cell, splits included.
    if (terrain.height_ranges)
        g.buffers.push_back({.name = macro_names::kRanges, .bytes_per_copy = sizeof(glm::vec2), .usage = kStorageBuffer,
                             .persistent = true, .only_on_terrain = true});
}

PassDecl macro_setup_pass(uint32_t k, const MacroTerrain& terrain) {
    PassDecl p{.name = "macro_setup", .kind = PassKind::copy, .phase = Phase::load};
    p.uses = {use(macro_names::kCells, Use::transfer_write), use(macro_names::kMacros, Use::transfer_write),
              use(macro_names::kField, Use::transfer_write), use(macro_names::kHeights, Use::transfer_write)};
    if (terrain.height_ranges) p.uses.push_back(use(macro_names::kRanges, Use::transfer_write));
    p.settings = fmt::format("macro_cells={}{}{}", k,
                             terrain.max_unplanarity
                                 ? fmt::format(", on a terrain split above {} unplanarity", *terrain.max_unplanarity)
                                 : "",
                             terrain.height_ranges ? ", height ranges on a terrain" : "");
    p.record = [k, terrain](PassContext& pc) {
        *terrain.count = 0;
        const GeneratedPopulation* grass = first_grass(pc.populations());
        if (!grass || grass->instances.empty()) return;
        const GrassField field = field_of(grass);
        const std::vector<shader::GrassCell> cells = grass_cells(field, grass->instances);
        std::vector<MacroInstance> macros;
        if (macros_on_terrain(pc.populations())) {
            const std::vector<float> heights = upload_grid_heights(pc, field, *grass);
            macros = terrain.max_unplanarity
                         ? macro_instances_on_terrain(field.cells, k, heights, *terrain.max_unplanarity)
                         : macro_instances(field.cells, k);
            if (terrain.height_ranges) {
                std::vector<glm::vec2> ranges;
                ranges.reserve(macros.size());
                for (const MacroInstance& m : macros) ranges.push_back(macro_height_range(heights, field.cells, m));
                pc.upload(macro_names::kRanges, ranges.data(), ranges.size() * sizeof(glm::vec2));
            }
        } else {
            macros = macro_instances(field.cells, k);
        }
        *terrain.count = uint32_t(macros.size());
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

void use_macro_buffers(PassDecl& pass, const MacroTerrain& terrain) {
    pass.uses.push_back(use(macro_names::kField, Use::uniform, 3));
    pass.uses.push_back(use(macro_names::kCells, Use::storage_read, 4));
    pass.uses.push_back(use(macro_names::kMacros, Use::vertex));
    pass.uses.push_back(use(macro_names::kHeights, Use::storage_read, 5));
    if (terrain.height_ranges) pass.uses.push_back(use(macro_names::kRanges, Use::storage_read, 6));
}

void record_ground_and_macros(PassContext& pc, const RasterState& ground, const RasterState& flat,
                              const RasterState& on_terrain, const std::string& vertex_buffer, uint32_t vertex_count,
                              const MacroTerrain& terrain) {
    pc.bind(pc.raster_pipeline(ground));
    pc.draw_scene(SceneFilter::all);
    if (*terrain.count == 0) return;
    pc.bind(pc.raster_pipeline(macros_on_terrain(pc.populations()) ? on_terrain : flat));
    const std::array<std::string, 2> buffers{vertex_buffer, macro_names::kMacros};
    pc.draw(buffers, vertex_count, *terrain.count);
}

}  // namespace canopy::grass
