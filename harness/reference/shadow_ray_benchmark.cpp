#include "reference/shadow_ray_benchmark.hpp"

#include "reference/embree_scene.hpp"
#include "reference/parallel_for.hpp"
#include "reference/pixel_integrator.hpp"
#include "reference/reference_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>

namespace canopy {

namespace {

// Enough rays for a stable measurement while the batch stays under ~100 MB.
constexpr uint64_t kMaxRecordedRays = 2'000'000;
constexpr double kMinBareSeconds = 1.0;
constexpr size_t kRaysPerTask = 4096;

// Stands in for the Embree tracer: keeps every ray the integrator asks for and reports all
// of them unoccluded (the rays an integrator generates never depend on earlier results).
class RecordingTracer {
public:
    explicit RecordingTracer(std::vector<RTCRay>& rays) : rays_(rays) {}
    void trace(ShadowPacket& packet) {
        for (int lane = 0; lane < ShadowPacket::kWidth; ++lane) {
            if (packet.valid[lane] == 0) continue;
            RTCRay ray{};
            ray.org_x = packet.rays.org_x[lane];
            ray.org_y = packet.rays.org_y[lane];
            ray.org_z = packet.rays.org_z[lane];
            ray.tnear = packet.rays.tnear[lane];
            ray.dir_x = packet.rays.dir_x[lane];
            ray.dir_y = packet.rays.dir_y[lane];
            ray.dir_z = packet.rays.dir_z[lane];
            ray.time = 0.0f;
            ray.tfar = packet.rays.tfar[lane];
            ray.mask = 0xffffffffu;
            ray.id = 0;
            ray.flags = 0;
            rays_.push_back(ray);
        }
    }

private:
    std::vector<RTCRay>& rays_;
};

std::vector<RTCRay> record_shadow_rays(const Scene& scene, const EmbreeScene& embree, int width, int height,
                                       const ReferenceSettings& settings, uint64_t expected_rays) {
    const uint64_t rays_per_row = std::max<uint64_t>(expected_rays / uint64_t(height), 1);
    const int row_stride = int(std::clamp<uint64_t>((rays_per_row * uint64_t(height)) / kMaxRecordedRays + 1, 1,
                                                    uint64_t(height)));
    const int rows = (height + row_stride - 1) / row_stride;
    const PixelIntegrator integrator(scene, embree, width, height, settings);
    std::vector<std::vector<RTCRay>> per_row(static_cast<size_t>(rows));
    parallel_for(size_t(rows), settings.threads, [&](size_t row, int) {
        RecordingTracer recorder(per_row[row]);
        const int y = int(row) * row_stride;
        for (int x = 0; x < width; ++x) integrator.integrate(x, y, recorder);
    });
    std::vector<RTCRay> rays;
    for (const auto& row : per_row) rays.insert(rays.end(), row.begin(), row.end());
    return rays;
}

// Rays per second of a plain rtcOccluded1 loop over `rays`, repeated until it has run long enough.
double bare_occluded1_rate(RTCScene scene, const std::vector<RTCRay>& rays, int threads) {
    if (rays.empty()) return 0.0;
    const size_t tasks = (rays.size() + kRaysPerTask - 1) / kRaysPerTask;
    std::atomic<uint64_t> occluded{0};
    uint64_t traced = 0;
    const auto start = std::chrono::steady_clock::now();
    double seconds = 0.0;
    do {
        parallel_for(tasks, threads, [&](size_t task, int) {
            RTCIntersectContext context{};
            rtcInitIntersectContext(&context);
            const size_t begin = task * kRaysPerTask, end = std::min(begin + kRaysPerTask, rays.size());
            uint64_t blocked = 0;
            for (size_t i = begin; i < end; ++i) {
                RTCRay ray = rays[i];
                rtcOccluded1(scene, &context, &ray);
                blocked += ray.tfar < 0.0f ? 1 : 0;
            }
            occluded += blocked;
        });
        traced += rays.size();
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } while (seconds < kMinBareSeconds);
    return double(traced) / seconds;
}

}  // namespace

ShadowRayBenchmark benchmark_shadow_rays(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width,
                                         int height, const ReferenceSettings& settings) {
    const EmbreeScene embree(scene, meshes);
    const ReferenceImages images = render_reference(scene, embree, width, height, settings);
    const std::vector<RTCRay> rays = record_shadow_rays(scene, embree, width, height, settings, images.shadow_rays);

    ShadowRayBenchmark result;
    result.rays = images.shadow_rays;
    result.reference_rays_per_second = images.seconds > 0.0 ? double(images.shadow_rays) / images.seconds : 0.0;
    result.bare_rays_per_second = bare_occluded1_rate(embree.shadow_scene(), rays, settings.threads);
    result.ratio = result.bare_rays_per_second > 0.0 ? result.reference_rays_per_second / result.bare_rays_per_second
                                                     : 0.0;
    return result;
}

}  // namespace canopy
