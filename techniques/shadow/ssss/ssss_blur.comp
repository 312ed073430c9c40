#version 450
#extension GL_GOOGLE_include_directive : require
// SSSS step 3: one axis of the separable anisotropic Gaussian over the hard shadows in screen
// space (Gumbau 2011, 6.2.3), K taps over +-3 sigma of this pixel's own width, each on a whole
// pixel and weighted by the Gaussian of its actual offset (ssss_filter.h). Pixels the screen pass
// masked (no blocker nearby: sigma 0) and the background are left as they are (6.2.2). Taps on
// other surfaces (distance to the observer differs by more than depth_error from where the tap's
// view ray meets this pixel's tangent plane, relative) are either dropped or, with lazy shadowing
// (6.3.2), replaced by the hard shadow of the point where the tap's view ray meets that plane --
// the shadow the occluder hides from view.
// Reads kernel (taps K), depth_error and lazy from frame.technique.
#define FRAME_BINDING 2
#include "ssss_params.h"
#include "separable_filter.glsl"
#include "frame_uniforms.glsl"
#include "shading.h"
#include "shadow_common.h"
#include "light_space.glsl"
#include "ssss_common.glsl"
#include "ssss_filter.h"

layout(set = 0, binding = 3) uniform sampler2D shadow_depth;  // the depth shadow map
layout(set = 0, binding = 4) uniform sampler2D normals;       // world normals of the camera pass

// World-space direction of the view ray through the centre of pixel `pixel`.
vec3 pixel_ray(vec2 pixel) {
    vec2 ndc = (pixel + 0.5) / vec2(filter_pass.extent) * 2.0 - 1.0;
    vec4 far_point = frame.inverse_view_proj * vec4(ndc, 1.0, 1.0);
    return normalize(far_point.xyz / far_point.w - frame.camera_position.xyz);
}

vec4 filter_texel(ivec2 xy) {
    vec4 centre = fetch(xy, 0);
    float sigma = filter_pass.direction.x == 1 ? centre.g : centre.b;
    if (!ssss_blurs(sigma, centre.a)) return centre;

    int taps = frame.technique.kernel;
    float depth_error = frame.technique.depth_error;
    bool lazy = frame.technique.lazy;
    vec3 n = texelFetch(normals, xy, 0).xyz;
    vec3 camera = frame.camera_position.xyz;
    vec3 centre_from_camera = pixel_ray(vec2(xy)) * centre.a;

    float sum = 0.0, weights = 0.0;
    for (int i = 0; i < taps; ++i) {
        int offset = ssss_tap_offset(i, taps, sigma);
        vec4 s = fetch(xy, offset);
        float value = s.r;
        // The pixel fetch() read (clamped at the image's edge) is the one whose distance is tested.
        ivec2 read = clamp(xy + offset * filter_pass.direction, ivec2(0), filter_pass.src_extent - 1);
        float expected = ssss_expected_distance(n, pixel_ray(vec2(read)), centre_from_camera, centre.a);
        if (!ssss_same_surface(s.a, expected, depth_error)) {
            if (!lazy) continue;
            vec3 ray = pixel_ray(vec2(xy + offset * filter_pass.direction));
            float t = ssss_tangent_plane_distance(n, ray, centre_from_camera);
            if (t <= 0.0) continue;
            value = hard_shadow_test(shadow_depth, light_space_point(camera + ray * t, n));
        }
        float w = ssss_tap_weight(offset, sigma);
        sum += w * value;
        weights += w;
    }
    return vec4(weights > 0.0 ? sum / weights : centre.r, centre.g, centre.b, centre.a);
}
