#include "scene/height_field.hpp"

#include "scene/scene_limits.hpp"
#include "shaders/height_field.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace canopy {

namespace {

// The grid quad holding a local point and the point's place in it, clamped to the grid.
struct QuadPoint {
    glm::uvec2 quad;
    glm::vec2 f;
};

QuadPoint locate(const HeightField& field, glm::vec2 local_xz) {
    const glm::vec2 quads = glm::vec2(field.vertices - 1u);
    const glm::vec2 g = glm::clamp((local_xz / field.size + 0.5f) * quads, glm::vec2(0.0f), quads);
    const glm::uvec2 quad = glm::min(glm::uvec2(g), field.vertices - 2u);
    return {quad, g - glm::vec2(quad)};
}

glm::vec4 quad_heights(const HeightField& field, glm::uvec2 q) {
    return {field.vertex(q.x, q.y), field.vertex(q.x + 1, q.y), field.vertex(q.x, q.y + 1), field.vertex(q.x + 1, q.y + 1)};
}

// A lattice value in [0, 1] from the seed and the lattice point (a 32-bit integer hash).
float lattice_value(uint32_t seed, int x, int z) {
    uint32_t h = seed * 0x9E3779B9u ^ uint32_t(x) * 0x85EBCA6Bu ^ uint32_t(z) * 0xC2B2AE35u;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return float(h >> 8) / float(1u << 24);
}

float value_noise(uint32_t seed, glm::vec2 p) {
    const glm::vec2 cell = glm::floor(p);
    const glm::vec2 f = p - cell;
    const glm::vec2 s = f * f * (3.0f - 2.0f * f);  // smoothstep: C1 across lattice lines
    const int x = int(cell.x), z = int(cell.y);
    const float a = lattice_value(seed, x, z), b = lattice_value(seed, x + 1, z);
    const float c = lattice_value(seed, x, z + 1), d = lattice_value(seed, x + 1, z + 1);
    return glm::mix(glm::mix(a, b, s.x), glm::mix(c, d, s.x), s.y);
}

}  // namespace

float HeightField::at(glm::vec2 local_xz) const {
    const QuadPoint p = locate(*this, local_xz);
    return shader::height_field_quad(quad_heights(*this, p.quad), p.f);
}

glm::vec2 HeightField::range(glm::vec2 lo, glm::vec2 hi) const {
    // Each triangle's heights lie between its vertices', so the vertices of every quad the
    // rectangle touches bound the surface over it.
    const glm::uvec2 first = locate(*this, lo).quad, last = locate(*this, hi).quad;
    glm::vec2 out(vertex(first.x, first.y), vertex(first.x, first.y));
    for (uint32_t z = first.y; z <= last.y + 1; ++z)
        for (uint32_t x = first.x; x <= last.x + 1; ++x) {
            const float h = vertex(x, z);
            out = {std::min(out.x, h), std::max(out.y, h)};
        }
    return out;
}

HeightField hills_height_field(glm::vec2 size, glm::uvec2 vertices, uint32_t periods, uint32_t seed, float scale) {
    HeightField field;
    field.vertices = vertices;
    field.size = size;
    field.heights.resize(size_t(vertices.x) * vertices.y);
    for (uint32_t z = 0; z < vertices.y; ++z)
        for (uint32_t x = 0; x < vertices.x; ++x) {
            const glm::vec2 uv = glm::vec2(x, z) / glm::vec2(vertices - 1u);
            const glm::vec2 p = uv * float(periods);
            const float v = (value_noise(seed, p) + 0.5f * value_noise(seed + 1, 2.0f * p)) / 1.5f;
            field.heights[size_t(z) * vertices.x + x] = scale * v;
        }
    return field;
}

HeightField height_field_from_image(const Image& image, glm::vec2 size, float scale, const std::string& file) {
    if (image.width < 2 || image.height < 2 || image.width > limits::kMaxHeightFieldVertices ||
        image.height > limits::kMaxHeightFieldVertices)
        throw std::invalid_argument(fmt::format("height map {} is {}x{}: it needs 2 to {} pixels a side, one a grid vertex",
                                                file, image.width, image.height, limits::kMaxHeightFieldVertices));
    HeightField field;
    field.vertices = {uint32_t(image.width), uint32_t(image.height)};
    field.size = size;
    field.heights.resize(size_t(image.width) * size_t(image.height));
    for (int z = 0; z < image.height; ++z)
        for (int x = 0; x < image.width; ++x) {
            const float v = image.pixels[(size_t(z) * size_t(image.width) + size_t(x)) * 4];
            if (!std::isfinite(v) || v < 0.0f || v > 1.0f)
                throw std::invalid_argument(fmt::format("height map {}: pixel ({}, {}) is {}, outside [0, 1]", file, x, z, v));
            field.heights[size_t(z) * size_t(image.width) + size_t(x)] = scale * v;
        }
    return field;
}

TriangleMesh build_height_field_mesh(const HeightField& field) {
    TriangleMesh mesh;
    const glm::uvec2 n = field.vertices;
    const glm::vec2 step = field.size / glm::vec2(n - 1u);
    mesh.vertices.resize(size_t(n.x) * n.y);
    for (uint32_t z = 0; z < n.y; ++z)
        for (uint32_t x = 0; x < n.x; ++x)
            mesh.vertices[size_t(z) * n.x + x] = {
                glm::vec3(float(x) * step.x - 0.5f * field.size.x, field.vertex(x, z), float(z) * step.y - 0.5f * field.size.y),
                glm::vec3(0.0f)};
    mesh.indices.reserve(size_t(n.x - 1) * (n.y - 1) * 6);
    for (uint32_t z = 0; z + 1 < n.y; ++z)
        for (uint32_t x = 0; x + 1 < n.x; ++x) {
            const uint32_t v00 = z * n.x + x, v10 = v00 + 1, v01 = v00 + n.x, v11 = v01 + 1;
            // Counter-clockwise from +y, split along (1, 0)-(0, 1) as shaders/height_field.h reads it.
            for (uint32_t i : {v00, v01, v10, v11, v10, v01}) mesh.indices.push_back(i);
        }
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        Vertex& a = mesh.vertices[mesh.indices[t]];
        Vertex& b = mesh.vertices[mesh.indices[t + 1]];
        Vertex& c = mesh.vertices[mesh.indices[t + 2]];
        const glm::vec3 area_normal = glm::cross(b.position - a.position, c.position - a.position);
        a.normal += area_normal;
        b.normal += area_normal;
        c.normal += area_normal;
    }
    for (Vertex& v : mesh.vertices) v.normal = glm::normalize(v.normal);
    return mesh;
}

}  // namespace canopy
