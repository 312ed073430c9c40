// `canopy report`'s page (report/html_report.hpp) and the Markdown it converts
// (report/markdown_html.hpp), without a browser; tests/report/report_in_chromium.sh opens a real
// page in headless Chromium.
#include "report/html_report.hpp"
#include "report/markdown_html.hpp"
#include "run/block_bootstrap.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace canopy;
namespace fs = std::filesystem;

namespace {

size_t count(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
}

// The first 24 bytes of a PNG of `width` pixels: all the page reads of it.
void write_png_header(const fs::path& file, uint32_t width) {
    fs::create_directories(file.parent_path());
    std::string bytes = "\x89PNG\r\n\x1a\n";
    bytes += std::string("\0\0\0\x0dIHDR", 8);
    for (int shift = 24; shift >= 0; shift -= 8) bytes += char((width >> shift) & 0xff);
    bytes += std::string("\0\0\0\x40", 4);  // height 64
    std::ofstream(file, std::ios::binary) << bytes;
}

CaseResult make_case(const std::string& id, const std::string& technique, double ratio, double flip) {
    CaseResult c;
    c.id = id;
    c.scene = "tiny";
    c.technique = technique;
    c.resolution = {96, 64};
    c.params = {{"kernel", ParamValue{3LL}}};
    for (int r = 0; r < 10; ++r) {
        c.ratio.per_round.push_back(ratio * (1.0 + 0.001 * (r % 3)));
        c.gpu_frame.samples_ms.push_back(10 * ratio);
    }
    c.ratio.estimate = median_with_ci(c.ratio.per_round, bootstrap_seed(id));
    c.gpu_frame.stats.count = 10;
    c.gpu_frame.stats.median = 10 * ratio;
    ImageMetrics m{};
    m.flip_mean = flip;
    m.columns = ErrorColumns{.visibility = true, .shadow_regions = true};
    m.visibility_rmse = flip / 2;
    m.penumbra_rmse = flip / 3;
    c.image_error = m;
    c.image_png = "images/" + id + ".png";
    c.error_map_png = "images/" + id + ".error.png";
    c.flip_map_png = "images/" + id + ".flip.png";
    return c;
}

RunRecord make_run() {
    RunRecord run;
    run.experiment = "report-test";
    run.description = "two <cases> & a reference";
    run.status = "complete";
    run.rounds = 10;
    GroupRecord group;
    group.name = "tiny 96x64";
    group.scene = "tiny";
    group.resolution = {96, 64};
    run.cases = {make_case("a", "shadow.hard", 1.0, 0.05), make_case("b", "shadow.pcf", 1.5, 0.03)};
    run.cases[0].group_baseline = true;
    for (const CaseResult& c : run.cases) group.cases.push_back(c.id);
    run.groups.push_back(group);
    ReferenceRecord reference;
    reference.scene = "tiny";
    reference.resolution = {96, 64};
    reference.image_png = "images/reference_tiny_96x64.png";
    reference.error_map_scale = 0.25;
    run.references.push_back(reference);
    return run;
}

void write_images(const fs::path& dir, const RunRecord& run) {
    for (const CaseResult& c : run.cases) {
        write_png_header(dir / c.image_png, 96);
        write_png_header(dir / c.error_map_png, 144);  // the heat map with its colour bar beside it
        write_png_header(dir / c.flip_map_png, 144);
    }
    write_png_header(dir / run.references[0].image_png, 96);
}

}  // namespace

TEST_CASE("Markdown: headings shift, tables become sortable with numeric sort keys, text is escaped") {
    const std::string html = markdown_to_html(
        "# Title <x>\n\nSome **bold** and `code` text\ncontinued.\n\n| row | 512 |\n|---|---:|\n| VSM | **1.18** [1.17, 1.19] |\n"
        "| ESM | - |\n\n- **holds** — a claim\n  continued\n- another\n",
        2);
    CHECK(html.find("<h3>Title &lt;x&gt;</h3>") != std::string::npos);
    CHECK(html.find("<p>Some <strong>bold</strong> and <code>code</code> text continued.</p>") != std::string::npos);
    CHECK(html.find("<div class=\"table-scroll\"><table class=\"sortable\">") != std::string::npos);
    CHECK(html.find("<th>row</th><th>512</th>") != std::string::npos);
    CHECK(html.find("<td class=\"num\" data-value=\"1.18\"><strong>1.18</strong> [1.17, 1.19]</td>") != std::string::npos);
    CHECK(html.find("<td class=\"num\">-</td>") != std::string::npos);
    CHECK(html.find("<li><strong>holds</strong> — a claim continued</li>") != std::string::npos);
    CHECK(count(html, "<li>") == 2);
    CHECK(markdown_to_html("<script>alert(1)</script>").find("<script>") == std::string::npos);
}

TEST_CASE("the page holds every section, each image once, and nothing from elsewhere") {
    const test::TempFolder folder;
    const RunRecord run = make_run();
    write_images(folder.path(), run);
    std::ofstream(folder.path() / "paper.md") << "# TEST-T1 — a table\n\n| row | 96x64 |\n|---|---:|\n| hard | 1.00 |\n";
    const std::string html = html_report(run, folder.path(), HtmlReportOptions{});

    for (const char* section : {"id=\"environment\"", "id=\"results\"", "id=\"pareto\"", "id=\"paper\"", "id=\"images\""})
        CHECK_MESSAGE(html.find(section) != std::string::npos, section);
    CHECK(html.find("two &lt;cases&gt; &amp; a reference") != std::string::npos);
    CHECK(html.find("<h3>TEST-T1 — a table</h3>") != std::string::npos);
    // 2 cases x 3 images + the reference, each embedded once; 2 x 4 panels point at them.
    CHECK(count(html, "data:image/png;base64,") == 7);
    CHECK(count(html, "<img alt=") == 8);
    // A heat map is 1.5 x the image's width: its colour bar lies beyond the panel's right edge.
    CHECK(count(html, "style=\"width: 150.000%\"") == 4);
    CHECK(count(html, "style=\"width: 100.000%\"") == 4);
    // The Pareto charts: the shadow family's axes, one chart each, with both cases.
    CHECK(count(html, "<svg class=\"pareto\"") == 2);
    CHECK(count(html, "data-case=\"b\"") == 2);
    // Its points numbered in the SVG (no script needed), by the rows of the table below.
    CHECK(count(html, "<text class=\"point-label\"") == 4);
    CHECK(count(html, "<th>#</th><th>on the front</th>") == 2);
    CHECK(count(html, "<td class=\"num\" data-value=\"2\">2</td><td>yes</td><td>shadow.pcf</td>") == 2);
    // Self-contained.
    CHECK(html.find("<script src") == std::string::npos);
    CHECK(html.find("<link") == std::string::npos);
    CHECK(html.find("http://") == std::string::npos);
    CHECK(html.find("https://") == std::string::npos);
    CHECK(html.find("id=\"selftest-result\"") != std::string::npos);
}

TEST_CASE("every table scrolls sideways in its own box rather than be cut off at the page's edge") {
    const test::TempFolder folder;
    const RunRecord run = make_run();
    write_images(folder.path(), run);
    std::ofstream(folder.path() / "paper.md") << "| row | 96x64 |\n|---|---:|\n| hard | 1.00 |\n";
    const std::string html = html_report(run, folder.path(), HtmlReportOptions{});
    CHECK(html.find(".table-scroll { overflow-x: auto;") != std::string::npos);
    CHECK(html.find("<div class=\"table-scroll\"><table class=\"sortable\" id=\"results-table\">") != std::string::npos);
    // Every table: the environment, the results, two Pareto fronts' and the paper's.
    CHECK(count(html, "<table") == 5);
    CHECK(count(html, "<div class=\"table-scroll\"><table") == 5);
    CHECK(count(html, "</table></div>") == 5);
}

TEST_CASE("the Pareto fronts may be drawn on any registered metric; an unknown one is refused before writing") {
    const test::TempFolder folder;
    const RunRecord run = make_run();
    HtmlReportOptions options;
    options.pareto_metrics = {"flip_mean"};
    const std::string html = html_report(run, folder.path(), options);
    CHECK(count(html, "<svg class=\"pareto\"") == 1);
    CHECK(html.find("aria-label=\"Pareto front: FLIP against time ratio\"") != std::string::npos);
    options.pareto_metrics = {"flip"};  // a claim name, not a results.json name
    CHECK_THROWS_WITH_AS(write_html_report(folder.path(), folder.path() / "report.html", options),
                         doctest::Contains("no error metric 'flip'"), std::invalid_argument);
    CHECK_FALSE(fs::exists(folder.path() / "report.html"));
}

TEST_CASE("linked images point into the run folder; missing images leave an empty panel, not a broken one") {
    const test::TempFolder folder;
    RunRecord run = make_run();
    write_images(folder.path(), run);
    fs::remove(folder.path() / run.cases[1].flip_map_png);
    HtmlReportOptions options;
    options.embed_images = false;
    const std::string html = html_report(run, folder.path(), options);
    CHECK(html.find("data:image/png") == std::string::npos);
    CHECK(html.find("src=\"images/a.png\"") != std::string::npos);
    CHECK(count(html, "src=\"images/reference_tiny_96x64.png\"") == 2);
    CHECK(html.find("FLIP: none") != std::string::npos);
    // No paper.md here: neither a paper section nor a link to one.
    CHECK(html.find("id=\"paper\"") == std::string::npos);
    CHECK(html.find("href=\"#paper\"") == std::string::npos);
    CHECK(html.find("href=\"#pareto\"") != std::string::npos);
    CHECK(count(html, "<img alt=") == 7);
}

TEST_CASE("a case without shown parameters is named by its technique alone, never \"shadow.hard -\"") {
    const test::TempFolder folder;
    RunRecord run = make_run();
    run.cases[0].params.clear();  // shadow.hard at its defaults: parameters "-"
    run.cases.push_back(make_case("c", "shadow.pcf", 2.0, 0.1));  // slower and worse: dominated by shadow.hard
    run.groups[0].cases.push_back("c");
    write_images(folder.path(), run);
    const std::string html = html_report(run, folder.path(), HtmlReportOptions{});
    CHECK(html.find("<h4><strong>shadow.hard</strong> — tiny 96x64</h4>") != std::string::npos);
    CHECK(html.find("<td>shadow.hard</td></tr>") != std::string::npos);  // c's "dominated by"
    CHECK(html.find("shadow.hard: time") != std::string::npos);        // the chart's tooltip
    CHECK(html.find("shadow.hard -") == std::string::npos);
}

TEST_CASE("a --quick run's Pareto section says why nothing is dominated and draws no front line") {
    const test::TempFolder folder;
    RunRecord run = make_run();
    CHECK(html_report(run, folder.path(), HtmlReportOptions{}).find("id=\"pareto-unjudged\"") == std::string::npos);
    run.rounds = 3;
    run.quick = true;
    for (CaseResult& c : run.cases) c.ratio.per_round.resize(3);
    const std::string html = html_report(run, folder.path(), HtmlReportOptions{});
    CHECK(html.find("<p class=\"warning\" id=\"pareto-unjudged\">--quick: 3 rounds, fewer than the 6 a paired time "
                    "interval needs") != std::string::npos);
    CHECK(html.find("No front line is drawn.") != std::string::npos);
    CHECK(count(html, "<svg class=\"pareto\"") == 2);
    CHECK(html.find("<polyline") == std::string::npos);
}

TEST_CASE("write_html_report reads results.json and names what is missing") {
    const test::TempFolder folder;
    CHECK_THROWS_WITH_AS(write_html_report(folder.path(), folder.path() / "report.html", HtmlReportOptions{}),
                         doctest::Contains("results.json"), std::runtime_error);
    CHECK_FALSE(fs::exists(folder.path() / "report.html"));
}
