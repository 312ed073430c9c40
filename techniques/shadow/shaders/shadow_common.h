// Shadow-map helpers shared by GLSL and C++ (see shared_math.h).
#ifndef CANOPY_SHADOW_COMMON_H
#define CANOPY_SHADOW_COMMON_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

// |cos| below which a receiver counts as grazing: the depth slope is clamped there so the
// slope-scaled bias stays finite (a slope of about 20 texels of depth per texel, 87 degrees).
CANOPY_CONST float GRAZING_COS = 0.05f;

// Gradient of the stored depth (distance along the light's axis) per shadow texel (u, v) on
// the receiver's tangent plane, in world units: the "receiver plane" of Isidoro 2006.
//   view_normal: receiver normal in light view space (unit).
//   view_ray:    light view-space direction of the lookup, scaled so that z = -1:
//                position / view_depth for perspective lights, (0, 0, -1) for orthographic.
//   texel_world: world size of one texel at the receiver's depth.
// For a plane n.P = c seen through image-plane coordinates s, depth d(s) = c / n.(s, -1), so
// dd/ds = -d n_xy / n.(s, -1), and one texel spans texel_world / d in s. Map u and v grow
// with view x and y. The denominator is clamped at grazing angles so the result stays finite.
CANOPY_FN vec2 depth_gradient_per_texel(vec3 view_normal, vec3 view_ray, float texel_world) {
    float facing = dot(view_normal, view_ray);
    float limit = GRAZING_COS * length(view_ray);
    float clamped = facing < 0.0f ? min(facing, -limit) : max(facing, limit);
    return -texel_world * vec2(view_normal.x, view_normal.y) / clamped;
}

// The largest depth change across one texel step in u and v together (L1 norm of the gradient).
CANOPY_FN float depth_change_per_texel(vec2 gradient) {
    return abs(gradient.x) + abs(gradient.y);
}

// Receiver-side depth bias in normalised shadow depth (fraction of the light's depth range):
//   constant_bias:   fraction of the depth range, added everywhere;
//   slope_texels:    multiples of the receiver plane's depth change across one texel; a
//                    nearest-texel lookup is off by up to half a texel in u and v, so
//                    slope_texels >= 0.5 keeps a flat receiver clear of acne;
//   depth_per_texel: depth_change_per_texel(gradient) / depth range.
CANOPY_FN float slope_scaled_bias(float constant_bias, float slope_texels, float depth_per_texel) {
    return constant_bias + slope_texels * depth_per_texel;
}

// 1 where the receiver (already biased) is not behind the stored occluder depth, else 0.
CANOPY_FN float depth_test(float receiver_depth, float occluder_depth) {
    return receiver_depth <= occluder_depth ? 1.0f : 0.0f;
}

// Offset in texels of sample `i` of a k x k grid centred on the lookup (k odd or even).
CANOPY_FN vec2 grid_offset(int i, int k) {
    float half_span = 0.5f * float(k - 1);
    return vec2(float(i % k) - half_span, float(i / k) - half_span);
}

// Light-space position -> shadow-map uv (0..1, row 0 at v = 0) and the receiver's normalised
// linear depth. `light_clip` is light_proj * light_view * world.
CANOPY_FN vec2 shadow_uv(vec4 light_clip) {
    vec2 ndc = vec2(light_clip.x, light_clip.y) / light_clip.w;  // no swizzles: glm has none
    return ndc * 0.5f + 0.5f;
}

CANOPY_FN float normalised_light_depth(float view_depth, float near_plane, float inv_range) {
    return (view_depth - near_plane) * inv_range;
}

// The texel of a size.x x size.y map under uv (NEAREST), clamped to the map.
CANOPY_FN ivec2 nearest_texel(vec2 uv, ivec2 size) {
    return clamp(ivec2(floor(uv * vec2(size))), ivec2(0), size - ivec2(1));
}

// True when uv falls on the shadow map (receivers outside it are treated as lit).
CANOPY_FN bool inside_shadow_map(vec2 uv) {
    return uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f;
}

CANOPY_END_NAMESPACE

#endif
