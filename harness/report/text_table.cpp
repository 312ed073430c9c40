#include "report/text_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace canopy {

namespace {

// Display width: UTF-8 continuation bytes take no column ("±", "²").
size_t columns(const std::string& text) {
    return size_t(std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

std::string padded(const std::string& text, size_t width, bool right) {
    const size_t fill = width - std::min(width, columns(text));
    std::string out;
    out.reserve(text.size() + fill);
    if (right) out.append(fill, ' ');
    out += text;
    if (!right) out.append(fill, ' ');
    return out;
}

}  // namespace

std::string render_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                         const std::vector<bool>& right_aligned) {
    std::vector<size_t> width(header.size());
    for (size_t c = 0; c < header.size(); ++c) {
        width[c] = std::max<size_t>(columns(header[c]), 3);
        for (const auto& row : rows) width[c] = std::max(width[c], columns(row[c]));
    }
    auto line = [&](const std::vector<std::string>& cells) {
        std::string out = "|";
        for (size_t c = 0; c < cells.size(); ++c) {
            out += ' ';
            out += padded(cells[c], width[c], right_aligned[c]);
            out += " |";
        }
        return out + "\n";
    };
    std::string out = line(header) + "|";
    for (size_t c = 0; c < header.size(); ++c)
        out += right_aligned[c] ? std::string(width[c] + 1, '-') + ":|" : std::string(width[c] + 2, '-') + "|";
    out += "\n";
    for (const auto& row : rows) out += line(row);
    return out;
}

std::string metric_cell(double value) {
    if (std::isnan(value)) return "-";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    return fmt::format("{:.4g}", value);
}

std::string metric_cell(double value, bool meaningful) { return meaningful ? metric_cell(value) : "n/a"; }

std::string table_cell(const MetricInfo& metric, const ImageMetrics& m) {
    const double value = m.*metric.value;
    return metric_cell(metric.percent ? 100.0 * value : value, group_declared(metric.group, m.columns));
}

std::string ratio_number(double ratio) {
    return std::abs(ratio) >= 0.1 || ratio == 0.0 || !std::isfinite(ratio) ? fmt::format("{:.2f}", ratio)
                                                                         : fmt::format("{:.2g}", ratio);
}

std::vector<const MetricInfo*> shown_metrics(const RunRecord& run, MetricShown where) {
    std::vector<const MetricInfo*> shown;
    for (const MetricInfo& metric : registered_metrics()) {
        if (!metric.shown_in(where)) continue;
        const bool declared = std::any_of(run.cases.begin(), run.cases.end(), [&](const CaseResult& c) {
            return c.image_error && group_declared(metric.group, c.image_error->columns) &&
                   (!metric.only_when_measured || std::isfinite((*c.image_error).*metric.value));
        });
        if (declared) shown.push_back(&metric);
    }
    return shown;
}

std::string ratio_cell(const Estimate& ratio) {
    if (ratio.count == 0 || std::isnan(ratio.value)) return "-";
    return fmt::format("{} [{}, {}]", ratio_number(ratio.value), ratio_number(ratio.ci.low), ratio_number(ratio.ci.high));
}

}  // namespace canopy
