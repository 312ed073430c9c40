#version 450
#extension GL_GOOGLE_include_directive : require
// population_flat.frag for draws through population.vert: the population's alpha mask discards
// first (population_alpha.glsl), then the same flat shading.
#include "draw_constants.glsl"
#include "lit_pass_output.h"
#include "population_alpha.glsl"

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 0) out vec4 out_color;

void main() {
    population_alpha_test();
    const vec3 towards_light = normalize(vec3(0.3, 0.8, 0.5));
    float facing = abs(dot(normalize(world_normal), towards_light));
    out_color = lit_pass_output(draw.albedo.rgb * (0.25 + 0.75 * facing), true, 1.0);
}
