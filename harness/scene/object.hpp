// One object of a scene: a shape or a mesh, its material and the transforms of its copies.
#pragma once

#include <glm/glm.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace canopy {

// Where a value came from, so errors found after parsing can still name file:line.
struct SourceLocation {
    std::filesystem::path file;
    int line = 0;  // 1-based; 0 when unknown
};

struct Transform {
    glm::vec3 translate{0.0f};
    glm::vec3 rotate_degrees{0.0f};  // Euler angles, applied X, then Y, then Z
    glm::vec3 scale{1.0f};
    // Applied after scale/rotate/translate: an [[object]] instance placing the transformed object
    // (world = instance * object). Identity for plain objects.
    glm::mat4 outer{1.0f};
    glm::mat4 matrix() const;  // outer * T * Rz * Ry * Rx * S
};

enum class ShapeType { plane, box, sphere, cylinder, mesh, heightfield };

struct HeightField;  // scene/height_field.hpp

struct Material {
    glm::vec3 albedo{0.8f, 0.8f, 0.8f};  // diffuse reflectance in [0,1]
};

struct Object {
    std::string name;
    ShapeType shape = ShapeType::box;
    glm::vec2 plane_size{10.0f, 10.0f};  // plane: extent in x and z, normal +y
    glm::vec3 box_size{1.0f, 1.0f, 1.0f};
    float radius = 0.5f;                 // sphere, cylinder
    float height = 1.0f;                 // cylinder, along +y, centred at the origin
    int segments = 32;                   // sphere and cylinder tessellation
    std::filesystem::path mesh_file;     // mesh: absolute path (resolved against the config's folder)
    std::shared_ptr<const HeightField> height_field;  // heightfield: its grid, made when the scene is read
    std::filesystem::path height_map_file;  // heightfield from an image: absolute path; empty for hills
    Material material;
    bool casts_shadows = true;
    // One transform per drawn copy; a plain object has exactly one.
    std::vector<Transform> instances{Transform{}};
    SourceLocation where;
};

}  // namespace canopy
