#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.pcss: percentage-closer soft shadows (Fernando 2005; Gumbau 2011 eq 6.1):
// 1. blocker search: average depth of the map texels nearer the light than the receiver,
//    over the region where blockers can hide the light from the receiver;
// 2. penumbra width by the parallel-planes estimate (eq 6.1);
// 3. PCF over a kernel x kernel grid spanning that width, each tap against the receiver plane.
#include "pcss_params.h"
#include "forward_lighting.glsl"
#include "shadow_filtering.h"

float stored_depth(vec2 uv) {
    return texelFetch(shadow_depth, nearest_texel(uv, textureSize(shadow_depth, 0)), 0).r;
}

// Grid tap i of a k x k grid spanning [-radius, radius] texels in u and v.
vec2 spread_offset(int i, int k, float radius) {
    return k > 1 ? grid_offset(i, k) * (2.0 * radius / float(k - 1)) : vec2(0.0);
}

float shadow_visibility(ShadowQuery q) {
    float near_plane = frame.shadow_depth_range.x;
    float range = frame.shadow_depth_range.y - near_plane;
    float texel_image = frame.shadow_texel.z;  // one texel's size on the light's image plane (z = 1)
    float w_light = light_width();
    float max_radius = frame.technique.max_radius;
    float d_receiver = q.view_depth;
    float reference = q.receiver_depth - slope_scaled_bias(frame.technique.bias_constant, frame.technique.bias_slope, q.depth_per_texel);
    float texel = shadow_texel_uv();

    // 1. Blocker search over the light's frustum from the receiver, cut at the near plane.
    float search_radius = clamp(0.5 * w_light * (d_receiver - near_plane) / (d_receiver * near_plane) / texel_image,
                                0.5, max_radius);
    int bs = frame.technique.blocker_search;
    float blocker_sum = 0.0;
    int blockers = 0;
    for (int i = 0; i < bs * bs; ++i) {
        vec2 offset = spread_offset(i, bs, search_radius);
        float z = stored_depth(q.uv + offset * texel);
        if (z < reference + dot(q.depth_gradient, offset)) {
            blocker_sum += z;
            ++blockers;
        }
    }
    if (blockers == 0) return 1.0;  // nothing between the receiver and the light
    float d_blocker = near_plane + (blocker_sum / float(blockers)) * range;

    // 2. Penumbra width at the receiver (world units), as a radius in shadow-map texels.
    float w_penumbra = pcss_penumbra_width(d_receiver, d_blocker, w_light);
    float filter_radius = clamp(0.5 * w_penumbra / (d_receiver * texel_image), 0.5, max_radius);

    // 3. PCF over the penumbra.
    int k = frame.technique.kernel;
    float lit = 0.0;
    for (int i = 0; i < k * k; ++i) {
        vec2 offset = spread_offset(i, k, filter_radius);
        lit += depth_test(reference + dot(q.depth_gradient, offset), stored_depth(q.uv + offset * texel));
    }
    return lit / float(k * k);
}
