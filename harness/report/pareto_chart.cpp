#include "report/pareto_chart.hpp"

#include "report/markdown_html.hpp"
#include "report/text_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace canopy {

namespace {

constexpr double kWidth = 560, kHeight = 340;
constexpr double kLeft = 70, kRight = 20, kTop = 16, kBottom = 46;

struct Range {
    double low, high;
    bool log = false;  // log_axis: positions by log10
    double at(double v) const { return log ? std::log10(v) : v; }
    double map(double v, double from, double to) const {
        return from + (at(v) - at(low)) / (at(high) - at(low)) * (to - from);
    }
};

// Round tick values covering [low, high]: about five evenly spaced; on a log axis 1, 2 and 5 times
// each power of ten, or only the powers where those would be more than eight.
std::vector<double> ticks(const Range& r) {
    if (r.log) {
        std::vector<double> values;
        for (const bool powers_only : {false, true}) {
            values.clear();
            for (int e = int(std::floor(std::log10(r.low))); e <= int(std::ceil(std::log10(r.high))); ++e)
                for (double m : {1.0, 2.0, 5.0}) {
                    const double v = m * std::pow(10.0, e);
                    if ((m == 1.0 || !powers_only) && v >= r.low * (1 - 1e-9) && v <= r.high * (1 + 1e-9)) values.push_back(v);
                }
            if (values.size() <= 8) break;
        }
        return values;
    }
    const double span = r.high - r.low;
    const double raw = span / 5.0;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (raw <= m * magnitude) {
            step = m * magnitude;
            break;
        }
    std::vector<double> values;
    for (double v = std::ceil(r.low / step) * step; v <= r.high + 1e-9 * span; v += step) values.push_back(v);
    return values;
}

Range padded(double low, double high) {
    if (log_axis(low, high)) {
        const double pad = std::pow(high / low, 0.06);
        return {low / pad, high * pad, true};
    }
    if (!(high > low)) {
        const double pad = low == 0 ? 1.0 : std::abs(low) * 0.1;
        return {low - pad, high + pad};
    }
    const double pad = 0.06 * (high - low);
    return {low - pad, high + pad};
}

struct Box {
    double left, top, right, bottom;
    bool overlaps(const Box& o) const { return left < o.right && o.left < right && top < o.bottom && o.top < bottom; }
};

// The label of point `index` (its number, index + 1: its row in the table beside the chart) at the
// first place around the point (right, below right, left, ...) that stays inside the plot and
// covers neither another point nor a number already placed; the first place where none does.
// `taken` holds every point's box, at their indices, then the numbers placed.
std::string number_label(size_t index, double cx, double cy, std::vector<Box>& taken) {
    const std::string text = std::to_string(index + 1);
    const double width = 6.0 * double(text.size()), height = 9.0;
    struct Place {
        double dx, dy;  // of the text's baseline start from the point
    };
    const Place places[] = {{6, -4}, {6, 11}, {-6 - width, -4}, {-6 - width, 11}, {-width / 2, -7}, {-width / 2, 16}};
    const Box plot{kLeft, kTop, kWidth - kRight, kHeight - kBottom};
    Box chosen{};
    bool found = false;
    for (const Place& place : places) {
        const Box box{cx + place.dx, cy + place.dy - height, cx + place.dx + width, cy + place.dy};
        const bool inside = box.left >= plot.left && box.right <= plot.right && box.top >= plot.top && box.bottom <= plot.bottom;
        bool clear = true;
        for (size_t j = 0; j < taken.size(); ++j) clear = clear && (j == index || !taken[j].overlaps(box));
        if (inside && clear) {
            chosen = box;
            found = true;
            break;
        }
    }
    if (!found) chosen = Box{cx + places[0].dx, cy + places[0].dy - height, cx + places[0].dx + width, cy + places[0].dy};
    taken.push_back(chosen);
    return fmt::format("<text class=\"point-label\" x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\">{}</text>\n", chosen.left,
                       chosen.bottom, text);
}

}  // namespace

bool log_axis(double low, double high) { return low > 0 && std::isfinite(high) && high / low >= kLogAxisSpan; }

std::string pareto_svg(const ParetoFront& front, const MetricInfo& metric,
                       const std::function<std::string(const CaseResult&)>& label) {
    if (front.points.empty()) return "";
    const double scale = metric.percent ? 100.0 : 1.0;
    double x_low = INFINITY, x_high = -INFINITY, y_low = INFINITY, y_high = -INFINITY;
    for (const ParetoPoint& p : front.points) {
        x_low = std::min({x_low, p.time_ratio.value, std::isfinite(p.time_ratio.ci.low) ? p.time_ratio.ci.low : p.time_ratio.value});
        x_high = std::max({x_high, p.time_ratio.value, std::isfinite(p.time_ratio.ci.high) ? p.time_ratio.ci.high : p.time_ratio.value});
        y_low = std::min(y_low, scale * p.error);
        y_high = std::max(y_high, scale * p.error);
    }
    const Range x = padded(x_low, x_high), y = padded(y_low, y_high);
    const auto px = [&](double v) { return x.map(v, kLeft, kWidth - kRight); };
    const auto py = [&](double v) { return y.map(v, kHeight - kBottom, kTop); };

    std::string svg = fmt::format(
        "<svg class=\"pareto\" viewBox=\"0 0 {} {}\" width=\"{}\" height=\"{}\" "
        "role=\"img\" aria-label=\"Pareto front: {} against time ratio\">\n",
        kWidth, kHeight, kWidth, kHeight, html_escape(metric.column));
    svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#999\"/>\n", kLeft, kTop,
                       kWidth - kLeft - kRight, kHeight - kTop - kBottom);
    for (double t : ticks(x))
        svg += fmt::format("<line x1=\"{0}\" x2=\"{0}\" y1=\"{1}\" y2=\"{2}\" stroke=\"#eee\"/><text x=\"{0}\" y=\"{3}\" "
                           "font-size=\"11\" text-anchor=\"middle\">{4}</text>\n",
                           px(t), kTop, kHeight - kBottom, kHeight - kBottom + 14, ratio_number(t));
    for (double t : ticks(y))
        svg += fmt::format("<line x1=\"{0}\" x2=\"{1}\" y1=\"{2}\" y2=\"{2}\" stroke=\"#eee\"/><text x=\"{3}\" y=\"{4}\" "
                           "font-size=\"11\" text-anchor=\"end\">{5}</text>\n",
                           kLeft, kWidth - kRight, py(t), kLeft - 4, py(t) + 4, metric_cell(t));
    svg += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"12\" text-anchor=\"middle\">GPU time / group baseline "
                       "(median, 95 % interval{})</text>\n",
                       (kLeft + kWidth - kRight) / 2, kHeight - 10, x.log ? "; log scale" : "");
    svg += fmt::format("<text transform=\"translate(14 {}) rotate(-90)\" font-size=\"12\" text-anchor=\"middle\">{} "
                       "({} is better{})</text>\n",
                       (kTop + kHeight - kBottom) / 2, html_escape(metric.column), to_string(metric.better),
                       y.log ? "; log scale" : "");

    // The front line: a staircase, by time, through the undominated points whose error beats every
    // faster one's (an undominated point within noise of a better one is left off it), so it never
    // turns back. None when dominance was not judged (too few rounds: no front to draw).
    std::vector<const ParetoPoint*> undominated, steps;
    for (const ParetoPoint& p : front.points)
        if (!p.dominated) undominated.push_back(&p);
    std::stable_sort(undominated.begin(), undominated.end(),
                     [](const ParetoPoint* a, const ParetoPoint* b) { return a->time_ratio.value < b->time_ratio.value; });
    for (const ParetoPoint* p : undominated)
        if (steps.empty() || (metric.better == Better::lower ? p->error < steps.back()->error : p->error > steps.back()->error))
            steps.push_back(p);
    if (front.judged && steps.size() > 1) {
        std::string points = fmt::format("{:.1f},{:.1f}", px(steps[0]->time_ratio.value), py(scale * steps[0]->error));
        for (size_t i = 1; i < steps.size(); ++i)
            points += fmt::format(" {0:.1f},{1:.1f} {0:.1f},{2:.1f}", px(steps[i]->time_ratio.value),
                                  py(scale * steps[i - 1]->error), py(scale * steps[i]->error));
        svg += fmt::format("<polyline class=\"front\" points=\"{}\" fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"1.5\"/>\n",
                           points);
    }
    std::vector<Box> taken;  // what a number must not cover: the points, then the numbers placed
    for (const ParetoPoint& p : front.points) {
        const double cx = px(p.time_ratio.value), cy = py(scale * p.error);
        taken.push_back({cx - 4.5, cy - 4.5, cx + 4.5, cy + 4.5});
    }
    for (size_t i = 0; i < front.points.size(); ++i) {
        const ParetoPoint& p = front.points[i];
        const double cx = px(p.time_ratio.value), cy = py(scale * p.error);
        const std::string colour = p.dominated ? "#888" : "#1f77b4";
        if (std::isfinite(p.time_ratio.ci.low) && std::isfinite(p.time_ratio.ci.high))
            svg += fmt::format("<line x1=\"{:.1f}\" x2=\"{:.1f}\" y1=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\"/>\n",
                               px(p.time_ratio.ci.low), px(p.time_ratio.ci.high), cy, cy, colour);
        svg += fmt::format(
            "<circle class=\"{}\" data-case=\"{}\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4.5\" fill=\"{}\" stroke=\"{}\"><title>{}. {}: "
            "time {}, {} {}{}</title></circle>\n",
            p.dominated ? "dominated" : "front", html_escape(p.result->id), cx, cy, p.dominated ? "white" : colour, colour,
            i + 1, html_escape(label(*p.result)), ratio_cell(p.time_ratio), html_escape(metric.column), metric_cell(scale * p.error),
            p.dominated ? " (dominated)" : "");
        svg += number_label(i, cx, cy, taken);
    }
    return svg + "</svg>\n";
}

}  // namespace canopy
