#include "report/result_columns.hpp"

#include "metrics/reference_degeneracy.hpp"

#include "report/pareto.hpp"

#include "metrics/metric_registry.hpp"
#include "report/text_table.hpp"
#include "run/case_labels.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

namespace canopy {

namespace {

using Cells = std::vector<std::string>;
using Headers = std::vector<ResultColumn::MarkdownHeader>;

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string full(double value) { return fmt::format("{}", value); }
std::string ms3(double value) { return fmt::format("{:.3f}", value); }
std::string mib(uint64_t bytes) { return fmt::format("{:.2f}", double(bytes) / (1024.0 * 1024.0)); }
bool timed(const CaseResult& c) { return c.gpu_frame.stats.count > 0; }

using CsvBound = ResultColumn::Bound<std::string>;
using MarkdownBound = ResultColumn::Bound<ResultColumn::MarkdownHeader>;
using CaseCell = std::function<std::string(const RunRecord&, const CaseResult&)>;

// A column of one CSV cell, not in results.md.
ResultColumn csv_only(std::string name, CaseCell cell) {
    ResultColumn column;
    column.csv = [name, cell](const RunRecord& run) {
        return CsvBound{{name}, [&run, cell](const CaseResult& c) { return Cells{cell(run, c)}; }};
    };
    column.name = std::move(name);
    return column;
}

// A column of one CSV cell that results.md shows too.
ResultColumn both(std::string name, CaseCell cell, std::string markdown_header, bool right, CaseCell markdown_cell) {
    ResultColumn column = csv_only(std::move(name), std::move(cell));
    column.markdown = [markdown_header, right, markdown_cell](const RunRecord& run) {
        return MarkdownBound{{{markdown_header, right}},
                             [&run, markdown_cell](const CaseResult& c) { return Cells{markdown_cell(run, c)}; }};
    };
    return column;
}

// Triangles a count (1234, 45.6k, 24.6M, 1.23G): three figures are what a table needs.
std::string count_text(uint64_t n) {
    if (n < 10000) return std::to_string(n);
    const char* suffix[] = {"k", "M", "G", "T"};
    double value = double(n);
    int s = -1;
    while (value >= 999.5 && s < 3) {  // 999,999 is "1M", not "1e+03k"
        value /= 1000.0;
        ++s;
    }
    return fmt::format("{:.3g}{}", value, suffix[s]);
}

// The triangles each case's frame submitted and rasterised (CaseResult::primitives): two CSV
// cells, and one results.md column when any case was counted.
ResultColumn primitives_column() {
    ResultColumn column;
    column.name = "triangles_submitted, triangles_rasterised";
    column.csv = [](const RunRecord&) {
        return CsvBound{{"triangles_submitted", "triangles_rasterised"}, [](const CaseResult& c) {
                            if (!c.primitives) return Cells{"", ""};
                            return Cells{std::to_string(c.primitives->submitted), std::to_string(c.primitives->rasterised)};
                        }};
    };
    column.markdown = [](const RunRecord& run) {
        bool counted = false;
        for (const CaseResult& c : run.cases) counted = counted || c.primitives.has_value();
        if (!counted) return MarkdownBound{{}, [](const CaseResult&) { return Cells{}; }};
        return MarkdownBound{{{"triangles submitted / rasterised", true}}, [](const CaseResult& c) {
                                 return Cells{c.primitives ? count_text(c.primitives->submitted) + " / " +
                                                                 count_text(c.primitives->rasterised)
                                                           : "-"};
                             }};
    };
    return column;
}

// The CPU passes' counts (CaseResult::counters): "counter_<name>" per name the run holds, and one
// results.md column ("near_cells 104, ...") when any case counted.
ResultColumn counters_column() {
    ResultColumn column;
    column.name = "counters";
    const auto names = [](const RunRecord& run) {
        std::vector<std::string> seen;
        for (const CaseResult& c : run.cases)
            for (const auto& [name, value] : c.counters)
                if (std::find(seen.begin(), seen.end(), name) == seen.end()) seen.push_back(name);
        return seen;
    };
    const auto value_of = [](const CaseResult& c, const std::string& name) -> std::optional<double> {
        for (const auto& [n, v] : c.counters)
            if (n == name) return v;
        return std::nullopt;
    };
    column.csv = [names, value_of](const RunRecord& run) {
        const std::vector<std::string> counted = names(run);
        CsvBound bound;
        for (const std::string& name : counted) bound.headers.push_back("counter_" + name);
        bound.cells = [counted, value_of](const CaseResult& c) {
            Cells cells;
            for (const std::string& name : counted) {
                const std::optional<double> v = value_of(c, name);
                cells.push_back(v ? full(*v) : "");
            }
            return cells;
        };
        return bound;
    };
    column.markdown = [names](const RunRecord& run) {
        if (names(run).empty()) return MarkdownBound{{}, [](const CaseResult&) { return Cells{}; }};
        return MarkdownBound{{{"counts", false}}, [](const CaseResult& c) {
                                 std::string text;
                                 for (const auto& [name, value] : c.counters) {
                                     const bool whole = value >= 0 && value < 1e18 && value == std::floor(value);
                                     text += fmt::format("{}{} {}", text.empty() ? "" : ", ", name,
                                                         whole ? count_text(uint64_t(value)) : fmt::format("{:.3g}", value));
                                 }
                                 return Cells{text.empty() ? "-" : text};
                             }};
    };
    return column;
}

// A column results.md shows and results.csv does not.
ResultColumn markdown_only(std::string name, Headers headers, std::function<Cells(const CaseResult&)> cells) {
    ResultColumn column;
    column.name = std::move(name);
    column.csv = [](const RunRecord&) { return CsvBound{{}, [](const CaseResult&) { return Cells{}; }}; };
    column.markdown = [headers, cells](const RunRecord&) { return MarkdownBound{headers, cells}; };
    return column;
}

// Names of the run's GPU (or CPU) passes, in the order they are first seen: techniques differ.
std::vector<std::string> pass_names(const RunRecord& run, std::vector<TimingSeries> CaseResult::*passes) {
    std::vector<std::string> names;
    std::set<std::string> seen;
    for (const CaseResult& c : run.cases)
        for (const TimingSeries& p : c.*passes)
            if (seen.insert(p.name).second) names.push_back(p.name);
    return names;
}

const TimingSeries* find_pass(const CaseResult& c, std::vector<TimingSeries> CaseResult::*passes, const std::string& name) {
    for (const TimingSeries& p : c.*passes)
        if (p.name == name) return &p;
    return nullptr;
}

// Per pass seen in the run: "<pass><suffix>_ms_median" and "_ms_mad" (empty where a case has no such pass).
ResultColumn pass_family(std::string name, std::vector<TimingSeries> CaseResult::*passes, std::string suffix) {
    ResultColumn column;
    column.name = std::move(name);
    column.csv = [passes, suffix](const RunRecord& run) {
        const std::vector<std::string> names = pass_names(run, passes);
        CsvBound bound;
        for (const std::string& pass : names) {
            bound.headers.push_back(fmt::format("{}{}_ms_median", pass, suffix));
            bound.headers.push_back(fmt::format("{}{}_ms_mad", pass, suffix));
        }
        bound.cells = [passes, names](const CaseResult& c) {
            Cells cells;
            for (const std::string& pass : names) {
                const TimingSeries* p = find_pass(c, passes, pass);
                cells.push_back(p ? full(p->stats.median) : "");
                cells.push_back(p ? full(p->stats.mad) : "");
            }
            return cells;
        };
        return bound;
    };
    return column;
}

// Every registered error metric (metrics/metric_registry.hpp): full precision in the CSV ("n/a"
// where the technique does not declare its group meaningful); in results.md those it shows whose
// group some case declares.
ResultColumn metric_family() {
    ResultColumn column;
    column.name = "error metrics";
    column.csv = [](const RunRecord&) {
        CsvBound bound;
        for (const MetricInfo& metric : registered_metrics()) bound.headers.emplace_back(metric.name);
        bound.cells = [](const CaseResult& c) {
            Cells cells;
            for (const MetricInfo& metric : registered_metrics()) {
                const auto& m = c.image_error;
                cells.push_back(!m ? "" : group_declared(metric.group, m->columns) ? full((*m).*metric.value) : "n/a");
            }
            return cells;
        };
        return bound;
    };
    column.markdown = [](const RunRecord& run) {
        const std::vector<const MetricInfo*> shown = shown_metrics(run, shown_in_markdown);
        MarkdownBound bound;
        for (const MetricInfo* metric : shown) bound.headers.push_back({std::string(metric->column), true});
        bound.cells = [shown](const CaseResult& c) {
            Cells cells;
            for (const MetricInfo* metric : shown) cells.push_back(c.image_error ? table_cell(*metric, *c.image_error) : "-");
            return cells;
        };
        return bound;
    };
    return column;
}

// Pareto dominance as pareto.md judges it (report/pareto.hpp), on the first error axis the run's
// techniques declare (default_pareto_metrics): the id of a case that dominates `c` in its group,
// or none. One definition, so results.md and pareto.md agree.
std::map<std::string, std::string> dominance(const RunRecord& run) {
    std::map<std::string, std::string> by;
    const std::vector<std::string> declared = default_pareto_metrics(run);
    // As pareto.md: an axis the registry does not hold is skipped.
    const auto metric = std::find_if(declared.begin(), declared.end(), [](const std::string& m) { return find_metric(m); });
    if (metric == declared.end()) return by;
    for (const ParetoFront& front : pareto_fronts(run, *metric))
        for (const ParetoPoint& p : front.points)
            if (p.dominated) by[p.result->id] = p.dominated_by;
    return by;
}

const CaseResult* case_by_id(const RunRecord& run, const std::string& id) {
    for (const CaseResult& c : run.cases)
        if (c.id == id) return &c;
    return nullptr;
}

std::string case_label(const CaseResult& c) { return case_name(c.technique, c.params_shown); }

ResultColumn dominance_column() {
    ResultColumn column;
    column.name = "dominated_by";
    column.csv = [](const RunRecord& run) {
        return CsvBound{{"dominated_by"}, [by = dominance(run)](const CaseResult& c) {
                            const auto it = by.find(c.id);
                            return Cells{it != by.end() ? quoted(it->second) : ""};
                        }};
    };
    column.markdown = [](const RunRecord& run) {
        bool measured = false;
        for (const CaseResult& c : run.cases) measured = measured || c.image_error.has_value();
        if (!measured) return MarkdownBound{{}, [](const CaseResult&) { return Cells{}; }};
        return MarkdownBound{{{"dominated by", false}}, [&run, by = dominance(run)](const CaseResult& c) {
                                 const auto it = by.find(c.id);
                                 const CaseResult* other = it != by.end() ? case_by_id(run, it->second) : nullptr;
                                 return Cells{other ? case_label(*other) : "-"};
                             }};
    };
    return column;
}

std::vector<ResultColumn> make_columns() {
    using R = const RunRecord&;
    using C = const CaseResult&;
    std::vector<ResultColumn> columns;
    columns.push_back(csv_only("id", [](R, C c) { return quoted(c.id); }));
    columns.push_back(both("scene", [](R, C c) { return quoted(c.scene); }, "scene", false, [](R, C c) { return c.scene; }));
    columns.push_back(csv_only("technique", [](R, C c) { return quoted(c.technique); }));
    columns.push_back(csv_only("params", [](R, C c) { return quoted(c.params_summary); }));
    {
        ResultColumn size;
        size.name = "resolution";
        size.csv = [](R) {
            return CsvBound{{"width", "height"}, [](C c) {
                                return Cells{std::to_string(c.resolution.width), std::to_string(c.resolution.height)};
                            }};
        };
        size.markdown = [](R) {
            return MarkdownBound{{{"resolution", false}, {"technique", false}, {"parameters", false}}, [](C c) {
                                     return Cells{fmt::format("{}x{}", c.resolution.width, c.resolution.height),
                                                  c.technique, c.params_shown};
                                 }};
        };
        columns.push_back(std::move(size));
    }
    columns.push_back(csv_only("ok", [](R, C c) { return c.ok ? "1" : "0"; }));
    columns.push_back(both("gpu_ms_median", [](R, C c) { return full(c.gpu_frame.stats.median); }, "GPU ms", true,
                           [](R, C c) { return timed(c) ? ms3(c.gpu_frame.stats.median) : "-"; }));
    columns.push_back(csv_only("gpu_ms_min", [](R, C c) { return full(c.gpu_frame.stats.min); }));
    columns.push_back(csv_only("gpu_ms_mean", [](R, C c) { return full(c.gpu_frame.stats.mean); }));
    columns.push_back(both("gpu_ms_mad", [](R, C c) { return full(c.gpu_frame.stats.mad); }, "± MAD", true,
                           [](R, C c) { return timed(c) ? ms3(c.gpu_frame.stats.mad) : "-"; }));
    columns.push_back(both("gpu_cv", [](R, C c) { return full(c.gpu_frame.stats.cv); }, "CV %", true,
                           [](R, C c) { return timed(c) ? fmt::format("{:.1f}", 100.0 * c.gpu_frame.stats.cv) : "-"; }));
    // The ratio's three CSV columns sit after the wall and CPU times; results.md shows it first.
    columns.push_back(markdown_only("ratio", {{"ratio", true}},
                                    [](C c) { return Cells{c.ok ? ratio_cell(c.ratio.estimate) : "-"}; }));
    columns.push_back(both("wall_ms_median", [](R, C c) { return full(c.wall.stats.median); }, "wall ms", true,
                           [](R, C c) { return timed(c) ? ms3(c.wall.stats.median) : "-"; }));
    columns.push_back(csv_only("wall_ms_mad", [](R, C c) { return full(c.wall.stats.mad); }));
    columns.push_back(csv_only("wall_cv", [](R, C c) { return full(c.wall.stats.cv); }));
    columns.push_back(csv_only("cpu_ms_median", [](R, C c) { return full(c.cpu.stats.median); }));
    {
        ResultColumn ratio;
        ratio.name = "ratio_ci95";
        ratio.csv = [](R) {
            return CsvBound{{"ratio", "ratio_ci95_low", "ratio_ci95_high"}, [](C c) {
                                const Estimate& r = c.ratio.estimate;
                                return c.ratio.measured() ? Cells{full(r.value), full(r.ci.low), full(r.ci.high)}
                                                          : Cells{"", "", ""};
                            }};
        };
        columns.push_back(std::move(ratio));
    }
    columns.push_back(csv_only("rounds", [](R, C c) { return std::to_string(c.gpu_frame.stats.count); }));
    columns.push_back(csv_only("frames_per_sample", [](R run, C) { return std::to_string(run.frames_per_sample); }));
    {
        ResultColumn passes = pass_family("passes", &CaseResult::passes, "_gpu");
        passes.markdown = [](R) {
            return MarkdownBound{{{"passes (GPU ms)", false}}, [](C c) {
                                     std::string text;
                                     for (const TimingSeries& p : c.passes)
                                         text += fmt::format("{}{} {:.3f}", text.empty() ? "" : ", ", p.name, p.stats.median);
                                     return Cells{text.empty() ? "-" : text};
                                 }};
        };
        columns.push_back(std::move(passes));
    }
    columns.push_back(pass_family("cpu passes", &CaseResult::cpu_passes, "_cpu"));
    columns.push_back(csv_only("record_cpu_ms_median", [](R, C c) { return full(c.record_cpu.stats.median); }));
    // The load phase, run once before the frames (bakes, uploads): its GPU time, and its wall time.
    columns.push_back(csv_only("load_gpu_ms", [](R, C c) { return c.load.pass_gpu_ms.empty() ? "" : full(c.load.gpu_ms); }));
    columns.push_back(csv_only("load_wall_ms", [](R, C c) { return c.load.pass_gpu_ms.empty() ? "" : full(c.load.wall_ms); }));
    columns.push_back(csv_only("timing_check_gap_ms", [](R, C c) {
        return c.timing_check.checked ? full(c.timing_check.gap_ms) : "";
    }));
    columns.push_back(csv_only("timing_check_agrees", [](R, C c) {
        return c.timing_check.checked ? (c.timing_check.agrees() ? "1" : "0") : "";
    }));
    columns.push_back(both("technique_memory_bytes", [](R, C c) { return std::to_string(c.memory.technique_bytes); },
                           "memory MiB", true, [](R, C c) { return mib(c.memory.technique_bytes); }));
    columns.push_back(csv_only("target_memory_bytes", [](R, C c) { return std::to_string(c.memory.target_bytes); }));
    columns.push_back(csv_only("scene_memory_bytes", [](R, C c) { return std::to_string(c.memory.scene_bytes); }));
    columns.push_back(csv_only("triangles", [](R, C c) { return std::to_string(c.triangles); }));
    columns.push_back(primitives_column());
    columns.push_back(counters_column());
    columns.push_back(csv_only("shadow_sampler", [](R, C c) { return quoted(c.shadow_sampler); }));
    columns.push_back(dominance_column());
    columns.push_back(csv_only("nonfinite_pixels", [](R, C c) { return std::to_string(c.nonfinite_pixels); }));
    columns.push_back(metric_family());
    columns.push_back(markdown_only("status", {{"status", false}},
                                    [](C c) { return Cells{c.ok ? "ok" : "FAILED: " + c.error}; }));
    columns.push_back(csv_only("device", [](R run, C) { return quoted(run.environment.device.name); }));
    columns.push_back(csv_only("commit", [](R run, C) { return quoted(run.environment.git_commit); }));
    {
        // A reference every technique matches (metrics/reference_degeneracy.hpp): the case's
        // errors say nothing about it. Shown in results.md when any case is flagged.
        ResultColumn flag;
        flag.name = "reference_flag";
        flag.csv = [](R run) {
            return CsvBound{{"reference_flag"}, [&run](C c) {
                                return Cells{quoted(degenerate_reference_text(degenerate_reasons(run, c)))};
                            }};
        };
        flag.markdown = [](R run) {
            const bool any = std::any_of(run.references.begin(), run.references.end(),
                                         [](const ReferenceRecord& r) { return !r.degenerate.empty(); });
            if (!any) return MarkdownBound{{}, [](C) { return Cells{}; }};
            return MarkdownBound{{{"flag", false}}, [&run](C c) {
                                     const std::string text = degenerate_reference_text(degenerate_reasons(run, c));
                                     return Cells{text.empty() ? "-" : "**" + text + "**"};
                                 }};
        };
        columns.push_back(std::move(flag));
    }
    return columns;
}

}  // namespace

const std::vector<ResultColumn>& result_columns() {
    static const std::vector<ResultColumn> columns = make_columns();
    return columns;
}

}  // namespace canopy
