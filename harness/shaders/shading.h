// canopy's one shading model, shared by every raster technique (GLSL) and the Embree
// reference (C++): Lambertian reflection of the light's irradiance times visibility, plus
// a constant ambient term. Only visibility differs between techniques and the reference.
#ifndef CANOPY_SHADING_H
#define CANOPY_SHADING_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

CANOPY_CONST float PI = 3.14159265358979f;

// Light types as stored in the frame uniforms (match canopy::LightType).
CANOPY_CONST int LIGHT_DIRECTIONAL = 0;
CANOPY_CONST int LIGHT_SPOT = 1;
CANOPY_CONST int LIGHT_RECT = 2;
CANOPY_CONST int LIGHT_SPHERE = 3;

// Outgoing radiance of a diffuse surface: albedo/pi * E * visibility + albedo * ambient.
CANOPY_FN vec3 lambert_radiance(vec3 albedo, vec3 irradiance, float visibility, vec3 ambient) {
    return albedo * (irradiance * (visibility / PI) + ambient);
}

// Spot cone: full intensity inside 90% of the half-angle, smooth to zero at the edge.
CANOPY_FN float spot_falloff(float cos_to_axis, float cos_half_angle) {
    float cos_inner = cos(acos(clamp(cos_half_angle, -1.0f, 1.0f)) * 0.9f);
    return smoothstep(cos_half_angle, cos_inner, cos_to_axis);
}

// Irradiance at `p` with normal `n` from a point-like emitter at `light_pos` with radiant
// intensity `intensity` (W/sr, colour included) along its axis `light_axis`. For a one-sided
// rect light the intensity falls with the cosine to its normal; a sphere emits uniformly.
// Raster techniques treat area lights as their centre here; the reference integrates the area.
CANOPY_FN vec3 point_irradiance(int light_type, vec3 p, vec3 n, vec3 light_pos, vec3 light_axis,
                                vec3 intensity, float cos_half_angle) {
    vec3 to_light = light_pos - p;
    float dist2 = max(dot(to_light, to_light), 1e-12f);
    vec3 l = to_light * inversesqrt(dist2);
    float cos_receiver = max(dot(n, l), 0.0f);
    float emitter = 1.0f;
    if (light_type == LIGHT_SPOT) emitter = spot_falloff(dot(-l, light_axis), cos_half_angle);
    if (light_type == LIGHT_RECT) emitter = max(dot(-l, light_axis), 0.0f);
    return intensity * (emitter * cos_receiver / dist2);
}

// Irradiance from a directional light of irradiance `irradiance` travelling along `direction`.
CANOPY_FN vec3 directional_irradiance(vec3 n, vec3 direction, vec3 irradiance) {
    return irradiance * max(dot(n, -direction), 0.0f);
}

CANOPY_END_NAMESPACE

#endif
