#include "grass_field.hpp"

#include "../shaders/cell_mirroring.h"
#include "../shaders/grass_density.h"
#include "density_thresholds.hpp"

#include "scene/height_field.hpp"

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

namespace {

// A smooth value noise in [0, 1] over [0, 1]^2: hashed lattice values blended by smoothstep.
float value_noise(glm::vec2 uv, uint32_t periods, uint32_t seed) {
    const glm::vec2 q = uv * float(periods);
    const glm::ivec2 c(glm::floor(q));
    const glm::vec2 f = q - glm::vec2(c);
    const auto lattice = [&](int dx, int dz) {
        return float(shader::grass_cell_hash(c + glm::ivec2(dx, dz), seed) & 0xffffu) / 65535.0f;
    };
    const glm::vec2 s = f * f * (3.0f - 2.0f * f);
    const float bottom = lattice(0, 0) + (lattice(1, 0) - lattice(0, 0)) * s.x;
    const float top = lattice(0, 1) + (lattice(1, 1) - lattice(0, 1)) * s.x;
    return bottom + (top - bottom) * s.y;
}

}  // namespace

DensityMap density_map(DensityPattern pattern, float low, float high, uint32_t texels, uint32_t periods, uint32_t seed) {
    if (texels == 0 || periods == 0) throw std::invalid_argument("density_map: texels and periods must be above 0");
    if (!(low >= 0.0f && high <= 1.0f)) throw std::invalid_argument("density_map: densities lie in [0, 1]");
    if (pattern == DensityPattern::uniform) return DensityMap{1, 1, {high}};
    DensityMap map{texels, texels, std::vector<float>(size_t(texels) * texels)};
    std::vector<float> noise;
    if (pattern == DensityPattern::clearings) {
        for (uint32_t j = 0; j < texels; ++j)
            for (uint32_t i = 0; i < texels; ++i)
                noise.push_back(value_noise({(float(i) + 0.5f) / float(texels), (float(j) + 0.5f) / float(texels)}, periods, seed));
    }
    float median = 0.5f;
    if (!noise.empty()) {
        std::vector<float> sorted = noise;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        median = sorted[sorted.size() / 2];
    }
    for (uint32_t j = 0; j < texels; ++j)
        for (uint32_t i = 0; i < texels; ++i) {
            const size_t k = size_t(j) * texels + i;
            float t = 0.0f;  // 0: low, 1: high
            if (pattern == DensityPattern::ramp_x) t = texels == 1 ? 1.0f : float(i) / float(texels - 1);
            if (pattern == DensityPattern::clearings) {
                const float e = std::clamp((noise[k] - (median - 0.05f)) / 0.1f, 0.0f, 1.0f);
                t = e * e * (3.0f - 2.0f * e);
            }
            map.values[k] = low + (high - low) * t;
        }
    return map;
}

DensityMap density_map_from_image(const Image& image, float low, float high, const std::string& file) {
    if (image.width <= 0 || image.height <= 0) throw std::invalid_argument(fmt::format("density map {} is empty", file));
    if (!(low >= 0.0f && high <= 1.0f && low <= high)) throw std::invalid_argument("density_map: densities lie in [0, 1]");
    DensityMap map{uint32_t(image.width), uint32_t(image.height), {}};
    map.values.reserve(size_t(image.width) * size_t(image.height));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float v = image.at(x, y)[0];
            if (!(v >= 0.0f && v <= 1.0f))
                throw std::invalid_argument(fmt::format("density map {}: texel ({}, {}) holds {}, outside [0, 1]: a density map "
                                                        "holds shares of the blades (an 8- or 16-bit image reads as [0, 1])",
                                                        file, x, y, v));
            map.values.push_back(low + (high - low) * v);
        }
    return map;
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

void check_terrain_fits(const GrassField& field) {
    if (!field.ground.terrain) return;
    const HeightField& t = *field.ground.terrain;
    const glm::vec2 extent = field.cell_size * glm::vec2(field.cells);
    const glm::vec2 centre = glm::vec2(field.origin.x, field.origin.z) + 0.5f * extent;
    const glm::vec2 terrain_centre(field.ground.origin.x, field.ground.origin.z);
    const float tolerance = 1e-4f * std::max(1.0f, std::max(extent.x, extent.y));
    const bool grid = t.vertices == field.cells + 1u;
    const bool size = glm::all(glm::lessThanEqual(glm::abs(t.size - extent), glm::vec2(tolerance)));
    const bool centred = glm::all(glm::lessThanEqual(glm::abs(terrain_centre - centre), glm::vec2(tolerance)));
    if (grid && size && centred) return;
    throw std::invalid_argument(fmt::format(
        "the field stands on the heightfield '{}', whose grid must be its cells (one grid quad a cell, "
        "shaders/grass_terrain.h): give it vertices = [{}, {}] (it has [{}, {}]), size = [{}, {}] (it has [{}, {}]) "
        "and translate x, z = {}, {} (it has {}, {}), or change cells_x, cells_z, cell_size, centre_x and centre_z",
        field.ground.name, field.cells.x + 1, field.cells.y + 1, t.vertices.x, t.vertices.y, extent.x, extent.y, t.size.x,
        t.size.y, centre.x, centre.y, terrain_centre.x, terrain_centre.y));
}

float terrain_height(const GrassField& field, glm::vec2 world_xz) { return field.ground.height_at(world_xz); }

glm::vec4 cell_corner_heights(const GrassField& field, glm::ivec2 cell) {
    if (!field.ground.terrain) return glm::vec4(0.0f);
    const auto at = [&](int dx, int dz) {
        return terrain_height(field, {field.origin.x + field.cell_size * float(cell.x + dx),
                                      field.origin.z + field.cell_size * float(cell.y + dz)});
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
                b.root.y += terrain_height(field, {b.root.x, b.root.z});
                b.density = shader::grass_root_density(corners, {patch.blades[i].root.x, patch.blades[i].root.z});
                if (!drawn_at_density(patch.blades[i].threshold, b.density)) continue;
                ++drawn;
                if (visit) visit(b);
            }
        }
    return drawn;
}

}  // namespace canopy::grass
