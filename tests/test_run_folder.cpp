// What a run's folder holds and who may write there: the run's identity, the output-folder
// decision (new, continue, refuse, replace), results.json read back exactly, and paths recorded
// relative to the checkout.
#include "config/experiment.hpp"
#include "core/error.hpp"
#include "report/atomic_file.hpp"
#include "report/json_record_reader.hpp"
#include "report/json_report.hpp"
#include "run/experiment_runner.hpp"
#include "run/kernel_scaling.hpp"
#include "run/output_folder.hpp"
#include "run/recorded_path.hpp"
#include "run/run_identity.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace canopy;
namespace fs = std::filesystem;

namespace {

Experiment tiny_experiment() {
    Experiment e;
    e.name = "tiny";
    e.config_hash = "5d8ae7b4e274bd95";
    return e;
}

Environment lavapipe() {
    Environment env;
    env.device.name = "llvmpipe (LLVM 15.0.6, 256 bits)";
    env.device.driver_info = "Mesa 22.3.6 (LLVM 15.0.6)";
    env.git_commit = "3a3b7f9";
    env.build_type = "Release";
    env.lp_num_threads = "unset";
    env.nproc = 2;
    return env;
}

RunIdentity identity(bool quick = true, ImageOutput images = ImageOutput::all, std::string hash = "5d8ae7b4e274bd95") {
    Experiment e = tiny_experiment();
    e.config_hash = std::move(hash);
    RunOptions options;
    options.quick = quick;
    options.images = images;
    return make_run_identity(e, options, lavapipe());
}

// A record with every kind of value a results.json holds, including the awkward ones.
RunRecord awkward_record(const RunIdentity& id) {
    RunRecord run;
    run.experiment = "tiny";
    run.description = "a \"quoted\" description";
    run.config_file = "tests/data/experiments/tiny.toml";
    run.identity = id;
    run.warmup_frames = 1;
    run.rounds = 3;
    run.frames_per_sample = 1;
    run.quick = true;
    run.shard = "2/3";  // as a merged run would not have it, but every field must read back
    run.merged_from = {{"1/3", "node-1", "2026-01-01T00:00:00Z", "2026-01-01T00:01:00Z", 3, {"tiny 96x64"}}};
    run.started_at = "2026-01-01T00:00:00Z";
    run.resumed_at = {"2026-01-01T00:01:00Z"};
    run.status = "interrupted";
    run.planned_cases = 3;
    run.reference_enabled = true;
    run.camera_path = CameraPath{2, {{{0, 1, 2}, {0, 0, 0}, 0.0f}, {{1.0f / 3.0f, 2, 3}, {0, 0.5f, 0}, 30.0f}}};
    run.distance_bands = DistanceBands{1.0 / 3.0, 30.5};
    ReferenceRecord r;
    r.scene = "tiny";
    r.resolution = {96, 64};
    r.key = "00ff";
    r.seconds = 0.1234567890123456789;
    r.shadow_rays = 1ull << 40;
    r.light_samples = 64;
    r.pixel_samples = 4;
    r.error_map_scale = 1.0 / 3.0;
    r.image_png = "images/reference_tiny_96x64.png";
    r.pixel_visibility_key = "0123456789abcdef";
    r.pixel_visibility_from_cache = true;
    r.pixel_visibility_seconds = 0.1 + 0.2;
    r.pixel_visibility_shadow_rays = 1ull << 40;
    r.pixel_visibility_samples = 1024;
    r.pixel_visibility_exr = "images/reference_tiny_96x64.pixel_visibility.exr";
    r.degenerate = {"uniform image", "no lit pixels"};
    run.references.push_back(r);
    run.inputs = {{"tests/data/experiments/tiny.toml", "0123456789abcdef"}, {"tests/data/scenes/tiny.toml", "fedcba9876543210"}};
    run.environment.git_commit = "abc";
    run.environment.git_dirty = true;
    run.environment.dirty_files = {"harness/a.cpp", "configs/b \"quoted\".toml"};
    run.environment.binary_commit = "def";
    run.environment.binary_dirty = true;
    CaseResult c;
    c.id = "tiny_96x64_shadow.pcf_kernel-3";
    c.scene = "tiny";
    c.scene_variant = "{ file = \"../scenes/tiny.toml\", name = \"tiny\", light_casts_shadows = false }";
    c.technique = "shadow.pcf";
    c.resolution = {96, 64};
    c.params = {{"exact", true}, {"kernel", 3LL}, {"pattern", std::string("grid")}, {"radius", 1.0}};
    c.gpu_frame = {"gpu_frame", {0.1, 0.2 + 1e-17, 1.0 / 7.0}, {3, 0.2, 0.1, 1.0 / 7.0, 0.15, 0.05, 0.33}};
    c.wall = {"wall", {1, 2, 3}, {3, 2, 1, 3, 2, 1, 0.5}};
    c.passes = {{"shadow_map", {0.01, 0.02, 0.03}, {3, 0.02, 0.01, 0.03, 0.02, 0.01, 0.5}}};
    c.cpu = {"cpu", {1.5, 2.5, 3.5}, {3, 2.5, 1.5, 3.5, 2.5, 1, 0.4}};
    c.sample_start_s = {0.0, 0.25, 1.0 / 3.0};
    c.cpu_passes = {{"lod_select", {0.5, 0.25, 1.0 / 9.0}, {3, 0.25, 1.0 / 9.0, 0.5, 0.3, 0.1, 0.6}}};
    c.record_cpu = {"record_cpu", {0.05, 0.06, 0.07}, {3, 0.06, 0.05, 0.07, 0.06, 0.01, 0.1}};
    c.timing_check = check_pass_timing({{0.01, 0.02, 0.03}}, {1, 2, 3});
    c.path_frames = {{c.gpu_frame, c.passes}, {c.wall, c.passes}};
    c.group = 0;
    c.chunk = 1;
    c.node = "node-7";
    c.ratio.per_round = {1.5, 2.0 / 3.0, 1.75};
    c.ratio.estimate = {1.5, {2.0 / 3.0, 1.75}, 3};
    GroupRecord g;
    g.name = "tiny 96x64";
    g.scene = "tiny";
    g.resolution = {96, 64};
    g.cases = {"tiny_96x64_shadow.hard", c.id};
    MeasurementChunk chunk;
    chunk.cases = g.cases;
    chunk.started_at = "2026-01-01T00:00:01Z";
    chunk.seconds = 0.1 + 0.2;
    chunk.orders = {{0, 1}, {1, 0}, {0, 1}};
    chunk.baseline_gpu_ms = {0.05, 0.3, 1.0 / 11.0};
    g.chunks = {chunk, chunk};
    run.groups.push_back(g);
    c.memory = {262144, 100, 7};
    c.load = {{{"bake_front", 0.25}, {"bake_side", 1.0 / 3.0}}, 0.6, 0.75, 4096};
    c.triangles = 14;
    c.primitives = PrimitiveCounts{24576000000ull, 6144};
    c.counters = {{"near_cells", 220}, {"far_share", 1.0 / 3.0}};
    c.popping_per_pair = {0.25, std::numeric_limits<double>::quiet_NaN(), 1.0 / 7.0};
    c.shadow_sampler = "compare";
    ImageMetrics m{};
    m.mae = 0.01;
    m.rmse = std::sqrt(2.0) / 100.0;
    m.psnr = std::numeric_limits<double>::infinity();
    m.max_error = 0.5;
    m.max_x = 3;
    m.max_y = 4;
    m.ssim = 0.999;
    m.flip_mean = 0.02;
    m.flip_median_weighted = 0.03;
    m.light_bleeding = std::numeric_limits<double>::quiet_NaN();
    m.over_darkening = 1e-300;
    m.penumbra_rmse = 0.07;
    m.umbra_pixels = 10;
    m.lit_pixels = 20;
    m.penumbra_pixels = 30;
    m.visibility_mae = 1.0 / 3.0;
    m.visibility_rmse = std::numeric_limits<double>::quiet_NaN();
    m.visibility_penumbra_rmse = 0.25;
    m.visibility_pixels = 40;
    m.visibility_penumbra_pixels = 5;
    m.visibility_excluded = 1e-7;
    m.columns = {.visibility = true, .shadow_regions = false};
    c.image_error = m;
    c.visibility_exr = "images/a.visibility.exr";
    c.image_exr = "images/a.exr";
    c.image_png = "images/a.png";
    c.error_map_png = "images/a.error.png";
    c.flip_map_png = "images/a.flip.png";
    run.cases.push_back(c);
    CaseResult failed = c;
    failed.id = "tiny_96x64_shadow.pcf_kernel-5";
    failed.ok = false;
    failed.error = "12 pixels are NaN or Inf";
    failed.primitives.reset();
    failed.image_error.reset();
    failed.ratio = {};
    run.cases.push_back(failed);
    return run;
}

}  // namespace

TEST_CASE("a run's identity: what differs is named, field by field") {
    CHECK(identity_differences(identity(), identity()).empty());
    // --quick shortens the measurement: the option and the settings it changes are named.
    const auto quick = identity_differences(identity(true), identity(false));
    REQUIRE(quick.size() == 3);
    CHECK(quick[0] == "quick: the folder's run has 'true', this one 'false'");
    CHECK(quick[1] == "warmup_frames: the folder's run has '1', this one '5'");
    CHECK(quick[2] == "rounds: the folder's run has '3', this one '30'");
    const auto two = identity_differences(identity(true, ImageOutput::png, "aaaa"), identity(true, ImageOutput::all));
    REQUIRE(two.size() == 2);
    CHECK(two[0].find("config_hash") == 0);
    CHECK(two[1].find("images: the folder's run has 'png', this one 'all'") == 0);
    // The device, the build and the thread count are part of it: timings of one run compare.
    for (const char* field : {"device", "driver", "commit", "build_type", "lp_num_threads", "heap", "nproc", "reference",
                              "rounds", "frames_per_sample", "round_order", "chunk_limits", "test_ballast"})
        CHECK_MESSAGE(identity().find(field) != nullptr, field);
    // Options alone (the timing settings --quick sets among them) a rerun can match; a config, a
    // commit, or a shard's run against a whole one's decide what resuming may offer.
    CHECK_FALSE(only_options_differ(identity(), identity()));
    CHECK(only_options_differ(identity(true), identity(false)));
    CHECK(only_options_differ(identity(true, ImageOutput::png), identity(true, ImageOutput::all)));
    CHECK_FALSE(only_options_differ(identity(true, ImageOutput::png, "aaaa"), identity(true, ImageOutput::all)));
    RunIdentity other_commit = identity();
    for (auto& [name, value] : other_commit.fields)
        if (name == "commit") value = "0000000";
    CHECK_FALSE(only_options_differ(other_commit, identity()));
    RunIdentity shard = identity();
    shard.fields.emplace_back("shard", "1/2");
    CHECK(only_options_differ(shard, identity()));
}

TEST_CASE("results.json reads back exactly: every field, NaN, infinity, every digit") {
    const test::TempFolder folder;
    const fs::path dir = folder.path() / "roundtrip";
    fs::create_directories(dir);
    const RunRecord run = awkward_record(identity());
    write_json_report(dir / "results.json", run);
    const RunRecord back = read_json_report(dir / "results.json");
    // Written again, the cases, references and run fields are the same text: nothing was lost.
    const nlohmann::json a = nlohmann::json::parse(json_report(run)), b = nlohmann::json::parse(json_report(back));
    for (const char* key : {"cases", "groups", "references", "run_identity", "status", "error", "started_at", "resumed_at",
                            "rounds", "frames_per_sample", "measured_frames", "warmup_frames", "quick", "planned_cases", "config", "description", "camera_path", "distance_bands",
                            "inputs", "environment"})
        CHECK_MESSAGE(a[key].dump() == b[key].dump(), key);
    CHECK(back.cases[0].gpu_frame.samples_ms[2] == 1.0 / 7.0);
    CHECK(back.cases[0].ratio.per_round[1] == 2.0 / 3.0);
    CHECK(back.cases[0].node == "node-7");
    CHECK(back.cases[0].scene_variant == run.cases[0].scene_variant);
    CHECK(back.references[0].degenerate == run.references[0].degenerate);
    CHECK(back.environment.dirty_files == run.environment.dirty_files);
    CHECK(back.environment.commit_mismatch());
    CHECK(commit_text(back.environment) == "abc (with uncommitted changes: harness/a.cpp, configs/b \"quoted\".toml); "
                                           "the binary was built from def (with uncommitted changes), not this checkout's commit");
    CHECK(back.shard == "2/3");
    REQUIRE(back.merged_from.size() == 1);
    CHECK(back.merged_from[0].groups == std::vector<std::string>{"tiny 96x64"});
    CHECK(back.cases[0].ratio.estimate.ci.high == 1.75);
    CHECK(back.cases[1].ratio.measured() == false);  // the failed case has none
    CHECK(back.groups[0].chunks[1].baseline_gpu_ms[2] == 1.0 / 11.0);
    CHECK(back.cases[0].cpu_passes[0].samples_ms[2] == 1.0 / 9.0);
    CHECK(back.cases[0].timing_check.checked);
    CHECK(back.cases[0].timing_check.gap_ms == run.cases[0].timing_check.gap_ms);
    REQUIRE(back.cases[0].path_frames.size() == 2);
    CHECK(back.cases[0].path_frames[1].gpu_frame.name == "wall");
    REQUIRE(back.cases[0].primitives.has_value());
    CHECK(back.cases[0].primitives->submitted == 24576000000ull);
    CHECK(back.cases[0].primitives->rasterised == 6144);
    CHECK_FALSE(back.cases[1].primitives.has_value());  // the failed case was not counted
    CHECK(back.cases[0].counters == run.cases[0].counters);  // in the order counted
    REQUIRE(back.cases[0].popping_per_pair.size() == 3);
    CHECK(back.cases[0].popping_per_pair[0] == 0.25);
    CHECK(std::isnan(back.cases[0].popping_per_pair[1]));  // a pair with no finite pixel
    CHECK(back.cases[0].popping_per_pair[2] == 1.0 / 7.0);
    REQUIRE(back.camera_path.has_value());
    CHECK(back.camera_path->poses[1].position.x == 1.0f / 3.0f);
    REQUIRE(back.distance_bands.has_value());
    CHECK(back.distance_bands->middle_from == 1.0 / 3.0);
    CHECK(back.distance_bands->far_from == 30.5);
    CHECK(std::isinf(back.cases[0].image_error->psnr));
    CHECK(std::isnan(back.cases[0].image_error->light_bleeding));
    CHECK(back.cases[0].image_error->visibility_mae == 1.0 / 3.0);
    CHECK(back.cases[0].image_error->columns == ErrorColumns{.visibility = true, .shadow_regions = false});
    CHECK(back.references[0].pixel_visibility_seconds == 0.1 + 0.2);
    CHECK(std::get<bool>(back.cases[0].params[0].second) == true);
    CHECK(std::get<long long>(back.cases[0].params[1].second) == 3);
    CHECK(std::get<double>(back.cases[0].params[3].second) == 1.0);
    CHECK(identity_differences(back.identity, identity()).empty());

    // A file written before a group of columns existed (here coverage) reads it as undeclared.
    nlohmann::json older = a;
    older["cases"][0]["image_error"]["columns"].erase("coverage");
    older["cases"][0]["image_error"].erase("coverage_mae");
    write_json_report(dir / "results.json", run);
    {
        std::ofstream out(dir / "results.json");
        out << older.dump();
    }
    const RunRecord old_back = read_json_report(dir / "results.json");
    CHECK_FALSE(old_back.cases[0].image_error->columns.coverage);
    CHECK(old_back.cases[0].image_error->columns.visibility);
    CHECK(std::isnan(old_back.cases[0].image_error->coverage_mae));
}

TEST_CASE("results.json of another version or no results.json at all are refused with the reason") {
    const test::TempFolder folder;
    const fs::path dir = folder.path() / "version";
    fs::create_directories(dir);
    write_text_atomically(dir / "results.json", R"({"canopy_results_version": 1, "cases": []})");
    CHECK_THROWS_WITH(read_json_report(dir / "results.json"),
                      doctest::Contains("results version 1, this canopy reads version 3"));
    write_text_atomically(dir / "results.json", "{ not json");
    CHECK_THROWS_WITH(read_json_report(dir / "results.json"), doctest::Contains("not a canopy results.json"));
}

TEST_CASE("an output folder: new or empty starts, the same run continues, anything else is refused") {
    const test::TempFolder folder;
    const fs::path dir = folder.path() / "plan";
    // New, then empty: a fresh run; --resume there has nothing to continue.
    CHECK_FALSE(plan_output_folder(dir, identity(), false, false).previous);
    CHECK_THROWS_WITH_AS(plan_output_folder(dir, identity(), false, true), doctest::Contains("nothing to resume"),
                         ConfigError);
    fs::create_directories(dir);
    CHECK_FALSE(plan_output_folder(dir, identity(), false, false).previous);

    // Holding a run of the same identity: continued, with or without --resume.
    write_json_report(dir / "results.json", awkward_record(identity()));
    for (bool resume : {false, true}) {
        const OutputFolderPlan plan = plan_output_folder(dir, identity(), false, resume);
        REQUIRE(plan.previous);
        CHECK(plan.previous->cases.size() == 2);
        CHECK_FALSE(plan.replace);
    }
    // Another config, other options: refused, naming what differs and what to do.
    try {
        plan_output_folder(dir, identity(false, ImageOutput::all, "ffff"), false, false);
        FAIL("not refused");
    } catch (const ConfigError& e) {
        const std::string text = e.formatted();
        CHECK(text.find(dir.string() + ": error: the folder holds another run") == 0);
        CHECK(text.find("config_hash: the folder's run has '5d8ae7b4e274bd95', this one 'ffff'") != std::string::npos);
        CHECK(text.find("quick: the folder's run has 'true', this one 'false'") != std::string::npos);
        CHECK(text.find("--force") != std::string::npos);
        // A config no option can match: resuming is not offered.
        CHECK(text.find("resume") == std::string::npos);
        CHECK(text.find("cannot continue it") != std::string::npos);
    }
    // Options alone differ: running with the folder's options resumes it.
    try {
        plan_output_folder(dir, identity(true, ImageOutput::png), false, true);
        FAIL("not refused");
    } catch (const ConfigError& e) {
        CHECK(e.formatted().find("run with the options of the folder's run to resume it") != std::string::npos);
    }
    // --force replaces it (without --resume).
    const OutputFolderPlan forced = plan_output_folder(dir, identity(false), true, false);
    CHECK(forced.replace);
    REQUIRE(forced.previous);  // the run replaced: its recorded files are what --force removes
    CHECK(forced.previous->cases.size() == 2);

    // Files but no run: refused, with --force too (canopy removes only what a run of its recorded).
    fs::remove(dir / "results.json");
    std::ofstream(dir / "notes.txt") << "mine";
    for (bool force : {false, true})
        CHECK_THROWS_WITH_AS(plan_output_folder(dir, identity(), force, false), doctest::Contains("holds no canopy run"),
                             ConfigError);
    // A results.json canopy cannot read is no run of canopy's either.
    std::ofstream(dir / "results.json") << "{ my own notes";
    CHECK_THROWS_WITH_AS(plan_output_folder(dir, identity(), true, false), doctest::Contains("with or without --force"),
                         ConfigError);
    fs::remove(dir / "results.json");
    // A file is no folder.
    CHECK_THROWS_WITH_AS(plan_output_folder(dir / "notes.txt", identity(), false, false),
                         doctest::Contains("names a file"), ConfigError);
}

TEST_CASE("committed results are refused without --force, even when empty or new") {
    const test::TempFolder folder;
    const fs::path root = folder.path() / "committed";
    for (const fs::path& dir : {root / "results" / "paper" / "G-T7.1", root / "results" / "baselines" / "x" / "y",
                                root / "results" / "paper"}) {
        CAPTURE(dir.string());
        CHECK(is_committed_results_folder(dir));
        CHECK_THROWS_WITH_AS(plan_output_folder(dir, identity(), false, false),
                             doctest::Contains("committed results"), ConfigError);
        CHECK_FALSE(plan_output_folder(dir, identity(), true, false).previous);
    }
    CHECK(is_committed_results_folder(root / "results" / "runs" / ".." / "paper" / "x"));
    CHECK_FALSE(is_committed_results_folder(root / "results" / "runs" / "paper"));
    CHECK_FALSE(is_committed_results_folder(root / "paper"));
    CHECK_FALSE(fs::exists(root));  // deciding writes nothing
}

TEST_CASE("replacing a run removes the files it recorded only; a killed run's temporary files are cleaned") {
    const test::TempFolder folder;
    const fs::path dir = folder.path() / "replace";
    fs::create_directories(dir / "images");
    // The run recorded one case with two images and one reference image.
    RunRecord run;
    CaseResult c;
    c.id = "a";
    c.image_exr = "images/a.exr";
    c.error_map_png = "images/a.error.png";
    run.cases.push_back(c);
    ReferenceRecord r;
    r.image_png = "images/reference.png";
    run.references.push_back(r);
    for (const char* name : {"results.json", "results.csv", "results.md", "results.gbench.json", "paper.md",
                             "paper.json", "pareto.md", "report.html", "notes.txt", "images/a.exr", "images/a.error.png",
                             "images/reference.png", "images/.a.tmp123.png", ".results.tmp9.json", "images/keep.txt",
                             "images/holiday.png", "images/b.exr"})
        std::ofstream(dir / name) << "x";
    remove_temporary_files(dir);
    CHECK_FALSE(fs::exists(dir / "images/.a.tmp123.png"));
    CHECK_FALSE(fs::exists(dir / ".results.tmp9.json"));
    CHECK(fs::exists(dir / "results.json"));
    std::ofstream(dir / "experiment.toml") << "mine";  // beside a run that wrote no copy of its config
    CHECK(remove_run_outputs(dir, run) == 11);
    CHECK(fs::exists(dir / "experiment.toml"));
    run.inputs = {{"experiment.toml", "0"}};  // a run that did write it
    std::ofstream(dir / "results.json") << "x";
    CHECK(remove_run_outputs(dir, run) == 2);
    CHECK_FALSE(fs::exists(dir / "experiment.toml"));
    // Whatever is not recorded stays, whatever its name or extension.
    for (const char* kept : {"notes.txt", "images/keep.txt", "images/holiday.png", "images/b.exr"})
        CHECK_MESSAGE(fs::exists(dir / kept), kept);
    CHECK_FALSE(fs::exists(dir / "images/a.exr"));
    CHECK_FALSE(fs::exists(dir / "images/reference.png"));
    // A recorded name that climbs out of the folder is not removed.
    std::ofstream(folder.path() / "outside.txt") << "x";
    c.image_png = "../outside.txt";
    run.cases = {c};
    remove_run_outputs(dir, run);
    CHECK(fs::exists(folder.path() / "outside.txt"));
}

TEST_CASE("paths in results are relative to the checkout, not the machine's folders") {
    const fs::path checkout = CANOPY_SOURCE_DIR;
    CHECK(recorded_path(checkout / "configs" / "scenes" / "spheres.toml") == "configs/scenes/spheres.toml");
    CHECK(recorded_path(checkout / "configs" / ".." / "tests" / "data" / "scenes" / "tiny.toml") ==
          "tests/data/scenes/tiny.toml");
    CHECK(recorded_path("/nowhere/else.toml") == "/nowhere/else.toml");

    ScalingOptions options;
    options.scene_file = (checkout / "configs" / "scenes" / "spheres.toml").string();
    const std::string report = kernel_scaling_report({}, lavapipe(), options);
    CHECK(report.find("Scene `configs/scenes/spheres.toml`") != std::string::npos);
    CHECK(report.find(checkout.string()) == std::string::npos);
}
