// Lemme's walk of a ray through the vertical slices of a volume-based patch (§5.2, eq 5.7-5.21),
// in GLSL and C++, so the unit tests step the very code grass.volume's fragment shader runs.
// The volume is its cuboid in unit coordinates q in [0, 1]^3 (q.y: height over the patch's top);
// it holds n slices per direction, slice k of either direction in the plane q = (k + 0.5) / n
// (eq 5.9's grid), and a ray is the segment from its entry e to its exit, e + lambda d with
// lambda in [0, 1].
// canopy's repairs, both listed in REPRODUCE.md: eq 5.16 divides by d's x or z component, zero
// for a ray parallel to the slices of that direction: such an axis is never hit (its planes lie
// beyond the segment); and eq 5.21 moves the next plane by the ray's sign, not by the plane's
// normal (which points the same way for rays going either way).
#ifndef CANOPY_GRASS_VOLUME_WALK_H
#define CANOPY_GRASS_VOLUME_WALK_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

// Farther than any lambda of the segment: where an axis is never hit.
CANOPY_CONST float VOLUME_NEVER = 1e30f;
// Below this, a segment moves less than a millionth of the volume along an axis: it runs along
// that axis's slices (and at most grazes one edge-on), so eq 5.16 is not evaluated.
CANOPY_CONST float VOLUME_PARALLEL = 1e-6f;

// The cuboid in patch space: q = (p - origin) / extent.
struct VolumeBox {
    vec4 origin;  // xyz
    vec4 extent;  // xyz, each above 0
};

struct VolumeWalk {
    vec2 first;    // eq 5.12: the first plane ahead of the entry in x and in z
    vec2 step;     // eq 5.21: +-1/n by the sign of d per axis, 0 for a parallel axis
    vec2 inverse;  // 1 / d in x and z (eq 5.16); 0 for a parallel axis
};

struct VolumeHit {
    float lambda;  // along the segment; above 1: the segment leaves the volume first
    int axis;      // 0: a plane x = const (a slice baked along x), 1: a plane z = const
    int slice;     // k of that plane, 0 .. n - 1 inside the volume
};

// Where the segment from `eye` (q space) along `d` first enters the unit cube, as a fraction
// of d: 0 when the eye is inside. The segment is known to reach the cube (it ends on a face).
CANOPY_FN float volume_entry(vec3 eye, vec3 d) {
    float t = 0.0f;
    for (int a = 0; a < 3; ++a) {
        if (abs(d[a]) < VOLUME_PARALLEL) continue;  // within the slab all along: no bound
        float near_face = ((d[a] > 0.0f ? 0.0f : 1.0f) - eye[a]) / d[a];
        t = max(t, near_face);
    }
    return min(t, 1.0f);
}

// eq 5.8-5.12 on one axis: the first plane ahead of entry coordinate e for a ray of direction
// component d: the lower corner of e's cell (eq 5.9), and for a positive d the plane above it.
CANOPY_FN float volume_first_plane(float e, float d, float n) {
    float half_gap = 0.5f / n;                                  // eq 5.8
    float lower = floor((e - half_gap) * n) / n + half_gap;     // eq 5.9
    float sign_d = d > 0.0f ? 1.0f : (d < 0.0f ? -1.0f : 0.0f);  // eq 5.10
    return lower + (sign_d + abs(sign_d)) * half_gap;           // eq 5.11-5.12
}

// `n`: the planes per unit of q in x and in z (a macro-cell of k x l cells, grass_macro_cells.h,
// holds n k along x and n l along z); the float overloads are the one-cell volume's n and n.
CANOPY_FN VolumeWalk volume_walk(vec3 e, vec3 d, vec2 n) {
    VolumeWalk w;
    w.first = vec2(volume_first_plane(e.x, d.x, n.x), volume_first_plane(e.z, d.z, n.y));
    vec2 moves = vec2(abs(d.x) >= VOLUME_PARALLEL ? 1.0f : 0.0f, abs(d.z) >= VOLUME_PARALLEL ? 1.0f : 0.0f);
    w.step = vec2(d.x > 0.0f ? 1.0f : -1.0f, d.z > 0.0f ? 1.0f : -1.0f) * moves / n;
    w.inverse = vec2(moves.x > 0.0f ? 1.0f / d.x : 0.0f, moves.y > 0.0f ? 1.0f / d.z : 0.0f);
    return w;
}

CANOPY_FN VolumeWalk volume_walk(vec3 e, vec3 d, float n) { return volume_walk(e, d, vec2(n, n)); }

// The next plane the segment meets after crossing `crossed` planes of each axis (eq 5.15-5.17,
// the planes moved on by eq 5.21 once per crossing).
CANOPY_FN VolumeHit volume_next_hit(VolumeWalk w, vec3 e, ivec2 crossed, vec2 n) {
    vec2 plane = w.first + vec2(crossed) * w.step;
    float to_x = w.inverse.x != 0.0f ? (plane.x - e.x) * w.inverse.x : VOLUME_NEVER;  // eq 5.15-5.16
    float to_z = w.inverse.y != 0.0f ? (plane.y - e.z) * w.inverse.y : VOLUME_NEVER;
    VolumeHit hit;
    hit.axis = to_x <= to_z ? 0 : 1;  // eq 5.17
    hit.lambda = min(to_x, to_z);
    hit.slice = int(floor(hit.axis == 0 ? plane.x * n.x : plane.y * n.y));  // (k + 0.5) / n -> k
    return hit;
}

CANOPY_FN VolumeHit volume_next_hit(VolumeWalk w, vec3 e, ivec2 crossed, float n) {
    return volume_next_hit(w, e, crossed, vec2(n, n));
}

// The footprint of a pixel on a slice plane, for a filtered lookup (textureGrad: the walk's loop
// is not uniform control flow, so implicit derivatives are undefined there, and a cuboid's faces
// would make them jump): a pixel `pixel` world units across at the hit (its view depth over the
// focal length) seen along unit `ray` on a plane across `axis` (0: x = const, 1: z = const) spans
// pixel / cos(theta) along the ray's tilt in the plane and `pixel` across it. Returned as the two
// gradients of the lookup (u, v) (xy and zw), u running along z (axis 0) or x (axis 1) and v down
// the height, `texel_world` world units for u and for v to go from 0 to 1. A ray almost in the
// plane gives the coarsest level.
CANOPY_FN vec4 volume_slice_footprint(vec3 ray, int axis, float pixel, vec2 texel_world) {
    vec3 normal = axis == 0 ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 0.0f, 1.0f);
    float cos_theta = max(abs(dot(ray, normal)), 1e-3f);
    vec3 tilt = ray - dot(ray, normal) * normal;  // the ray's direction within the plane
    float tilt_length = length(tilt);
    tilt = tilt_length > 1e-6f ? tilt / tilt_length : vec3(0.0f, 1.0f, 0.0f);
    vec3 across = cross(normal, tilt);
    vec3 g1 = tilt * (pixel / cos_theta);
    vec3 g2 = across * pixel;
    float u1 = axis == 0 ? g1.z : g1.x;
    float u2 = axis == 0 ? g2.z : g2.x;
    return vec4(u1 / texel_world.x, -g1.y / texel_world.y, u2 / texel_world.x, -g2.y / texel_world.y);
}

CANOPY_END_NAMESPACE

#endif
