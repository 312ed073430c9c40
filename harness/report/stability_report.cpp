#include "report/stability_report.hpp"

#include "report/atomic_file.hpp"
#include "report/text_table.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

namespace canopy {

namespace {

std::string pct(double fraction) { return fmt::format("{:.1f} %", 100.0 * fraction); }

std::string load_text(const std::array<double, 3>& load) { return std::isnan(load[0]) ? "?" : fmt::format("{:.2f}", load[0]); }

}  // namespace

std::string stability_markdown(const StabilityResult& r) {
    const Environment& e = r.environment;
    std::string out = fmt::format("# canopy bench stability: {}\n\n", r.experiment);
    out += fmt::format("- `{}` run {} times, each a separate `canopy run --no-reference --images none` (or the run "
                       "folders given): per case {} "
                       "warm-up frames, then {} rounds of {} frame{} (each group's cases interleaved round by round)\n",
                       r.config_file, r.runs.size(), r.warmup_frames, r.rounds, r.frames_per_sample,
                       r.frames_per_sample == 1 ? "" : "s");
    out += fmt::format("- device: {} ({}); CPU: {}, nproc {}, allowed CPUs {}, LP_NUM_THREADS {}\n", e.device.name,
                       e.device.driver_info, e.cpu_model, e.nproc, e.cpus_allowed, e.lp_num_threads);
    out += fmt::format("- canopy {} ({} build), commit {}\n", e.canopy_version, e.build_type, commit_text(e));
    std::string loads;
    for (size_t k = 0; k < r.runs.size(); ++k)
        loads += fmt::format("{}run {}: {} -> {} ({:.0f} s)", k ? "; " : "", k + 1, load_text(r.runs[k].load_before),
                             load_text(r.runs[k].load_after), r.runs[k].seconds);
    if (!loads.empty())
        out += fmt::format("- load average (1 min) before -> after each run, on {} CPUs: {}\n", e.nproc, loads);
    out += fmt::format("- targets: run-to-run spread of the ratio <= {:.0f} % for cases over {:.0f} ms; within-run CV "
                       "<= {:.0f} %\n\n",
                       100 * kTargetRatioSpread, kTargetSpreadAboveMs, 100 * kTargetWithinRunCv);

    std::vector<std::string> header{"case", "GPU ms", "ratio", "ratio per run", "spread", "std/mean",
                                    "within-run CV (median, max)", "spread target", "CV target", "spread (CPU time)"};
    std::vector<bool> right{false, true, true, false, true, true, true, false, false, true};
    std::vector<std::vector<std::string>> rows;
    size_t spread_applies = 0, spread_met = 0, cv_met = 0;
    for (const CaseStability& c : r.cases) {
        std::string per_run;
        for (double x : c.ratios) per_run += fmt::format("{}{:.3f}", per_run.empty() ? "" : " ", x);
        std::string spread_target;
        if (c.group_baseline) spread_target = "baseline";
        else if (!c.spread_target_applies()) spread_target = fmt::format("n/a (under {:.0f} ms)", kTargetSpreadAboveMs);
        else spread_target = c.meets_spread_target() ? "reached" : "NOT reached";
        if (c.spread_target_applies()) {
            ++spread_applies;
            spread_met += c.meets_spread_target() ? 1 : 0;
        }
        cv_met += c.meets_cv_target() ? 1 : 0;
        rows.push_back({c.label, fmt::format("{:.2f}", c.median_ms), c.group_baseline ? "1" : fmt::format("{:.3f}", c.ratio_median),
                        c.group_baseline ? "-" : per_run, c.group_baseline ? "-" : pct(c.ratio_spread),
                        c.group_baseline ? "-" : pct(c.ratio_cv),
                        fmt::format("{}, {}", pct(c.within_cv_median), pct(c.within_cv_max)), spread_target,
                        c.meets_cv_target() ? "reached" : "NOT reached",
                        c.cpu_ratios.empty() ? "-" : pct(c.cpu_ratio_spread)});
    }
    out += render_table(header, rows, right);
    out += fmt::format("\n{} of {} cases over {:.0f} ms reach the spread target; {} of {} cases reach the within-run "
                       "CV target.\n",
                       spread_met, spread_applies, kTargetSpreadAboveMs, cv_met, r.cases.size());
    out += "\nratio: the case's GPU time relative to its group's baseline, median of the per-round ratios of one run; "
           "spread: (max - min) / median of that ratio over the runs; std/mean: its standard deviation over the runs "
           "relative to the mean; within-run CV: standard deviation / mean of the case's samples (one per round) "
           "within a run; spread (CPU time): the spread of the same ratio computed from the process's CPU time per "
           "frame instead of GPU timestamps, for comparison (on lavapipe a timestamp interval also counts time the "
           "rasterising thread waited for a CPU). Numbers taken while the load average is above 0 measure the instrument on a shared "
           "machine, as it will be used; the load column says how shared.\n";
    return out;
}

std::string stability_json(const StabilityResult& r) {
    nlohmann::json runs = nlohmann::json::array();
    for (const StabilityRun& run : r.runs)
        runs.push_back({{"folder", run.folder.filename().string()},
                        {"load_average_before", run.load_before},
                        {"load_average_after", run.load_after},
                        {"seconds", run.seconds}});
    nlohmann::json cases = nlohmann::json::array();
    for (const CaseStability& c : r.cases)
        cases.push_back({{"id", c.id},
                         {"label", c.label},
                         {"group_baseline", c.group_baseline},
                         {"median_gpu_ms", c.median_ms},
                         {"ratio_per_run", c.ratios},
                         {"within_run_cv_per_run", c.cvs},
                         {"ratio_median", c.ratio_median},
                         {"ratio_spread", c.ratio_spread},
                         {"ratio_std_over_mean", c.ratio_cv},
                         {"within_run_cv_median", c.within_cv_median},
                         {"within_run_cv_max", c.within_cv_max},
                         {"spread_target_applies", c.spread_target_applies()},
                         {"spread_target_reached", c.meets_spread_target()},
                         {"cv_target_reached", c.meets_cv_target()},
                         {"cpu_time_ratio_per_run", c.cpu_ratios},
                         {"cpu_time_ratio_spread", c.cpu_ratio_spread}});
    const nlohmann::json j = {{"experiment", r.experiment},
                              {"config", r.config_file},
                              {"warmup_frames", r.warmup_frames},
                              {"rounds", r.rounds},
                              {"frames_per_sample", r.frames_per_sample},
                              {"targets",
                               {{"ratio_spread", kTargetRatioSpread},
                                {"within_run_cv", kTargetWithinRunCv},
                                {"spread_applies_above_ms", kTargetSpreadAboveMs}}},
                              {"environment", r.environment},
                              {"runs", runs},
                              {"cases", cases}};
    return j.dump(2) + "\n";
}

void write_stability_report(const std::filesystem::path& dir, const StabilityResult& result) {
    write_text_atomically(dir / "stability.md", stability_markdown(result));
    write_text_atomically(dir / "stability.json", stability_json(result));
}

}  // namespace canopy
