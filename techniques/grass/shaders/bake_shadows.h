// A shadowed bake's light views (GLSL and C++): grass.slices with bake_shadows renders the patch
// (tiled: with its 8 neighbours) into one depth layer per baked light direction (Y+, X+, Z+, X-,
// Z-, btf_light_direction's order), each an orthographic view looking along -L_i, and each bake
// fragment looks itself up in them: the visibility of light i at a baked texel. Boulanger bakes his
// BTF rows with the shadow mask (§4.2.6, L1034: "the BTF images are generated using the shadow
// mask algorithm"); canopy bakes what the mask approximates, the shadows the patch's blades cast.
#ifndef CANOPY_GRASS_BAKE_SHADOWS_H
#define CANOPY_GRASS_BAKE_SHADOWS_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

CANOPY_CONST int BAKE_SHADOW_LIGHTS = 5;

struct BakeShadows {
    // Patch space -> light i's depth layer: its bake camera with the depth moved towards the light
    // by the bias, so a blade does not shadow itself.
    mat4 lookup[BAKE_SHADOW_LIGHTS];
    // x: how far a looked-up point moves along the blade's normal, to the light's side (patch
    // units): a blade steep to the light spans many depths within one texel of its light view, and
    // a depth bias alone leaves it shadowing itself.
    vec4 offsets;
};

// The point a bake fragment looks up for light `l`: `p` moved `offset` along the unit normal `n`
// turned to the light's side.
CANOPY_FN vec3 bake_shadow_point(vec3 p, vec3 n, vec3 l, float offset) {
    return p + (dot(n, l) >= 0.0f ? n : -n) * offset;
}

// Where patch point `p` falls in a light's depth layer: (u, v) in [0, 1] and the compared depth.
CANOPY_FN vec3 bake_shadow_coord(mat4 lookup, vec3 p) {
    vec4 clip = lookup * vec4(p, 1.0f);
    return vec3(clip.x * 0.5f + 0.5f, clip.y * 0.5f + 0.5f, clip.z);
}

// Boulanger eq 4.7: a baked visibility (all blades casting) thinned by the local density, "1 -
// (1 - valueFromShadowMask) . localDensity": half the blades, about half the shadow.
CANOPY_FN float bake_shadow_at_density(float baked_visibility, float density) {
    return 1.0f - (1.0f - clamp(baked_visibility, 0.0f, 1.0f)) * clamp(density, 0.0f, 1.0f);
}

CANOPY_END_NAMESPACE

#endif
