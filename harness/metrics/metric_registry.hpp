// Every error metric canopy reports, listed once (metric_registry.cpp): its name in results.json
// and results.csv, its name in [paper] claims, its column in the Markdown and console tables, its
// unit, which way is better, the group of columns it belongs to (core/error_columns.hpp), how far
// `canopy compare` lets it move between two runs, and what it means. The JSON writer and reader,
// the CSV, Markdown, console and paper reporters, the [paper] claim parser, `canopy compare` and
// `canopy metrics` iterate over this list and spell no metric themselves: a metric computed in
// compute_metrics (image_metrics.hpp) is added to every report by one entry here.
#pragma once

#include "core/error_columns.hpp"
#include "metrics/image_metrics.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace canopy {

enum class Better { lower, higher };
const char* to_string(Better better);  // "lower", "higher"

// The groups of ErrorColumns: a technique's family declares which of the last three mean something
// for it; a report prints "n/a" for a metric of an undeclared group.
enum class MetricGroup { whole_image, shadow_regions, visibility, coverage };

struct MetricGroupInfo {
    MetricGroup group;
    std::string_view key;          // results.json image_error.columns key ("" for whole_image: always meaningful)
    bool ErrorColumns::*declared;  // the family's declaration (nullptr for whole_image)
    std::string_view description;  // words for table titles and `canopy metrics`
};
std::span<const MetricGroupInfo> metric_groups();
const MetricGroupInfo& group_info(MetricGroup group);
// Whether a technique that declares `columns` measures something with metrics of this group.
bool group_declared(MetricGroup group, const ErrorColumns& columns);

// |candidate - baseline| <= absolute + relative * |baseline| passes `canopy compare`.
struct CompareTolerance {
    double relative = 0;
    double absolute = 0;
};

// Where a metric is shown besides results.json and results.csv (which hold every metric).
enum MetricShown : unsigned {
    shown_in_json_and_csv = 0,
    shown_in_markdown = 1u << 0,     // results.md's table
    shown_in_console = 1u << 1,      // the compact table `canopy run` prints
    shown_in_paper_tables = 1u << 2, // paper.md's error tables
};

struct MetricInfo {
    std::string_view name;    // results.json image_error key and results.csv header
    std::string_view claim;   // its name in [[paper.claim]] metric = "..."
    std::string_view column;  // Markdown and console header
    std::string_view title;   // in words: paper tables' titles, `canopy metrics`
    std::string_view unit;
    Better better;
    MetricGroup group;
    double ImageMetrics::*value;
    CompareTolerance tolerance;
    unsigned shown = shown_in_json_and_csv;  // MetricShown flags
    bool percent = false;                    // tables show 100 x the value (a fraction of pixels)
    // Tables show the column only when some case measured it (a finite value): a metric that
    // needs an experiment setting (popping: [camera_path] popping = true).
    bool only_when_measured = false;
    // results.json writes a non-finite value as null; a metric that may be legitimately +infinite
    // (PSNR of identical images) records that in this boolean key beside it.
    std::string_view infinite_key = {};
    std::string_view doc = {};
    // A per-band metric ([reference] distance_bands) is measured over that band's pixels only.
    DistanceBand band = DistanceBand::none;

    bool shown_in(MetricShown where) const { return (shown & where) != 0; }
    // The value, or NaN where the technique does not declare the metric's group meaningful.
    double meaningful_value(const ImageMetrics& m) const;
};

// Pixel counts behind the metrics: results.json only (and the reference's classes in paper.md).
struct MetricCountInfo {
    std::string_view name;   // results.json image_error key
    std::string_view label;  // paper.md's table of the reference's pixel classes ("" = not there)
    MetricGroup group;
    long long ImageMetrics::*value;
    std::string_view doc;
};

// The lists, in the order of results.csv's columns and of every table.
std::span<const MetricInfo> registered_metrics();
std::span<const MetricCountInfo> registered_metric_counts();

const MetricInfo* find_metric(std::string_view name);        // by results.json name
const MetricInfo* find_claim_metric(std::string_view claim); // by [paper] claim name

// What a [paper] claim may compare: "time" (the GPU median), then every metric's claim name.
inline constexpr std::string_view kTimeClaim = "time";
std::vector<std::string> claim_metric_names();
// Which way a claim metric is better ("time": lower); throws std::invalid_argument for an unknown name.
Better claim_metric_better(std::string_view claim);

// Tests only: every function above answers from `metrics` and `counts` instead of canopy's own
// lists while this object lives, to show that a metric added to the list reaches every report.
class ScopedMetricRegistry {
public:
    ScopedMetricRegistry(std::span<const MetricInfo> metrics, std::span<const MetricCountInfo> counts);
    ~ScopedMetricRegistry();
    ScopedMetricRegistry(const ScopedMetricRegistry&) = delete;
    ScopedMetricRegistry& operator=(const ScopedMetricRegistry&) = delete;

private:
    std::span<const MetricInfo> previous_metrics_;
    std::span<const MetricCountInfo> previous_counts_;
};

}  // namespace canopy
