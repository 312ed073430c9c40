// The metric registry (metrics/metric_registry.hpp) is the one place a metric is named: every
// registered metric reaches results.json (and back through its reader), results.csv, results.md,
// the console table, paper.md's tables, [paper] claims, `canopy compare` and `canopy metrics` —
// checked for canopy's own list and for a test list with a metric no reporter has heard of.
#include "config/experiment_config.hpp"
#include "core/error.hpp"
#include "core/registry.hpp"
#include "metrics/metric_registry.hpp"
#include "report/console_table.hpp"
#include "report/csv_report.hpp"
#include "report/json_record_reader.hpp"
#include "report/json_report.hpp"
#include "report/markdown_report.hpp"
#include "report/metric_list.hpp"
#include "report/paper_report.hpp"
#include "run/run_comparison.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>

using namespace canopy;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string part; std::getline(in, part, separator);) out.push_back(part);
    return out;
}

// Markdown table cells, trimmed.
std::vector<std::string> cells(const std::string& line) {
    std::vector<std::string> out;
    for (std::string cell : split(line, '|')) {
        const size_t first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
        out.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
    }
    if (!out.empty()) out.erase(out.begin());  // before the first '|'
    return out;
}

// The cell under `column` in the first table row after the header, or "" when there is no such column.
std::string cell_under(const std::string& table, const std::string& column, size_t header_line = 0) {
    const auto lines = split(table, '\n');
    const auto header = cells(lines.at(header_line));
    const auto row = cells(lines.at(header_line + 2));
    for (size_t i = 0; i < header.size(); ++i)
        if (header[i] == column) return row.at(i);
    return "";
}

// A distinct, easily found value per registered metric, and a count per registered count.
ImageMetrics distinct_metrics() {
    ImageMetrics m{};
    m.columns = {.visibility = true, .shadow_regions = true, .coverage = true};  // every group shows (no one family declares all)
    size_t i = 0;
    for (const MetricInfo& metric : registered_metrics()) m.*metric.value = 0.1 + 0.001 * double(++i);
    long long n = 100;
    for (const MetricCountInfo& count : registered_metric_counts()) m.*count.value = ++n;
    m.max_x = 7;
    m.max_y = 8;
    return m;
}

CaseResult error_case() {
    CaseResult c;
    c.id = "tiny_96x64_shadow.hard";
    c.scene = "tiny";
    c.technique = "shadow.hard";
    c.resolution = {96, 64};
    c.params_shown = "-";
    c.gpu_frame = {"gpu_frame", {1.0, 1.0, 1.0}, {3, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0}};
    c.wall = c.cpu = c.gpu_frame;
    c.image_error = distinct_metrics();
    return c;
}

RunRecord error_run() {
    RunRecord run;
    run.experiment = "registry";
    run.identity.fields = {{"config_hash", "1234"}};
    run.cases.push_back(error_case());
    ReferenceRecord reference;
    reference.scene = "tiny";
    reference.resolution = {96, 64};
    run.references.push_back(reference);
    return run;
}

// One row compared with itself on `claim_metric` ("" = no claim: the tables only).
PaperComparison one_row_paper(const std::string& claim_metric) {
    PaperComparison paper;
    paper.id = "R";
    paper.columns = {"96x64"};
    paper.rows = {{"hard", "shadow.hard", {}, {}}};
    if (claim_metric.empty()) return paper;
    PaperClaim claim;
    claim.text = "hard is about as good as itself";
    claim.left = claim.right = "hard";
    claim.metric = claim_metric;
    claim.relation = "about";
    claim.tolerance = 0.0;
    paper.claims.push_back(claim);
    return paper;
}

Experiment parse_claim(const std::string& metric, const std::string& relation) {
    static const test::TempFolder folder("canopy-test-metric-registry");
    const std::string name = fmt::format("{}-{}.toml", metric, relation);
    const fs::path file = folder.write(
        // Distance bands, which a claim on a band's FLIP needs.
        name, fmt::format("[experiment]\nscenes = [\"{}/scenes/tiny.toml\"]\n[[technique]]\nname = \"shadow.hard\"\n"
                          "[reference]\ndistance_bands = [1, 2]\n[paper]\nid = \"R\"\ncolumns = [\"96x64\"]\n[[paper.row]]\nlabel = \"hard\"\n"
                          "technique = \"shadow.hard\"\n[[paper.claim]]\ntext = \"t\"\nleft = \"hard\"\n"
                          "right = \"hard\"\nmetric = \"{}\"\nrelation = \"{}\"\nstates = \"direction\"\n"
                          "why = \"no number\"\n",
                          CANOPY_TEST_DATA, metric, relation));
    return load_experiment(file, TechniqueRegistry::instance());
}

// Every registered metric and count, whatever the list holds, in every output.
void check_every_metric_everywhere() {
    const RunRecord run = error_run();
    const ImageMetrics& m = *run.cases[0].image_error;
    REQUIRE_FALSE(registered_metrics().empty());

    // results.json, and back.
    const nlohmann::json json = nlohmann::json::parse(json_report(run));
    const nlohmann::json& image_error = json.at("cases").at(0).at("image_error");
    const test::TempFolder folder("canopy-test-metric-registry");
    const fs::path file = folder.write("results.json", json_report(run));
    const ImageMetrics back = *read_json_report(file).cases.at(0).image_error;
    for (const MetricCountInfo& count : registered_metric_counts()) {
        const std::string name(count.name);
        CAPTURE(name);
        CHECK(image_error.at(std::string(count.name)).get<long long>() == m.*count.value);
        CHECK(back.*count.value == m.*count.value);
    }

    const std::string csv = csv_report(run);
    const auto csv_lines = split(csv, '\n');
    REQUIRE(csv_lines.size() == 2);
    const auto csv_header = split(csv_lines[0], ','), csv_row = split(csv_lines[1], ',');
    REQUIRE(csv_header.size() == csv_row.size());
    const std::string markdown = markdown_table(run), console = console_table(run);
    const std::string paper = paper_report(one_row_paper(""), run, RunToRunNoise{});
    const std::string list = metric_list();

    std::set<std::string> names, claims, columns;
    for (const MetricInfo& metric : registered_metrics()) {
        const std::string name(metric.name);
        CAPTURE(name);
        const double value = m.*metric.value;
        CHECK(names.insert(name).second);
        CHECK(claims.insert(std::string(metric.claim)).second);
        CHECK(columns.insert(std::string(metric.column)).second);
        CHECK_FALSE(metric.doc.empty());
        CHECK_FALSE(metric.title.empty());
        // Nothing that would split a Markdown cell or a CSV column.
        for (std::string_view text : {metric.name, metric.claim, metric.column, metric.title, metric.unit, metric.doc})
            CHECK(text.find('|') == std::string_view::npos);
        CHECK(name.find_first_of(",\" ") == std::string::npos);
        CHECK(find_metric(name) == &metric);
        CHECK(find_claim_metric(metric.claim) == &metric);

        CHECK(image_error.at(name).get<double>() == value);
        CHECK(back.*metric.value == value);

        const auto at = std::find(csv_header.begin(), csv_header.end(), name);
        REQUIRE(at != csv_header.end());
        CHECK(std::stod(csv_row[size_t(at - csv_header.begin())]) == value);

        const std::string cell = fmt::format("{:.4g}", metric.percent ? 100.0 * value : value);
        CHECK(cell_under(markdown, std::string(metric.column)) == (metric.shown_in(shown_in_markdown) ? cell : ""));
        CHECK(cell_under(console, std::string(metric.column), 1) == (metric.shown_in(shown_in_console) ? cell : ""));
        const bool in_paper = paper.find("## canopy: " + std::string(metric.title) + " (") != std::string::npos;
        CHECK(in_paper == metric.shown_in(shown_in_paper_tables));

        // [paper] claims: the parser accepts its name, "better" follows its direction, the judge reads it.
        const Experiment parsed = parse_claim(std::string(metric.claim), "better");
        CHECK(parsed.paper->claims.at(0).metric == metric.claim);
        CHECK(parsed.paper->claims.at(0).relation == (metric.better == Better::lower ? "less" : "greater"));
        const auto verdicts = judge_claims(one_row_paper(std::string(metric.claim)), run, RunToRunNoise{});
        CHECK(verdicts.at(0).outcome == "holds");
        CHECK(verdicts.at(0).because.find(fmt::format("{:.4g}", value)) != std::string::npos);

        // `canopy compare`: a move within the tolerance passes, twice the tolerance is flagged by name.
        CHECK(std::isfinite(metric.tolerance.relative));
        CHECK(std::isfinite(metric.tolerance.absolute));
        CHECK(metric.tolerance.relative >= 0);
        CHECK(metric.tolerance.absolute >= 0);
        const double allowed = metric.tolerance.absolute + metric.tolerance.relative * std::abs(value);
        CHECK(allowed > 0);
        RunRecord moved = run;
        moved.cases[0].image_error.value().*metric.value = value + 0.5 * allowed;
        CHECK(compare_runs(run, moved, {}).passed());
        moved.cases[0].image_error.value().*metric.value = value + 2.0 * allowed;
        const RunComparison flagged = compare_runs(run, moved, {});
        CHECK_FALSE(flagged.passed());
        bool named = false;
        for (const MetricChange& change : flagged.cases.at(0).errors) named |= change.out_of_tolerance && change.metric == name;
        CHECK(named);

        CHECK(list.find("| " + name + " ") != std::string::npos);
    }
    // Nothing else in the CSV's metric part: every column between nonfinite_pixels and device is registered.
    const auto first = std::find(csv_header.begin(), csv_header.end(), "nonfinite_pixels");
    const auto last = std::find(csv_header.begin(), csv_header.end(), "device");
    REQUIRE(first != csv_header.end());
    CHECK(size_t(last - first - 1) == registered_metrics().size());
    CHECK(claim_metric_names().size() == registered_metrics().size() + 1);
}

}  // namespace

TEST_CASE("every field of ImageMetrics is a registered metric or count, once") {
    // A double or count added to ImageMetrics without an entry in metric_registry.cpp changes the
    // struct's size but not this sum (besides them: max_error's pixel and the declared groups).
    size_t bytes = 2 * sizeof(int) + sizeof(ErrorColumns);
    std::vector<double ImageMetrics::*> values;
    for (const MetricInfo& metric : registered_metrics()) {
        CHECK(std::find(values.begin(), values.end(), metric.value) == values.end());
        values.push_back(metric.value);
        bytes += sizeof(double);
    }
    std::vector<long long ImageMetrics::*> counts;
    for (const MetricCountInfo& count : registered_metric_counts()) {
        CHECK(std::find(counts.begin(), counts.end(), count.value) == counts.end());
        counts.push_back(count.value);
        bytes += sizeof(long long);
    }
    const size_t padded = (bytes + alignof(ImageMetrics) - 1) / alignof(ImageMetrics) * alignof(ImageMetrics);
    CHECK(sizeof(ImageMetrics) == padded);
}

TEST_CASE("canopy's metrics reach every report, the JSON reader, claims, compare and `canopy metrics`") {
    check_every_metric_everywhere();
}

TEST_CASE("a metric added to the list reaches them too, with no other change") {
    // A metric no reporter has heard of (stored in the mae field, which this list does not
    // register), in a group, shown everywhere; and PSNR for its infinite key.
    const MetricInfo metrics[] = {
        {.name = "blade_coverage_error", .claim = "blade_coverage", .column = "blade cov", .title = "blade coverage error",
         .unit = "fraction of pixels", .better = Better::lower, .group = MetricGroup::visibility,
         .value = &ImageMetrics::mae, .tolerance = {1e-2, 1e-6},
         .shown = shown_in_markdown | shown_in_console | shown_in_paper_tables,
         .doc = "a test metric"},
        *find_metric("psnr_db"),
    };
    const MetricCountInfo counts[] = {
        {"blade_pixels", "blades", MetricGroup::visibility, &ImageMetrics::umbra_pixels, "a test count"},
    };
    const ScopedMetricRegistry scoped(metrics, counts);
    REQUIRE(registered_metrics().size() == 2);
    check_every_metric_everywhere();

    const RunRecord run = error_run();
    const nlohmann::json json = nlohmann::json::parse(json_report(run));
    CHECK_FALSE(json.at("cases").at(0).at("image_error").contains("rmse"));
    CHECK(csv_report(run).find(",nonfinite_pixels,blade_coverage_error,psnr_db,device,") != std::string::npos);
    CHECK(paper_report(one_row_paper(""), run, RunToRunNoise{}).find("| blades | 101 |") != std::string::npos);
    // Undeclared group: no column where no case declares it, n/a beside a case that does, no verdict.
    RunRecord undeclared = run;
    undeclared.cases[0].image_error->columns = {};
    CHECK(cell_under(markdown_table(undeclared), "blade cov") == "");
    RunRecord mixed = undeclared;
    mixed.cases.insert(mixed.cases.begin(), run.cases[0]);
    mixed.cases[1].id += "_other";
    CHECK(markdown_table(mixed).find(" n/a |") != std::string::npos);
    CHECK(judge_claims(one_row_paper("blade_coverage"), undeclared, RunToRunNoise{}).at(0).outcome == "not measured");
    // A name not in the list is refused with the list's names.
    try {
        parse_claim("rmse", "less");
        FAIL("a claim on a metric the list does not hold was accepted");
    } catch (const ConfigError& e) {
        CHECK(e.hint().find("use one of: time, blade_coverage, psnr") != std::string::npos);
    }
}

TEST_CASE("PSNR's infinity survives results.json; time claims are better when lower") {
    RunRecord run = error_run();
    run.cases[0].image_error->psnr = std::numeric_limits<double>::infinity();
    const nlohmann::json json = nlohmann::json::parse(json_report(run));
    CHECK(json.at("cases").at(0).at("image_error").at("psnr_db").is_null());
    CHECK(json.at("cases").at(0).at("image_error").at("psnr_infinite").get<bool>());
    const test::TempFolder folder("canopy-test-metric-registry");
    CHECK(std::isinf(read_json_report(folder.write("results.json", json_report(run))).cases.at(0).image_error->psnr));

    CHECK(parse_claim("time", "better").paper->claims.at(0).relation == "less");
    CHECK(claim_metric_better("time") == Better::lower);
    CHECK_THROWS_AS(claim_metric_better("nope"), std::invalid_argument);
}

TEST_CASE("a results.json written before a metric was added reads it as not measured") {
    const RunRecord run = error_run();
    nlohmann::json json = nlohmann::json::parse(json_report(run));
    json["cases"][0]["image_error"].erase("visibility_excluded");
    const test::TempFolder folder("canopy-test-metric-registry");
    const ImageMetrics back = *read_json_report(folder.write("results.json", json.dump())).cases.at(0).image_error;
    CHECK(std::isnan(back.visibility_excluded));
    CHECK(back.rmse == run.cases[0].image_error->rmse);
}

TEST_CASE("harness/metrics/README.md documents every registered metric and count") {
    std::ifstream in(fs::path(CANOPY_SOURCE_DIR) / "harness" / "metrics" / "README.md");
    REQUIRE(in);
    const std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const MetricInfo& metric : registered_metrics())
        CHECK_MESSAGE(readme.find("`" + std::string(metric.name) + "`") != std::string::npos, std::string(metric.name));
    for (const MetricCountInfo& count : registered_metric_counts())
        CHECK_MESSAGE(readme.find("`" + std::string(count.name) + "`") != std::string::npos, std::string(count.name));
}
