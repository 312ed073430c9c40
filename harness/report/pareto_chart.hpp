// A Pareto front as an inline SVG chart for `canopy report`: time ratio (x, with its 95 %
// interval as a bar) against the error (y); the front's configurations filled and joined, the
// dominated ones hollow. Every point carries its label as a tooltip and a data-case attribute.
#pragma once

#include "metrics/metric_registry.hpp"
#include "report/pareto.hpp"

#include <functional>
#include <string>

namespace canopy {

std::string pareto_svg(const ParetoFront& front, const MetricInfo& metric,
                       const std::function<std::string(const CaseResult&)>& label);

}  // namespace canopy
