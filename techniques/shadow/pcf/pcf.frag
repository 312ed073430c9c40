#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.pcf: percentage-closer filtering (Reeves et al. 1987): the average of depth tests
// over a k x k grid or a Poisson disk of k*k samples, each optionally a hardware 2x2
// bilinear depth compare. Each tap compares against the receiver plane's depth at the tap
// (receiver-plane bias), or against one depth biased for the kernel's whole reach.
// technique_param: 0 bias_constant, 1 bias_slope, 2 kernel k, 3 pattern (0 grid, 1 poisson),
//                  4 hardware 2x2 (0/1), 5 sample count, 6 reach in texels, 7 receiver plane (0/1)
#include "forward_lighting.glsl"

float shadow_visibility(ShadowQuery q) {
    int kernel = int(technique_param(2));
    bool poisson = technique_param(3) > 0.5;
    bool hardware = technique_param(4) > 0.5;
    int count = int(technique_param(5));
    float reach = technique_param(6);
    bool receiver_plane = technique_param(7) > 0.5;

    // With the receiver plane, the bias only covers the half-texel of a nearest lookup;
    // without it, it must cover the depth change across the whole kernel.
    float slope = technique_param(1) * (receiver_plane ? 1.0 : reach + 1.0);
    float reference = q.receiver_depth - slope_scaled_bias(technique_param(0), slope, q.depth_per_texel);
    int resolution = int(shadow_resolution());
    float texel = shadow_texel_uv();

    float lit = 0.0;
    for (int i = 0; i < count; ++i) {
        vec2 offset = poisson ? sample_offset(i) * reach : grid_offset(i, kernel);
        vec2 uv = q.uv + offset * texel;
        float tap_reference = receiver_plane ? reference + dot(q.depth_gradient, offset) : reference;
        if (hardware) {
            lit += texture(shadow_compare, vec3(uv, tap_reference));
        } else {
            lit += depth_test(tap_reference, texelFetch(shadow_depth, nearest_texel(uv, ivec2(resolution)), 0).r);
        }
    }
    return lit / float(count);
}
