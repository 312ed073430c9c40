#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.pcf: percentage-closer filtering (Reeves et al. 1987): the average of depth tests
// over a k x k grid or a Poisson disk of k*k samples, each optionally a hardware 2x2
// bilinear depth compare. Each tap compares against the receiver plane's depth at the tap
// (receiver-plane bias), or against one depth biased for the kernel's whole reach.
#include "pcf_params.h"
#include "forward_lighting.glsl"

float shadow_visibility(ShadowQuery q) {
    int kernel = frame.technique.kernel;
    bool poisson = frame.technique.pattern == PCF_PATTERN_POISSON;
    bool hardware = frame.technique.hardware_2x2;
    int count = frame.technique.count;
    float reach = frame.technique.reach;
    bool receiver_plane = frame.technique.receiver_plane;

    // With the receiver plane, the bias only covers the half-texel of a nearest lookup;
    // without it, it must cover the depth change across the whole kernel.
    float slope = frame.technique.bias_slope * (receiver_plane ? 1.0 : reach + 1.0);
    float reference = q.receiver_depth - slope_scaled_bias(frame.technique.bias_constant, slope, q.depth_per_texel);
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
