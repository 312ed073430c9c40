// Shared by the SSSS camera pass and its screen-space blur: the hard shadow test of a world
// point, exactly as shadow.hard does it (slope-scaled bias on the exact receiver plane).
// Needs frame_uniforms.glsl and shadow_common.h. technique_params[0].xy = bias constant, slope.

struct LightLookup {
    vec2 uv;
    float receiver_depth;  // normalised linear light depth
    float view_depth;      // world units along the light's axis
    float bias;
};

LightLookup light_lookup(vec3 world, vec3 n) {
    vec4 light_view_pos = frame.light_view * vec4(world, 1.0);
    LightLookup l;
    l.view_depth = -light_view_pos.z;
    l.uv = shadow_uv(frame.light_proj * light_view_pos);
    l.receiver_depth = normalised_light_depth(l.view_depth, frame.shadow_depth_range.x, frame.shadow_depth_range.z);
    bool perspective = frame.shadow_depth_range.w > 0.5;
    float texel_world = frame.shadow_texel.z * (perspective ? l.view_depth : 1.0);
    vec3 view_ray = perspective ? light_view_pos.xyz / l.view_depth : vec3(0.0, 0.0, -1.0);
    vec2 gradient = depth_gradient_per_texel(mat3(frame.light_view) * n, view_ray, texel_world) * frame.shadow_depth_range.z;
    l.bias = slope_scaled_bias(frame.technique_params[0].x, frame.technique_params[0].y, depth_change_per_texel(gradient));
    return l;
}

float stored_depth_at(sampler2D map, vec2 uv) {
    int resolution = int(frame.shadow_texel.x);
    ivec2 t = clamp(ivec2(floor(uv * float(resolution))), ivec2(0), ivec2(resolution - 1));
    return texelFetch(map, t, 0).r;
}

// 1 lit, 0 in shadow; points off the map or beyond its far plane are lit.
float hard_shadow_test(sampler2D map, LightLookup l) {
    if (!inside_shadow_map(l.uv) || l.receiver_depth > 1.0) return 1.0;
    return depth_test(l.receiver_depth - l.bias, stored_depth_at(map, l.uv));
}

// Direction to the light from `world` (for the facing test).
vec3 to_light_from(vec3 world) {
    return int(frame.light_position.w) == LIGHT_DIRECTIONAL ? -frame.light_axis.xyz
                                                             : normalize(frame.light_position.xyz - world);
}

float area_light_width() {
    int type = int(frame.light_position.w);
    return type == LIGHT_SPHERE ? 2.0 * frame.light_size.z : (type == LIGHT_RECT ? 0.5 * (frame.light_size.y + frame.light_size.z) : 0.0);
}
