#include "run/stability_bench.hpp"

#include "report/json_record_reader.hpp"
#include "run/group_measurement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <fcntl.h>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace canopy {

namespace {

double mean_of(const std::vector<double>& v) {
    return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

double relative_std(const std::vector<double>& v) {
    if (v.size() < 2) return 0.0;
    const double mean = mean_of(v);
    double squares = 0.0;
    for (double x : v) squares += (x - mean) * (x - mean);
    return mean != 0.0 ? std::sqrt(squares / double(v.size() - 1)) / mean : 0.0;
}

std::string label_of(const CaseResult& c) {
    return fmt::format("{} {}x{} {}{}", c.scene, c.resolution.width, c.resolution.height, c.technique,
                       c.params_shown.empty() || c.params_shown == "-" ? "" : " " + c.params_shown);
}

}  // namespace

int run_process(const std::vector<std::string>& argv, const std::filesystem::path& log) {
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("cannot start a run: fork failed");
    if (pid == 0) {
        const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, STDOUT_FILENO);
            dup2(fd, STDERR_FILENO);
            close(fd);
        }
        std::vector<char*> args;
        for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execv(args[0], args.data());
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw std::runtime_error("cannot wait for a run");
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

StabilityResult analyse_stability(const std::vector<RunRecord>& runs) {
    StabilityResult result;
    if (runs.empty()) return result;
    const RunRecord& first = runs.front();
    result.experiment = first.experiment;
    result.config_file = first.config_file;
    result.environment = first.environment;
    result.warmup_frames = first.warmup_frames;
    result.rounds = first.rounds;
    result.frames_per_sample = first.frames_per_sample;
    const std::string* hash = first.identity.find("config_hash");
    for (const RunRecord& run : runs) {
        const std::string* h = run.identity.find("config_hash");
        if (run.experiment != first.experiment || (hash && h && *h != *hash))
            throw std::runtime_error("the runs are not of one experiment and config");
    }
    for (const CaseResult& c : first.cases) {
        CaseStability s;
        s.id = c.id;
        s.label = label_of(c);
        s.group_baseline = c.group_baseline;
        std::vector<double> medians;
        for (const RunRecord& run : runs) {
            const auto it = std::find_if(run.cases.begin(), run.cases.end(), [&](const CaseResult& r) { return r.id == c.id; });
            if (it == run.cases.end() || !it->ok || it->gpu_frame.samples_ms.empty()) continue;
            medians.push_back(it->gpu_frame.stats.median);
            s.cvs.push_back(it->gpu_frame.stats.cv);
            if (it->ratio.measured()) s.ratios.push_back(it->ratio.estimate.value);
            // The baseline of its group and chunk in this run, for the CPU-time ratio.
            const auto base = std::find_if(run.cases.begin(), run.cases.end(), [&](const CaseResult& r) {
                return r.group == it->group && r.group_baseline;
            });
            if (base != run.cases.end() && base->ok && it->chunk == base->chunk && !it->group_baseline)
                s.cpu_ratios.push_back(median_of(paired_ratio(it->cpu.samples_ms, base->cpu.samples_ms, it->id).per_round));
        }
        if (medians.empty()) continue;
        s.median_ms = median_of(medians);
        s.within_cv_median = median_of(s.cvs);
        s.within_cv_max = *std::max_element(s.cvs.begin(), s.cvs.end());
        if (!s.ratios.empty()) {
            s.ratio_median = median_of(s.ratios);
            const auto [low, high] = std::minmax_element(s.ratios.begin(), s.ratios.end());
            s.ratio_spread = s.ratio_median > 0 ? (*high - *low) / s.ratio_median : 0.0;
            s.ratio_cv = relative_std(s.ratios);
        }
        if (!s.cpu_ratios.empty()) {
            const double m = median_of(s.cpu_ratios);
            const auto [low, high] = std::minmax_element(s.cpu_ratios.begin(), s.cpu_ratios.end());
            s.cpu_ratio_spread = m > 0 ? (*high - *low) / m : 0.0;
        }
        result.cases.push_back(std::move(s));
    }
    return result;
}

StabilityResult run_stability_bench(const std::filesystem::path& canopy, const StabilityOptions& options) {
    std::vector<RunRecord> records;
    std::vector<StabilityRun> runs;
    for (int k = 1; k <= options.runs; ++k) {
        StabilityRun run;
        run.folder = options.out / "runs" / fmt::format("run-{}", k);
        const std::filesystem::path log = options.out / "runs" / fmt::format("run-{}.log", k);
        std::filesystem::create_directories(run.folder.parent_path());
        std::vector<std::string> argv{canopy.string(), "run", options.experiment.string(), "--out", run.folder.string(),
                                      "--no-reference", "--images", "none", "--no-progress"};
        if (options.quick) argv.push_back("--quick");
        if (!options.device.empty()) argv.insert(argv.end(), {"--device", options.device});
        fmt::print(stderr, "stability: run {}/{} ...\n", k, options.runs);
        run.load_before = current_load_average();
        const auto start = std::chrono::steady_clock::now();
        const int status = run_process(argv, log);
        run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        run.load_after = current_load_average();
        if (status != 0)
            throw std::runtime_error(fmt::format("run {} of {} failed (exit code {}); its output is in {}", k,
                                                 options.runs, status, log.string()));
        records.push_back(read_json_report(run.folder / "results.json"));
        runs.push_back(run);
        fmt::print(stderr, "stability: run {}/{} took {:.1f} s, load average {:.2f} -> {:.2f}\n", k, options.runs,
                   run.seconds, run.load_before[0], run.load_after[0]);
    }
    StabilityResult result = analyse_stability(records);
    result.runs = std::move(runs);
    return result;
}

StabilityResult analyse_run_folders(const std::vector<std::filesystem::path>& folders) {
    std::vector<RunRecord> records;
    std::vector<StabilityRun> runs;
    for (const std::filesystem::path& folder : folders) {
        records.push_back(read_json_report(std::filesystem::is_directory(folder) ? folder / "results.json" : folder));
        StabilityRun run;
        run.folder = folder;
        run.load_before = records.back().environment.load_average;
        run.load_after.fill(std::numeric_limits<double>::quiet_NaN());
        runs.push_back(run);
    }
    StabilityResult result = analyse_stability(records);
    result.runs = std::move(runs);
    return result;
}

}  // namespace canopy
