// Reports keep the two kinds of error apart and say "n/a" for a column a technique's family does
// not declare meaningful (core/error_columns.hpp): CSV, Markdown, the console table, paper claims.
#include "config/paper_comparison.hpp"
#include "report/console_table.hpp"
#include "report/csv_report.hpp"
#include "report/markdown_report.hpp"
#include "report/paper_report.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <sstream>
#include <string>

using namespace canopy;

namespace {

CaseResult error_case(const std::string& technique, ErrorColumns columns) {
    CaseResult c;
    c.id = fmt::format("spheres_96x64_{}", technique);
    c.scene = "spheres";
    c.resolution = {96, 64};
    c.technique = technique;
    c.gpu_frame.stats = {20, 2.0, 1, 3, 2, 0.1, 0.05};
    c.wall.stats = c.gpu_frame.stats;
    ImageMetrics m{};
    m.rmse = 0.0123;
    m.psnr = 38.2;
    m.ssim = 0.987;
    m.flip_mean = 0.0456;
    m.light_bleeding = 0.00111;
    m.over_darkening = 0.00222;
    m.penumbra_rmse = 0.0333;
    m.visibility_mae = 0.0444;
    m.visibility_rmse = 0.0555;
    m.visibility_penumbra_rmse = 0.0666;
    m.visibility_excluded = 0.00077;
    m.coverage_mae = 0.0701;
    m.coverage_tile_mae = 0.0702;
    m.coverage_total_error = 0.0703;
    m.columns = columns;
    c.image_error = m;
    return c;
}

RunRecord two_families() {
    RunRecord run;
    run.cases.push_back(error_case("shadow.hard", {.visibility = true, .shadow_regions = true}));
    run.cases.push_back(error_case("grass.cards", {.coverage = true}));  // a family that changes the primary hits
    return run;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

long count(const std::string& text, const std::string& what) {
    long n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("CSV: the visibility columns, full precision, n/a where not declared") {
    const auto rows = lines(csv_report(two_families()));
    REQUIRE(rows.size() == 3);
    CHECK(rows[0].find(",penumbra_rmse,visibility_mae,visibility_rmse,visibility_penumbra_rmse,visibility_excluded,") !=
          std::string::npos);
    CHECK(rows[1].find(",0.0333,0.0444,0.0555,0.0666,0.00077,") != std::string::npos);
    CHECK(count(rows[1], "n/a") == 3);  // the coverage columns
    // The whole-image columns are meaningful for every technique; the 3 + 4 shadow ones are not here.
    CHECK(rows[2].find(",0.0123,38.2,") != std::string::npos);
    CHECK(rows[2].find(",0.0701,0.0702,0.0703,") != std::string::npos);
    CHECK(count(rows[2], ",n/a") == 7);
}

TEST_CASE("Markdown and console: V columns beside the whole-image ones, n/a where not declared") {
    const RunRecord run = two_families();
    const auto table = lines(markdown_table(run));
    REQUIRE(table.size() == 4);
    for (const char* column : {" RMSE", "FLIP", "penumbra RMSE", "V RMSE", "V MAE", "V penumbra RMSE", "V excluded %"})
        CHECK_MESSAGE(table[0].find(column) != std::string::npos, column);
    CHECK(table[2].find("0.0555") != std::string::npos);
    CHECK(table[2].find("0.077") != std::string::npos);  // percent
    CHECK(count(table[2], "n/a") == 3);
    CHECK(count(table[3], "n/a") == 7);
    CHECK(table[3].find("0.0456") != std::string::npos);  // FLIP stays
    CHECK(table[3].find("0.0702") != std::string::npos);  // coverage over tiles
    CHECK(table[3].find("7.03") != std::string::npos);    // coverage total, percent

    const std::string console = console_table(run);
    CHECK(console.find("V RMSE") != std::string::npos);
    CHECK(count(console, "n/a") == 3);  // the first row's coverage; penumbra RMSE and V RMSE of the second
    CHECK(console.find("0.0702") != std::string::npos);
    CHECK(console.find("0.0555") != std::string::npos);

    const std::string report = markdown_report(run);
    CHECK(report.find("How wrong the technique's shadow is") != std::string::npos);
}

TEST_CASE("Markdown and console: a run of one family shows only the groups it declares") {
    RunRecord grass;
    grass.cases.push_back(error_case("grass.cards", {.coverage = true}));
    const std::string markdown = markdown_report(grass), console = console_table(grass);
    for (const std::string& text : {markdown_table(grass), console}) {
        CHECK(text.find("cov tile MAE") != std::string::npos);
        CHECK(text.find("V RMSE") == std::string::npos);
        CHECK(text.find("penumbra RMSE") == std::string::npos);
        CHECK(text.find("n/a") == std::string::npos);
    }
    CHECK(markdown.find("How wrong the technique's shadow is") == std::string::npos);
    CHECK(markdown.find("Where the blades are") != std::string::npos);
    // The CSV keeps every column, so its header does not depend on the run.
    CHECK(csv_report(grass).find(",visibility_rmse,") != std::string::npos);

    RunRecord shadow;
    shadow.cases.push_back(error_case("shadow.hard", {.visibility = true, .shadow_regions = true}));
    CHECK(markdown_report(shadow).find("cov tile MAE") == std::string::npos);
    CHECK(markdown_report(shadow).find("Where the blades are") == std::string::npos);
}

TEST_CASE("paper claims may name the visibility metrics; an undeclared column judges nothing") {
    PaperComparison paper;
    paper.id = "T";
    paper.column_key = "screen";
    paper.columns = {"96x64"};
    paper.rows = {{"hard", "shadow.hard", {}, {}}, {"cards", "grass.cards", {}, {}}};
    PaperClaim claim;
    claim.text = "hard's shadow is closer to the truth than itself plus noise";
    claim.left = "hard";
    claim.right = "hard";
    claim.metric = "visibility_rmse";
    claim.relation = "about";
    claim.tolerance = 0.01;
    paper.claims.push_back(claim);
    claim.left = claim.right = "cards";
    paper.claims.push_back(claim);
    const auto verdicts = judge_claims(paper, two_families(), RunToRunNoise{});
    REQUIRE(verdicts.size() == 2);
    CHECK(verdicts[0].outcome == "holds");
    CHECK(verdicts[0].because.find("0.0555") != std::string::npos);
    CHECK(verdicts[1].outcome == "not measured");
}
