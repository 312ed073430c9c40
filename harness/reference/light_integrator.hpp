// Irradiance times visibility from one light at one shading point: the per-light half of the
// reference's shading. A template over the shadow-ray tracer so the benchmark can record the
// exact rays the renderer traces (shadow_ray_benchmark.cpp) with the same code.
#pragma once

#include "reference/light_sampling.hpp"
#include "reference/shadow_packet.hpp"
#include "shading.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace canopy {

// Shadow rays stop this fraction of their length short of the point on the light, so geometry
// the light is mounted on (a ceiling around a rect light) does not block it.
inline constexpr float kShadowRayEndGap = 1e-4f;

// Offset of shadow-ray origins along the geometric normal. Float error in a hit point grows
// with its coordinates and with the camera ray's length, so the offset scales with both
// (about 2^-14 of them), with a floor relative to the scene's size for hits near the origin.
inline float shadow_ray_offset(glm::vec3 hit_point, float hit_distance, float scene_extent) {
    const glm::vec3 magnitude = glm::abs(hit_point);
    const float largest = std::max(magnitude.x, std::max(magnitude.y, magnitude.z));
    return 6e-5f * (largest + hit_distance + 1e-3f * scene_extent);
}

struct SurfacePoint {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit shading normal, turned towards the viewer
    glm::vec3 origin{0.0f};              // shadow-ray origin: position offset along the geometric normal
};

struct LightEstimate {
    glm::vec3 irradiance{0.0f};  // estimate of the integral of E * V over the light
    glm::vec3 variance{0.0f};    // of that estimate (sample variance / N; conservative under stratification)
    float visible_fraction = 0.0f;  // fraction of samples above the horizon and unoccluded (if asked for)
    // Integral of E * V over the integral of E, from the same samples: the irradiance-weighted
    // visibility that a raster technique's visibility stands for (0 or 1 for point-like lights);
    // -1 where no sample carries irradiance (the light does not reach the point).
    float weighted_visibility = -1.0f;
};

// `key` makes the light samples of this shading point independent of all others.
// `want_visibility`: also trace samples that carry no irradiance but are above the horizon, so
// that visible_fraction is the geometric fraction of the light that can be seen.
template <class Tracer>
LightEstimate integrate_light(const PreparedLight& light, const SurfacePoint& surface, uint64_t key,
                              bool want_visibility, Tracer& tracer) {
    using namespace shader;
    LightEstimate estimate;
    const glm::vec3 p = surface.position, n = surface.normal;
    // Every lane starts as an untraced ray from the shadow-ray origin (shadow_packet.hpp).
    ShadowPacket packet(surface.origin);

    if (light.type == LightType::directional || light.type == LightType::spot) {
        glm::vec3 irradiance;
        glm::vec3 direction;
        float t_far;
        if (light.type == LightType::directional) {
            irradiance = directional_irradiance(n, light.direction, light.power);
            direction = -light.direction;
            t_far = light.shadow_reach;
        } else {
            irradiance = point_irradiance(LIGHT_SPOT, p, n, light.position, light.direction, light.power,
                                          light.cos_half_angle);
            direction = light.position - surface.origin;
            t_far = 1.0f - kShadowRayEndGap;
        }
        const bool above_horizon = glm::dot(n, direction) > 0.0f;
        const bool carries = std::max(irradiance.r, std::max(irradiance.g, irradiance.b)) > 0.0f;
        const bool trace = light.casts_shadows && above_horizon && (carries || want_visibility);
        packet.set(0, surface.origin, direction, t_far, trace);
        if (trace) tracer.trace(packet);
        const float visibility = (above_horizon && !packet.occluded(0)) ? 1.0f : 0.0f;
        estimate.irradiance = irradiance * visibility;
        estimate.visible_fraction = visibility;
        if (carries) estimate.weighted_visibility = visibility;
        return estimate;
    }

    if (light.type == LightType::sphere && sphere_light_encloses(light, p)) {
        // Inside the emitter every direction sees radiance L = power / (pi r^2): E = pi L, unoccluded.
        estimate.irradiance = light.power / (light.sphere_radius * light.sphere_radius);
        estimate.visible_fraction = 1.0f;
        estimate.weighted_visibility = 1.0f;
        return estimate;
    }

    const int count = light.sample_count;
    const StratifiedPatterns::Set set = light.patterns.set(key);
    const glm::vec2 shift = unit_pair(mix_bits(key ^ 0x5bd1e995u));
    const float trace_all_above = (light.casts_shadows && want_visibility) ? 1.0f : 0.0f;
    const glm::vec3 origin = surface.origin;
    AreaLightSamples samples;
    // Sums of (contribution - first contribution): shifted data keeps the variance accurate in float.
    float reference_value = -1.0f;
    double sum = 0.0, sum_squares = 0.0, weight_sum = 0.0, seen_weight_sum = 0.0;
    int visible = 0;
    for (int first = 0; first < count; first += ShadowPacket::kWidth) {
        const int lanes = std::min(ShadowPacket::kWidth, count - first);
        sample_area_light(light, p, n, set, first, shift, samples);
        // Branch-free lane loops (bitwise & and |, no short-circuits) so that they vectorise.
        const int casts = light.casts_shadows ? 1 : 0;
        int active = 0;
        // Every lane gets a direction and length, traced or not; Embree only writes tfar.
        for (int lane = 0; lane < ShadowPacket::kWidth; ++lane) {
            packet.rays.dir_x[lane] = samples.target_x[lane] - origin.x;
            packet.rays.dir_y[lane] = samples.target_y[lane] - origin.y;
            packet.rays.dir_z[lane] = samples.target_z[lane] - origin.z;
            packet.rays.tfar[lane] = 1.0f - kShadowRayEndGap;
            const int trace = int(lane < lanes) & casts &
                              (int(samples.weight[lane] > 0.0f) | int(samples.above_horizon[lane] * trace_all_above > 0.0f));
            packet.valid[lane] = -trace;
            active += trace;
        }
        packet.active = active;
        tracer.trace(packet);
        if (reference_value < 0.0f) reference_value = samples.weight[0];
        float packet_sum = 0.0f, packet_squares = 0.0f, packet_visible = 0.0f, packet_weight = 0.0f,
              packet_seen_weight = 0.0f;
        for (int lane = 0; lane < ShadowPacket::kWidth; ++lane) {
            const float in_range = lane < lanes ? 1.0f : 0.0f;
            const float occluded = float(int(packet.valid[lane] != 0) & int(packet.rays.tfar[lane] < 0.0f));
            const float seen = samples.above_horizon[lane] * (1.0f - occluded) * in_range;
            const float deviation = (seen * samples.weight[lane] - reference_value) * in_range;
            packet_sum += deviation;
            packet_squares += deviation * deviation;
            packet_visible += seen;
            packet_weight += samples.weight[lane] * in_range;
            packet_seen_weight += seen * samples.weight[lane];
        }
        sum += packet_sum;
        sum_squares += packet_squares;
        visible += int(packet_visible);
        weight_sum += packet_weight;
        seen_weight_sum += packet_seen_weight;
    }
    const double mean_deviation = sum / count;
    const double variance_of_mean =
        count > 1 ? std::max(sum_squares - sum * mean_deviation, 0.0) / (double(count) * double(count - 1)) : 0.0;
    estimate.irradiance = light.power * float(double(reference_value) + mean_deviation);
    estimate.variance = light.power * light.power * float(variance_of_mean);
    estimate.visible_fraction = float(visible) / float(count);
    if (weight_sum > 0.0) estimate.weighted_visibility = float(std::min(seen_weight_sum / weight_sum, 1.0));
    return estimate;
}

}  // namespace canopy
