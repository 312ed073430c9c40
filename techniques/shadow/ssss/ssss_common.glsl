// Shared by the SSSS camera pass and its screen-space blur: the hard shadow test of a world
// point exactly as shadow.hard does it (slope-scaled bias on the exact receiver plane).
// Needs ssss_params.h, frame_uniforms.glsl, shading.h, shadow_common.h and light_space.glsl.

float receiver_bias(LightSpacePoint p) {
    return slope_scaled_bias(frame.technique.bias_constant, frame.technique.bias_slope, p.depth_per_texel);
}

// The texel of `map` (the shadow map or the smaller coarse map) under uv.
float stored_depth_at(sampler2D map, vec2 uv) {
    return texelFetch(map, nearest_texel(uv, textureSize(map, 0)), 0).r;
}

// 1 lit, 0 in shadow; points off the map or beyond its far plane are lit.
float hard_shadow_test(sampler2D map, LightSpacePoint p) {
    if (!on_shadow_map(p)) return 1.0;
    return depth_test(p.receiver_depth - receiver_bias(p), stored_depth_at(map, p.uv));
}
