// A Pareto front as an inline SVG chart for `canopy report`: time ratio (x, with its 95 %
// interval as a bar) against the error (y); the front's configurations filled and joined, the
// dominated ones hollow. Every point is numbered in the SVG itself (its index in front.points plus
// one: the row of the table beside the chart), placed clear of the other points and numbers, and
// carries its label as a tooltip and a data-case attribute.
// An axis whose values span a factor of kLogAxisSpan or more is logarithmic (log_axis).
#pragma once

#include "metrics/metric_registry.hpp"
#include "report/pareto.hpp"

#include <functional>
#include <string>

namespace canopy {

// An axis is logarithmic when its values (for time, the intervals' ends too) are all positive and
// the largest is at least kLogAxisSpan times the smallest: a linear axis would squeeze all but
// the largest into its first twentieth (grass's impostors run at 0.02 x the geometry's time).
inline constexpr double kLogAxisSpan = 20.0;
bool log_axis(double low, double high);

std::string pareto_svg(const ParetoFront& front, const MetricInfo& metric,
                       const std::function<std::string(const CaseResult&)>& label);

}  // namespace canopy
