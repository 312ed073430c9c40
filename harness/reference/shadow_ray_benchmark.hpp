// Is the reference renderer's shadow-ray throughput close to what Embree can do? Measures, on
// one scene in one run:
//   reference: shadow rays traced by render_reference / its wall time (BVH build excluded;
//              camera rays, sampling and shading included);
//   bare:      the same shadow rays (recorded from an evenly spaced subset of image rows, same
//              origins, directions and lengths) traced with a plain multithreaded loop of
//              rtcOccluded1 calls, no shading, on the same number of threads.
// ratio = reference / bare (above 1 when packets beat single rays by more than shading costs).
#pragma once

#include "reference/reference_settings.hpp"
#include "scene/geometry.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <vector>

namespace canopy {

struct ShadowRayBenchmark {
    double reference_rays_per_second = 0;
    double bare_rays_per_second = 0;
    double ratio = 0;
    uint64_t rays = 0;  // shadow rays of the reference render
};

ShadowRayBenchmark benchmark_shadow_rays(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width,
                                         int height, const ReferenceSettings& settings);

}  // namespace canopy
