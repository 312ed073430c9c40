#include "macro_cells.hpp"

#include "grass_passes.hpp"
#include "grass_population.hpp"
#include "patch_bake.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>

namespace canopy::grass {

namespace {

// The first grass population's field, or nullopt-like: a 0 x 0 field.
GrassField field_of(const GeneratedPopulation* population) {
    if (!population) return GrassField{.cells = {0, 0}};
    return grass_population_spec(population->params).field;
}

}  // namespace

std::vector<glm::vec4> macro_instances(glm::uvec2 cells, uint32_t k) {
    std::vector<glm::vec4> macros;
    k = std::max(k, 1u);
    for (uint32_t z = 0; z < cells.y; z += k)
        for (uint32_t x = 0; x < cells.x; x += k)
            macros.emplace_back(float(x), float(z), float(std::min(k, cells.x - x)), float(std::min(k, cells.y - z)));
    return macros;
}

uint32_t macro_count(glm::uvec2 cells, uint32_t k) {
    k = std::max(k, 1u);
    return ((cells.x + k - 1) / k) * ((cells.y + k - 1) / k);
}

std::vector<shader::GrassCell> grass_cells(const GrassField& field, std::span<const PopulationInstance> copies) {
    if (copies.size() != size_t(field.cells.x) * field.cells.y)
        throw std::logic_error(fmt::format("grass_cells: {} copies for a field of {} x {} cells", copies.size(),
                                           field.cells.x, field.cells.y));
    std::vector<shader::GrassCell> cells(copies.size());
    for (size_t c = 0; c < copies.size(); ++c) {
        const glm::ivec2 cell(int(c % field.cells.x), int(c / field.cells.x));
        cells[c].densities = copies[c].data;
        cells[c].signs = glm::vec4(mirror_signs(field, cell), 0.0f, 0.0f);
    }
    return cells;
}

shader::GrassMacroField macro_field(const GrassField& field, uint32_t k, float top) {
    shader::GrassMacroField f;
    f.origin_size = glm::vec4(field.origin, field.cell_size);
    f.cells = glm::ivec4(int(field.cells.x), int(field.cells.y), int(k), 0);
    f.patch_top = glm::vec4(top, 0.0f, 0.0f, 0.0f);
    return f;
}

void declare_macro_buffers(FrameGraph& g) {
    g.buffers.push_back({.name = macro_names::kCells, .bytes_per_copy = sizeof(shader::GrassCell),
                         .usage = kStorageBuffer, .persistent = true});
    g.buffers.push_back({.name = macro_names::kMacros, .bytes_per_copy = sizeof(glm::vec4), .usage = kVertexBuffer,
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
        const std::vector<glm::vec4> macros = macro_instances(field.cells, k);
        const shader::GrassMacroField placement = macro_field(field, k, cell_frame(prototype_bounds(grass)).max.y);
        pc.upload(macro_names::kCells, cells.data(), cells.size() * sizeof(shader::GrassCell));
        pc.upload(macro_names::kMacros, macros.data(), macros.size() * sizeof(glm::vec4));
        pc.upload(macro_names::kField, &placement, sizeof(placement));
    };
    return p;
}

VertexLayout macro_layout() {
    VertexLayout layout;
    layout.bindings = {{uint32_t(sizeof(QuadVertex)), false}, {uint32_t(sizeof(glm::vec4)), true}};
    layout.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(offsetof(QuadVertex, position))},
                         {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(offsetof(QuadVertex, uv))},
                         {2, 1, VK_FORMAT_R32G32B32A32_SFLOAT, 0}};
    return layout;
}

void record_ground_and_macros(PassContext& pc, const RasterState& ground, const RasterState& over,
                              const std::string& vertex_buffer, uint32_t vertex_count, uint32_t k) {
    pc.bind(pc.raster_pipeline(ground));
    pc.draw_scene(SceneFilter::all);
    const GeneratedPopulation* grass = first_grass(pc.populations());
    if (!grass || grass->instances.empty()) return;
    const GrassField field = field_of(grass);
    const uint32_t macros = macro_count(field.cells, k);
    pc.bind(pc.raster_pipeline(over));
    const std::array<std::string, 2> buffers{vertex_buffer, macro_names::kMacros};
    pc.draw(buffers, vertex_count, macros);
}

}  // namespace canopy::grass
