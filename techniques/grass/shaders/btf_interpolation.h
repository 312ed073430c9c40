// Boulanger's slice BTF (2008, §4.2.3 and App. A), GLSL and C++: a slice is baked under five
// light directions, Y+, X+, Z+, X- and Z- (patch space), and lit by any other through the
// spherical barycentric coordinates of the light within the quarter of the hemisphere whose three
// baked directions enclose it (eq A.1-A.2: each weight is the area of the spherical triangle the
// light makes with the other two directions, over pi/2).
//
// canopy computes those areas with Van Oosterom and Strackee's formula (tan(E/2) =
// |a.(b x c)| / (1 + a.b + b.c + c.a)) instead of eq A.6's three arccosines: the same area, but
// eq A.6 divides by sqrt(lx^2 + lz^2) and sqrt(lx^2 + ly^2), which vanish with the sun at the
// zenith (and at the horizon along an axis), where this formula reaches their limits: a light on
// a baked direction gives that direction weight 1 and the others 0. tests/test_btf_interpolation
// checks it against eq A.6 inside the quarter. A light below the horizon is taken at the horizon
// (Y- is not baked, B L881), and a zero vector as the zenith.
#ifndef CANOPY_GRASS_BTF_INTERPOLATION_H
#define CANOPY_GRASS_BTF_INTERPOLATION_H

#include "shading.h"

CANOPY_BEGIN_NAMESPACE

// The baked light directions, in the order of a slice's lit layers (Figure 4.6's rows 2-6).
CANOPY_CONST int BTF_LIGHTS = 5;
CANOPY_FN vec3 btf_light_direction(int row) {
    if (row == 0) return vec3(0.0f, 1.0f, 0.0f);
    if (row == 1) return vec3(1.0f, 0.0f, 0.0f);
    if (row == 2) return vec3(0.0f, 0.0f, 1.0f);
    if (row == 3) return vec3(-1.0f, 0.0f, 0.0f);
    return vec3(0.0f, 0.0f, -1.0f);
}

// The area of the spherical triangle of unit vectors a, b, c (Van Oosterom and Strackee 1983).
CANOPY_FN float btf_spherical_area(vec3 a, vec3 b, vec3 c) {
    float det = abs(dot(a, cross(b, c)));
    float den = 1.0f + dot(a, b) + dot(b, c) + dot(c, a);
    return 2.0f * atan(det, den);
}

// A light direction (toward the light, patch space) as Appendix A takes it: unit, not below the horizon.
// Scaled by its largest component before normalising, so no length overflows or underflows.
CANOPY_FN vec3 btf_light_on_hemisphere(vec3 toward_light) {
    vec3 l = vec3(toward_light.x, max(toward_light.y, 0.0f), toward_light.z);
    float largest = max(max(abs(l.x), l.y), abs(l.z));
    if (!(largest > 0.0f)) return vec3(0.0f, 1.0f, 0.0f);
    l = l / largest;
    return l / length(l);
}

// The weights of the five baked rows for `toward_light` (eq A.1-A.2): at most three are non-zero,
// Y+ and the X and Z directions on the light's side; they sum to 1.
struct BtfWeights {
    vec4 w0123;  // Y+, X+, Z+, X-
    float w4;    // Z-
};

CANOPY_FN BtfWeights btf_light_weights(vec3 toward_light) {
    vec3 l = btf_light_on_hemisphere(toward_light);
    vec3 a = vec3(l.x >= 0.0f ? 1.0f : -1.0f, 0.0f, 0.0f);  // A: X+ or X-
    vec3 b = vec3(0.0f, 1.0f, 0.0f);                        // B: Y+
    vec3 c = vec3(0.0f, 0.0f, l.z >= 0.0f ? 1.0f : -1.0f);  // C: Z+ or Z-
    const float quarter = 1.5707963267948966f;              // A(ABC) = pi / 2
    float wx = btf_spherical_area(l, b, c) / quarter;       // A(LBC)
    float wy = btf_spherical_area(l, c, a) / quarter;       // A(LCA)
    float wz = btf_spherical_area(l, a, b) / quarter;       // A(LAB)
    // Floating point leaves the sum within ~1e-6 of 1; make it exact.
    float sum = wx + wy + wz;
    wx /= sum;
    wy /= sum;
    wz /= sum;
    BtfWeights w;
    w.w0123 = vec4(wy, l.x >= 0.0f ? wx : 0.0f, l.z >= 0.0f ? wz : 0.0f, l.x >= 0.0f ? 0.0f : wx);
    w.w4 = l.z >= 0.0f ? 0.0f : wz;
    return w;
}

CANOPY_FN float btf_weight(BtfWeights w, int row) {
    if (row == 0) return w.w0123.x;
    if (row == 1) return w.w0123.y;
    if (row == 2) return w.w0123.z;
    if (row == 3) return w.w0123.w;
    return w.w4;
}

// What a slice's bake stores under baked light `row` (eq 4.2's C_i): the blade's albedo times its
// cosine to the light on the side the bake sees, plus gamma times the other side's (eq 4.1's
// transmission term). `n`: the blade's unit normal turned toward the bake's viewer.
CANOPY_FN vec3 btf_baked_row(vec3 albedo, vec3 n, int row, float transmission) {
    float c = dot(n, btf_light_direction(row));
    return albedo * (max(c, 0.0f) + transmission * max(-c, 0.0f));
}

// Eq 4.2 in canopy's one shading model (shading.h's lambert_radiance): the ambient row lit by the
// ambient light, plus the interpolated rows (sum of alpha_i C_i) times the light's irradiance
// normal to it, over pi.
CANOPY_FN vec3 btf_radiance(vec3 albedo, vec3 interpolated_rows, vec3 normal_irradiance, vec3 ambient) {
    return albedo * ambient + interpolated_rows * (normal_irradiance / PI);
}

CANOPY_END_NAMESPACE

#endif
