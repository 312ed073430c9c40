// The interface of a screen-shadow camera pass (ScreenShadowNeeds): include this file and
// define `vec4 screen_shadow_data(vec3 world_position, vec3 world_normal)`; the normal buffer
// is written here. Scene geometry comes from scene.vert.
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"

layout(set = 0, binding = 1) uniform sampler2D shadow_depth;  // NEAREST
layout(set = 0, binding = 4) uniform sampler2D coarse_map;    // NEAREST, ShadowMapNeeds::coarse_filters result

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 0) out vec4 out_shadow_data;
layout(location = 1) out vec4 out_normal;

vec4 screen_shadow_data(vec3 position, vec3 normal);

void main() {
    vec3 n = normalize(world_normal);
    if (dot(n, frame.camera_position.xyz - world_position) < 0.0) n = -n;  // as the lit pass
    out_normal = vec4(n, 1.0);
    out_shadow_data = screen_shadow_data(world_position, n);
}
