// The lit pass shared by every shadow technique. A technique's fragment shader includes this
// file and defines only `float shadow_visibility(ShadowQuery q)`; shading is identical for all.
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "shading.h"
#include "shadow_common.h"

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

// Technique parameters, named for readability in technique shaders.
float technique_param(int i) { return frame.technique_params[i / 4][i % 4]; }
vec2 sample_offset(int i) { vec4 v = frame.sample_offsets[i / 2]; return (i % 2 == 0) ? v.xy : v.zw; }
float shadow_resolution() { return frame.shadow_texel.x; }
float shadow_texel_uv() { return frame.shadow_texel.y; }
// The area light's width for penumbra estimates: mean side of a rect, diameter of a sphere.
float light_width() {
    int type = int(frame.light_position.w);
    return type == LIGHT_SPHERE ? 2.0 * frame.light_size.z : (type == LIGHT_RECT ? 0.5 * (frame.light_size.y + frame.light_size.z) : 0.0);
}

void main() {
    vec3 n = normalize(world_normal);
    // Two-sided surfaces: shade the side the camera sees (the reference does the same).
    if (dot(n, frame.camera_position.xyz - world_position) < 0.0) n = -n;

    int light_type = int(frame.light_position.w);
    vec3 irradiance;
    vec3 to_light;
    if (light_type == LIGHT_DIRECTIONAL) {
        to_light = -frame.light_axis.xyz;
        irradiance = directional_irradiance(n, frame.light_axis.xyz, frame.light_intensity.rgb);
    } else {
        to_light = normalize(frame.light_position.xyz - world_position);
        irradiance = point_irradiance(light_type, world_position, n, frame.light_position.xyz,
                                      frame.light_axis.xyz, frame.light_intensity.rgb, frame.light_axis.w);
    }

    float visibility = 1.0;
    float cos_theta = dot(n, to_light);
    if (cos_theta > 0.0 && max(irradiance.r, max(irradiance.g, irradiance.b)) > 0.0) {
        vec4 light_view_pos = frame.light_view * vec4(world_position, 1.0);
        ShadowQuery q;
        q.view_depth = -light_view_pos.z;
        q.uv = shadow_uv(frame.light_proj * light_view_pos);
        q.receiver_depth = normalised_light_depth(q.view_depth, frame.shadow_depth_range.x, frame.shadow_depth_range.z);
        bool perspective = frame.shadow_depth_range.w > 0.5;
        float texel_world = frame.shadow_texel.z * (perspective ? q.view_depth : 1.0);
        vec3 view_ray = perspective ? light_view_pos.xyz / q.view_depth : vec3(0.0, 0.0, -1.0);
        vec3 view_normal = mat3(frame.light_view) * n;
        q.depth_gradient = depth_gradient_per_texel(view_normal, view_ray, texel_world) * frame.shadow_depth_range.z;
        q.depth_per_texel = depth_change_per_texel(q.depth_gradient);
        q.cos_theta = cos_theta;
        q.position = world_position;
        q.normal = n;
        if (inside_shadow_map(q.uv) && q.receiver_depth <= 1.0) visibility = shadow_visibility(q);
    }
    out_color = vec4(lambert_radiance(draw.albedo.rgb, irradiance, visibility, frame.ambient.rgb), 1.0);
}
