// For fragment shaders that draw populations through population.vert: call
// population_alpha_test() first in main() to discard what the population's alpha mask cuts away
// (harness/shaders/alpha_mask.h; opaque populations pass everything). Not for scene.vert's draws,
// which do not write these inputs.
#include "alpha_mask.h"

layout(location = 2) in vec3 population_local_position;
layout(location = 3) flat in vec4 population_alpha_mask;

void population_alpha_test() {
    if (!alpha_mask_opaque(population_alpha_mask, population_local_position)) discard;
}
