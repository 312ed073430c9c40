// `canopy metrics`: every registered error metric (metrics/metric_registry.hpp) with its names,
// unit, direction, group, compare tolerance and meaning, as a Markdown table.
#pragma once

#include <string>

namespace canopy {

std::string metric_list();

}  // namespace canopy
