// The Embree ground truth that raster shadow techniques are measured against.
//
// Shading is the raster lit pass's (shading.h, as techniques/shadow/shaders/forward_lighting.glsl
// uses it) with visibility made physically correct and area lights integrated:
//   radiance = albedo * (sum over lights of E_l * V_l / pi + ambient)
// at the surface a camera ray hits, its interpolated normal turned towards the viewer.
//   directional, spot: shading.h's irradiance times one hard shadow ray;
//   rect, sphere:      the integral of L cos cos / d^2 (rect) or L cos over the subtended cone
//                      (sphere) with visibility, estimated with `light_samples` stratified samples
//                      (light_sampling.hpp).
// Every light contributes; the visibility image is about scene.shadow_light() only. Lights are
// not geometry: they are not seen by camera rays and do not occlude. Camera rays that hit
// nothing (or are clipped by the camera's near/far planes, as in the rasteriser) return
// scene.background. Objects with casts_shadows = false are seen but occlude no light; lights
// with casts_shadows = false are never occluded.
#pragma once

#include "core/image.hpp"
#include "reference/embree_scene.hpp"
#include "reference/reference_settings.hpp"
#include "scene/geometry.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace canopy {

struct ReferenceImages {
    Image radiance;    // linear RGB, A = 1
    // Per-pixel variance of the radiance estimate (of the pixel mean), RGB, A = 1:
    // max(S^2_sub, s^2_light) / P, where S^2_sub is the unbiased sample variance of the P
    // sub-pixel radiance estimates and s^2_light the mean over them of the light-sampling variance
    // (sum over lights of (albedo/pi)^2 * power^2 * sample variance / N). Conservative for the
    // stratified estimators; noisy per pixel when P is small, so average it over regions.
    Image variance;
    // R: fraction of the shadow light visible from the surface seen at the pixel (unoccluded and
    //    above its horizon), mean over the pixel's samples that see a surface facing the light;
    // G: 1 when every sample of the pixel sees a surface facing the shadow light (n.l > 0 towards
    //    its centre), else 0 (background, back-facing, silhouettes);
    // B: the population coverage, the fraction of the pixel's samples whose primary hit is a copy of
    //    one of the scene's populations (a grass blade), what ErrorColumns::coverage compares. A = 1.
    // With no shadow-casting light, R = G = 0.
    Image visibility;
    double seconds = 0;  // wall time (including the BVH build when given meshes)
    uint64_t shadow_rays = 0;
};

// Builds the Embree scene and renders. Throws ConfigError (naming file:line) for scene content
// the reference cannot represent. `progress` receives the finished fraction in [0, 1], called
// from worker threads but never concurrently.
ReferenceImages render_reference(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width,
                                 int height, const ReferenceSettings& settings,
                                 const std::function<void(double)>& progress = {});

// Renders with an existing Embree scene (e.g. one with alpha tests, or shared with a benchmark).
ReferenceImages render_reference(const Scene& scene, const EmbreeScene& embree, int width, int height,
                                 const ReferenceSettings& settings,
                                 const std::function<void(double)>& progress = {});

}  // namespace canopy
