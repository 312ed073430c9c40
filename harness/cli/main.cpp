// canopy: runs rendering techniques over configured scenes and tabulates time and error.
#include "config/experiment_config.hpp"
#include "core/registry.hpp"
#include "gpu/context.hpp"
#include "report/markdown_report.hpp"
#include "run/experiment_runner.hpp"
#include "run/interrupt.hpp"

#include <CLI/CLI.hpp>
#include <fmt/chrono.h>
#include <fmt/format.h>

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;
using namespace canopy;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailedCases = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitInterrupted = 130;

int list_techniques() {
    for (const Technique* t : TechniqueRegistry::instance().all()) {
        fmt::print("{}\n  {}\n  from: {}\n  parameters:\n", t->name(), t->summary(), t->paper());
        for (const ParamSpec& p : t->params())
            fmt::print("    {:<14} {:<28} default {:<8} {}\n", p.name, p.type_and_range(), to_string(p.default_value), p.doc);
        fmt::print("\n");
    }
    return kExitOk;
}

int list_devices() {
    for (const DeviceInfo& d : GpuContext::list_devices())
        fmt::print("{}: {}  [{}]  driver {} ({}), Vulkan {}\n", d.index, d.name, d.type, d.driver_name, d.driver_info,
                   d.api_version);
    return kExitOk;
}

fs::path default_out_dir(const std::string& experiment) {
    return fs::path("results") / "runs" / fmt::format("{:%Y-%m-%d-%H%M%S}-{}", fmt::localtime(std::time(nullptr)), experiment);
}

int run(const fs::path& config, const std::string& out, bool quick, const std::string& device, bool progress) {
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    // Everything is checked (config, scenes, meshes, device support) before anything is written.
    const Experiment experiment = load_experiment(config, registry);
    GpuContext gpu(device);
    const PreparedExperiment prepared = prepare_experiment(experiment, registry, gpu);

    RunOptions options;
    options.out_dir = out.empty() ? default_out_dir(experiment.name) : fs::path(out);
    options.quick = quick;
    options.show_progress = progress;
    fmt::print(stderr, "canopy: {} cases on {} ({}); writing to {}\n", prepared.cases.size(), gpu.info().name,
               gpu.info().driver_info, options.out_dir.string());
    install_interrupt_handler();
    const RunRecord record = run_experiment(prepared, registry, gpu, options);

    fmt::print("{}\n", markdown_table(record));
    fmt::print("results: {}\n", fs::absolute(options.out_dir).string());
    fmt::print("  results.json, results.csv, results.md; images in images/ (EXR linear, PNG sRGB)\n");
    if (record.status == "interrupted") {
        fmt::print(stderr, "canopy: interrupted after {} of {} cases; the finished ones are saved\n", record.cases.size(),
                   record.planned_cases);
        return kExitInterrupted;
    }
    if (record.status == "failed") {
        for (const auto& c : record.cases)
            if (!c.ok) fmt::print(stderr, "canopy: case {} FAILED: {}\n", c.id, c.error);
        return kExitFailedCases;
    }
    return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"canopy: benchmark real-time rendering techniques for nature scenes against a ray-traced reference.\n"
                 "Measures how long each technique takes and how far its image is from the truth."};
    app.require_subcommand(1);
    app.footer("Exit codes: 0 success, 1 a case failed (e.g. NaN pixels), 2 bad input (the message names file:line),\n"
               "130 interrupted (finished cases are kept). Set CANOPY_VALIDATION=1 for Vulkan validation layers.");

    std::string config_path, out_dir, device;
    bool quick = false, no_progress = false;
    CLI::App* run_cmd = app.add_subcommand("run", "Run an experiment: scenes x techniques x parameters x resolutions.");
    run_cmd->add_option("experiment", config_path, "experiment TOML, e.g. configs/experiments/default.toml")->required();
    run_cmd->add_option("--out", out_dir, "output folder (default results/runs/<date>-<experiment>/)");
    run_cmd->add_flag("--quick", quick, "1 warm-up and 3 measured frames per case, for smoke tests");
    run_cmd->add_option("--device", device, "Vulkan device: index or part of its name (default: lavapipe)");
    run_cmd->add_flag("--no-progress", no_progress, "no progress bar or lines on stderr");
    run_cmd->footer("Writes results.json (every sample, statistics, parameters, environment), results.csv, results.md\n"
                    "and per case an EXR (linear float) and a PNG (sRGB) into the output folder.");

    CLI::App* list_cmd = app.add_subcommand("list", "List every technique with its parameters (type, range, default).");
    CLI::App* devices_cmd = app.add_subcommand("devices", "List the Vulkan devices canopy can run on.");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kExitOk : kExitBadInput;
    }

    try {
        if (*list_cmd) return list_techniques();
        if (*devices_cmd) return list_devices();
        if (*run_cmd) return run(config_path, out_dir, quick, device, !no_progress);
    } catch (const ConfigError& e) {
        fmt::print(stderr, "{}\n", e.formatted());
        return kExitBadInput;
    } catch (const GpuError& e) {
        fmt::print(stderr, "canopy: Vulkan error: {}\n", e.what());
        return kExitFailedCases;
    } catch (const std::exception& e) {
        fmt::print(stderr, "canopy: error: {}\n", e.what());
        return kExitFailedCases;
    }
    return kExitOk;
}
