// One pixel of the reference image: stratified camera rays through the pixel, each shaded with
// every light (light_integrator.hpp). A template over the shadow-ray tracer so the renderer and
// the shadow-ray benchmark run the same code.
#pragma once

#include "reference/embree_scene.hpp"
#include "reference/light_integrator.hpp"
#include "reference/primary_hit.hpp"
#include "reference/reference_settings.hpp"
#include "scene/camera.hpp"

#include <vector>

namespace canopy {

struct PixelEstimate {
    glm::vec3 radiance{0.0f};
    glm::vec3 variance{0.0f};     // of the radiance estimate (the pixel mean)
    float visible_fraction = 0.0f;  // shadow light, mean over the samples that see a surface facing it
    float facing = 0.0f;            // 1 when every sample sees a surface facing the shadow light
    float population_coverage = 0.0f;  // fraction of the samples whose primary hit is a population's copy
};

class PixelIntegrator {
public:
    // Throws ConfigError for lights or a camera the reference cannot represent.
    PixelIntegrator(const Scene& scene, const EmbreeScene& embree, int width, int height,
                    const ReferenceSettings& settings);

    template <class Tracer>
    PixelEstimate integrate(int x, int y, Tracer& tracer) const;

private:
    struct SubpixelResult {
        glm::vec3 radiance{0.0f};
        glm::vec3 light_variance{0.0f};  // variance of `radiance` from light sampling alone
        bool facing = false;
        bool population = false;  // the primary hit is a population's copy
        float visible_fraction = 0.0f;
    };
    template <class Tracer>
    SubpixelResult shade(const Ray& ray, uint64_t key, Tracer& tracer) const;

    const EmbreeScene& embree_;
    Camera camera_;
    glm::vec3 camera_forward_{0.0f, 0.0f, -1.0f};
    glm::vec3 ambient_{0.0f};
    glm::vec3 background_{0.0f};
    std::vector<PreparedLight> lights_;
    int shadow_light_ = -1;  // index into lights_, -1 when no light casts shadows
    int width_ = 0, height_ = 0;
    int pixel_samples_ = 1;
    uint64_t seed_ = 1;
};

template <class Tracer>
PixelEstimate PixelIntegrator::integrate(int x, int y, Tracer& tracer) const {
    const uint64_t pixel = uint64_t(y) * uint64_t(width_) + uint64_t(x);
    const uint32_t pattern = uint32_t(random_key(seed_, 0x9a11u, pixel));
    glm::dvec3 sum(0.0), sum_squares(0.0), light_variance(0.0);
    float visible_sum = 0.0f;
    int facing_count = 0, population_count = 0;
    for (int sample = 0; sample < pixel_samples_; ++sample) {
        const glm::vec2 jitter = cmj_sample(uint32_t(sample), uint32_t(pixel_samples_), pattern);
        const Ray ray = primary_ray(camera_, width_, height_, float(x) + jitter.x, float(y) + jitter.y);
        const SubpixelResult result = shade(ray, random_key(seed_, pixel, uint64_t(sample)), tracer);
        const glm::dvec3 radiance(result.radiance);
        sum += radiance;
        sum_squares += radiance * radiance;
        light_variance += glm::dvec3(result.light_variance);
        if (result.population) ++population_count;
        if (result.facing) {
            ++facing_count;
            visible_sum += result.visible_fraction;
        }
    }
    const double count = double(pixel_samples_);
    PixelEstimate estimate;
    const glm::dvec3 mean = sum / count;
    estimate.radiance = glm::vec3(mean);
    // Variance of the mean: the larger of the spread between sub-pixel estimates (which includes
    // coverage and shading changes across the pixel) and the light-sampling variance alone.
    const glm::dvec3 within = light_variance / count;  // mean per-sample light variance
    glm::dvec3 between = within;
    if (pixel_samples_ > 1) between = glm::max(sum_squares - sum * mean, glm::dvec3(0.0)) / (count - 1.0);
    estimate.variance = glm::vec3(glm::max(between, within) / count);
    estimate.visible_fraction = facing_count > 0 ? visible_sum / float(facing_count) : 0.0f;
    estimate.facing = facing_count == pixel_samples_ ? 1.0f : 0.0f;
    estimate.population_coverage = float(population_count) / float(pixel_samples_);
    return estimate;
}

template <class Tracer>
PixelIntegrator::SubpixelResult PixelIntegrator::shade(const Ray& ray, uint64_t key, Tracer& tracer) const {
    SubpixelResult result;
    const std::optional<PrimaryHit> hit = trace_primary(embree_, camera_, camera_forward_, ray);
    if (!hit) {
        result.radiance = background_;
        return result;
    }
    result.population = embree_.geometry(hit->geometry).population >= 0;
    const SurfacePoint& surface = hit->surface;
    const glm::vec3 normal = surface.normal;

    glm::vec3 irradiance(0.0f), irradiance_variance(0.0f);
    for (size_t index = 0; index < lights_.size(); ++index) {
        const bool is_shadow_light = int(index) == shadow_light_;
        const LightEstimate estimate =
            integrate_light(lights_[index], surface, random_key(key, index), is_shadow_light, tracer);
        irradiance += estimate.irradiance;
        irradiance_variance += estimate.variance;
        if (is_shadow_light) {
            result.facing = glm::dot(normal, direction_to_light_center(lights_[index], surface.position)) > 0.0f;
            result.visible_fraction = estimate.visible_fraction;
        }
    }
    // Transmission (Boulanger eq 4.1's gamma): the light the other side receives, gamma times, its
    // shadow rays leaving from that side.
    if (const float gamma = embree_.transmission(hit->geometry); gamma > 0.0f) {
        const SurfacePoint back{surface.position, -surface.normal, 2.0f * surface.position - surface.origin};
        for (size_t index = 0; index < lights_.size(); ++index) {
            const LightEstimate estimate =
                integrate_light(lights_[index], back, random_key(key, lights_.size() + index), false, tracer);
            irradiance += gamma * estimate.irradiance;
            irradiance_variance += gamma * gamma * estimate.variance;
        }
    }
    const glm::vec3 albedo = embree_.albedo(hit->geometry, hit->primitive, hit->u, hit->v);
    result.radiance = shader::lambert_radiance(albedo, irradiance, 1.0f, ambient_);
    const glm::vec3 scale = albedo / shader::PI;
    result.light_variance = scale * scale * irradiance_variance;
    return result;
}

}  // namespace canopy
