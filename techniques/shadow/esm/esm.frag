#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.esm: visibility = exp(c (z_occluder - z_receiver)) from the prefiltered exp(c z).
// Linear storage: the LINEAR lookup blends exp(c z) itself, the right filter. Log storage (c z):
// the four texels are blended as exponentials in log space (esm_log_bilinear), since blending
// the logs would be a geometric mean.
#include "esm_params.h"
#include "forward_lighting.glsl"
#include "shadow_filtering.h"
#include "bilinear_texels.glsl"

float shadow_visibility(ShadowQuery q) {
    float c = frame.technique.exponent;
    if (frame.technique.log_space) {
        BilinearTexels b = bilinear_texels(moment_map, q.uv);
        float filtered_log = esm_log_bilinear(vec4(b.t00.r, b.t10.r, b.t01.r, b.t11.r), b.f);
        return esm_visibility_log(filtered_log, q.receiver_depth, c);
    }
    return esm_visibility(texture(moment_map, q.uv).r, q.receiver_depth, c);
}
