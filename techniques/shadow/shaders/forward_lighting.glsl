// The lit pass shared by every shadow technique. A technique's fragment shader includes this
// file (after its params header) and defines only `float shadow_visibility(ShadowQuery q)`;
// shading is identical for all.
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "scene_lighting.glsl"
#include "lit_pass_output.h"
#include "shadow_common.h"
#include "light_space.glsl"

layout(set = 0, binding = 1) uniform sampler2D shadow_depth;          // NEAREST, no compare
layout(set = 0, binding = 2) uniform sampler2DShadow shadow_compare;  // LINEAR depth compare (hardware 2x2 PCF)
layout(set = 0, binding = 3) uniform sampler2D moment_map;            // LINEAR, prefiltered statistics (MomentMapNeeds)
layout(set = 0, binding = 4) uniform sampler2D coarse_map;            // NEAREST, ShadowMapNeeds::coarse_filters result
layout(set = 0, binding = 5) uniform sampler2D screen_shadow;         // NEAREST, ScreenShadowNeeds result

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 0) out vec4 out_color;

struct ShadowQuery {
    vec2 uv;               // shadow-map coordinates of the receiver
    float receiver_depth;  // normalised linear light depth of the receiver (0 = near, 1 = far)
    vec2 depth_gradient;   // receiver plane's normalised depth change per shadow texel in u and v
    float depth_per_texel; // |depth_gradient.x| + |depth_gradient.y|
    float cos_theta;       // dot(normal, direction to light)
    float view_depth;      // receiver's linear light-space depth in world units
    vec3 position;
    vec3 normal;
};

float shadow_visibility(ShadowQuery q);

// Technique parameters are frame.technique.<name> (the technique's params header); these name
// the rest for readability in technique shaders.
vec2 sample_offset(int i) { vec4 v = frame.sample_offsets[i / 2]; return (i % 2 == 0) ? v.xy : v.zw; }
float shadow_resolution() { return frame.shadow_texel.x; }
float shadow_texel_uv() { return frame.shadow_texel.y; }
void main() {
    vec3 n = camera_side_normal(world_normal, world_position);
    vec3 irradiance = scene_light_irradiance(world_position, n);

    float visibility = 1.0;
    float cos_theta = dot(n, direction_to_light(world_position));
    bool lit = cos_theta > 0.0 && max(irradiance.r, max(irradiance.g, irradiance.b)) > 0.0;
    if (lit) {
        LightSpacePoint p = light_space_point(world_position, n);
        ShadowQuery q;
        q.uv = p.uv;
        q.receiver_depth = p.receiver_depth;
        q.view_depth = p.view_depth;
        q.depth_gradient = p.depth_gradient;
        q.depth_per_texel = p.depth_per_texel;
        q.cos_theta = cos_theta;
        q.position = world_position;
        q.normal = n;
        if (on_shadow_map(p)) visibility = shadow_visibility(q);
    }
    // Alpha: the visibility the technique gave the light (lit_pass_output.h), for the technique-isolated error.
    out_color = lit_pass_output(lambert_radiance(draw.albedo.rgb, irradiance, visibility, frame.ambient.rgb), lit,
                                visibility);
}
