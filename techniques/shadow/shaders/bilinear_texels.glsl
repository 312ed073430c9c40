// The four texels a LINEAR, CLAMP_TO_EDGE lookup of `map` at uv would blend, fetched one by one,
// and the fraction between them, for lookups that must combine them in their own space
// (shadow_filtering.h: esm_log_bilinear, power_cdf_bilinear_statistics). Texel order
// (x, y) = (0, 0), (1, 0), (0, 1), (1, 1). The texels are chosen from the same floor() the
// fraction comes from, so texels and weights always agree (a hardware gather chooses with its
// own sub-texel rounding).
struct BilinearTexels {
    vec4 t00, t10, t01, t11;
    vec2 f;
};

BilinearTexels bilinear_texels(sampler2D map, vec2 uv) {
    ivec2 size = textureSize(map, 0);
    vec2 st = uv * vec2(size) - 0.5;
    vec2 base = floor(st);
    ivec2 lo = clamp(ivec2(base), ivec2(0), size - 1);
    ivec2 hi = clamp(ivec2(base) + 1, ivec2(0), size - 1);
    BilinearTexels b;
    b.t00 = texelFetch(map, lo, 0);
    b.t10 = texelFetch(map, ivec2(hi.x, lo.y), 0);
    b.t01 = texelFetch(map, ivec2(lo.x, hi.y), 0);
    b.t11 = texelFetch(map, hi, 0);
    b.f = st - base;
    return b;
}
