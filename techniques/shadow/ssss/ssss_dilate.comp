#version 450
#extension GL_GOOGLE_include_directive : require
// SSSS coarse map, step 2 (Gumbau 2011, 6.2.1): one axis of the dilation -- a min filter whose
// reach grows with the light's size (L1614). Each coarse texel's blocker spreads as far as its
// outer penumbra can reach (ssss_dilation_texels: half of eq 6.1's width for a receiver up to the
// user's maximum occluder distance behind it), so a receiver in that penumbra finds the blocker.
// The reach shrinks as blockers get farther from the light, so the two separable passes give
// exactly the square footprint of every blocker. The loop stops at the reach of a blocker on the
// near plane (the farthest any reaches), or at the pass's radius, a cap on the cost.
// Reads coarse_block (shadow texels per coarse texel) and occluder_distance (a fraction of the
// light's depth range) from frame.technique.
#define FRAME_BINDING 2
#include "ssss_params.h"
#include "separable_filter.glsl"
#include "frame_uniforms.glsl"
#include "shading.h"
#include "shadow_common.h"
#include "light_space.glsl"
#include "ssss_filter.h"

// Shadow texels the blocker stored as normalised depth z reaches.
float reach_of(float z) {
    float near_plane = frame.shadow_depth_range.x, far_plane = frame.shadow_depth_range.y;
    float d_blocker = near_plane + z * (far_plane - near_plane);
    float max_distance = frame.technique.occluder_distance * (far_plane - near_plane);
    return ssss_dilation_texels(d_blocker, max_distance, far_plane, light_width(), frame.shadow_texel.z,
                                frame.shadow_depth_range.w > 0.5);
}

vec4 filter_texel(ivec2 xy) {
    int block = frame.technique.coarse_block;
    int radius = min(filter_pass.radius, int(ceil(reach_of(0.0) / float(block))) + 1);
    float lowest = fetch(xy, 0).r;
    for (int i = -radius; i <= radius; ++i) {
        float z = fetch(xy, i).r;
        if (z < lowest && ssss_dilation_reaches(i, reach_of(z), block)) lowest = z;
    }
    return vec4(lowest, 0.0, 0.0, 1.0);
}
