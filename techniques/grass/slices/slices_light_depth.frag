#version 450
#extension GL_GOOGLE_include_directive : require
// grass.slices with bake_shadows, load phase: the patch seen from one baked light direction
// (bake_shadows.h); the depth of its alpha-tested blades, every blade casting.
#include "blade_alpha.h"

layout(location = 2) in vec2 strip_uv;
layout(location = 4) flat in float taper;

void main() {
    if (!blade_opaque(strip_uv, taper)) discard;
}
