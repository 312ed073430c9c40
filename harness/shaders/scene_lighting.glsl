// The scene light's irradiance at a surface point, by canopy's one shading model (shading.h),
// for every family's lit passes (GLSL only; include after frame_uniforms.glsl). Surfaces are
// two-sided: the normal is turned to the side the camera sees, as the reference shades them.
#include "shading.h"

vec3 camera_side_normal(vec3 world_normal, vec3 world_position) {
    vec3 n = normalize(world_normal);
    return dot(n, frame.camera_position.xyz - world_position) < 0.0 ? -n : n;
}

// The frame's light (the scene's shadow light, else its first) at `p` with unit normal `n`.
vec3 scene_light_irradiance(vec3 p, vec3 n) {
    int light_type = int(frame.light_position.w);
    return light_type == LIGHT_DIRECTIONAL
        ? directional_irradiance(n, frame.light_axis.xyz, frame.light_intensity.rgb)
        : point_irradiance(light_type, p, n, frame.light_position.xyz, frame.light_axis.xyz,
                           frame.light_intensity.rgb, frame.light_axis.w);
}
