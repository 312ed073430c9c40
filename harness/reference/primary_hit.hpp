// The surface a camera ray sees, exactly as the reference shades it: clipped to the camera's
// near and far planes measured along the view axis (as the rasteriser clips), the interpolated
// normal turned towards the viewer (as forward_lighting.glsl), and the shadow-ray origin moved off
// the surface along the geometric normal. Shared by the radiance reference (pixel_integrator.hpp)
// and the pixel-centre visibility (pixel_visibility.hpp), so both see the same hits.
#pragma once

#include "reference/embree_scene.hpp"
#include "reference/light_integrator.hpp"
#include "scene/camera.hpp"

#include <optional>

namespace canopy {

// Throws ConfigError (the scene's file) for a camera whose rays primary_ray cannot build, which
// would otherwise render as all background.
void check_camera_representable(const Scene& scene);

struct PrimaryHit {
    SurfacePoint surface;
    float view_depth = 0.0f;  // distance along the camera's view axis
    unsigned geometry = RTC_INVALID_GEOMETRY_ID;  // EmbreeScene::geometry()'s ID, for the material
    uint64_t primitive = 0;  // the triangle within the geometry (a population's: copy * T + triangle)
    float u = 0.0f, v = 0.0f;                      // the hit's barycentrics (weights of vertices 1, 2)
};

// `forward`: the camera's unit view direction. nullopt when the ray sees the background.
inline std::optional<PrimaryHit> trace_primary(const EmbreeScene& embree, const Camera& camera, glm::vec3 forward,
                                               const Ray& ray) {
    const float along_axis = glm::dot(ray.direction, forward);
    RTCRayHit hit{};  // every field defined; Embree writes the hit
    hit.ray.org_x = ray.origin.x;
    hit.ray.org_y = ray.origin.y;
    hit.ray.org_z = ray.origin.z;
    hit.ray.dir_x = ray.direction.x;
    hit.ray.dir_y = ray.direction.y;
    hit.ray.dir_z = ray.direction.z;
    hit.ray.tnear = along_axis > 0.0f ? camera.near_plane / along_axis : 0.0f;
    hit.ray.tfar = along_axis > 0.0f ? camera.far_plane / along_axis : 0.0f;
    hit.ray.time = 0.0f;
    hit.ray.mask = 0xffffffffu;
    hit.ray.id = 0;
    hit.ray.flags = 0;
    hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    hit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    RTCIntersectContext context{};
    rtcInitIntersectContext(&context);
    rtcIntersect1(embree.visible_scene(), &context, &hit);
    if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

    const EmbreeHit resolved = embree.resolve(hit.hit);
    PrimaryHit result;
    result.geometry = resolved.geometry;
    result.primitive = resolved.primitive;
    result.u = hit.hit.u;
    result.v = hit.hit.v;
    const float distance = hit.ray.tfar;
    result.view_depth = distance * along_axis;
    SurfacePoint& surface = result.surface;
    surface.position = ray.origin + distance * ray.direction;
    glm::vec3 geometric_normal = resolved.geometric_normal;
    const float geometric_length = glm::length(geometric_normal);
    geometric_normal = geometric_length > 0.0f ? geometric_normal / geometric_length : -ray.direction;
    if (glm::dot(geometric_normal, ray.direction) > 0.0f) geometric_normal = -geometric_normal;
    glm::vec3 normal = embree.shading_normal(resolved.geometry, resolved.primitive, hit.hit.u, hit.hit.v);
    if (normal == glm::vec3(0.0f)) normal = geometric_normal;
    // Two-sided surfaces: shade the side the camera sees, exactly as forward_lighting.glsl.
    if (glm::dot(normal, camera.position - surface.position) < 0.0f) normal = -normal;
    surface.normal = normal;
    surface.origin = surface.position + shadow_ray_offset(surface.position, distance, embree.extent()) * geometric_normal;
    return result;
}

}  // namespace canopy
