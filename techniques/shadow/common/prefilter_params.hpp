// The moment map that the parameters every prefiltered (moment-map) shadow technique shares ask
// for (prefilter_param_list.h declares them: map resolution, channel precision, prefilter width).
#pragma once

#include "core/param.hpp"
#include "shadow_plan.hpp"

namespace canopy {

bool half_precision(const ParamSet& params);  // precision == fp16

// The moment map for `channels` (1, 2 or 4) statistics at the chosen precision, prefiltered by
// a horizontal then a vertical pass of `filter_shader` (box by default) of width `filter`
// (even widths round up to the next odd one; width 1 means no prefilter passes at all).
MomentMapNeeds moment_map_needs(const ParamSet& params, int channels, std::span<const uint32_t> fragment_spirv,
                                std::array<float, 4> clear_value, std::span<const uint32_t> filter_shader = {});

}  // namespace canopy
