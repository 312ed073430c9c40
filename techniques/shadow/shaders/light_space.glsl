// A receiver as the shadow light sees it, shared by the lit pass and screen-space shadow
// passes: where it falls on the shadow map, its normalised light depth, and the receiver
// plane's depth gradient per texel (for bias). Needs frame_uniforms.glsl, shading.h and
// shadow_common.h.

struct LightSpacePoint {
    vec2 uv;               // shadow-map coordinates
    float receiver_depth;  // normalised linear light depth (0 = near, 1 = far)
    float view_depth;      // linear light-space depth in world units
    vec2 depth_gradient;   // receiver plane's normalised depth change per shadow texel in u and v
    float depth_per_texel; // |depth_gradient.x| + |depth_gradient.y|
};

LightSpacePoint light_space_point(vec3 world, vec3 n) {
    vec4 light_view_pos = frame.light_view * vec4(world, 1.0);
    LightSpacePoint p;
    p.view_depth = -light_view_pos.z;
    p.uv = shadow_uv(frame.light_proj * light_view_pos);
    p.receiver_depth = normalised_light_depth(p.view_depth, frame.shadow_depth_range.x, frame.shadow_depth_range.z);
    bool perspective = frame.shadow_depth_range.w > 0.5;
    float texel_world = frame.shadow_texel.z * (perspective ? p.view_depth : 1.0);
    vec3 view_ray = perspective ? light_view_pos.xyz / p.view_depth : vec3(0.0, 0.0, -1.0);
    p.depth_gradient = depth_gradient_per_texel(mat3(frame.light_view) * n, view_ray, texel_world) * frame.shadow_depth_range.z;
    p.depth_per_texel = depth_change_per_texel(p.depth_gradient);
    return p;
}

// True when the point is covered by the shadow map (others are lit).
bool on_shadow_map(LightSpacePoint p) { return inside_shadow_map(p.uv) && p.receiver_depth <= 1.0; }

// Unit direction from `world` towards the light (against the direction of travel for
// directional lights).
vec3 direction_to_light(vec3 world) {
    return int(frame.light_position.w) == LIGHT_DIRECTIONAL ? -frame.light_axis.xyz
                                                             : normalize(frame.light_position.xyz - world);
}

// The area light's width for penumbra estimates: mean side of a rect, diameter of a sphere.
float light_width() {
    int type = int(frame.light_position.w);
    return type == LIGHT_SPHERE ? 2.0 * frame.light_size.z
         : type == LIGHT_RECT   ? 0.5 * (frame.light_size.y + frame.light_size.z)
                                : 0.0;
}
