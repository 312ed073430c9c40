#version 450
#extension GL_GOOGLE_include_directive : require
// Lemme's coverage-preserving rescale (eq 4.11-4.15) of one max-alpha level of a baked grass slice
// array (common/mip_passes.hpp runs it after grass_mip_reduce.comp, level by level): one workgroup
// per layer counts level 0's texels above a_r (eq 4.11), finds the reference a'_r at which this
// level keeps as many (the k-th largest alpha found by bisection on its bits, and halfway to the
// next smaller alpha: common/mip_chain.cpp's coverage_reference, ties kept alike), and scales
// every alpha by a_r / a'_r (eq 4.14-4.15, mip_scale_alpha).
#include "mip_filters.h"
#include "blade_texels.h"

layout(local_size_x = 256) in;

layout(set = 0, binding = 1, rgba32f) uniform readonly image2DArray base;
layout(set = 0, binding = 2, rgba32f) uniform image2DArray level;

shared uint counted;
shared uint largest_below;  // float bits of the largest alpha under the k-th (alphas are >= 0)
shared uint any_below;

// How many texels of `image`'s layer hold an alpha above (strictly: above_only) or at least `a`.
uint count_alphas(bool of_base, int layer, float a, bool above_only) {
    barrier();
    if (gl_LocalInvocationIndex == 0) counted = 0u;
    barrier();
    ivec2 size = of_base ? imageSize(base).xy : imageSize(level).xy;
    uint mine = 0u;
    for (int i = int(gl_LocalInvocationIndex); i < size.x * size.y; i += 256) {
        ivec3 p = ivec3(i % size.x, i / size.x, layer);
        float alpha = of_base ? imageLoad(base, p).w : imageLoad(level, p).w;
        if (above_only ? alpha > a : alpha >= a) ++mine;
    }
    atomicAdd(counted, mine);
    barrier();
    return counted;
}

void main() {
    int layer = int(gl_WorkGroupID.x);
    ivec2 base_size = imageSize(base).xy;
    ivec2 size = imageSize(level).xy;
    uint n = uint(size.x * size.y);
    float coverage = float(count_alphas(true, layer, GRASS_ALPHA_REFERENCE, true)) / float(base_size.x * base_size.y);
    uint k = uint(round(clamp(coverage, 0.0, 1.0) * float(n)));
    // The k-th largest alpha: the largest a with at least k texels at or above it.
    bool none_kept = k == 0u;
    if (none_kept) k = 1u;  // nothing strictly above the largest alpha: find the largest itself
    uint lo = 0u, hi = floatBitsToUint(1.0) + 1u;
    while (hi - lo > 1u) {
        uint mid = lo + (hi - lo) / 2u;
        if (count_alphas(false, layer, uintBitsToFloat(mid), false) >= k) lo = mid; else hi = mid;
    }
    float kth = uintBitsToFloat(lo);
    // Coverage 0: the reference is the largest alpha itself (nothing passes).
    float reference;
    if (none_kept) {
        reference = kth;
    } else {
        barrier();
        if (gl_LocalInvocationIndex == 0) {
            largest_below = 0u;
            any_below = 0u;
        }
        barrier();
        for (int i = int(gl_LocalInvocationIndex); i < size.x * size.y; i += 256) {
            float alpha = imageLoad(level, ivec3(i % size.x, i / size.x, layer)).w;
            if (alpha < kth) {
                atomicMax(largest_below, floatBitsToUint(alpha));
                atomicOr(any_below, 1u);
            }
        }
        barrier();
        // Halfway to the next smaller alpha; below the k-th by half where none is smaller.
        reference = any_below != 0u ? 0.5 * (kth + uintBitsToFloat(largest_below)) : 0.5 * kth;
    }
    float scale = GRASS_ALPHA_REFERENCE / max(reference, 1e-6);
    barrier();
    for (int i = int(gl_LocalInvocationIndex); i < size.x * size.y; i += 256) {
        ivec3 p = ivec3(i % size.x, i / size.x, layer);
        imageStore(level, p, mip_scale_alpha(imageLoad(level, p), scale));
    }
}
