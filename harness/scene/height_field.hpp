// Terrain heights on a regular grid: the `heightfield` object shape (a hilly ground) and what
// populations standing on it read (grass on a height map, Lemme §6.4.4). The grid's vertices
// span the object's size, centred on its origin; between them the surface is the mesh's two
// triangles per quad (shaders/height_field.h), so every reader agrees with the drawn ground.
#pragma once

#include "core/image.hpp"
#include "scene/geometry.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace canopy {

struct HeightField {
    glm::uvec2 vertices{2, 2};  // grid vertices along x and z, at least 2 each
    glm::vec2 size{1.0f, 1.0f};  // extent in x and z (local space, centred)
    std::vector<float> heights;  // world units, row-major, row 0 at z = -size.y / 2

    float vertex(uint32_t x, uint32_t z) const { return heights[size_t(z) * vertices.x + x]; }
    // The surface's height at a local (x, z); points outside the grid take its nearest edge.
    float at(glm::vec2 local_xz) const;
    // Bounds of the height over the rectangle [lo, hi] (local x, z; lo <= hi): the lowest and
    // highest vertex of the grid quads it touches, which contain the surface's own extremes.
    glm::vec2 range(glm::vec2 lo, glm::vec2 hi) const;
};

// Smooth hills: two octaves of a seeded value noise (smoothstep between lattice values, the
// second octave twice as fine and half as strong), `periods` lattice cells across the field,
// scaled to [0, scale].
HeightField hills_height_field(glm::vec2 size, glm::uvec2 vertices, uint32_t periods, uint32_t seed, float scale);

// From an image's first channel, one pixel a vertex: v in [0, 1] gives scale * v; its first row
// along -z and its first column along -x (the image seen from above with -z up). Throws
// std::invalid_argument, naming `file` and the pixel, for a value outside [0, 1] or not finite,
// or an image under 2 x 2.
HeightField height_field_from_image(const Image& image, glm::vec2 size, float scale, const std::string& file);

// The ground itself: two triangles a grid quad, split along the (1, 0)-(0, 1) diagonal, with
// smooth normals (the area-weighted sum of the triangles' around each vertex).
TriangleMesh build_height_field_mesh(const HeightField& field);

}  // namespace canopy
