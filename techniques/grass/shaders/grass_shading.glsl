// The grass family's lit output (GLSL only), shared by every grass representation: canopy's one
// shading model (harness/shaders/shading.h, scene_lighting.glsl), Lambertian under the scene's
// light plus ambient, two-sided (the side the camera sees, as the reference shades), with no shadowing: the
// "local" reference mode, which isolates the representation's own error. Include after
// frame_uniforms.glsl.
#include "scene_lighting.glsl"

// `transmission`: Boulanger eq 4.1's gamma (FamilyPopulation::transmission, the population's
// DrawConstants albedo.w): the other side's irradiance, gamma times, is added, as the reference does.
vec4 grass_lit_output(vec3 albedo, vec3 world_position, vec3 world_normal, float alpha, float transmission) {
    vec3 n = camera_side_normal(world_normal, world_position);
    vec3 irradiance = scene_light_irradiance(world_position, n);
    if (transmission > 0.0) irradiance += transmission * scene_light_irradiance(world_position, -n);
    // Alpha carries the outline's coverage for alpha-to-coverage (the pipeline's alpha-to-one then
    // stores 1 in the covered samples) and the population coverage the harness compares
    // (common/grass_family.hpp); the harness shows images with A = 1.
    return vec4(lambert_radiance(albedo, irradiance, 1.0, frame.ambient.rgb), alpha);
}
