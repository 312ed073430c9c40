#version 450
#extension GL_GOOGLE_include_directive : require
// (E[z], E[z^2]) for VSM and the Gaussian CDF. The second moment gets the variance of the
// depth over the texel's footprint (Donnelly & Lauritzen 2006, section 4.2): 0.25 * |grad z|^2,
// so a tilted planar receiver does not shadow itself.
#include "moment_output.glsl"

vec4 depth_statistics(float z) {
    float dx = dFdx(z), dy = dFdy(z);
    return vec4(z, z * z + 0.25 * (dx * dx + dy * dy), 0.0, 1.0);
}
