// Triangle meshes built from a scene: primitives tessellated, mesh files loaded.
// The raster renderer and the Embree reference both draw these exact triangles.
#pragma once

#include "scene/scene.hpp"

#include <cstdint>
#include <vector>

namespace canopy {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
};

// Triangles of one object in its local space.
struct TriangleMesh {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;  // three per triangle, counter-clockwise seen from the front
    size_t triangle_count() const { return indices.size() / 3; }
};

struct Bounds {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};
    void extend(const glm::vec3& p);
    bool empty() const { return min.x > max.x; }
    glm::vec3 center() const { return 0.5f * (min + max); }
    float radius() const;  // of the bounding sphere around center()
};

// Builds the local-space mesh of one object. Throws ConfigError (naming object.where) when a
// mesh file cannot be read, holds no triangles or crashes assimp (files are read in a child
// process: scene/isolated_mesh_import.hpp).
TriangleMesh build_object_mesh(const Object& object);

// All objects' meshes, in scene.objects order, then every population's prototype mesh (local
// space, its own transform not applied), in scene.populations order: population p's is
// meshes[scene.objects.size() + p] (prototype_mesh). Throws ConfigError (naming the object or
// population) when a copy may place a vertex outside the scene's coordinate range, or a
// population's copies hold too many triangles (scene/scene_limits.hpp).
std::vector<TriangleMesh> build_scene_meshes(const Scene& scene);

// Population `index`'s prototype mesh within build_scene_meshes' result; throws std::logic_error
// when `meshes` does not hold one mesh per object and population.
const TriangleMesh& prototype_mesh(const Scene& scene, const std::vector<TriangleMesh>& meshes, size_t index);

// World-space bounds of every instance of every object and every copy of every population (a
// copy by its prototype's box: exact for moved, scaled or mirrored copies, loose for rotated ones).
Bounds scene_bounds(const Scene& scene, const std::vector<TriangleMesh>& meshes);

}  // namespace canopy
