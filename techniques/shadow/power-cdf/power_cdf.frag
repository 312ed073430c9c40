#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.power-cdf: the depth CDF reconstructed as t^beta from the filtered minimum, maximum
// and mean (Gumbau eq 7.5-7.7). The lookup blends the four texels' means bilinearly and takes
// the min and max over the same texels (power_cdf_bilinear_statistics): a LINEAR lookup would
// blend the mins and maxes too, which are then no longer a min and a max. The receiver depth is
// reduced by the storage format's rounding error (frame.technique.depth_roundoff: relative, 2 ulp), so a
// planar receiver whose stored min, max and mean were rounded below its exact depth stays lit,
// as eq 7.1 requires.
#include "power_cdf_params.h"
#include "forward_lighting.glsl"
#include "shadow_filtering.h"
#include "bilinear_texels.glsl"

float shadow_visibility(ShadowQuery q) {
    BilinearTexels b = bilinear_texels(moment_map, q.uv);
    vec3 s = power_cdf_bilinear_statistics(b.t00.rgb, b.t10.rgb, b.t01.rgb, b.t11.rgb, b.f);  // (z_min, z_max, mean)
    float receiver = q.receiver_depth * (1.0 - frame.technique.depth_roundoff);
    return power_cdf_visibility(s.x, s.y, s.z, receiver);
}
