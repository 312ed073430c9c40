// Stand-ins for the Embree reference (run/reference_provider.cpp, run/reference_tiles.cpp,
// reference/shadow_ray_benchmark.cpp) in a timing-only build (timing_only.hpp).
#include "reference/shadow_ray_benchmark.hpp"
#include "run/reference_provider.hpp"
#include "run/reference_tiles.hpp"
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

RowBand tile_rows(int, size_t, size_t) { throw_timing_only("the ray-traced reference's tiles"); }
std::string tile_key(const std::string&, size_t, size_t) { throw_timing_only("the ray-traced reference's tiles"); }

uint64_t render_reference_tile(const Scene&, const std::vector<TriangleMesh>&, int, int, const ReferenceSettings&, size_t,
                               size_t, const std::filesystem::path&, const std::function<void(double)>&) {
    throw_timing_only("the ray-traced reference");
}

void merge_reference_tiles(const Scene&, const std::vector<TriangleMesh>&, int, int, const ReferenceSettings&, size_t,
                           const std::filesystem::path&, const std::filesystem::path&) {
    throw_timing_only("the ray-traced reference");
}

ShadowRayBenchmark benchmark_shadow_rays(const Scene&, const std::vector<TriangleMesh>&, int, int,
                                         const ReferenceSettings&) {
    throw_timing_only("the shadow-ray benchmark");
}

}  // namespace canopy
