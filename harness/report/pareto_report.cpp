#include "report/pareto_report.hpp"

#include "metrics/metric_registry.hpp"
#include "report/atomic_file.hpp"
#include "report/text_table.hpp"
#include "run/case_labels.hpp"
#include "run/run_comparison.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace canopy {

namespace {

std::string front_table(const ParetoFront& front, const MetricInfo& metric) {
    std::vector<const ParetoPoint*> order;
    for (const ParetoPoint& p : front.points) order.push_back(&p);
    std::stable_sort(order.begin(), order.end(),
                     [](const ParetoPoint* a, const ParetoPoint* b) { return a->time_ratio.value < b->time_ratio.value; });
    std::vector<std::vector<std::string>> rows;
    for (const ParetoPoint* p : order) {
        const CaseResult& c = *p->result;
        std::string by;
        if (p->dominated)
            for (const ParetoPoint& q : front.points)
                if (q.result->id == p->dominated_by)
                    by = case_name(q.result->technique, q.result->params_shown);
        rows.push_back({p->dominated ? "" : "front", c.technique, c.params_shown, ratio_cell(p->time_ratio),
                        metric_cell(metric.percent ? 100.0 * p->error : p->error), by});
    }
    std::string text = render_table({"", "technique", "parameters", "time ratio", std::string(metric.column), "dominated by"},
                                    rows, {false, false, false, true, true, false});
    if (!front.unmeasured.empty())
        text += fmt::format("\nNot on the chart (no time or no {}): {}.\n", metric.column, fmt::join(front.unmeasured, ", "));
    return text;
}

}  // namespace

std::string pareto_report(const RunRecord& run, const std::vector<std::string>& wanted) {
    const std::vector<std::string> metrics = wanted.empty() ? default_pareto_metrics(run) : wanted;
    std::string body;
    for (const std::string& name : metrics) {
        const MetricInfo* metric = find_metric(name);
        if (!metric) continue;
        for (const ParetoFront& front : pareto_fronts(run, name)) {
            if (front.points.empty()) continue;
            body += fmt::format("\n## {} — {} ({}{} is better)\n\n", front.group, metric->title,
                                metric->unit.empty() ? "" : fmt::format("{}, ", metric->unit), to_string(metric->better));
            body += front_table(front, *metric);
        }
    }
    if (body.empty()) return "";
    return fmt::format(
               "# Pareto fronts — {}\n\n"
               "Per scene and resolution: time is the GPU time relative to the group's baseline (median [95 % "
               "interval]), measured in the same rounds. A configuration is dominated when another is neither "
               "significantly worse in error (by more than the metric's compare tolerance) nor significantly slower "
               "(the interval of their paired time ratio lies above 1), and is significantly better in one: faster (the interval lies below 1) or lower in error by more than the "
               "metric's compare tolerance (`canopy metrics`). \"front\" marks the others. Rows by time.{}\n",
               run.experiment, run.rounds < int(kMinComparedRounds) ? "\n\n" + too_few_rounds_note(run) : "") +
           body;
}

void write_pareto_report(const std::filesystem::path& path, const RunRecord& run) {
    const std::string text = pareto_report(run);
    if (!text.empty()) write_text_atomically(path, text);
}

}  // namespace canopy
