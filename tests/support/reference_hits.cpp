#include "support/reference_hits.hpp"

#include "scene/camera.hpp"

namespace canopy::test {

std::vector<std::optional<ReferenceHit>> reference_hits(const Scene& scene, const EmbreeScene& embree, uint32_t width,
                                                        uint32_t height) {
    const glm::vec3 forward = glm::normalize(scene.camera.target - scene.camera.position);
    std::vector<std::optional<ReferenceHit>> hits(size_t(width) * height);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const Ray ray = primary_ray(scene.camera, int(width), int(height), float(x) + 0.5f, float(y) + 0.5f);
            if (const std::optional<PrimaryHit> hit = trace_primary(embree, scene.camera, forward, ray))
                hits[size_t(y) * width + x] = ReferenceHit{*hit, embree.geometry(hit->geometry)};
        }
    return hits;
}

RTCRayHit trace_down(const EmbreeScene& embree, float x, float z, float from_y, float length) {
    RTCRayHit ray{};
    ray.ray.org_x = x;
    ray.ray.org_y = from_y;
    ray.ray.org_z = z;
    ray.ray.dir_y = -1.0f;
    ray.ray.tfar = length;
    ray.ray.mask = 0xffffffffu;
    ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    ray.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    RTCIntersectContext context{};
    rtcInitIntersectContext(&context);
    rtcIntersect1(embree.visible_scene(), &context, &ray);
    return ray;
}

}  // namespace canopy::test
