#include "core/plan_requirements.hpp"

#include <fmt/format.h>

namespace canopy {

std::vector<std::string> plan_requirements(const FramePlan& plan) {
    std::vector<std::string> needs;
    if (plan.needs_area_light) needs.emplace_back("an area light (rect or sphere)");
    else if (plan.shadow_map || plan.moment_map) needs.emplace_back("a shadow-casting light (any type)");
    if (plan.shadow_map && plan.shadow_map->compare_sampler)
        needs.push_back(fmt::format("depth-compare sampling of {} on the device", to_string(plan.shadow_map->format)));
    const bool compute = (plan.moment_map && !plan.moment_map->prefilter.empty()) ||
                         (plan.shadow_map && !plan.shadow_map->coarse_filters.empty()) ||
                         (plan.screen_shadow && !plan.screen_shadow->filters.empty());
    if (compute) needs.emplace_back("compute filter passes (shaderStorageImageWriteWithoutFormat)");
    return needs;
}

}  // namespace canopy
