#version 450
#extension GL_GOOGLE_include_directive : require
// SSSS step 3: one axis of the separable anisotropic Gaussian over the hard shadows in screen
// space (Gumbau 2011, 6.2.3), K taps over +-3 sigma of this pixel's own width. Taps on other
// surfaces (distance to the observer differs by more than depth_error, relative) are either
// dropped or, with lazy shadowing (6.3.2), replaced by the hard shadow of the point where the
// tap's view ray meets this pixel's tangent plane — the shadow the occluder hides from view.
// params: x = taps K, y = depth_error, z = lazy (0/1)
#define FRAME_BINDING 2
#include "separable_filter.glsl"
#include "frame_uniforms.glsl"
#include "shading.h"
#include "shadow_common.h"
#include "light_space.glsl"
#include "ssss_common.glsl"

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
    if (sigma < 0.25 || centre.a > 1e29) return centre;  // no penumbra here, or background

    int taps = int(filter_pass.params.x);
    float depth_error = filter_pass.params.y;
    bool lazy = filter_pass.params.z > 0.5;
    float spacing = taps > 1 ? 6.0 * sigma / float(taps - 1) : 0.0;
    vec3 n = texelFetch(normals, xy, 0).xyz;
    vec3 camera = frame.camera_position.xyz;
    vec3 centre_point = camera + pixel_ray(vec2(xy)) * centre.a;

    float sum = 0.0, weights = 0.0;
    for (int i = 0; i < taps; ++i) {
        float offset = (float(i) - 0.5 * float(taps - 1)) * spacing;
        int pixel_offset = int(round(offset));
        vec4 s = fetch(xy, pixel_offset);
        float value = s.r;
        if (abs(s.a - centre.a) > depth_error * centre.a) {
            if (!lazy) continue;
            vec3 ray = pixel_ray(vec2(xy + pixel_offset * filter_pass.direction));
            float facing = dot(n, ray);
            if (abs(facing) < 1e-4) continue;
            float t = dot(n, centre_point - camera) / facing;
            if (t <= 0.0) continue;
            value = hard_shadow_test(shadow_depth, light_space_point(camera + ray * t, n));
        }
        float w = exp(-0.5 * offset * offset / (sigma * sigma));
        sum += w * value;
        weights += w;
    }
    return vec4(weights > 0.0 ? sum / weights : centre.r, centre.g, centre.b, centre.a);
}
