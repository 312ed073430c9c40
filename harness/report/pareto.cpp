#include "report/pareto.hpp"

#include "core/registry.hpp"
#include "metrics/metric_registry.hpp"
#include "run/case_ratio.hpp"
#include "run/run_comparison.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace canopy {

namespace {

const MetricInfo& metric_info(const std::string& metric) {
    const MetricInfo* info = find_metric(metric);
    if (!info) throw std::invalid_argument(fmt::format("unknown error metric '{}' (`canopy metrics` lists them)", metric));
    return *info;
}

// The error of `a` minus the error of `b`, signed so that positive is worse.
double worse_by(const MetricInfo& info, double a, double b) { return info.better == Better::lower ? a - b : b - a; }

}  // namespace

bool dominates(const ParetoPoint& b, const ParetoPoint& a, const std::string& metric) {
    const MetricInfo& info = metric_info(metric);
    if (!std::isfinite(a.error) || !std::isfinite(b.error) || a.result == b.result) return false;
    // As canopy compare: fewer rounds than this (--quick measures 3) give no interval to judge by.
    if (std::min(a.result->ratio.per_round.size(), b.result->ratio.per_round.size()) < kMinComparedRounds) return false;
    const double b_worse_by = worse_by(info, b.error, a.error);
    const double tolerance = info.tolerance.absolute + info.tolerance.relative * std::abs(a.error);
    if (b_worse_by > tolerance) return false;  // B's error is significantly worse
    const Estimate ratio = time_ratio(*b.result, *a.result).estimate;  // time(B) / time(A)
    if (!std::isfinite(ratio.ci.low) || !std::isfinite(ratio.ci.high)) return false;
    if (ratio.ci.low > 1.0) return false;  // B is significantly slower
    const bool significantly_faster = ratio.ci.high < 1.0;
    const bool significantly_better_error = -b_worse_by > tolerance;
    return significantly_faster || significantly_better_error;
}

std::vector<ParetoFront> pareto_fronts(const RunRecord& run, const std::string& metric) {
    const MetricInfo& info = metric_info(metric);
    std::vector<ParetoFront> fronts;
    for (size_t g = 0; g < run.groups.size(); ++g) {
        ParetoFront front{run.groups[g].name, metric, {}, {}, false};
        for (const CaseResult& c : run.cases) {
            if (c.group != g || !c.ok) continue;
            const double error = c.image_error ? info.meaningful_value(*c.image_error) : std::nan("");
            Estimate ratio;
            if (c.group_baseline)
                ratio = Estimate{1.0, {1.0, 1.0}, c.gpu_frame.samples_ms.size()};
            else if (c.ratio.measured())
                ratio = c.ratio.estimate;
            else
                ratio.value = std::nan("");
            if (!std::isfinite(error) || !std::isfinite(ratio.value)) {
                front.unmeasured.push_back(c.id);
                continue;
            }
            front.points.push_back(ParetoPoint{&c, ratio, error, false, ""});
        }
        front.judged = std::count_if(front.points.begin(), front.points.end(), [](const ParetoPoint& p) {
                           return p.result->ratio.per_round.size() >= kMinComparedRounds;
                       }) >= 2;
        for (ParetoPoint& a : front.points)
            for (const ParetoPoint& b : front.points)
                if (dominates(b, a, metric)) {
                    a.dominated = true;
                    a.dominated_by = b.result->id;
                    break;
                }
        fronts.push_back(std::move(front));
    }
    return fronts;
}

std::string too_few_rounds_note(const RunRecord& run) {
    if (run.rounds >= int(kMinComparedRounds)) return "";
    return fmt::format("{}{} rounds, fewer than the {} a paired time interval needs (as canopy compare). A configuration "
                       "is dominated only by one shown not significantly slower, which takes that interval, so none "
                       "is judged dominated: every one is marked as on the front.",
                       run.quick ? "--quick: " : "This run measured ", run.rounds, kMinComparedRounds);
}

std::vector<std::string> default_pareto_metrics(const RunRecord& run) {
    std::vector<std::string> metrics;
    for (const CaseResult& c : run.cases) {
        const Technique* technique = TechniqueRegistry::instance().find(c.technique);
        if (!technique) continue;
        for (const std::string& m : technique->pareto_errors())
            if (std::find(metrics.begin(), metrics.end(), m) == metrics.end()) metrics.push_back(m);
    }
    return metrics;
}

}  // namespace canopy
