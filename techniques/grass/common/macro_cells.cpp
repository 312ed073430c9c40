#include "macro_cells.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace canopy::grass {

std::vector<MacroInstance> macro_instances(glm::uvec2 cells, uint32_t k) {
    std::vector<MacroInstance> macros;
    k = std::max(k, 1u);
    for (uint32_t z = 0; z < cells.y; z += k)
        for (uint32_t x = 0; x < cells.x; x += k)
            macros.emplace_back(x, z, std::min(k, cells.x - x), std::min(k, cells.y - z));
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

shader::GrassMacroField macro_field(const GrassField& field, uint32_t k, float top, float transmission) {
    shader::GrassMacroField f;
    f.origin_size = glm::vec4(field.origin, field.cell_size);
    f.cells = glm::ivec4(int(field.cells.x), int(field.cells.y), int(k), 0);
    f.patch_top = glm::vec4(top, transmission, 0.0f, 0.0f);
    return f;
}

}  // namespace canopy::grass
