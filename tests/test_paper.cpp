// The [paper] table of an experiment: parsing with file:line errors, and claim verdicts.
#include "config/experiment_config.hpp"
#include "report/paper_report.hpp"
#include "report/text_table.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

using namespace canopy;
namespace fs = std::filesystem;

namespace {

fs::path write_experiment(const std::string& name, const std::string& paper_section) {
    static const test::TempFolder folder("canopy-test-paper");  // this process's, removed at exit
    return folder.write(name, "[experiment]\nscenes = [\"" + std::string(CANOPY_TEST_DATA) + "/scenes/tiny.toml\"]\n"
                              "[[technique]]\nname = \"shadow.hard\"\n[[technique]]\nname = \"shadow.pcf\"\n"
                              "[technique.params]\nkernel = [3, 5]\n" +
                                  paper_section);
}

const std::string kPaper = R"(
[paper]
id = "T1"
unit = "fps"
column_key = "screen"
columns = ["96x64"]
baseline = "hard"
[[paper.row]]
label = "hard"
technique = "shadow.hard"
values = [400]
[[paper.row]]
label = "PCF 3"
technique = "shadow.pcf"
params = { kernel = 3 }
values = [200]
[[paper.row]]
label = "PCF 5"
technique = "shadow.pcf"
params = { kernel = 5 }
values = [100]
[[paper.claim]]
text = "PCF 5 costs more than PCF 3"
left = "PCF 5"
right = "PCF 3"
relation = "greater"
states = "magnitude"
[[paper.claim]]
text = "PCF 3 costs about as much as hard shadows"
left = "PCF 3"
right = "hard"
relation = "about"
tolerance = 0.1
tolerance_reason = "the test's own, to show a tolerance other than the table's"
states = "magnitude"
[[paper.claim]]
text = "PCF 5 is closer to the truth in the penumbra than hard shadows"
left = "PCF 5"
right = "hard"
metric = "penumbra_rmse"
relation = "less"
states = "direction"
why = "no number"
)";

// The tests of one run's numbers alone: no spread between runs added to the intervals.
const RunToRunNoise kNoNoise{};

// A case of the one group (tiny 96x64) measured in the same rounds as the others, with these GPU
// samples, one per round.
CaseResult fake_case(const std::string& technique, long long kernel, std::vector<double> samples, double penumbra_rmse) {
    CaseResult c;
    c.id = technique + "_" + std::to_string(kernel);
    c.technique = technique;
    c.scene = "tiny";
    c.resolution = {96, 64};
    c.params = {{"resolution", 1024LL}};
    if (technique == "shadow.pcf") c.params.push_back({"kernel", kernel});
    c.gpu_frame.samples_ms = std::move(samples);
    c.gpu_frame.stats = summarize(c.gpu_frame.samples_ms);
    ImageMetrics m{};
    m.penumbra_rmse = penumbra_rmse;
    m.columns = {.visibility = true, .shadow_regions = true};  // the shadow family's
    c.image_error = m;
    return c;
}

std::vector<double> constant(double ms, size_t rounds = 20) { return std::vector<double>(rounds, ms); }

// `ms` times a and b in turn: a per-round ratio that swings between them.
std::vector<double> alternating(double ms, double a, double b, size_t rounds = 20) {
    std::vector<double> v;
    for (size_t r = 0; r < rounds; ++r) v.push_back(ms * (r % 2 ? b : a));
    return v;
}

}  // namespace

TEST_CASE("a [paper] table is parsed with its rows and claims") {
    const Experiment e = load_experiment(write_experiment("ok.toml", kPaper), TechniqueRegistry::instance());
    REQUIRE(e.paper.has_value());
    CHECK(e.paper->id == "T1");
    REQUIRE(e.paper->rows.size() == 3);
    CHECK(e.paper->rows[1].params.at("kernel") == ParamValue(3LL));
    CHECK(e.paper->rows[2].values == std::vector<double>{100});
    REQUIRE(e.paper->claims.size() == 3);
    CHECK(e.paper->claims[2].metric == "penumbra_rmse");
}

TEST_CASE("claims are judged per column from canopy's numbers") {
    const Experiment e = load_experiment(write_experiment("judge.toml", kPaper), TechniqueRegistry::instance());
    RunRecord run;
    run.cases = {fake_case("shadow.hard", 0, constant(10.0), 0.06), fake_case("shadow.pcf", 3, constant(10.5), 0.04),
                 fake_case("shadow.pcf", 5, constant(20.0), 0.03)};
    auto verdicts = judge_claims(*e.paper, run, kNoNoise);
    REQUIRE(verdicts.size() == 3);
    CHECK(verdicts[0].outcome == "holds");  // 20 > 10.5 in every round
    CHECK(verdicts[1].outcome == "holds");  // 10.5 / 10 within 10 % in every round
    CHECK(verdicts[2].outcome == "holds");  // 0.03 < 0.06
    run.cases[1].gpu_frame.samples_ms = constant(12.0);  // now 20 % above hard in every round
    verdicts = judge_claims(*e.paper, run, kNoNoise);
    CHECK(verdicts[1].outcome == "does not hold");
    CHECK(verdicts[1].because.find("ratio 1.20 [1.20, 1.20]") != std::string::npos);
    std::string report = paper_report(*e.paper, run, kNoNoise);
    CHECK(report.find("# T1") != std::string::npos);
    CHECK(report.find("2.00 → **1.20** [1.20, 1.20]") != std::string::npos);  // paper 400 vs 200 fps: twice the time

    // A ratio of 1.1 at the median that swings between 0.95 and 1.25 from round to round: its
    // interval reaches both sides of the 10 % tolerance -> within noise.
    run.cases[1].gpu_frame.samples_ms = alternating(10.0, 0.95, 1.25);
    verdicts = judge_claims(*e.paper, run, kNoNoise);
    CHECK(verdicts[1].outcome == "within noise");
    // PCF 5 at 1.05 x PCF 3 at the median, swinging between 0.8 and 1.3: within noise.
    std::vector<double> pcf5;
    for (size_t r = 0; r < 20; ++r) pcf5.push_back(run.cases[1].gpu_frame.samples_ms[r] * (r % 4 < 2 ? 0.8 : 1.3));
    run.cases[2].gpu_frame.samples_ms = pcf5;
    verdicts = judge_claims(*e.paper, run, kNoNoise);
    CHECK(verdicts[0].outcome == "within noise");
    CHECK_FALSE(verdicts[0].holds());
    // The rows' medians alone (10.0 x 1.1 and 10.0 x 1.1 x 1.05) would say "holds": the verdict
    // comes from the paired rounds.
    run.cases.pop_back();  // no PCF 5 case: not measured, never "holds"
    verdicts = judge_claims(*e.paper, run, kNoNoise);
    CHECK(verdicts[0].outcome == "not measured");
    CHECK_FALSE(verdicts[0].decided());
}

TEST_CASE("no verdict rests on a case whose reference is degenerate (every technique matches it)") {
    const Experiment e = load_experiment(write_experiment("degenerate.toml", kPaper), TechniqueRegistry::instance());
    RunRecord run;
    run.cases = {fake_case("shadow.hard", 0, constant(10.0), 0.06), fake_case("shadow.pcf", 3, constant(10.5), 0.04),
                 fake_case("shadow.pcf", 5, constant(20.0), 0.03)};
    ReferenceRecord reference;
    reference.scene = "tiny";
    reference.resolution = {96, 64};
    run.references = {reference};
    REQUIRE(judge_claims(*e.paper, run, kNoNoise)[2].outcome == "holds");
    // A camera inside a closed sphere: no lit pixel, one colour everywhere.
    run.references[0].degenerate = {"no lit pixels", "uniform image"};
    for (const ClaimVerdict& v : judge_claims(*e.paper, run, kNoNoise)) {
        CAPTURE(v.text);
        CHECK(v.outcome == "not judged: flagged case");
        CHECK_FALSE(v.decided());
        CHECK(v.because.find("every case it compares is flagged") != std::string::npos);
    }
    // paper.md flags the reference under its heading and says why beside each verdict.
    const std::string report = paper_report(*e.paper, run, kNoNoise);
    CHECK(report.find("not judged: flagged case") != std::string::npos);
    CHECK(report.find("**Flagged:** tiny 96x64: degenerate reference: no lit pixels, uniform image.") != std::string::npos);
    run.references[0].degenerate.clear();
    CHECK(paper_report(*e.paper, run, kNoNoise).find("Flagged") == std::string::npos);
}

TEST_CASE("a timing claim from too few samples says so instead of a verdict") {
    const Experiment e = load_experiment(write_experiment("few.toml", kPaper), TechniqueRegistry::instance());
    RunRecord run;
    run.cases = {fake_case("shadow.hard", 0, constant(10.0, 3), 0.06), fake_case("shadow.pcf", 3, constant(10.5, 3), 0.04),
                 fake_case("shadow.pcf", 5, constant(20.0, 3), 0.03)};  // --quick: 3 rounds
    auto verdicts = judge_claims(*e.paper, run, kNoNoise);
    CHECK(verdicts[0].outcome == "too few samples");  // 20 > 10.5, but from 3 rounds each
    CHECK(verdicts[0].because.find("too few samples (3 < 6)") == 0);
    CHECK_FALSE(verdicts[0].decided());
    CHECK(verdicts[1].outcome == "too few samples");
    CHECK(verdicts[2].outcome == "holds");  // an error claim: renders are deterministic
    // One case short is enough to withhold the verdict; at the minimum it is given.
    auto set_rounds = [&](size_t i, size_t rounds) {
        run.cases[i].gpu_frame.samples_ms = constant(run.cases[i].gpu_frame.samples_ms[0], rounds);
        run.cases[i].gpu_frame.stats = summarize(run.cases[i].gpu_frame.samples_ms);
    };
    set_rounds(0, kMinTimingSamples);
    set_rounds(2, kMinTimingSamples);
    verdicts = judge_claims(*e.paper, run, kNoNoise);
    CHECK(verdicts[0].outcome == "too few samples");  // PCF 3 still has 3
    set_rounds(1, kMinTimingSamples);
    verdicts = judge_claims(*e.paper, run, kNoNoise);
    CHECK(verdicts[0].outcome == "holds");
    CHECK(verdicts[1].outcome == "holds");
    const std::string report = paper_report(*e.paper, run, kNoNoise);
    CHECK(report.find("too few samples") != std::string::npos);  // the note on the rule
}

TEST_CASE("paper table errors name file:line and the fix") {
    auto error_of = [](const std::string& name, const std::string& section) {
        try {
            load_experiment(write_experiment(name, section), TechniqueRegistry::instance());
        } catch (const ConfigError& e) {
            return e.formatted();
        }
        return std::string("no error");
    };
    const std::string wrong_label = error_of("label.toml", R"(
[paper]
id = "T"
columns = ["96x64"]
baseline = "hrad"
[[paper.row]]
label = "hard"
technique = "shadow.hard"
)");
    CHECK(wrong_label.find("label.toml:") != std::string::npos);
    CHECK(wrong_label.find("did you mean 'hard'") != std::string::npos);

    const std::string wrong_count = error_of("count.toml", R"(
[paper]
id = "T"
columns = ["a", "b"]
[[paper.row]]
label = "hard"
technique = "shadow.hard"
values = [1, 2, 3]
)");
    CHECK(wrong_count.find("3 values for 2 columns") != std::string::npos);

    const std::string wrong_relation = error_of("relation.toml", R"(
[paper]
id = "T"
columns = ["a"]
[[paper.row]]
label = "hard"
technique = "shadow.hard"
[[paper.claim]]
text = "x"
left = "hard"
right = "hard"
relation = "smaller"
)");
    CHECK(wrong_relation.find("relation.toml:20") != std::string::npos);
    CHECK(wrong_relation.find("less") != std::string::npos);
}

TEST_CASE("time ratios keep two figures however small: a 70x speed-up does not print as 0.01") {
    CHECK(ratio_number(1.0) == "1.00");
    CHECK(ratio_number(0.155) == "0.15");
    CHECK(ratio_number(0.0142) == "0.014");
    CHECK(ratio_number(0.0023) == "0.0023");
    CHECK(ratio_number(0.0) == "0.00");
    CHECK(ratio_cell(Estimate{0.0142, {0.0139, 0.0145}, 10}) == "0.014 [0.014, 0.015]");
}

TEST_CASE("a row may time one pass, its share of the frame paired round by round; a claim may compare two columns") {
    const std::string paper = R"(
[paper]
id = "T2"
unit = "ms"
column_key = "scene"
columns = ["high", "ant"]
baseline = "frame"
[[paper.row]]
label = "frame"
technique = "shadow.hard"
values = [10, 80]
[[paper.row]]
label = "lit pass"
technique = "shadow.hard"
pass = "lit"
values = [5, 20]
[[paper.claim]]
text = "the lit pass is less than the frame"
left = "lit pass"
right = "frame"
states = "magnitude"
[[paper.claim]]
text = "the high view is faster than the ant's"
left = "frame"
right = "frame"
left_column = "high"
right_column = "ant"
states = "magnitude"
)";
    const Experiment e = load_experiment(write_experiment("pass.toml", paper), TechniqueRegistry::instance());
    REQUIRE(e.paper);
    CHECK(pass_label(e.paper->rows[1]) == "lit");
    CHECK(e.paper->claims[1].left_column == "high");
    // Two views, each its own group: the lit pass is a fixed share of each round's frame, however
    // the rounds swing.
    const auto view = [](const std::string& scene, double ms, double share, size_t group) {
        CaseResult c = fake_case("shadow.hard", 0, alternating(ms, 0.8, 1.3), 0.0);
        c.id = scene;
        c.scene = scene;
        c.group = group;
        TimingSeries lit;
        lit.name = "lit";
        for (double s : c.gpu_frame.samples_ms) lit.samples_ms.push_back(share * s);
        lit.stats = summarize(lit.samples_ms);
        c.passes = {lit};
        return c;
    };
    RunRecord run;
    run.cases = {view("high", 10.0, 0.5, 0), view("ant", 80.0, 0.25, 1)};
    const std::string report = paper_report(*e.paper, run, kNoNoise);
    CHECK(report.find("| lit pass | 0.50 → **0.50** [0.50, 0.50] | 0.25 → **0.25** [0.25, 0.25] |") != std::string::npos);
    CHECK(report.find("5 ms / 5.") != std::string::npos);  // raw: the pass's own median
    const auto verdicts = judge_claims(*e.paper, run, kNoNoise);
    REQUIRE(verdicts.size() == 2);
    CHECK(verdicts[0].outcome == "holds");
    CHECK(verdicts[1].outcome == "holds");
    CHECK(verdicts[1].because.find("high vs ant") != std::string::npos);
    CHECK(verdicts[1].because.find("not paired") != std::string::npos);
    // A case without the pass: no number, not a verdict.
    run.cases[0].passes.clear();
    run.cases[1].passes.clear();
    CHECK(judge_claims(*e.paper, run, kNoNoise)[0].outcome == "not measured");
}

TEST_CASE("a row may sum several passes round by round (Lemme's t_v over his three volume levels)") {
    const std::string paper = R"(
[paper]
id = "T4"
unit = "ms"
column_key = "scene"
columns = ["high"]
baseline = "frame"
[[paper.row]]
label = "frame"
technique = "shadow.hard"
values = [10]
[[paper.row]]
label = "two passes"
technique = "shadow.hard"
pass = ["depth", "lit"]
values = [6]
)";
    const Experiment e = load_experiment(write_experiment("passes.toml", paper), TechniqueRegistry::instance());
    REQUIRE(e.paper);
    CHECK(pass_label(e.paper->rows[1]) == "depth + lit");
    CHECK(e.paper->rows[1].passes == std::vector<std::string>{"depth", "lit"});
    // The two passes are 0.2 and 0.4 of every round's frame, rounds swinging: their sum is 0.6 of it.
    CaseResult c = fake_case("shadow.hard", 0, alternating(10.0, 0.8, 1.3), 0.0);
    c.id = c.scene = "high";
    for (const auto& [name, share] : {std::pair{"depth", 0.2}, std::pair{"lit", 0.4}}) {
        TimingSeries pass;
        pass.name = name;
        for (double s : c.gpu_frame.samples_ms) pass.samples_ms.push_back(share * s);
        pass.stats = summarize(pass.samples_ms);
        c.passes.push_back(pass);
    }
    RunRecord run;
    run.cases = {c};
    const std::string report = paper_report(*e.paper, run, kNoNoise);
    CHECK(report.find("| two passes | 0.60 → **0.60** [0.60, 0.60] |") != std::string::npos);
    // A case missing one of them: no number.
    run.cases[0].passes.pop_back();
    CHECK(paper_report(*e.paper, run, kNoNoise).find("| two passes | 0.60 → - |") != std::string::npos);
    // An empty list is refused, naming the row.
    const std::string list = "[\"depth\", \"lit\"]";
    const std::string empty = std::string(paper).replace(paper.find(list), list.size(), "[]");
    CHECK_THROWS_WITH_AS(load_experiment(write_experiment("passes-empty.toml", empty), TechniqueRegistry::instance()),
                         doctest::Contains("lists no pass"), ConfigError);
}

TEST_CASE("a claim across columns names both, and only both") {
    const auto error_of = [](const std::string& claim) {
        const std::string paper = "\n[paper]\nid = \"T3\"\ncolumns = [\"a\", \"b\"]\n[[paper.row]]\nlabel = \"x\"\n"
                                  "technique = \"shadow.hard\"\n[[paper.claim]]\ntext = \"t\"\nleft = \"x\"\nright = \"x\"\n"
                                  "states = \"direction\"\nwhy = \"no number\"\n" +
                                  claim;
        try {
            load_experiment(write_experiment("cross.toml", paper), TechniqueRegistry::instance());
        } catch (const ConfigError& e) {
            return e.formatted();
        }
        return std::string();
    };
    CHECK(error_of("left_column = \"a\"\n").find("needs both left_column and right_column") != std::string::npos);
    CHECK(error_of("left_column = \"a\"\nright_column = \"c\"\n").find("'c' is not one of the paper's columns") !=
          std::string::npos);
    CHECK(error_of("left_column = \"a\"\nright_column = \"b\"\ncolumn = \"a\"\n").find("not column") != std::string::npos);
    CHECK(error_of("left_column = \"a\"\nright_column = \"b\"\n").empty());
}

TEST_CASE("a claim may compare with a factor or an offset of the right row: 'at most a quarter', 'at most 0.02 more'") {
    const std::string paper = kPaper + R"(
[[paper.claim]]
text = "PCF 3 costs less than 0.6 x PCF 5"
left = "PCF 3"
right = "PCF 5"
factor = 0.6
states = "magnitude"
[[paper.claim]]
text = "PCF 3's penumbra error is at most 0.015 above PCF 5's"
left = "PCF 3"
right = "PCF 5"
metric = "penumbra_rmse"
offset = 0.015
states = "direction"
why = "canopy target"
)";
    const Experiment e = load_experiment(write_experiment("factor.toml", paper), TechniqueRegistry::instance());
    RunRecord run;
    run.cases = {fake_case("shadow.hard", 0, constant(10.0), 0.06), fake_case("shadow.pcf", 3, constant(10.5), 0.04),
                 fake_case("shadow.pcf", 5, constant(20.0), 0.03)};
    auto verdicts = judge_claims(*e.paper, run, kNoNoise);
    REQUIRE(verdicts.size() == 5);
    CHECK(verdicts[3].outcome == "holds");  // 10.5 / 20 = 0.525 < 0.6
    CHECK(verdicts[3].because.find("below 0.6 x PCF 5's") != std::string::npos);
    CHECK(verdicts[4].outcome == "holds");  // 0.04 < 0.03 + 0.015
    run.cases[1].gpu_frame.samples_ms = constant(13.0);  // 0.65 > 0.6
    run.cases[1].image_error->penumbra_rmse = 0.05;       // 0.05 >= 0.045
    verdicts = judge_claims(*e.paper, run, kNoNoise);
    CHECK(verdicts[3].outcome == "does not hold");
    CHECK(verdicts[4].outcome == "does not hold");
    // Offsets are for error metrics; factor and offset go with less or greater.
    const auto error_of = [](const std::string& claim) {
        try {
            load_experiment(write_experiment("bad-factor.toml", kPaper + "[[paper.claim]]\ntext = \"t\"\nleft = \"hard\"\n"
                                                                             "right = \"PCF 3\"\n" + claim),
                            TechniqueRegistry::instance());
        } catch (const ConfigError& e) {
            return e.formatted();
        }
        return std::string();
    };
    CHECK(error_of("offset = 0.1\n").find("'offset' applies to error metrics") != std::string::npos);
    CHECK(error_of("relation = \"about\"\nfactor = 2\n").find("go with less or greater") != std::string::npos);
    CHECK(error_of("factor = 0\n").find("must be positive") != std::string::npos);
}

TEST_CASE("paper.json holds paper.md's numbers as data: ratios with intervals, times, errors, verdicts") {
    const Experiment e = load_experiment(write_experiment("data.toml", kPaper), TechniqueRegistry::instance());
    RunRecord run;
    run.experiment = "T1-run";
    run.environment.git_commit = "0123abcd";
    run.environment.device.name = "llvmpipe (test)";
    run.cases = {fake_case("shadow.hard", 0, constant(10.0), 0.06), fake_case("shadow.pcf", 3, constant(12.0), 0.04)};
    const nlohmann::json data = paper_data(*e.paper, run, kNoNoise);
    CHECK(data["id"] == "T1");
    // Where the numbers come from: the run's commit and device, and its whole environment.
    CHECK(data["commit"] == "0123abcd");
    CHECK(data["device"] == "llvmpipe (test)");
    CHECK(data["environment"]["commit"] == "0123abcd");
    CHECK(data["columns"] == nlohmann::json::array({"96x64"}));
    REQUIRE(data["rows"].size() == 3);
    const nlohmann::json& pcf3 = data["rows"][1];
    CHECK(pcf3["label"] == "PCF 3");
    CHECK(pcf3["params"]["kernel"] == "3");
    CHECK(pcf3["paper_values"][0].get<double>() == 200);
    CHECK(pcf3["paper_ratio"][0].get<double>() == doctest::Approx(2.0));  // 400 fps against 200: twice the time
    CHECK(pcf3["canopy_ratio"][0]["median"].get<double>() == doctest::Approx(1.2));
    CHECK(pcf3["canopy_ratio"][0]["low"].get<double>() == doctest::Approx(1.2));
    CHECK(pcf3["canopy_ms"][0]["median"].get<double>() == doctest::Approx(12.0));
    CHECK(pcf3["case_ids"][0] == "shadow.pcf_3");
    CHECK(pcf3["errors"]["penumbra_rmse"][0].get<double>() == doctest::Approx(0.04));
    // PCF 5 has no case: nulls, not zeros.
    const nlohmann::json& pcf5 = data["rows"][2];
    CHECK(pcf5["canopy_ratio"][0].is_null());
    CHECK(pcf5["canopy_ms"][0].is_null());
    CHECK(pcf5["errors"]["penumbra_rmse"][0].is_null());
    // The claims, as judge_claims (and paper.md) has them.
    const std::vector<ClaimVerdict> verdicts = judge_claims(*e.paper, run, kNoNoise);
    REQUIRE(data["claims"].size() == verdicts.size());
    for (size_t i = 0; i < verdicts.size(); ++i) {
        CHECK(data["claims"][i]["outcome"] == verdicts[i].outcome);
        CHECK(data["claims"][i]["text"] == verdicts[i].text);
    }
    CHECK(data["claims"][1]["outcome"] == "does not hold");  // 1.2 is outside 10 % of hard
}
