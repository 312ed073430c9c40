// Stand-ins for the Embree reference (run/reference_provider.cpp, reference/shadow_ray_benchmark.cpp)
// in a timing-only build (timing_only.hpp).
#include "reference/shadow_ray_benchmark.hpp"
#include "run/reference_provider.hpp"
#include "timing_only/timing_only.hpp"

#include <utility>

namespace canopy {

// Every run makes a provider; only asking it for a reference needs Embree.
ReferenceProvider::ReferenceProvider(std::filesystem::path cache_dir, ReferenceSettings settings)
    : cache_dir_(std::move(cache_dir)), settings_(settings) {}

const ReferenceEntry& ReferenceProvider::get(const Scene&, const std::vector<TriangleMesh>&, int, int,
                                             const std::function<void(double)>&, const std::function<void(bool)>&) {
    throw_timing_only("the ray-traced reference");
}

const ReferenceImages& ReferenceProvider::images(const Scene&, const std::vector<TriangleMesh>&, int, int,
                                                 const std::function<void(double)>&) {
    throw_timing_only("the ray-traced reference");
}

ShadowRayBenchmark benchmark_shadow_rays(const Scene&, const std::vector<TriangleMesh>&, int, int,
                                         const ReferenceSettings&) {
    throw_timing_only("the shadow-ray benchmark");
}

}  // namespace canopy
