#include "report/metric_list.hpp"

#include "metrics/metric_registry.hpp"
#include "report/text_table.hpp"

#include <fmt/format.h>

namespace canopy {

namespace {

std::string shown_where(const MetricInfo& metric) {
    std::string out = "json, csv";
    for (const auto& [flag, name] : {std::pair{shown_in_markdown, "results.md"}, std::pair{shown_in_console, "console"},
                                     std::pair{shown_in_paper_tables, "paper.md"}})
        if (metric.shown_in(flag)) out += fmt::format(", {}", name);
    return out;
}

}  // namespace

std::string metric_list() {
    std::vector<std::vector<std::string>> rows;
    for (const MetricInfo& m : registered_metrics())
        rows.push_back({std::string(m.name), std::string(m.claim), std::string(m.column), m.unit.empty() ? "-" : std::string(m.unit),
                        to_string(m.better), std::string(group_info(m.group).key.empty() ? "whole_image" : group_info(m.group).key),
                        fmt::format("{:g} + {:g} x abs(baseline)", m.tolerance.absolute, m.tolerance.relative),
                        shown_where(m), std::string(m.doc)});
    std::string out = render_table({"results.json / csv", "[paper] claim", "column", "unit", "better", "group",
                                    "compare tolerance", "shown in", "meaning"},
                                   rows, {false, false, false, false, false, false, false, false, false});
    out += "\nPixel counts (results.json): ";
    std::string counts;
    for (const MetricCountInfo& c : registered_metric_counts()) counts += fmt::format("{}{} ({})", counts.empty() ? "" : "; ", c.name, c.doc);
    out += counts + ".\n";
    out += "Groups: a technique's family declares which of shadow_regions, visibility and coverage mean something for it "
           "(core/error_columns.hpp); reports print n/a for the others. A [paper] claim may also compare `time` "
           "(the GPU median; lower is better) and use relation = \"better\" for the metric's better direction.\n";
    return out;
}

}  // namespace canopy
