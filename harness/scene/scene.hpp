// The scene description: what a scene config says, independent of how it is rendered.
// Raster techniques and the ray-traced reference both consume exactly this.
#pragma once

#include "scene/object.hpp"
#include "scene/population.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace canopy {

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

struct Scene {
    std::string name;
    std::filesystem::path file;          // the TOML it came from
    // The experiment's overrides of the file (a scene variant), as written there on one line
    // ("{ file = \"../scenes/grass.toml\", name = \"grass-far\", camera = { ... } }"), "" for none.
    std::string variant;
    Camera camera;
    std::vector<Light> lights;           // the first shadow-casting light is the one techniques shadow
    glm::vec3 ambient{0.03f, 0.03f, 0.03f};  // constant ambient radiance multiplied by albedo
    glm::vec3 background{0.0f, 0.0f, 0.0f};  // radiance of rays that hit nothing
    std::vector<Object> objects;
    std::vector<Population> populations;  // drawn by techniques that declare their kind

    // The light that shadow techniques work with, or nullptr if no light casts shadows.
    const Light* shadow_light() const;
};

}  // namespace canopy
