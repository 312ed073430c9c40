#include "reference/light_sampling.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace canopy {

namespace {

constexpr float kPi = 3.14159265358979323846f;

bool is_finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

const char* light_type_name(LightType type) {
    switch (type) {
        case LightType::directional: return "directional";
        case LightType::spot: return "spot";
        case LightType::rect: return "rect";
        case LightType::sphere: return "sphere";
    }
    return "unknown";
}

[[noreturn]] void reject(const Light& light, const std::string& message, const std::string& hint = {}) {
    throw ConfigError(light.where.file, light.where.line,
                      fmt::format("the reference renderer cannot represent this {} light: {}",
                                  light_type_name(light.type), message),
                      hint);
}

// Orthonormal basis around unit `w` (Duff et al. 2017, branchless).
void basis_around(glm::vec3 w, glm::vec3& t, glm::vec3& b) {
    const float sign = std::copysign(1.0f, w.z);
    const float a = -1.0f / (sign + w.z);
    const float c = w.x * w.y * a;
    t = glm::vec3(1.0f + sign * w.x * w.x * a, sign * c, -sign * w.x);
    b = glm::vec3(c, sign + w.y * w.y * a, -w.y);
}

}  // namespace

void check_light_representable(const Light& light) {
    switch (light.type) {
        case LightType::directional:
        case LightType::spot:
        case LightType::rect:
        case LightType::sphere: break;
        default:
            throw ConfigError(light.where.file, light.where.line,
                              fmt::format("the reference renderer does not know light type {}", int(light.type)),
                              "supported light types: directional, spot, rect, sphere");
    }
    if (!is_finite(light.position) || !is_finite(light.direction) || !is_finite(light.color) ||
        !std::isfinite(light.intensity))
        reject(light, "position, direction, colour and intensity must be finite");
    if (light.type != LightType::sphere && glm::length(light.direction) <= 0.0f)
        reject(light, "its direction is the zero vector");
    if (light.type == LightType::spot &&
        !(light.spot_angle_degrees > 0.0f && light.spot_angle_degrees < 180.0f))
        reject(light, fmt::format("spot angle {} is outside (0, 180) degrees", light.spot_angle_degrees));
    if (light.type == LightType::rect) {
        if (!(light.rect_size.x > 0.0f && light.rect_size.y > 0.0f) || !std::isfinite(light.rect_size.x) ||
            !std::isfinite(light.rect_size.y))
            reject(light, fmt::format("its size {} x {} is not positive", light.rect_size.x, light.rect_size.y));
        const glm::vec3 right = glm::cross(glm::normalize(light.direction), light.rect_up_hint);
        if (!is_finite(right) || glm::length(right) < 1e-6f * glm::length(light.rect_up_hint) ||
            glm::length(light.rect_up_hint) <= 0.0f)
            reject(light, "its up hint is zero or parallel to its direction, so the rectangle has no orientation",
                   "set `up` to any vector not parallel to `direction`");
    }
    if (light.type == LightType::sphere && !(light.sphere_radius > 0.0f && std::isfinite(light.sphere_radius)))
        reject(light, fmt::format("its radius {} is not positive", light.sphere_radius),
               "use a spot light for a point emitter");
}

void limit_shadow_reach(std::vector<PreparedLight>& lights, float scene_radius) {
    const float reach = 2.0f * scene_radius * 1.001f + 1e-3f;
    for (PreparedLight& light : lights)
        if (std::isfinite(reach) && reach > 0.0f) light.shadow_reach = reach;
}

std::vector<PreparedLight> prepare_lights(const Scene& scene, int area_samples, uint64_t seed) {
    std::vector<PreparedLight> prepared;
    prepared.reserve(scene.lights.size());
    for (size_t index = 0; index < scene.lights.size(); ++index) {
        const Light& light = scene.lights[index];
        check_light_representable(light);
        PreparedLight p;
        p.type = light.type;
        p.power = light.color * light.intensity;
        p.position = light.position;
        p.direction = light.type == LightType::sphere ? glm::vec3(0.0f, -1.0f, 0.0f) : glm::normalize(light.direction);
        p.cos_half_angle = std::cos(glm::radians(light.spot_angle_degrees));
        p.casts_shadows = light.casts_shadows;
        if (light.type == LightType::rect) p.rect = rect_light_frame(light);
        p.sphere_radius = light.sphere_radius;
        if (light.is_area()) {
            p.sample_count = std::max(area_samples, 1);
            const float aspect = light.type == LightType::rect ? light.rect_size.x / light.rect_size.y : 1.0f;
            p.patterns = StratifiedPatterns(p.sample_count, aspect, random_key(seed, 0x11647u, index));
        }
        prepared.push_back(std::move(p));
    }
    return prepared;
}

namespace {

constexpr int kLanes = AreaLightSamples::kWidth;

// In-place square root of 16 lanes; explicit SIMD because -fmath-errno keeps the compiler from
// vectorising std::sqrt.
inline void sqrt_lanes(float* values) {
#if defined(__SSE__)
    for (int i = 0; i < kLanes; i += 4) _mm_store_ps(values + i, _mm_sqrt_ps(_mm_load_ps(values + i)));
#else
    for (int i = 0; i < kLanes; ++i) values[i] = std::sqrt(values[i]);
#endif
}

// Wraps a sum of two numbers in [0,1) back into [0,1). Truncation rather than a comparison
// keeps the loops free of branches, so they vectorise.
inline float wrap_unit(float value) { return value - float(int(value)); }

void sample_rect(const PreparedLight& light, glm::vec3 p, glm::vec3 n, const float* xs, const float* ys,
                 glm::vec2 shift, AreaLightSamples& out) {
    const RectLightFrame& rect = light.rect;
    // target = centre + (x - 1/2) * width * right + (y - 1/2) * height * up
    const glm::vec3 along_x = rect.size.x * rect.right, along_y = rect.size.y * rect.up;
    const glm::vec3 corner = rect.center - 0.5f * along_x - 0.5f * along_y;
    alignas(64) float dx[kLanes], dy[kLanes], dz[kLanes], distance[kLanes];
    for (int i = 0; i < kLanes; ++i) {
        const float x = wrap_unit(xs[i] + shift.x), y = wrap_unit(ys[i] + shift.y);
        out.target_x[i] = corner.x + x * along_x.x + y * along_y.x;
        out.target_y[i] = corner.y + x * along_x.y + y * along_y.y;
        out.target_z[i] = corner.z + x * along_x.z + y * along_y.z;
        dx[i] = out.target_x[i] - p.x;
        dy[i] = out.target_y[i] - p.y;
        dz[i] = out.target_z[i] - p.z;
        distance[i] = dx[i] * dx[i] + dy[i] * dy[i] + dz[i] * dz[i];
    }
    sqrt_lanes(distance);
    for (int i = 0; i < kLanes; ++i) {
        const float inv_distance = 1.0f / distance[i];
        const float cos_receiver = (n.x * dx[i] + n.y * dy[i] + n.z * dz[i]) * inv_distance;
        const float cos_emitter =
            -(rect.normal.x * dx[i] + rect.normal.y * dy[i] + rect.normal.z * dz[i]) * inv_distance;
        // L * A * cos_r * cos_l / d^2 with L * A = power; 0 below the horizon or behind the light.
        out.weight[i] = std::max(cos_receiver, 0.0f) * std::max(cos_emitter, 0.0f) * inv_distance * inv_distance;
        out.above_horizon[i] = cos_receiver > 0.0f ? 1.0f : 0.0f;
    }
}

void sample_sphere(const PreparedLight& light, glm::vec3 p, glm::vec3 n, const StratifiedPatterns::Set& set,
                   int first, glm::vec2 shift, AreaLightSamples& out) {
    const float radius = light.sphere_radius;
    const glm::vec3 to_center = light.position - p;
    const float distance2 = glm::dot(to_center, to_center);
    const float distance = std::sqrt(distance2);
    const glm::vec3 axis = to_center / distance;
    // 1 - cos(theta_max) without cancellation for small, distant spheres.
    const float sin2_max = std::min(radius * radius / distance2, 1.0f);
    const float cone_height = sin2_max / (1.0f + std::sqrt(1.0f - sin2_max));
    // L * Omega * cos_r with L = power / (pi r^2), Omega = 2 pi (1 - cos_max).
    const float weight_scale = 2.0f * cone_height / (radius * radius);
    glm::vec3 tangent, bitangent;
    basis_around(axis, tangent, bitangent);
    // Shifting y by shift.y rotates the azimuth by 2 pi shift.y.
    const float rotate_cos = std::cos(2.0f * kPi * shift.y), rotate_sin = std::sin(2.0f * kPi * shift.y);
    const float* xs = set.x + first;
    const float* cos_azimuth = set.cos_azimuth + first;
    const float* sin_azimuth = set.sin_azimuth + first;
    alignas(64) float sin_theta[kLanes], cos_theta[kLanes], chord[kLanes];
    for (int i = 0; i < kLanes; ++i) {
        const float one_minus_cos = wrap_unit(xs[i] + shift.x) * cone_height;
        cos_theta[i] = 1.0f - one_minus_cos;
        sin_theta[i] = std::max(one_minus_cos * (2.0f - one_minus_cos), 0.0f);
    }
    sqrt_lanes(sin_theta);
    for (int i = 0; i < kLanes; ++i)
        chord[i] = std::max(radius * radius - distance2 * sin_theta[i] * sin_theta[i], 0.0f);
    sqrt_lanes(chord);
    for (int i = 0; i < kLanes; ++i) {
        const float c = cos_azimuth[i] * rotate_cos - sin_azimuth[i] * rotate_sin;
        const float s = sin_azimuth[i] * rotate_cos + cos_azimuth[i] * rotate_sin;
        const float a = sin_theta[i] * c, b = sin_theta[i] * s;
        const float wx = a * tangent.x + b * bitangent.x + cos_theta[i] * axis.x;
        const float wy = a * tangent.y + b * bitangent.y + cos_theta[i] * axis.y;
        const float wz = a * tangent.z + b * bitangent.z + cos_theta[i] * axis.z;
        // Nearest intersection with the sphere along w.
        const float hit_distance = distance * cos_theta[i] - chord[i];
        out.target_x[i] = p.x + hit_distance * wx;
        out.target_y[i] = p.y + hit_distance * wy;
        out.target_z[i] = p.z + hit_distance * wz;
        const float cos_receiver = n.x * wx + n.y * wy + n.z * wz;
        out.weight[i] = std::max(cos_receiver, 0.0f) * weight_scale;
        out.above_horizon[i] = cos_receiver > 0.0f ? 1.0f : 0.0f;
    }
}

}  // namespace

void sample_area_light(const PreparedLight& light, glm::vec3 p, glm::vec3 n, const StratifiedPatterns::Set& set,
                       int first, glm::vec2 shift, AreaLightSamples& samples) {
    if (light.type == LightType::rect)
        sample_rect(light, p, n, set.x + first, set.y + first, shift, samples);
    else
        sample_sphere(light, p, n, set, first, shift, samples);
}

glm::vec3 direction_to_light_center(const PreparedLight& light, glm::vec3 p) {
    if (light.type == LightType::directional) return -light.direction;
    const glm::vec3 to_light = light.position - p;
    const float length = glm::length(to_light);
    return length > 0.0f ? to_light / length : light.direction * -1.0f;
}

}  // namespace canopy
