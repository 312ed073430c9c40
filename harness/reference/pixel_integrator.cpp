#include "reference/pixel_integrator.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace canopy {

PixelIntegrator::PixelIntegrator(const Scene& scene, const EmbreeScene& embree, int width, int height,
                                 const ReferenceSettings& settings)
    : embree_(embree),
      camera_(scene.camera),
      ambient_(scene.ambient),
      background_(scene.background),
      lights_(prepare_lights(scene, settings.light_samples, settings.seed)),
      width_(width),
      height_(height),
      pixel_samples_(std::max(settings.pixel_samples, 1)),
      seed_(settings.seed) {
    check_camera_representable(scene);
    limit_shadow_reach(lights_, embree.extent());
    camera_forward_ = glm::normalize(scene.camera.target - scene.camera.position);
    if (const Light* shadow_light = scene.shadow_light()) shadow_light_ = int(shadow_light - scene.lights.data());
}

}  // namespace canopy
