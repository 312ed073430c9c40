// Lights as the reference renderer samples them.
//
// Point-like lights (directional, spot) use shading.h exactly as the raster lit pass does and
// one hard shadow ray. Area lights are integrated with stratified samples:
//   rect:   points uniform in area on the rectangle (see rect_light_frame.hpp), radiance
//           L = intensity / (width * height); a sample contributes L * A * cos_r * cos_l / d^2.
//   sphere: directions uniform in the solid angle Omega of the cone the sphere subtends,
//           radiance L = intensity / (pi r^2); a sample contributes L * Omega * cos_r.
// Both estimators are unbiased; `weight` below is a sample's contribution divided by the
// light's colour * intensity, so irradiance = colour * intensity * mean(weight * visibility).
// Lights are not geometry: camera rays pass through them and they cast no shadows.
#pragma once

#include "reference/rect_light_frame.hpp"
#include "reference/sample_patterns.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace canopy {

struct PreparedLight {
    LightType type = LightType::directional;
    glm::vec3 power{0.0f};      // colour * intensity: irradiance (directional) or radiant intensity
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit: travel direction (directional), axis (spot), normal (rect)
    float cos_half_angle = 1.0f;              // spot
    RectLightFrame rect;                      // rect
    float sphere_radius = 0.0f;               // sphere
    bool casts_shadows = true;
    int sample_count = 1;                     // shadow rays per shading point
    // Directional: how far a shadow ray goes. Nothing occludes beyond the scene's bounds, and a
    // finite segment is what Embree is given (first tried against rtcOccluded16's hangs on a grass
    // field, which finite segments did not end: shadow_packet.hpp traces single rays since).
    float shadow_reach = std::numeric_limits<float>::infinity();
    StratifiedPatterns patterns;              // area lights only
};

// Throws ConfigError naming light.where when the reference cannot represent the light
// (an unknown type, a degenerate rect or sphere, non-finite values).
void check_light_representable(const Light& light);

// Checks and prepares every light of the scene, in scene order. `area_samples` is the number of
// shadow rays per shading point for rect and sphere lights (point-like lights use one).
std::vector<PreparedLight> prepare_lights(const Scene& scene, int area_samples, uint64_t seed);
// Sets every light's shadow_reach for a scene whose geometry lies within a sphere of
// `scene_radius` (EmbreeScene::extent): twice that and a margin for the rays' origin offset.
void limit_shadow_reach(std::vector<PreparedLight>& lights, float scene_radius);

// A packet's worth of samples towards an area light, structure-of-arrays so it vectorises.
// Zeroed on construction, so no lane is ever left uninitialised (sample_area_light fills all 16).
struct alignas(64) AreaLightSamples {
    static constexpr int kWidth = 16;
    alignas(64) float target_x[kWidth] = {};  // the points on the light the shadow rays go to
    alignas(64) float target_y[kWidth] = {};
    alignas(64) float target_z[kWidth] = {};
    alignas(64) float weight[kWidth] = {};    // contribution / power; 0 where the sample cannot contribute
    alignas(64) float above_horizon[kWidth] = {};  // 1 where dot(n, direction to the sample) > 0, else 0
};

// Samples first .. first + 15 of `set`, taken at a receiver `p` with unit normal `n`, each
// point shifted by `shift` in [0,1)^2 (Cranley-Patterson rotation). Lanes past the light's
// sample count hold valid but unused samples.
//   rect:   x runs along right (width), y along up (height), uniform in area;
//   sphere: x -> cos(theta) uniform in [cos(theta_max), 1] and y -> azimuth around the direction
//           to the centre: uniform in the subtended cone's solid angle. Receivers inside the
//           sphere must be handled by the caller (see sphere_light_encloses).
void sample_area_light(const PreparedLight& light, glm::vec3 p, glm::vec3 n, const StratifiedPatterns::Set& set,
                       int first, glm::vec2 shift, AreaLightSamples& samples);

inline bool sphere_light_encloses(const PreparedLight& light, glm::vec3 p) {
    const glm::vec3 to_center = light.position - p;
    return glm::dot(to_center, to_center) <= light.sphere_radius * light.sphere_radius * 1.000001f;
}

// Unit direction from p towards the light's centre (for directional: -direction).
glm::vec3 direction_to_light_center(const PreparedLight& light, glm::vec3 p);

}  // namespace canopy
