#version 450
#extension GL_GOOGLE_include_directive : require
// SSSS step 2 (Gumbau 2011, 6.2-6.2.3): per pixel, the hard shadow, the eq 6.2 penumbra width
// in screen space (from the coarse, min-filtered map's blocker depth) turned into the
// anisotropic Gaussian's sigma along x and y, and the distance to the observer.
// Output: (hard shadow, sigma_x px, sigma_y px, distance to camera). sigma 0 = no penumbra
// possible here (lazy: the blur skips the pixel).
#include "screen_shadow_output.glsl"
#include "shading.h"
#include "shadow_common.h"
#include "shadow_filtering.h"
#include "light_space.glsl"
#include "ssss_common.glsl"

// A Gaussian-blurred step goes from 10 % to 90 % over 2.563 sigma: make that the penumbra width.
const float PENUMBRA_WIDTH_IN_SIGMAS = 2.563;

vec4 screen_shadow_data(vec3 p, vec3 n) {
    float d_observer = length(p - frame.camera_position.xyz);
    if (dot(n, direction_to_light(p)) <= 0.0) return vec4(0.0, 0.0, 0.0, d_observer);  // faces away: unlit
    LightSpacePoint l = light_space_point(p, n);
    float hard = hard_shadow_test(shadow_depth, l);
    if (!on_shadow_map(l)) return vec4(hard, 0.0, 0.0, d_observer);

    float coarse = stored_depth_at(coarse_map, l.uv);  // nearest blocker around, dilated
    if (coarse >= l.receiver_depth - receiver_bias(l)) return vec4(hard, 0.0, 0.0, d_observer);  // no blocker: no penumbra

    float near_plane = frame.shadow_depth_range.x;
    float d_blocker = near_plane + coarse * (frame.shadow_depth_range.y - near_plane);
    float width = ssss_screen_penumbra_width(l.view_depth, d_blocker, light_width(), d_observer);  // eq 6.2
    float sigma = width * frame.viewport.z / PENUMBRA_WIDTH_IN_SIGMAS;  // pixels
    // Anisotropy: a disk on the tangent plane projects to an ellipse whose screen x and y
    // extents shrink by sqrt(1 - n_x^2) and sqrt(1 - n_y^2) (n in view space).
    vec3 nv = normalize(mat3(frame.view) * n);
    return vec4(hard, sigma * sqrt(max(1.0 - nv.x * nv.x, 0.0)), sigma * sqrt(max(1.0 - nv.y * nv.y, 0.0)), d_observer);
}
