#include "report/console_table.hpp"

#include "metrics/metric_registry.hpp"
#include "report/text_table.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace canopy {

namespace {

// Cuts at a character boundary and marks the cut.
std::string shortened(const std::string& text, size_t width) {
    if (text.size() <= width) return text;
    size_t cut = width - 1;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    return text.substr(0, cut) + "…";
}

}  // namespace

std::string console_table(const RunRecord& run) {
    const bool failures = std::any_of(run.cases.begin(), run.cases.end(), [](const CaseResult& c) { return !c.ok; });
    std::vector<std::string> header = {"technique", "parameters", "GPU ms", "ratio [95% CI]"};
    std::vector<bool> right = {false, false, true, true};
    const std::vector<const MetricInfo*> metrics = shown_metrics(run, shown_in_console);
    for (const MetricInfo* metric : metrics) {
        header.emplace_back(metric->column);
        right.push_back(true);
    }
    if (failures) {
        header.push_back("status");
        right.push_back(false);
    }

    std::string out;
    std::vector<std::vector<std::string>> rows;
    std::string group;
    auto flush = [&] {
        if (!rows.empty()) out += (out.empty() ? "" : "\n") + group + "\n" + render_table(header, rows, right);
        rows.clear();
    };
    for (const CaseResult& c : run.cases) {
        const std::string this_group = fmt::format("{} {}x{}", c.scene, c.resolution.width, c.resolution.height);
        if (this_group != group) {
            flush();
            group = this_group;
        }
        const bool timed = c.gpu_frame.stats.count > 0;
        std::vector<std::string> row = {
            c.technique, shortened(c.params_shown, kConsoleParametersWidth),
            timed ? fmt::format("{:.3f}", c.gpu_frame.stats.median) : "-",
            c.ok ? ratio_cell(c.ratio.estimate) : "-"};
        for (const MetricInfo* metric : metrics) row.push_back(c.image_error ? table_cell(*metric, *c.image_error) : "-");
        if (failures) row.push_back(c.ok ? "ok" : "FAILED");
        rows.push_back(std::move(row));
    }
    flush();
    return out;
}

}  // namespace canopy
