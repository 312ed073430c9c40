#include "run/run_identity.hpp"

#include "config/experiment.hpp"
#include "run/environment.hpp"
#include "run/experiment_runner.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace canopy {

namespace {

const char* images_name(ImageOutput images) {
    switch (images) {
        case ImageOutput::all: return "all";
        case ImageOutput::png: return "png";
        case ImageOutput::none: return "none";
    }
    return "?";
}

std::string shown(const std::string* value) { return value ? "'" + *value + "'" : "nothing"; }

}  // namespace

const std::string* RunIdentity::find(const std::string& name) const {
    for (const auto& [key, value] : fields)
        if (key == name) return &value;
    return nullptr;
}

RunIdentity make_run_identity(const Experiment& experiment, const RunOptions& options, const Environment& environment) {
    RunIdentity identity;
    auto add = [&](std::string name, std::string value) { identity.fields.emplace_back(std::move(name), std::move(value)); };
    auto add_option = [&](std::string name, std::string value) {
        identity.set_by_options.push_back(name);
        add(std::move(name), std::move(value));
    };
    add("experiment", experiment.name);
    add("config_hash", experiment.config_hash);
    add_option("quick", options.quick ? "true" : "false");
    identity.set_by_options.push_back("shard");  // --shard: absent from whole runs (and runs older than shards)
    if (!options.shard.empty()) add("shard", options.shard);
    add_option("images", images_name(options.images));
    add_option("reference", options.reference && experiment.reference_enabled ? "on" : "off");
    // How the cases are timed: a run continuing another must pair its rounds the same way.
    const MeasurementSettings measurement = measurement_settings(experiment, options);
    add_option("warmup_frames", std::to_string(measurement.warmup_frames));
    add_option("rounds", std::to_string(measurement.rounds));
    add_option("frames_per_sample", std::to_string(measurement.frames_per_sample));
    add("pairing", to_string(measurement.pairing));
    add("round_order", "williams");
    add_option("chunk_limits",
               fmt::format("{} cases, {} MiB", options.chunk_limits.max_cases, options.chunk_limits.max_bytes >> 20));
    add_option("test_ballast",
               options.ballast ? fmt::format("{}={}", options.ballast->technique, options.ballast->iterations) : "none");
    add("device", environment.device.name);
    add("driver", environment.device.driver_info);
    // Timings of one run are compared with each other, so every part must come from one build on
    // the same threads.
    add("commit", environment.git_commit + (environment.git_dirty ? " (with uncommitted changes)" : ""));
    add("build_type", environment.build_type);
    add("lp_num_threads", environment.lp_num_threads);
    add("heap", environment.heap);
    add("nproc", std::to_string(environment.nproc));
    return identity;
}

std::vector<std::string> identity_differences(const RunIdentity& recorded, const RunIdentity& now) {
    std::vector<std::string> differences;
    for (const auto& [name, value] : now.fields) {
        const std::string* before = recorded.find(name);
        if (!before || *before != value)
            differences.push_back(fmt::format("{}: the folder's run has {}, this one '{}'", name, shown(before), value));
    }
    for (const auto& [name, value] : recorded.fields)
        if (!now.find(name)) differences.push_back(fmt::format("{}: the folder's run has '{}', this one nothing", name, value));
    return differences;
}

bool only_options_differ(const RunIdentity& recorded, const RunIdentity& now) {
    const auto by_option = [&](const std::string& name) {
        return std::find(now.set_by_options.begin(), now.set_by_options.end(), name) != now.set_by_options.end();
    };
    bool differs = false;
    for (const auto& [name, value] : now.fields) {
        const std::string* before = recorded.find(name);
        if (before && *before == value) continue;
        if (!by_option(name)) return false;
        differs = true;
    }
    for (const auto& [name, value] : recorded.fields)
        if (!now.find(name)) {
            if (!by_option(name)) return false;
            differs = true;
        }
    return differs;
}

}  // namespace canopy
