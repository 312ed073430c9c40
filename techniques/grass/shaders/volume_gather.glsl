// What a volume's ray gathers, front to back (Lemme eq 5.19-5.20), for grass_volume_fragment.glsl
// and its macro-cell version: the colour and opacity of its filtered hits, and the point whose
// depth the fragment writes, where the gathered opacity passes a_r (the first hit where it never
// does: a filtered texel's faint edge in front of a blade does not move it; Lemme writes the first
// blade's, "used for modifying the depth value"). Needs frame_uniforms.glsl and
// grass_slice_coverage.glsl.
struct VolumeGather {
    vec3 color;
    float alpha;
    vec3 depth_point;
};

VolumeGather volume_gather_start() { return VolumeGather(vec3(0.0), 0.0, vec3(0.0)); }

// Adds a hit of opacity hit_alpha at `world`; true once the ray is opaque enough to stop
// (Lemme's "sufficient opacity").
bool volume_gather_add(inout VolumeGather g, vec3 radiance, float hit_alpha, vec3 world) {
    float after = g.alpha + (1.0 - g.alpha) * hit_alpha;
    if (g.alpha == 0.0 || (g.alpha <= GRASS_ALPHA_REFERENCE && after > GRASS_ALPHA_REFERENCE)) g.depth_point = world;
    g.color += (1.0 - g.alpha) * hit_alpha * radiance;  // eq 5.19
    g.alpha = after;                                    // eq 5.20
    return g.alpha >= 0.999;
}

// The fragment's colour and coverage (grass_slice_coverage), its depth written; a ray that gathered
// nothing, or too little for the alpha test, is discarded.
vec4 volume_gather_output(VolumeGather g) {
    if (!(g.alpha > 0.0)) discard;
    float coverage = grass_slice_coverage(g.alpha);
    vec4 clip = frame.view_proj * vec4(g.depth_point, 1.0);
    gl_FragDepth = clip.z / clip.w;
    return vec4(g.color / g.alpha, coverage);
}
