// A whole (small) experiment through the runner: every output file, well formed, complete.
#include "config/experiment_config.hpp"
#include "report/image_files.hpp"
#include "run/experiment_runner.hpp"
#include "support/temp_folder.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace canopy;
namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

TEST_CASE("canopy run writes JSON, CSV, Markdown, EXR and PNG for every case") {
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    const Experiment experiment = load_experiment(std::string(CANOPY_TEST_DATA) + "/experiments/tiny.toml", registry);
    const GpuContext& gpu = test::gpu();
    const PreparedExperiment prepared = prepare_experiment(experiment, registry, gpu);
    REQUIRE(prepared.cases.size() == 3);

    const test::TempFolder folder("canopy-test-outputs");
    const fs::path out = folder.path() / "run";
    RunOptions options;
    options.out_dir = out;
    options.quick = true;
    options.show_progress = false;
    options.reference_cache_dir = out / "cache";
    const RunRecord record = run_experiment(prepared, registry, gpu, options);
    CHECK(record.status == "complete");

    const nlohmann::json json = nlohmann::json::parse(read_text(out / "results.json"));
    CHECK(json["status"] == "complete");
    CHECK(json["measured_frames"] == 3);
    const auto& env = json["environment"];
    for (const char* key : {"device", "driver_info", "commit", "nproc", "lp_num_threads", "heap", "cpu_model", "build_type", "config_hash"}) {
        CAPTURE(key);
        CHECK(env.contains(key));
    }
    CHECK(env["config_hash"] == experiment.config_hash);
    REQUIRE(json["cases"].size() == 3);
    for (const auto& c : json["cases"]) {
        CAPTURE(c["id"].get<std::string>());
        CHECK(c["ok"] == true);
        CHECK(c["timing"]["gpu_frame"]["samples_ms"].size() == 3);
        CHECK(c["timing"]["wall"]["stats_ms"]["median"].get<double>() > 0.0);
        CHECK(c["timing"]["passes"].size() == 2);
        CHECK(c["params"].contains("resolution"));
        CHECK(c["memory_bytes"]["technique"].get<uint64_t>() >= 256u * 256u * 4u);
        const Image exr = read_image(out / c["images"]["exr"].get<std::string>());
        const Image png = read_image(out / c["images"]["png"].get<std::string>());
        CHECK(exr.width == 96);
        CHECK(exr.height == 64);
        CHECK(png.width == 96);
        // Errors against the reference, and their maps.
        const auto& e = c["image_error"];
        REQUIRE(e.is_object());
        CHECK(e["rmse"].get<double>() >= 0.0);
        CHECK(e["ssim"].get<double>() <= 1.0);
        CHECK(e["flip_mean"].get<double>() >= 0.0);
        CHECK(e["nonfinite_pixels"] == 0);
        CHECK(e["umbra_pixels"].get<long long>() > 0);  // the box's shadow on the floor
        CHECK(fs::exists(out / c["images"]["error_map_png"].get<std::string>()));
        CHECK(fs::exists(out / c["images"]["flip_map_png"].get<std::string>()));
    }
    REQUIRE(json["references"].size() == 1);
    CHECK(json["references"][0]["from_cache"] == false);
    CHECK(json["references"][0]["shadow_rays"].get<uint64_t>() > 0);
    CHECK(fs::exists(out / json["references"][0]["images"]["exr"].get<std::string>()));
    CHECK(fs::exists(out / json["references"][0]["images"]["visibility_exr"].get<std::string>()));
    CHECK(json["cases"][1]["params"]["kernel"] == 3);
    CHECK(json["cases"][2]["params"]["kernel"] == 5);

    const std::string csv = read_text(out / "results.csv");
    CHECK(std::count(csv.begin(), csv.end(), '\n') == 4);  // header and three cases
    CHECK(csv.find("shadow_map_gpu_ms_median") != std::string::npos);
    const std::string md = read_text(out / "results.md");
    CHECK(md.find("| shadow.pcf") != std::string::npos);
    CHECK(md.find("llvmpipe") != std::string::npos);
    CHECK(md.find("penumbra RMSE") != std::string::npos);
    CHECK(csv.find(",rmse,psnr_db,") != std::string::npos);

    // A second run finds the reference in the cache.
    const fs::path again = folder.path() / "again";
    RunOptions second = options;
    second.out_dir = again;
    const RunRecord cached = run_experiment(prepared, registry, gpu, second);
    REQUIRE(cached.references.size() == 1);
    CHECK(cached.references[0].from_cache);
    CHECK(cached.cases[0].image_error->rmse == doctest::Approx(record.cases[0].image_error->rmse));

    // Atomic writes leave no temporary files behind.
    for (const auto& entry : fs::recursive_directory_iterator(out))
        CHECK_MESSAGE(entry.path().filename().string().find(".tmp") == std::string::npos, entry.path().string());
}
