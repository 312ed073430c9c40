#include "macro_cells.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
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

std::vector<float> grid_heights(const GrassField& field, std::span<const PopulationInstance> copies) {
    if (copies.size() != size_t(field.cells.x) * field.cells.y)
        throw std::logic_error(fmt::format("grid_heights: {} copies for a field of {} x {} cells", copies.size(),
                                           field.cells.x, field.cells.y));
    const size_t row = size_t(field.cells.x) + 1;
    std::vector<float> grid(row * (size_t(field.cells.y) + 1), 0.0f);
    for (uint32_t z = 0; z < field.cells.y; ++z)
        for (uint32_t x = 0; x < field.cells.x; ++x) {
            const PopulationInstance& copy = copies[size_t(z) * field.cells.x + x];
            const float h00 = copy.model[3].y - field.origin.y;
            // Each vertex once from the cell it is the (x0, z0) corner of; the far edges from the last cells.
            grid[size_t(z) * row + x] = h00;
            if (x + 1 == field.cells.x) grid[size_t(z) * row + x + 1] = h00 + copy.normal_matrix[0].w;
            if (z + 1 == field.cells.y) grid[size_t(z + 1) * row + x] = h00 + copy.normal_matrix[1].w;
            if (x + 1 == field.cells.x && z + 1 == field.cells.y)
                grid[size_t(z + 1) * row + x + 1] = h00 + copy.normal_matrix[2].w;
        }
    return grid;
}

float macro_unplanarity(std::span<const float> grid, glm::uvec2 cells, MacroInstance m) {
    const size_t row = size_t(cells.x) + 1;
    const auto at = [&](uint32_t x, uint32_t z) { return grid[size_t(z) * row + x]; };
    const uint32_t x0 = m.x, z0 = m.y, x1 = m.x + m.z, z1 = m.y + m.w;
    const float h00 = at(x0, z0), h10 = at(x1, z0), h01 = at(x0, z1), h11 = at(x1, z1);
    float worst = 0.0f;
    for (uint32_t z = z0; z <= z1; ++z)
        for (uint32_t x = x0; x <= x1; ++x) {
            const float u = float(x - x0) / float(m.z), v = float(z - z0) / float(m.w);
            const float bilinear = (h00 * (1.0f - u) + h10 * u) * (1.0f - v) + (h01 * (1.0f - u) + h11 * u) * v;
            worst = std::max(worst, std::abs(at(x, z) - bilinear));
        }
    return worst;
}

glm::vec2 macro_height_range(std::span<const float> grid, glm::uvec2 cells, MacroInstance m) {
    const size_t row = size_t(cells.x) + 1;
    glm::vec2 range(grid[size_t(m.y) * row + m.x]);
    for (uint32_t z = m.y; z <= uint32_t(m.y + m.w); ++z)
        for (uint32_t x = m.x; x <= uint32_t(m.x + m.z); ++x) {
            const float h = grid[size_t(z) * row + x];
            range = {std::min(range.x, h), std::max(range.y, h)};
        }
    return range;
}

std::vector<MacroInstance> macro_instances_on_terrain(glm::uvec2 cells, uint32_t k, std::span<const float> grid,
                                                      float max_unplanarity) {
    std::vector<MacroInstance> out;
    const std::function<void(MacroInstance)> place = [&](MacroInstance m) {
        if ((m.z == 1 && m.w == 1) || macro_unplanarity(grid, cells, m) <= max_unplanarity) {
            out.push_back(m);
            return;
        }
        const uint16_t wx = uint16_t((m.z + 1) / 2), wz = uint16_t((m.w + 1) / 2);
        for (uint16_t dz = 0; dz < m.w; dz = uint16_t(dz + wz))
            for (uint16_t dx = 0; dx < m.z; dx = uint16_t(dx + wx))
                place(MacroInstance(m.x + dx, m.y + dz, std::min<uint16_t>(wx, uint16_t(m.z - dx)),
                                    std::min<uint16_t>(wz, uint16_t(m.w - dz))));
    };
    for (const MacroInstance& m : macro_instances(cells, k)) place(m);
    return out;
}

shader::GrassMacroField macro_field(const GrassField& field, uint32_t k, float top, float transmission) {
    shader::GrassMacroField f;
    f.origin_size = glm::vec4(field.origin, field.cell_size);
    f.cells = glm::ivec4(int(field.cells.x), int(field.cells.y), int(k), 0);
    f.patch_top = glm::vec4(top, transmission, 0.0f, 0.0f);
    return f;
}

}  // namespace canopy::grass
