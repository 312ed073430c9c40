#version 450
#extension GL_GOOGLE_include_directive : require
// SSSS step 2 (Gumbau 2011, 6.2-6.2.3): per pixel, the hard shadow, the eq 6.2 penumbra width
// in screen space (from the coarse, dilated map's blocker depth) turned into the anisotropic
// Gaussian's sigma along x and y, and the distance to the observer.
// Output: (hard shadow, sigma_x px, sigma_y px, distance to camera). sigma 0 = no blocker in the
// dilated coarse map, so no penumbra can reach this pixel: the blur skips it (6.2.2's mask).
#include "ssss_params.h"
#include "screen_shadow_output.glsl"
#include "shading.h"
#include "shadow_common.h"
#include "light_space.glsl"
#include "ssss_common.glsl"
#include "ssss_filter.h"

// The coarse texel holding the block of the shadow texel under uv (block_min.comp's blocks).
float coarse_depth_at(vec2 uv) {
    ivec2 shadow_texel = nearest_texel(uv, textureSize(shadow_depth, 0));
    int block = frame.technique.coarse_block;
    return texelFetch(coarse_map, ssss_coarse_texel(shadow_texel, block, textureSize(coarse_map, 0)), 0).r;
}

vec4 screen_shadow_data(vec3 p, vec3 n) {
    float d_observer = length(p - frame.camera_position.xyz);
    if (dot(n, direction_to_light(p)) <= 0.0) return vec4(0.0, 0.0, 0.0, d_observer);  // faces away: unlit
    LightSpacePoint l = light_space_point(p, n);
    float hard = hard_shadow_test(shadow_depth, l);
    if (!on_shadow_map(l)) return vec4(hard, 0.0, 0.0, d_observer);

    float coarse = coarse_depth_at(l.uv);  // nearest blocker around, dilated
    if (coarse >= l.receiver_depth - receiver_bias(l)) return vec4(hard, 0.0, 0.0, d_observer);  // no blocker: no penumbra

    float near_plane = frame.shadow_depth_range.x;
    float d_blocker = near_plane + coarse * (frame.shadow_depth_range.y - near_plane);
    float view_depth = -(frame.view * vec4(p, 1.0)).z;  // eq 6.2's Z: depth along the camera's axis
    float sigma = ssss_sigma_pixels(l.view_depth, d_blocker, light_width(), view_depth, frame.viewport.z);  // eq 6.2
    vec3 view_normal = normalize(mat3(frame.view) * n);
    return vec4(hard, ssss_anisotropic_sigma(sigma, view_normal), d_observer);
}
