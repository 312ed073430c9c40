// A straight shadow edge whose position and penumbra are known in closed form, rendered on the
// test device and read back as a visibility profile across the edge.
//
// The scene: a 4 x 4 floor at y = 0, and a thin slab (0.02 thick) whose top face is at
// `occluder_height`, covering the floor on one side of a straight edge: x < edge (the edge runs
// along z) or, with `across_z`, z < edge (the edge runs along x). The light sits straight above
// the origin (or shines straight down), so the edge runs along one column (or row) of the shadow
// map and the floor is parallel to the map's image plane: every floor point has the same light
// depth, and floor position maps linearly to map texels. A small post in a corner fixes the scene
// bounds, so the light frustum (and with it the texel size and depth range) does not depend on
// the slab's height or the edge's position. The camera looks straight down from below the slab
// (at 0.8 of its height unless `camera_height` says otherwise), centred on the edge, so it sees
// only the floor, with image x along world x and image y along world z: the profile runs along
// image rows (edge along z, a wide image) or along image columns (`across_z`, a tall image), so
// both map axes and both screen axes get tested.
//
// Positions along the profile are `t`: shadow-map texels from the geometric edge, positive
// towards the lit side. The slab's edge is placed 0.3 texel from a texel boundary, so the
// rasterised map's edge (the boundary nearest the geometric one: texels are covered when their
// centre is) is unambiguous, at t = `boundary`.
#pragma once

#include "render/light_view.hpp"
#include "scene/camera.hpp"
#include "scene/geometry.hpp"
#include "shading.h"
#include "support/test_gpu.hpp"
#include "../shaders/shadow_common.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace canopy::test {

struct EdgeSetup {
    LightType light = LightType::directional;
    float light_size = 0.0f;       // rect: side of the square; sphere: diameter
    float light_height = 2.0f;     // spot, rect, sphere: height of the light's centre above x = z = 0
    float occluder_height = 0.5f;  // height of the slab's top face
    int resolution = 512;          // shadow (or moment) map width and height
    float window_texels = 24.0f;   // length of the profile on the floor, in shadow texels
    bool across_z = false;         // the edge runs along x and the profile along z (image columns)
    int image_length = 256;        // pixels along the profile
    int image_breadth = 64;        // pixels along the edge
    float camera_height = 0.0f;    // above the floor; 0: 0.8 of the slab's height
};

struct ProfileSample {
    double t = 0.0;        // shadow texels from the geometric edge, + towards the lit side
    double visibility = 0.0;
    glm::vec3 floor_point{0.0f};  // the world point of the image column (centre row)
};
using Profile = std::vector<ProfileSample>;

struct EdgeScene {
    EdgeSetup setup;
    Scene scene;
    LightView light_view;
    float edge = 0.0f;            // world x (or z, across_z) of the slab's edge
    int image_width = 0, image_height = 0;
    int map_axis = 0;             // 0: the map's u runs across the edge, 1: v
    double map_direction = 1.0;   // +1 when that map coordinate grows towards the lit side
    double edge_texel = 0.0;      // map coordinate of the geometric edge, texels
    double boundary = 0.0;        // t of the rasterised edge (nearest texel boundary)
    double texel_floor = 0.0;     // world size of one shadow texel on the floor
    double texel_image = 0.0;     // LightView::texel_world: per unit depth (perspective) or absolute
    double receiver_distance = 0.0;  // light-view depth of the floor, world units
    double blocker_distance = 0.0;   // light-view depth of the slab's top face
    double receiver_depth = 0.0;     // the floor's normalised light depth (0 near plane, 1 far)
    double blocker_depth = 0.0;      // the slab top's
    double camera_height = 0.0;
    double focal_pixels = 0.0;       // vertical focal length of the camera in pixels
};

inline constexpr float kFloorAlbedo = 0.8f;
inline constexpr float kAmbient = 0.05f;
inline constexpr float kSlabThickness = 0.02f;

inline glm::vec3 light_space(const LightView& lv, const glm::vec3& p) {
    const glm::vec4 view = lv.view * glm::vec4(p, 1.0f);
    const glm::vec2 uv = shader::shadow_uv(lv.projection * view);
    return {uv.x, uv.y, -view.z};  // (u, v, light-view depth)
}

inline Object scene_object(const char* name, ShapeType shape, float albedo) {
    static const Object defaults;  // (copied: GCC 12 warns, wrongly, on Object() inlined here)
    Object object = defaults;
    object.name = name;
    object.shape = shape;
    object.material.albedo = glm::vec3(albedo);
    return object;
}

inline EdgeScene make_edge_scene(const EdgeSetup& setup) {
    EdgeScene e;
    e.setup = setup;
    Scene& s = e.scene;
    s.name = "straight-edge";
    s.ambient = glm::vec3(kAmbient);
    s.background = glm::vec3(0.0f);

    Light light;
    light.type = setup.light;
    light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    light.position = glm::vec3(0.0f, setup.light_height, 0.0f);
    light.intensity = setup.light == LightType::directional ? 3.0f : 12.0f;
    light.spot_angle_degrees = 30.0f;
    light.rect_size = glm::vec2(setup.light_size);
    light.sphere_radius = 0.5f * setup.light_size;
    s.lights = {light};

    Object floor = scene_object("floor", ShapeType::plane, kFloorAlbedo);
    floor.plane_size = glm::vec2(4.0f);
    Object slab = scene_object("slab", ShapeType::box, 0.5f);
    Object post = scene_object("post", ShapeType::box, 0.5f);
    post.box_size = glm::vec3(0.05f);
    post.instances.front().translate = glm::vec3(-1.9f, 1.2f, 1.9f);
    // The slab covers the floor below `edge` along the profile axis (x, or z with across_z).
    const glm::vec3 across = setup.across_z ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    const glm::vec3 along = setup.across_z ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    const float top = setup.occluder_height;
    const float slab_width = 1.5f;
    auto place_slab = [&](float edge) {
        slab.box_size = slab_width * across + 4.0f * along + glm::vec3(0, kSlabThickness, 0);
        slab.instances.front().translate = (edge - 0.5f * slab_width) * across + glm::vec3(0, top - 0.5f * kSlabThickness, 0);
        s.objects = {floor, slab, post};
    };
    // The bounds, and so the light view, do not depend on where the edge is.
    place_slab(0.0f);
    e.light_view = compute_light_view(light, scene_bounds(s, build_scene_meshes(s)), uint32_t(setup.resolution));
    const LightView& lv = e.light_view;
    e.texel_image = lv.texel_world;

    // The map axis across the edge and its direction, from two points either side of the origin.
    const glm::vec3 a = light_space(lv, glm::vec3(0, top, 0) - 0.01f * across);
    const glm::vec3 b = light_space(lv, glm::vec3(0, top, 0) + 0.01f * across);
    e.map_axis = std::abs(b.x - a.x) > std::abs(b.y - a.y) ? 0 : 1;
    e.map_direction = (b[e.map_axis] - a[e.map_axis]) > 0.0f ? 1.0 : -1.0;

    // The edge 0.3 texel (at the slab's depth) off the origin, which maps to a texel boundary
    // (the map's centre): the rasterised edge is then the boundary 0.3 texel away.
    const float texel_at_top = lv.texel_world * (lv.perspective ? light_space(lv, glm::vec3(0.0f, top, 0.0f)).z : 1.0f);
    e.edge = 0.3f * texel_at_top;
    place_slab(e.edge);
    const glm::vec3 edge = light_space(lv, e.edge * across + glm::vec3(0, top, 0));
    e.edge_texel = double(edge[e.map_axis]) * setup.resolution;
    e.boundary = (std::round(e.edge_texel) - e.edge_texel) * e.map_direction;

    const glm::vec3 floor_centre = light_space(lv, glm::vec3(0.0f));
    e.receiver_distance = floor_centre.z;
    e.blocker_distance = edge.z;
    const double range = double(lv.far_plane) - double(lv.near_plane);
    e.receiver_depth = (e.receiver_distance - lv.near_plane) / range;
    e.blocker_depth = (e.blocker_distance - lv.near_plane) / range;
    e.texel_floor = lv.texel_world * (lv.perspective ? e.receiver_distance : 1.0);

    // Camera straight down from below the slab (image x = world x, image y = world z), centred on
    // the edge, the profile spanning window_texels of floor.
    e.image_width = setup.across_z ? setup.image_breadth : setup.image_length;
    e.image_height = setup.across_z ? setup.image_length : setup.image_breadth;
    const double window = setup.window_texels * e.texel_floor;
    // High by default, so the observer distance varies little across the strip.
    e.camera_height = setup.camera_height > 0.0f ? double(setup.camera_height) : 0.8 * top;
    const double tan_half = 0.5 * window / (e.camera_height * (setup.across_z ? 1.0 : double(e.image_width) / e.image_height));
    s.camera.position = e.edge * across + glm::vec3(0.0f, float(e.camera_height), 0.0f);
    s.camera.target = e.edge * across;
    s.camera.up = glm::vec3(0.0f, 0.0f, -1.0f);
    s.camera.fov_y_degrees = float(glm::degrees(2.0 * std::atan(tan_half)));
    s.camera.near_plane = 0.01f;
    s.camera.far_plane = 10.0f;
    e.focal_pixels = 0.5 * e.image_height / tan_half;
    return e;
}

// t of a world point (texels from the geometric edge, + towards the lit side).
inline double edge_t(const EdgeScene& e, const glm::vec3& p) {
    const glm::vec3 l = light_space(e.light_view, p);
    return (double(l[e.map_axis]) * e.setup.resolution - e.edge_texel) * e.map_direction;
}

// The floor's unshadowed irradiance at p, as the lit pass computes it (area lights by their centre).
inline float floor_irradiance(const Scene& scene, const glm::vec3& p) {
    const Light& l = scene.lights.front();
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    if (l.type == LightType::directional) return shader::directional_irradiance(n, l.direction, glm::vec3(l.intensity)).x;
    return shader::point_irradiance(int(l.type), p, n, l.position, l.direction, glm::vec3(l.intensity),
                                    std::cos(glm::radians(l.spot_angle_degrees))).x;
}

// Visibility along the profile, from the rendered luminance and the shading model:
// L = albedo (E V / pi + ambient), averaged over the middle half of the image across the profile.
inline Profile profile_from_image(const EdgeScene& e, const Image& image) {
    const Camera& camera = e.scene.camera;
    auto floor_point = [&](double px, double py) {
        const Ray r = primary_ray(camera, image.width, image.height, float(px), float(py));
        return r.origin + r.direction * (-r.origin.y / r.direction.y);
    };
    const bool columns = e.setup.across_z;  // the profile runs down the image
    const int length = columns ? image.height : image.width, breadth = columns ? image.width : image.height;
    Profile profile;
    for (int i = 0; i < length; ++i) {
        double sum = 0.0;
        int count = 0;
        for (int j = breadth / 4; j < 3 * breadth / 4; ++j, ++count) {
            const int x = columns ? j : i, y = columns ? i : j;
            const glm::vec3 p = floor_point(x + 0.5, y + 0.5);
            const double lit = kFloorAlbedo * floor_irradiance(e.scene, p) / shader::PI;
            sum += (image.luminance(x, y) - kFloorAlbedo * kAmbient) / lit;
        }
        ProfileSample sample;
        sample.floor_point = columns ? floor_point(0.5 * image.width, i + 0.5) : floor_point(i + 0.5, 0.5 * image.height);
        sample.t = edge_t(e, sample.floor_point);
        sample.visibility = sum / count;
        profile.push_back(sample);
    }
    return profile;
}

inline Profile render_profile(const EdgeScene& e, const std::string& technique, std::map<std::string, ParamValue> params) {
    params["resolution"] = (long long)e.setup.resolution;
    return profile_from_image(e, render_technique(e.scene, technique, params, e.image_width, e.image_height));
}

// The same sample positions with visibility from a model of the technique: visibility(sample).
inline Profile model_profile(const Profile& at, const std::function<double(const ProfileSample&)>& visibility) {
    Profile out = at;
    for (ProfileSample& s : out) s.visibility = visibility(s);
    return out;
}

// Where the profile first rises through `level` (linear between samples), in t; NaN if never.
inline double crossing(const Profile& p, double level) {
    for (size_t i = 1; i < p.size(); ++i)
        if (p[i - 1].visibility < level && p[i].visibility >= level) {
            const double a = (level - p[i - 1].visibility) / (p[i].visibility - p[i - 1].visibility);
            return p[i - 1].t + a * (p[i].t - p[i - 1].t);
        }
    return std::numeric_limits<double>::quiet_NaN();
}

struct EdgeMeasure {
    double centre = 0.0;  // 50 % crossing, texels from the geometric edge
    double width = 0.0;   // 10 % to 90 % rise, texels
    double umbra = 0.0;   // visibility at the shadow-side end of the strip
    double lit = 0.0;     // visibility at the lit-side end
};

inline EdgeMeasure measure(const Profile& p) {
    EdgeMeasure m;
    m.centre = crossing(p, 0.5);
    m.width = crossing(p, 0.9) - crossing(p, 0.1);
    m.umbra = p.front().visibility;
    m.lit = p.back().visibility;
    return m;
}

// One image pixel on the floor, in shadow texels (the profile's sampling step).
inline double pixel_texels(const Profile& p) { return std::abs(p[1].t - p[0].t); }

}  // namespace canopy::test
