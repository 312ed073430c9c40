// The samplers passes read their inputs with (one file per concept: gpu/pipeline.hpp makes pipelines).
#pragma once

#include "gpu/context.hpp"

namespace canopy {

// Clamp-to-edge samplers: NEAREST or LINEAR, optionally depth-compare (LESS_OR_EQUAL: a
// reference at or in front of the stored depth is lit).
VkSampler create_sampler(VkDevice device, VkFilter filter, bool compare = false);

}  // namespace canopy
