// The scene description: what a scene config says, independent of how it is rendered.
// Raster techniques and the ray-traced reference both consume exactly this.
#pragma once

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace canopy {

// Where a value came from, so errors found after parsing can still name file:line.
struct SourceLocation {
    std::filesystem::path file;
    int line = 0;  // 1-based; 0 when unknown
};

struct Camera {
    glm::vec3 position{0.0f, 2.0f, 6.0f};
    glm::vec3 target{0.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_y_degrees = 45.0f;  // vertical field of view
    float near_plane = 0.05f;
    float far_plane = 100.0f;
};

enum class LightType { directional, spot, rect, sphere };

// One light. Radiometric conventions (see configs/README.md):
//  - directional: `intensity` is the irradiance (W/m^2) on a surface facing the light.
//  - spot:        `intensity` is the radiant intensity (W/sr) on the axis; smooth falloff to the cone edge.
//  - rect:        one-sided area light facing `direction`; `intensity` is the radiant intensity along
//                 its normal, so its radiance is intensity / (width * height).
//  - sphere:      `intensity` is the radiant intensity in any direction, radiance = intensity / (pi r^2).
struct Light {
    LightType type = LightType::directional;
    glm::vec3 position{0.0f, 5.0f, 0.0f};   // spot, rect, sphere
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // directional (towards which light travels), spot, rect (normal)
    glm::vec3 color{1.0f, 1.0f, 1.0f};
    float intensity = 3.0f;
    float spot_angle_degrees = 30.0f;  // spot: half-angle of the cone
    glm::vec2 rect_size{1.0f, 1.0f};   // rect: width (along `right`), height
    float sphere_radius = 0.25f;       // sphere
    glm::vec3 rect_up_hint{0.0f, 0.0f, 1.0f};  // rect: orients the rectangle's height axis
    bool casts_shadows = true;
    SourceLocation where;

    bool is_area() const { return type == LightType::rect || type == LightType::sphere; }
    // The light's extent in world units: rect diagonal, sphere diameter, 0 for point-like lights.
    float size() const;
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

enum class ShapeType { plane, box, sphere, cylinder, mesh };

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
    Material material;
    bool casts_shadows = true;
    // One transform per drawn copy; a plain object has exactly one.
    std::vector<Transform> instances{Transform{}};
    SourceLocation where;
};

struct Scene {
    std::string name;
    std::filesystem::path file;          // the TOML it came from
    Camera camera;
    std::vector<Light> lights;           // the first shadow-casting light is the one techniques shadow
    glm::vec3 ambient{0.03f, 0.03f, 0.03f};  // constant ambient radiance multiplied by albedo
    glm::vec3 background{0.0f, 0.0f, 0.0f};  // radiance of rays that hit nothing
    std::vector<Object> objects;

    // The light that shadow techniques work with, or nullptr if no light casts shadows.
    const Light* shadow_light() const;
};

}  // namespace canopy
