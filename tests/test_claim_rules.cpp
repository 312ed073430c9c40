// The rules a [paper] claim is judged by (issue 35): the paper's number checked as a number, a
// direction only with its reason, the spread between runs in every timing interval, unequal
// quality flagged, and claims about what happens in time never judged on still images.
#include "config/claim_rules.hpp"
#include "config/experiment_config.hpp"
#include "config/paper_table_change.hpp"
#include "reference/reference_noise.hpp"
#include "report/json_report.hpp"
#include "report/paper_report.hpp"
#include "run/run_to_run_noise.hpp"
#include "support/config_error_of.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace canopy;
namespace fs = std::filesystem;

namespace {

const test::TempFolder& folder() {
    static const test::TempFolder f("canopy-test-claim-rules");
    return f;
}

// Two rows of the tiny scene, hard shadows and 3x3 PCF, with the paper's fps (400 and 200: PCF
// takes twice the time) and one claim.
std::string experiment_with(const std::string& claim) {
    return "[experiment]\nscenes = [\"" + std::string(CANOPY_TEST_DATA) +
           "/scenes/tiny.toml\"]\n[[technique]]\nname = \"shadow.hard\"\n[[technique]]\nname = \"shadow.pcf\"\n"
           "[technique.params]\nkernel = 3\n"
           "[paper]\nid = \"R\"\ncolumns = [\"96x64\"]\nbaseline = \"hard\"\n"
           "[[paper.row]]\nlabel = \"hard\"\ntechnique = \"shadow.hard\"\nvalues = [400]\n"
           "[[paper.row]]\nlabel = \"PCF\"\ntechnique = \"shadow.pcf\"\nvalues = [200]\n"
           "[[paper.row]]\nlabel = \"PCF, no number\"\ntechnique = \"shadow.pcf\"\n"
           "[[paper.claim]]\n" + claim;
}

Experiment load(const std::string& name, const std::string& claim) {
    return load_experiment(folder().write(name, experiment_with(claim)), TechniqueRegistry::instance());
}

std::string error_of(const std::string& claim) {
    const auto error = test::config_error_of([&] { load("refused.toml", claim); });
    return error ? error->formatted() : std::string("no error");
}

CaseResult fake_case(const std::string& technique, std::vector<double> samples, double flip) {
    CaseResult c;
    c.id = technique;
    c.technique = technique;
    c.scene = "tiny";
    c.resolution = {96, 64};
    c.params = {{"resolution", 1024LL}};
    if (technique == "shadow.pcf") c.params.push_back({"kernel", 3LL});
    c.gpu_frame.samples_ms = std::move(samples);
    c.gpu_frame.stats = summarize(c.gpu_frame.samples_ms);
    ImageMetrics m{};
    m.flip_mean = flip;
    m.columns = {.visibility = true, .shadow_regions = true};
    c.image_error = m;
    return c;
}

// 20 rounds of `ms` with a small alternation: a tight interval around `ms`.
std::vector<double> rounds(double ms, double swing = 0.004, size_t n = 20) {
    std::vector<double> v;
    for (size_t r = 0; r < n; ++r) v.push_back(ms * (r % 2 ? 1.0 + swing : 1.0 - swing));
    return v;
}

RunRecord run_of(double hard_ms, double pcf_ms, const std::string& device_type = "cpu") {
    RunRecord run;
    run.environment.device.name = device_type == "cpu" ? "llvmpipe (test)" : "A GPU (test)";
    run.environment.device.type = device_type;
    run.cases = {fake_case("shadow.hard", rounds(hard_ms), 0.05), fake_case("shadow.pcf", rounds(pcf_ms), 0.05)};
    return run;
}

}  // namespace

TEST_CASE("the claim lint: a number the paper gives is checked as a number, a direction says why") {
    // The table gives PCF/hard = 2: a direction check would not test it.
    CHECK(error_of("text = \"t\"\nleft = \"PCF\"\nright = \"hard\"\nrelation = \"greater\"\nstates = \"direction\"\n"
                   "why = \"no number\"\n")
              .find("the paper's table gives this claim's number (left/right = 2") != std::string::npos);
    // No states at all: refused, with both forms to write.
    const std::string missing = error_of("text = \"t\"\nleft = \"PCF\"\nright = \"hard\"\n");
    CHECK(missing.find("refused.toml:") != std::string::npos);
    CHECK(missing.find("states = \"magnitude\"") != std::string::npos);
    // A direction without its reason, or with one not on the list.
    CHECK(error_of("text = \"t\"\nleft = \"PCF, no number\"\nright = \"hard\"\nstates = \"direction\"\n")
              .find("must say why") != std::string::npos);
    CHECK(error_of("text = \"t\"\nleft = \"PCF, no number\"\nright = \"hard\"\nstates = \"direction\"\nwhy = \"no numbers\"\n")
              .find("did you mean 'no number'") != std::string::npos);
    // The text quotes a number a direction check would not test.
    CHECK(error_of("text = \"PCF is 545 % slower\"\nleft = \"PCF, no number\"\nright = \"hard\"\nstates = \"direction\"\n"
                   "why = \"no number\"\n")
              .find("quotes '545 %'") != std::string::npos);
    // A magnitude needs the paper's number: from the table, or given where the table has none;
    // never both.
    CHECK(error_of("text = \"t\"\nleft = \"PCF, no number\"\nright = \"hard\"\nstates = \"magnitude\"\n")
              .find("give the paper's ratio") != std::string::npos);
    CHECK(error_of("text = \"t\"\nleft = \"PCF\"\nright = \"hard\"\nstates = \"magnitude\"\nratio = 2\n")
              .find("taken from there") != std::string::npos);
    CHECK(error_of("text = \"t\"\nleft = \"PCF, no number\"\nright = \"hard\"\nstates = \"magnitude\"\nratio = 2\n") ==
          "no error");
    // A tolerance other than the rules' table says why; a reason with nothing to explain is refused.
    CHECK(error_of("text = \"t\"\nleft = \"PCF\"\nright = \"hard\"\nrelation = \"about\"\ntolerance = 0.3\n"
                   "states = \"magnitude\"\n")
              .find("must say why, before the run") != std::string::npos);
    CHECK(error_of("text = \"t\"\nleft = \"PCF\"\nright = \"hard\"\nstates = \"magnitude\"\nratio_tolerance = 0.5\n")
              .find("must say why, before the run") != std::string::npos);
    CHECK(error_of("text = \"t\"\nleft = \"PCF\"\nright = \"hard\"\nstates = \"magnitude\"\ntolerance_reason = \"x\"\n")
              .find("none differs") != std::string::npos);
    CHECK(error_of("text = \"t\"\nleft = \"PCF\"\nright = \"hard\"\nrelation = \"about\"\ntolerance = 0.3\n"
                   "tolerance_reason = \"the paper says roughly\"\nstates = \"magnitude\"\n") == "no error");
    // Something that happens in time: measured along a path, or said not to be tested.
    CHECK(error_of("text = \"macro-cells hide the replacement of cells\"\nleft = \"PCF\"\nright = \"hard\"\nmetric = \"flip\"\n"
                   "relation = \"about\"\nstates = \"direction\"\nwhy = \"no number\"\n")
              .find("'replacement', which happens from frame to frame") != std::string::npos);
    CHECK(error_of("text = \"macro-cells hide the replacement of cells\"\nleft = \"PCF\"\nright = \"hard\"\nmetric = \"flip\"\n"
                   "relation = \"about\"\nstates = \"direction\"\nwhy = \"no number\"\nuntested = \"still images\"\n") ==
          "no error");
}

TEST_CASE("the words that commit a claim to a number or to time") {
    CHECK(quoted_measurement("545 % faster") == "545 %");
    CHECK(quoted_measurement("177 against 15 fps") == "15 fps");
    CHECK(quoted_measurement("t_g 41.44 against t_v 23.31 ms") == "23.31 ms");
    CHECK(quoted_measurement("costs less than 0.6 x PCF 5") == "0.6 x");
    CHECK(quoted_measurement("×10 cheaper") == "×10");
    CHECK_FALSE(quoted_measurement("a 5x5 kernel, 1024x768, K23, L1040, 16 bits, Fig 7.4, within 0.02 of"));
    CHECK(quoted_event_in_time("hiding the Replacement of cells") == "Replacement");
    CHECK(quoted_event_in_time("no popping at the band's edge") == "popping");
    CHECK_FALSE(quoted_event_in_time("the field's populations"));
}

TEST_CASE("the tolerances and reasons are configs/README.md's table, and its count of exemptions is true") {
    std::ifstream in(fs::path(CANOPY_SOURCE_DIR) / "configs" / "README.md");
    std::stringstream text;
    text << in.rdbuf();
    const std::string readme = text.str();
    for (const ToleranceRule& rule : tolerance_rules()) {
        const std::regex row("\\| " + std::string(rule.key) + " \\| ([0-9.]+) \\|");
        std::smatch m;
        REQUIRE_MESSAGE(std::regex_search(readme, m, row), "configs/README.md has no row for ", rule.key);
        CHECK(std::stod(m[1]) == rule.tolerance);
    }
    for (const DirectionReason& reason : direction_reasons())
        CHECK_MESSAGE(readme.find(fmt::format("| `\"{}\"` |", reason.key)) != std::string::npos, reason.key);
    // Every committed claim with a tolerance of its own is counted in the README.
    size_t exempt = 0, claims = 0;
    for (const fs::directory_entry& file : fs::directory_iterator(fs::path(CANOPY_SOURCE_DIR) / "configs" / "experiments" / "paper")) {
        const Experiment e = load_experiment(file.path(), TechniqueRegistry::instance());
        if (!e.paper) continue;
        for (const PaperClaim& claim : e.paper->claims) {
            ++claims;
            exempt += claim.tolerance_reason.empty() ? 0 : 1;
        }
    }
    CHECK(claims > 40);
    std::smatch m;
    REQUIRE(std::regex_search(readme, m, std::regex("tolerance of their own \\(`tolerance_reason`\\): ([0-9]+)")));
    CHECK(size_t(std::stoul(m[1])) == exempt);
}

TEST_CASE("a ratio's interval holds the spread between runs: ±1.96 √(se_within² + σ_run²) on the log-ratio") {
    // A symmetric run interval of ±1.96 x 0.01 around ln 0.9; sigma 0.02.
    const double centre = std::log(0.9), se = 0.01, sigma = 0.02;
    const Estimate run{0.9, {std::exp(centre - 1.96 * se), std::exp(centre + 1.96 * se)}, 20};
    const Estimate wide = with_run_to_run_noise(run, sigma);
    const double half = 1.96 * std::sqrt(se * se + sigma * sigma);
    CHECK(wide.value == 0.9);
    CHECK(wide.ci.low == doctest::Approx(std::exp(centre - half)));
    CHECK(wide.ci.high == doctest::Approx(std::exp(centre + half)));
    // No spread known: the run's own interval.
    CHECK(with_run_to_run_noise(run, 0.0).ci.low == run.ci.low);
}

TEST_CASE("a margin inside the spread between runs reads 'within noise', outside it a verdict") {
    const Experiment e = load("margin.toml", "text = \"PCF costs more than hard shadows\"\nleft = \"PCF\"\nright = \"hard\"\n"
                                             "relation = \"greater\"\nstates = \"magnitude\"\n");
    // PCF 2 % above hard, its single-run interval tight and wholly above 1.
    const RunRecord run = run_of(10.0, 10.2);
    CHECK(judge_claims(*e.paper, run, RunToRunNoise{}).front().outcome == "holds");
    // Runs that move a ratio by 1.6 % (llvmpipe's committed stability run): the same data decide nothing.
    const RunToRunNoise spread{0.016, "a test's"};
    const ClaimVerdict v = judge_claims(*e.paper, run, spread).front();
    CHECK(v.outcome == "within noise");
    // A margin well beyond it still holds.
    CHECK(judge_claims(*e.paper, run_of(10.0, 12.0), spread).front().outcome == "holds");
    // paper.md and paper.json name the spread and where it comes from.
    CHECK(paper_report(*e.paper, run, spread).find("σ_run = 1.6 % (a test's)") != std::string::npos);
    CHECK(paper_data(*e.paper, run, spread)["run_to_run_noise"]["sigma_log_ratio"].get<double>() == 0.016);
}

TEST_CASE("the paper's number: × k of the paper's ratio, judged on a GPU, given without a verdict on a CPU rasteriser") {
    const Experiment e = load("magnitude.toml", "text = \"PCF costs twice hard shadows' time\"\nleft = \"PCF\"\nright = \"hard\"\n"
                                                "relation = \"greater\"\nstates = \"magnitude\"\n");
    // The paper: 400 fps against 200, PCF twice the time. canopy on a GPU: 1.4 times.
    ClaimVerdict v = judge_claims(*e.paper, run_of(10.0, 14.0, "discrete-gpu"), RunToRunNoise{}).front();
    CHECK(v.outcome == "holds");  // the direction
    CHECK(v.magnitude_stated);
    CHECK(v.magnitude_outcome == "does not hold");  // ×0.70, outside 1 ± 0.25
    CHECK(v.magnitude.find("×0.70") != std::string::npos);
    CHECK(v.magnitude.find("of the paper's 2") != std::string::npos);
    v = judge_claims(*e.paper, run_of(10.0, 19.0, "discrete-gpu"), RunToRunNoise{}).front();
    CHECK(v.magnitude_outcome == "holds");  // ×0.95
    // Near the tolerance's edge, the interval decides nothing.
    RunRecord edge = run_of(10.0, 15.0, "discrete-gpu");
    edge.cases[1].gpu_frame.samples_ms = rounds(15.0, 0.08);
    CHECK(judge_claims(*e.paper, edge, RunToRunNoise{}).front().magnitude_outcome == "within noise");
    // On lavapipe the same numbers are given, not judged.
    v = judge_claims(*e.paper, run_of(10.0, 15.0, "cpu"), RunToRunNoise{}).front();
    CHECK(v.magnitude_outcome == "not judged on a CPU rasteriser");
    CHECK(v.magnitude.find("×0.75") != std::string::npos);
    const std::string report = paper_report(*e.paper, run_of(10.0, 15.0, "cpu"), RunToRunNoise{});
    CHECK(report.find("not the paper's class of hardware") != std::string::npos);
    const nlohmann::json data = paper_data(*e.paper, run_of(10.0, 15.0, "cpu"), RunToRunNoise{});
    CHECK(data["claims"][0]["states"] == "magnitude");
    CHECK(data["claims"][0]["magnitude"]["outcome"] == "not judged on a CPU rasteriser");
}

TEST_CASE("a speed claim between rows of unequal quality says so") {
    const Experiment e = load("quality.toml", "text = \"PCF costs more than hard shadows\"\nleft = \"PCF\"\nright = \"hard\"\n"
                                              "relation = \"greater\"\nstates = \"magnitude\"\n");
    RunRecord run = run_of(10.0, 20.0);
    CHECK(judge_claims(*e.paper, run, RunToRunNoise{}).front().unequal_quality.empty());
    run.cases[1].image_error->flip_mean = 0.21;  // PCF's image much further from the truth
    const ClaimVerdict v = judge_claims(*e.paper, run, RunToRunNoise{}).front();
    CHECK(v.outcome == "holds");
    CHECK(v.unequal_quality.find("unequal quality") == 0);
    CHECK(v.unequal_quality.find("FLIP 0.21 vs 0.05") != std::string::npos);
    CHECK(paper_report(*e.paper, run, RunToRunNoise{}).find("**unequal quality: 96x64: FLIP 0.21 vs 0.05") != std::string::npos);
    CHECK(paper_data(*e.paper, run, RunToRunNoise{})["claims"][0]["unequal_quality"] == v.unequal_quality);
    // Within the metric's compare tolerance: no flag.
    run.cases[1].image_error->flip_mean = 0.05 * (1 + 1e-4);
    CHECK(judge_claims(*e.paper, run, RunToRunNoise{}).front().unequal_quality.empty());
}

TEST_CASE("a claim about what happens in time, judged on still images, reads 'not tested by canopy'") {
    const Experiment e = load("untested.toml", "text = \"PCF hides the replacement\"\nleft = \"PCF\"\nright = \"hard\"\n"
                                               "metric = \"flip\"\nrelation = \"about\"\nstates = \"direction\"\n"
                                               "why = \"no number\"\nuntested = \"replacement happens as the camera moves\"\n");
    const ClaimVerdict v = judge_claims(*e.paper, run_of(10.0, 20.0), RunToRunNoise{}).front();
    CHECK(v.outcome == "not tested by canopy");  // the images agree exactly: it would have read "holds"
    CHECK_FALSE(v.decided());
    CHECK(v.because == "replacement happens as the camera moves");
}

TEST_CASE("the spread between runs comes from this device's stability runs, else the largest elsewhere, named") {
    const auto write_stability = [&](const std::string& name, const std::string& device, const std::string& ratios) {
        folder().write(name, fmt::format(R"({{"environment": {{"device": "{}"}}, "runs": [{{}}, {{}}, {{}}],
            "cases": [{{"group_baseline": true, "ratio_per_run": [1, 1, 1]}},
                      {{"group_baseline": false, "ratio_per_run": {}}}]}})",
                                         device, ratios));
    };
    write_stability("stability/a/stability.json", "llvmpipe (test)", "[2.0, 2.04, 1.96]");
    write_stability("gpu/b/stability/stability.json", "A GPU", "[1.5, 1.5015, 1.4985]");
    const std::vector<fs::path> folders{folder().path() / "stability", folder().path() / "gpu" / "b" / "stability"};
    const RunToRunNoise cpu = run_to_run_noise(folders, "llvmpipe (test)");
    CHECK(cpu.sigma == doctest::Approx(log_ratio_sigma({2.0, 2.04, 1.96})));
    CHECK(cpu.sigma / 0.02 == doctest::Approx(1.0).epsilon(0.01));
    CHECK(cpu.source.find("stability.json (llvmpipe (test), 3 runs, the largest of 1 cases)") != std::string::npos);
    const RunToRunNoise gpu = run_to_run_noise(folders, "A GPU");
    CHECK(gpu.sigma / 0.001 == doctest::Approx(1.0).epsilon(0.01));
    // An unmeasured device takes the largest spread measured anywhere, and says so.
    const RunToRunNoise other = run_to_run_noise(folders, "another GPU");
    CHECK(other.sigma == cpu.sigma);
    CHECK(other.source.find("no stability run on this device") != std::string::npos);
    CHECK_FALSE(run_to_run_noise({folder().path() / "none"}, "x").known());
    // The committed stability run gives llvmpipe a spread (1-2 %).
    const RunToRunNoise committed =
        run_to_run_noise(stability_folders(CANOPY_SOURCE_DIR), "llvmpipe (LLVM 15.0.6, 256 bits)");
    CHECK(committed.sigma > 0.005);
    CHECK(committed.sigma < 0.05);
}

TEST_CASE("a run is judged again only when its config changed in [paper] alone") {
    const std::string base = experiment_with("text = \"t\"\nleft = \"PCF\"\nright = \"hard\"\nstates = \"magnitude\"\n");
    const fs::path file = folder().write("rejudge.toml", base);
    const Experiment now = load_experiment(file, TechniqueRegistry::instance());
    // The text the run measured: the same but for a claim's words.
    std::string at_run = base;
    at_run.replace(at_run.find("text = \"t\""), 10, "text = \"an older wording\"");
    const std::string recorded = hash_files(at_run, now.hashed_files);
    CHECK(paper_table_only_change(now, file, at_run, recorded).empty());
    // A hash the text does not give: another text or other scenes ran.
    CHECK(paper_table_only_change(now, file, at_run, "0123456789abcdef").find("hashes") != std::string::npos);
    // A measurement setting changed too.
    std::string measured_otherwise = at_run;
    measured_otherwise.replace(measured_otherwise.find("kernel = 3"), 10, "kernel = 5");
    CHECK(paper_table_only_change(now, file, measured_otherwise, hash_files(measured_otherwise, now.hashed_files))
              .find("outside its [paper] table") != std::string::npos);
}

TEST_CASE("the reference's noise: replicates perturbed by its own variance, the same for every case") {
    Image radiance(64, 64), variance(64, 64);
    for (size_t i = 0; i < radiance.pixels.size(); ++i) {
        radiance.pixels[i] = i % 4 == 3 ? 1.0f : 0.5f;
        variance.pixels[i] = i % 4 == 3 ? 1.0f : 0.0004f;  // std 0.02
    }
    const Image a = perturbed_reference(radiance, variance, 0), b = perturbed_reference(radiance, variance, 1);
    CHECK(a.pixels == perturbed_reference(radiance, variance, 0).pixels);  // deterministic: common to every case
    CHECK(a.pixels != b.pixels);                                           // replicates differ
    std::vector<double> offsets;
    size_t alpha_changed = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        if (i % 4 == 3) alpha_changed += a.pixels[i] == 1.0f ? 0 : 1;
        else offsets.push_back(double(a.pixels[i]) - 0.5);
    }
    CHECK(alpha_changed == 0);  // alpha kept
    double mean = 0;
    for (double o : offsets) mean += o;
    mean /= double(offsets.size());
    CHECK(std::abs(mean) < 0.002);
    CHECK(replicate_spread(offsets) / 0.02 == doctest::Approx(1.0).epsilon(0.05));
    // No variance, no noise.
    Image none(64, 64);
    CHECK(perturbed_reference(radiance, none, 3).pixels == radiance.pixels);
    CHECK(std::isnan(replicate_spread({1.0})));
    CHECK(replicate_spread({1.0, 3.0}) == doctest::Approx(std::sqrt(2.0)));
}

TEST_CASE("an error gap inside the reference's noise reads 'within noise'; the note says when it was not measured") {
    const Experiment e = load("error-noise.toml", "text = \"PCF is closer to the truth than hard shadows\"\nleft = \"PCF\"\n"
                                                  "right = \"hard\"\nmetric = \"flip\"\nrelation = \"less\"\n"
                                                  "states = \"direction\"\nwhy = \"no number\"\n");
    RunRecord run = run_of(10.0, 20.0);
    run.cases[0].image_error->flip_mean = 0.100;  // hard
    run.cases[1].image_error->flip_mean = 0.098;  // PCF: 0.002 better
    // Without replicates: decided on the nominal values, and said so.
    ClaimVerdict v = judge_claims(*e.paper, run, RunToRunNoise{}).front();
    CHECK(v.outcome == "holds");
    CHECK(v.because.find("the reference's noise was not measured") != std::string::npos);
    // The gap moves by ±0.003 between replicates of the reference: it decides nothing.
    const std::vector<double> hard{0.100, 0.103, 0.097, 0.101, 0.099, 0.104, 0.096, 0.100};
    std::vector<double> pcf{0.098, 0.097, 0.101, 0.095, 0.100, 0.094, 0.102, 0.098};
    run.cases[0].reference_replicates["flip_mean"] = hard;
    run.cases[1].reference_replicates["flip_mean"] = pcf;
    v = judge_claims(*e.paper, run, RunToRunNoise{}).front();
    CHECK(v.outcome == "within noise");
    CHECK(v.because.find("against the reference's noise ±") != std::string::npos);
    // Replicates that move both cases together (the common noise cancels in the gap): decided.
    for (size_t k = 0; k < pcf.size(); ++k) pcf[k] = hard[k] - 0.002 + (k % 2 ? 1e-4 : -1e-4);
    run.cases[1].reference_replicates["flip_mean"] = pcf;
    CHECK(judge_claims(*e.paper, run, RunToRunNoise{}).front().outcome == "holds");
    // A gap well outside the noise the other way: does not hold.
    run.cases[1].image_error->flip_mean = 0.2;
    for (double& p : pcf) p += 0.1;
    run.cases[1].reference_replicates["flip_mean"] = pcf;
    CHECK(judge_claims(*e.paper, run, RunToRunNoise{}).front().outcome == "does not hold");
}

TEST_CASE("a FLIP claim on a reference not converged for its margin reads 'within noise'") {
    const std::string claim = "text = \"PCF is closer to the truth than hard shadows\"\nleft = \"PCF\"\n"
                              "right = \"hard\"\nmetric = \"flip\"\nrelation = \"less\"\nstates = \"direction\"\n"
                              "why = \"no number\"\n";
    RunRecord run = run_of(10.0, 20.0);
    run.cases[0].image_error->flip_mean = 0.10;
    run.cases[1].image_error->flip_mean = 0.07;  // margin 0.03
    const auto with_convergence = [&](const std::string& flip) {
        std::string text = experiment_with(claim);
        text.replace(text.find("baseline = \"hard\"\n"), 18,
                     "baseline = \"hard\"\nreference_convergence_flip = " + flip +
                         "\nreference_convergence_source = \"a test's sweep\"\n");
        return load_experiment(folder().write("convergence-" + flip + ".toml", text), TechniqueRegistry::instance());
    };
    // FLIP(ref N, ref 4N) = 0.002: converged for a margin of 0.03 (at least 10 times it).
    CHECK(judge_claims(*with_convergence("0.002").paper, run, RunToRunNoise{}).front().outcome == "holds");
    // 0.005: not converged for 0.03 (under 10 x 0.005): nothing decided, and said why.
    const ClaimVerdict v = judge_claims(*with_convergence("0.005").paper, run, RunToRunNoise{}).front();
    CHECK(v.outcome == "within noise");
    CHECK(v.because.find("has not converged for this margin: FLIP(ref N, ref 4N) = 0.005") != std::string::npos);
    CHECK(v.because.find("a test's sweep") != std::string::npos);
    // Without a source the number is refused.
    std::string unsourced = experiment_with(claim);
    unsourced.replace(unsourced.find("baseline = \"hard\"\n"), 18, "baseline = \"hard\"\nreference_convergence_flip = 0.1\n");
    CHECK_THROWS_WITH_AS(load_experiment(folder().write("unsourced.toml", unsourced), TechniqueRegistry::instance()),
                         doctest::Contains("say where the reference's convergence was measured"), ConfigError);
}

TEST_CASE("results.json records each reference's noise per metric: the largest replicate spread of its cases") {
    RunRecord run = run_of(10.0, 20.0);
    ReferenceRecord reference;
    reference.scene = "tiny";
    reference.resolution = {96, 64};
    run.references.push_back(reference);
    run.cases[0].reference_replicates["flip_mean"] = {0.10, 0.12, 0.08};  // spread 0.02
    run.cases[1].reference_replicates["flip_mean"] = {0.10, 0.11, 0.09};  // spread 0.01
    const nlohmann::json j = nlohmann::json::parse(json_report(run));
    CHECK(j["references"][0]["metric_noise"]["flip_mean"].get<double>() == doctest::Approx(0.02));
    CHECK(j["cases"][1]["reference_replicates"]["flip_mean"].size() == 3);
}
