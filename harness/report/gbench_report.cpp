#include "report/gbench_report.hpp"

#include "report/atomic_file.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <numeric>

namespace canopy {

namespace {

using nlohmann::ordered_json;

// Google Benchmark's aggregates over repetitions (src/statistics.cc): mean, median, sample
// standard deviation, and cv = stddev / mean.
double aggregate(const std::vector<double>& v, const std::string& name) {
    if (v.empty()) return 0.0;
    const double mean = std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
    if (name == "mean") return mean;
    if (name == "median") return median_of(v);
    double squares = 0.0;
    for (double x : v) squares += (x - mean) * (x - mean);
    const double stddev = v.size() > 1 ? std::sqrt(squares / double(v.size() - 1)) : 0.0;
    if (name == "stddev") return stddev;
    return mean != 0.0 ? stddev / mean : 0.0;  // cv
}

// "2024-05-01T12:34:56Z" -> "2024-05-01T12:34:56+00:00", the form Google Benchmark writes.
std::string benchmark_date(const std::string& utc) {
    if (!utc.empty() && utc.back() == 'Z') return utc.substr(0, utc.size() - 1) + "+00:00";
    return utc;
}

ordered_json context(const RunRecord& run) {
    const Environment& e = run.environment;
    ordered_json caches = ordered_json::array();
    for (const CpuCache& c : e.caches)
        caches.push_back({{"type", c.type}, {"level", c.level}, {"size", c.size_bytes}, {"num_sharing", c.num_sharing}});
    ordered_json j;
    j["date"] = benchmark_date(run.started_at);
    j["host_name"] = e.hostname;
    j["executable"] = "canopy run " + run.config_file;
    j["num_cpus"] = e.nproc;
    j["mhz_per_cpu"] = std::lround(e.cpu_mhz);
    j["cpu_scaling_enabled"] = e.cpu_scaling;
    j["caches"] = caches;
    j["load_avg"] = e.load_average;
#if defined(NDEBUG)
    j["library_build_type"] = "release";
#else
    j["library_build_type"] = "debug";
#endif
    // Custom context (Google Benchmark's AddCustomContext writes extra string keys here), named as
    // in results.json's environment, so the file says which run, build and device it comes from.
    j["experiment"] = run.experiment;
    j["canopy_version"] = e.canopy_version;
    j["build_type"] = e.build_type;
    j["commit"] = e.git_commit;
    j["commit_dirty"] = e.git_dirty ? "true" : "false";
    j["config_hash"] = e.config_hash;
    j["device"] = e.device.name;
    j["driver_info"] = e.device.driver_info;
    j["cpu_model"] = e.cpu_model;
    j["lp_num_threads"] = e.lp_num_threads;
    j["heap"] = e.heap;
    j["status"] = run.status;
    j["measurement"] = std::to_string(run.warmup_frames) + " warm-up frames, " + std::to_string(run.rounds) +
                       " rounds of " + std::to_string(run.frames_per_sample) +
                       " frames per case, each group's cases interleaved";
    return j;
}

struct Counter {
    std::string name;
    std::vector<double> values;  // per round
};

ordered_json entry_head(const std::string& name, size_t family, const std::string& run_type, int repetitions) {
    ordered_json j;
    j["name"] = name;
    j["family_index"] = family;
    j["per_family_instance_index"] = 0;
    j["run_name"] = name;
    j["run_type"] = run_type;
    j["repetitions"] = repetitions;
    return j;
}

void add_case(ordered_json& benchmarks, const CaseResult& c, size_t family, int frames_per_sample) {
    const std::string name = c.id + "/manual_time";
    const std::vector<double>& gpu = c.gpu_frame.samples_ms;
    const int repetitions = int(gpu.size());
    if (!c.ok || gpu.empty()) {
        ordered_json j = entry_head(name, family, "iteration", std::max(repetitions, 1));
        j["repetition_index"] = 0;
        j["threads"] = 1;
        j["error_occurred"] = true;
        j["error_message"] = c.ok ? "not measured" : c.error;
        j["iterations"] = 0;
        j["real_time"] = 0.0;
        j["cpu_time"] = 0.0;
        j["time_unit"] = "ms";
        benchmarks.push_back(j);
        return;
    }
    std::vector<Counter> counters{{"wall_ms", c.wall.samples_ms}};
    if (c.ratio.per_round.size() == gpu.size()) counters.push_back({"ratio", c.ratio.per_round});
    for (const TimingSeries& p : c.passes)
        if (p.samples_ms.size() == gpu.size()) counters.push_back({p.name + "_ms", p.samples_ms});
    // The technique's counts (one frame's, the same in every repetition).
    for (const auto& [name, value] : c.counters)
        counters.push_back({"counter_" + name, std::vector<double>(gpu.size(), value)});
    const std::vector<double>& cpu = c.cpu.samples_ms.size() == gpu.size() ? c.cpu.samples_ms : gpu;

    for (int r = 0; r < repetitions; ++r) {
        ordered_json j = entry_head(name, family, "iteration", repetitions);
        j["repetition_index"] = r;
        j["threads"] = 1;
        j["iterations"] = frames_per_sample;
        j["real_time"] = gpu[size_t(r)];
        j["cpu_time"] = cpu[size_t(r)];
        j["time_unit"] = "ms";
        for (const Counter& counter : counters) j[counter.name] = counter.values[size_t(r)];
        benchmarks.push_back(j);
    }
    if (repetitions < 2) return;  // Google Benchmark writes aggregates for repeated runs only
    for (const std::string aggregate_name : {"mean", "median", "stddev", "cv"}) {
        ordered_json j = entry_head(name, family, "aggregate", repetitions);
        j["name"] = name + "_" + aggregate_name;
        j["threads"] = 1;
        j["aggregate_name"] = aggregate_name;
        j["aggregate_unit"] = aggregate_name == "cv" ? "percentage" : "time";
        j["iterations"] = repetitions;
        j["real_time"] = aggregate(gpu, aggregate_name);
        j["cpu_time"] = aggregate(cpu, aggregate_name);
        j["time_unit"] = "ms";
        for (const Counter& counter : counters) j[counter.name] = aggregate(counter.values, aggregate_name);
        benchmarks.push_back(j);
    }
}

}  // namespace

std::string gbench_report(const RunRecord& run) {
    ordered_json benchmarks = ordered_json::array();
    for (size_t i = 0; i < run.cases.size(); ++i) add_case(benchmarks, run.cases[i], i, run.frames_per_sample);
    ordered_json j;
    j["context"] = context(run);
    j["benchmarks"] = benchmarks;
    return j.dump(2) + "\n";
}

void write_gbench_report(const std::filesystem::path& path, const RunRecord& run) {
    write_text_atomically(path, gbench_report(run));
}

}  // namespace canopy
