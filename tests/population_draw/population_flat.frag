#version 450
#extension GL_GOOGLE_include_directive : require
// tests/test_population_draw.cpp's lit pass: the albedo under a fixed, oblique direction (so a
// copy's yaw and normal matrix show in its shading), fully visible, as the lit pass writes it.
#include "draw_constants.glsl"
#include "lit_pass_output.h"

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 0) out vec4 out_color;

void main() {
    const vec3 towards_light = normalize(vec3(0.3, 0.8, 0.5));
    float facing = abs(dot(normalize(world_normal), towards_light));
    out_color = lit_pass_output(draw.albedo.rgb * (0.25 + 0.75 * facing), true, 1.0);
}
