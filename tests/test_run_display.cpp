// What a run shows a person: case labels that tell swept rows apart, progress that says where a
// reference comes from and how long is left, a compact console table, and what a technique needs.
#include "config/experiment_config.hpp"
#include "core/graph_requirements.hpp"
#include "report/console_table.hpp"
#include "report/markdown_report.hpp"
#include "run/case_labels.hpp"
#include "run/progress.hpp"

#include <doctest/doctest.h>

#include <cstdio>
#include <sstream>
#include <string>

using namespace canopy;

namespace {

const Technique& technique(const std::string& name) {
    const Technique* t = TechniqueRegistry::instance().find(name);
    REQUIRE(t != nullptr);
    return *t;
}

Case make_case(const std::string& name, const std::map<std::string, ParamValue>& given) {
    Case c;
    c.technique = name;
    c.params = ParamSet::resolve(technique(name).params(), given, {}, {}, name);
    c.id = name;
    return c;
}

// Everything a Progress prints, as lines, for a non-terminal stream.
class Captured {
public:
    Captured() : file_(std::tmpfile()) {}
    ~Captured() { std::fclose(file_); }
    std::FILE* file() { return file_; }
    std::string text() {
        std::fflush(file_);
        std::rewind(file_);
        std::string out;
        char buffer[512];
        while (size_t n = std::fread(buffer, 1, sizeof buffer, file_)) out.append(buffer, n);
        return out;
    }

private:
    std::FILE* file_;
};

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

size_t display_columns(const std::string& line) {
    size_t n = 0;
    for (unsigned char c : line) n += (c & 0xC0) != 0x80 ? 1 : 0;
    return n;
}

}  // namespace

TEST_CASE("a swept parameter shows on every row, also where its value is the default") {
    // kernel = [3, 5] with default 3: the rows read kernel=3 and kernel=5, never "-".
    const std::vector<Case> cases = {make_case("shadow.pcf", {{"kernel", 3LL}}), make_case("shadow.pcf", {{"kernel", 5LL}}),
                                     make_case("shadow.hard", {})};
    for (const ParamSpec& spec : technique("shadow.pcf").params())
        if (spec.name == "kernel") REQUIRE(to_string(spec.default_value) == "3");  // the premise
    const CaseLabels labels(cases, TechniqueRegistry::instance());
    CHECK(labels.parameters(cases[0]) == "kernel=3");
    CHECK(labels.parameters(cases[1]) == "kernel=5");
    CHECK(labels.parameters(cases[2]) == "-");  // nothing swept, nothing changed
    CHECK(labels.swept("shadow.pcf", "kernel"));
    CHECK_FALSE(labels.swept("shadow.pcf", "resolution"));

    // A value changed from its default but not swept still shows; swept across two entries counts.
    const std::vector<Case> two_entries = {make_case("shadow.pcf", {{"resolution", 256LL}}),
                                           make_case("shadow.pcf", {{"resolution", 256LL}, {"kernel", 7LL}})};
    const CaseLabels split(two_entries, TechniqueRegistry::instance());
    CHECK(split.parameters(two_entries[0]) == "resolution=256 kernel=3");
    CHECK(split.parameters(two_entries[1]) == "resolution=256 kernel=7");
}

TEST_CASE("the swept label reaches the tables of a loaded experiment") {
    const Experiment e =
        load_experiment(std::string(CANOPY_TEST_DATA) + "/experiments/tiny.toml", TechniqueRegistry::instance());
    const std::vector<Case> cases = expand_cases(e, TechniqueRegistry::instance());
    const CaseLabels labels(cases, TechniqueRegistry::instance());
    REQUIRE(cases.size() == 3);
    CHECK(labels.parameters(cases[1]) == "resolution=256 kernel=3");
    CHECK(labels.parameters(cases[2]) == "resolution=256 kernel=5");
}

TEST_CASE("ETA: mean case time times cases left, plus the references still to obtain") {
    CHECK_FALSE(estimate_remaining_seconds(0, 0, 10, 5, 1, 1).has_value());  // nothing measured yet
    CHECK(*estimate_remaining_seconds(6.0, 3, 7, 0, 0, 2) == doctest::Approx(14.0));
    CHECK(*estimate_remaining_seconds(6.0, 3, 7, 10.0, 1, 2) == doctest::Approx(34.0));
    CHECK(*estimate_remaining_seconds(6.0, 3, 0, 10.0, 1, 0) == doctest::Approx(0.0));
    CHECK(clock_text(65) == "1:05");
    CHECK(clock_text(3725) == "1:02:05");
}

TEST_CASE("progress says where a reference comes from, when it is done, the ETA and the end") {
    Captured out;
    {
        Progress progress(4, 2, out.file(), false);
        progress.kept_case(0, "tiny 96x64 shadow.hard -");
        progress.reference_started(1, "tiny 96x64", false);
        progress.reference_progress(1, "tiny 96x64", 0.5);
        progress.reference_finished(1, "tiny 96x64", 2.0, false);
        progress.start_case(1, "tiny 96x64 shadow.pcf kernel=3");
        progress.finish_case(1, "tiny 96x64 shadow.pcf kernel=3", 3.0, true);
        progress.reference_started(2, "big 640x360", true);
        progress.reference_finished(2, "big 640x360", 0.0, true);
        progress.done();
    }
    const auto text = lines(out.text());
    REQUIRE(text.size() == 7);
    CHECK(text[0] == "[1/4] tiny 96x64 shadow.hard - kept from the earlier run");
    CHECK(text[1] == "[2/4] ray-tracing reference tiny 96x64 ...");
    CHECK(text[2] == "[2/4] reference tiny 96x64 ray-traced in 2.0 s");
    CHECK(text[3] == "[2/4] tiny 96x64 shadow.pcf kernel=3 ...");
    // 2 cases left at 3 s each, 1 reference left at 2 s: 8 s.
    CHECK(text[4] == "[2/4] tiny 96x64 shadow.pcf kernel=3 done in 3.0 s, ETA 0:08");
    CHECK(text[5] == "[3/4] reference big 640x360: from the cache");
    CHECK(text[6].find("finished 2 of 4 cases in ") == 0);
    CHECK(text[6].find("(1 kept from the earlier run)") != std::string::npos);
}

TEST_CASE("not on a terminal, a long group or reference says where it is at least every heartbeat") {
    Captured out;
    {
        // A heartbeat of 0 s: every round and every reference step is due a line.
        Progress progress(40, 1, out.file(), false, 0.0);
        progress.reference_progress(0, "field 640x360", 0.25);
        progress.start_group(0, "field 640x360", 40, 20, 3);
        progress.group_round("field 640x360", 1, 16, 4, 20);
        progress.group_round("field 640x360", 3, 9, 1, 20);  // more chunks than planned (memory split one)
    }
    const auto text = lines(out.text());
    REQUIRE(text.size() == 4);
    CHECK(text[0].find("[1/40] ray-tracing reference field 640x360 25%, elapsed 0:00") == 0);
    CHECK(text[1] == "[1/40] measuring field 640x360: 40 cases interleaved, 20 rounds, in 3 chunks or more ...");
    CHECK(text[2].find("[0/40] measuring field 640x360: chunk 2/3 (16 cases), round 4/20, elapsed 0:00, ETA ") == 0);
    CHECK(text[3].find("chunk 4/4+ (9 cases), round 1/20") != std::string::npos);

    // With the default heartbeat (30 s) a round that follows a line by less prints nothing.
    Captured quiet;
    {
        Progress progress(40, 1, quiet.file(), false);
        progress.start_group(0, "field 640x360", 40, 20, 3);
        progress.group_round("field 640x360", 0, 16, 1, 20);
        progress.reference_progress(0, "field 640x360", 0.5);
    }
    CHECK(lines(quiet.text()).size() == 1);
}

TEST_CASE("the console table is compact; results.md keeps every column") {
    RunRecord run;
    for (int kernel : {3, 5, 7}) {
        CaseResult c;
        c.scene = "a-scene-with-a-long-name";
        c.resolution = {1920, 1080};
        c.technique = "shadow.power-cdf";
        c.params_shown = "resolution=2048 precision=fp16 filter=" + std::to_string(kernel) + " pattern=poisson exact=true";
        c.gpu_frame.stats = {20, 123.456, 1, 1, 1, 12.3, 0.1};
        c.wall.stats = c.gpu_frame.stats;
        c.passes = {{"shadow_map", {}, c.gpu_frame.stats}, {"moment_prefilter_x", {}, c.gpu_frame.stats},
                    {"moment_prefilter_y", {}, c.gpu_frame.stats}, {"lit", {}, c.gpu_frame.stats}};
        ImageMetrics m{};
        m.rmse = 0.012345;
        m.psnr = 38.1234;
        m.ssim = 0.98765;
        m.flip_mean = 0.0123456;
        m.light_bleeding = 0.0012345;
        m.over_darkening = 0.0012345;
        m.penumbra_rmse = 0.0612345;
        c.image_error = m;
        c.ok = kernel != 7;
        c.error = c.ok ? "" : "123 pixels are NaN or Inf";
        run.cases.push_back(c);
    }
    const std::string table = console_table(run);
    for (const std::string& line : lines(table)) {
        CAPTURE(line);
        CHECK(display_columns(line) <= 120);
    }
    CHECK(table.find("a-scene-with-a-long-name 1920x1080\n") == 0);
    CHECK(table.find("penumbra RMSE") != std::string::npos);
    CHECK(table.find("FAILED") != std::string::npos);
    CHECK(table.find("resolution=2048 precision=fp16 …") != std::string::npos);  // cut, and says so
    CHECK(table.find("moment_prefilter_x") == std::string::npos);

    const std::string full = markdown_table(run);
    CHECK(full.find("moment_prefilter_x") != std::string::npos);
    CHECK(full.find("pattern=poisson exact=true") != std::string::npos);
    CHECK(full.find("123 pixels are NaN or Inf") != std::string::npos);
    CHECK(lines(full)[0].size() > 200);  // why the console gets the compact one
}

TEST_CASE("a technique's requirements, in words, from its plan at the defaults") {
    auto needs = [](const std::string& name) {
        const Technique& t = technique(name);
        std::string all;
        for (const std::string& need : graph_requirements(t.graph(ParamSet::resolve(t.params(), {}, {}, {}, name))))
            all += need + "; ";
        return all;
    };
    CHECK(needs("shadow.pcss").find("an area light (rect or sphere)") != std::string::npos);
    CHECK(needs("shadow.ssss").find("an area light (rect or sphere)") != std::string::npos);
    CHECK(needs("shadow.hard").find("area light") == std::string::npos);
    CHECK(needs("shadow.hard").find("a shadow-casting light") != std::string::npos);
    CHECK(needs("shadow.vsm").find("compute filter passes") != std::string::npos);
    CHECK(needs("shadow.hard").find("a scene without populations") != std::string::npos);  // renders none
}
