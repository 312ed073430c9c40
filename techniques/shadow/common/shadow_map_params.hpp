// The shadow map that the parameters every shadow-map technique shares ask for
// (shadow_map_param_list.h declares them).
#pragma once

#include "core/param.hpp"
#include "shadow_plan.hpp"

namespace canopy {

// The shadow map these parameters ask for (compare sampler off).
ShadowMapNeeds shadow_map_needs(const ParamSet& params);

}  // namespace canopy
