#include "grass_field.hpp"

#include "../shaders/cell_mirroring.h"
#include "../shaders/grass_density.h"
#include "density_thresholds.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace canopy::grass {

namespace {

glm::vec3 cell_point(const GrassField& field, glm::ivec2 cell, glm::vec2 signs, glm::vec3 patch_point) {
    const glm::vec3 mirrored = shader::grass_mirror_patch_point(patch_point, signs);
    return field.origin + field.cell_size * (glm::vec3(float(cell.x), 0.0f, float(cell.y)) + mirrored);
}

}  // namespace

float DensityMap::sample(glm::vec2 uv) const {
    if (width == 0 || height == 0) return 1.0f;
    if (values.size() != size_t(width) * height)
        throw std::logic_error(fmt::format("density map: {} values for {} x {} texels", values.size(), width, height));
    // Texel centres at (i + 0.5) / width: the bilinear filter of a GPU sampler, clamped.
    const float x = std::clamp(uv.x * float(width) - 0.5f, 0.0f, float(width - 1));
    const float y = std::clamp(uv.y * float(height) - 0.5f, 0.0f, float(height - 1));
    const uint32_t x0 = uint32_t(x), y0 = uint32_t(y);
    const uint32_t x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
    const float fx = x - float(x0), fy = y - float(y0);
    const auto at = [&](uint32_t i, uint32_t j) { return values[size_t(j) * width + i]; };
    const float bottom = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * fx;
    const float top = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * fx;
    return bottom + (top - bottom) * fy;
}

glm::vec2 mirror_signs(const GrassField& field, glm::ivec2 cell) {
    return field.mirror ? shader::grass_mirror_signs(cell, field.mirror_seed) : glm::vec2(1.0f);
}

glm::vec3 field_point(const GrassField& field, glm::ivec2 cell, glm::vec3 patch_point) {
    return cell_point(field, cell, mirror_signs(field, cell), patch_point);
}

glm::vec4 cell_corner_densities(const GrassField& field, glm::ivec2 cell) {
    const glm::vec2 cells(field.cells);
    const auto at = [&](int dx, int dz) {
        return field.density.sample({float(cell.x + dx) / cells.x, float(cell.y + dz) / cells.y});
    };
    return {at(0, 0), at(1, 0), at(0, 1), at(1, 1)};
}

uint64_t for_each_drawn_blade(const GrassField& field, const BladePatch& patch,
                              const std::function<void(const FieldBlade&)>& visit) {
    uint64_t drawn = 0;
    for (uint32_t z = 0; z < field.cells.y; ++z)
        for (uint32_t x = 0; x < field.cells.x; ++x) {
            const glm::ivec2 cell{int(x), int(z)};
            const glm::vec2 signs = mirror_signs(field, cell);
            const glm::vec4 corners = shader::grass_patch_corner_densities(cell_corner_densities(field, cell), signs);
            for (uint32_t i = 0; i < patch.blades.size(); ++i) {
                FieldBlade b;
                b.cell = cell;
                b.blade = i;
                b.root = cell_point(field, cell, signs, patch.blades[i].root);
                b.density = shader::grass_root_density(corners, {patch.blades[i].root.x, patch.blades[i].root.z});
                if (!drawn_at_density(patch.blades[i].threshold, b.density)) continue;
                ++drawn;
                if (visit) visit(b);
            }
        }
    return drawn;
}

}  // namespace canopy::grass
