// Parameters every shadow-map technique shares: map resolution, depth format and bias.
// Their values occupy technique_params slots 0 and 1 (bias) in the frame uniforms.
#pragma once

#include "core/technique.hpp"

#include <vector>

namespace canopy {

// resolution, depth_format, bias_constant, bias_slope (see the shadow.hard README).
std::vector<ParamSpec> shadow_map_params();

// The shadow map these parameters ask for (compare sampler off).
ShadowMapNeeds shadow_map_needs(const ParamSet& params);

// Writes bias_constant to values[0] and bias_slope to values[1].
void write_bias_params(const ParamSet& params, ShaderParams& shader);

}  // namespace canopy
