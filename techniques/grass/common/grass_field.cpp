#include "grass_field.hpp"

#include "../shaders/cell_mirroring.h"
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

glm::vec3 field_point(const GrassField& field, glm::ivec2 cell, glm::vec3 patch_point) {
    return cell_point(field, cell, shader::grass_mirror_signs(cell, field.mirror_seed), patch_point);
}

uint64_t for_each_drawn_blade(const GrassField& field, const BladePatch& patch,
                              const std::function<void(const FieldBlade&)>& visit) {
    uint64_t drawn = 0;
    const glm::vec2 extent = field.cell_size * glm::vec2(field.cells);
    for (uint32_t z = 0; z < field.cells.y; ++z)
        for (uint32_t x = 0; x < field.cells.x; ++x) {
            const glm::ivec2 cell{int(x), int(z)};
            const glm::vec2 signs = shader::grass_mirror_signs(cell, field.mirror_seed);
            for (uint32_t i = 0; i < patch.blades.size(); ++i) {
                FieldBlade b;
                b.cell = cell;
                b.blade = i;
                b.root = cell_point(field, cell, signs, patch.blades[i].root);
                b.density = field.density.sample({(b.root.x - field.origin.x) / extent.x, (b.root.z - field.origin.z) / extent.y});
                if (!drawn_at_density(patch.blades[i].threshold, b.density)) continue;
                ++drawn;
                if (visit) visit(b);
            }
        }
    return drawn;
}

}  // namespace canopy::grass
