#include "report/comparison_report.hpp"

#include "report/text_table.hpp"

#include <fmt/format.h>

#include <cmath>

namespace canopy {

namespace {

std::string percent(double fraction) {
    if (std::isnan(fraction)) return "-";
    return fmt::format("{:+.1f} %", 100.0 * fraction);
}

std::string change_cell(const Estimate& e) {
    if (e.count == 0 || std::isnan(e.value)) return "-";
    return fmt::format("{} [{}, {}]", percent(e.value), percent(e.ci.low), percent(e.ci.high));
}

std::string run_line(const char* role, const ComparedRun& r) {
    const RunRecord& run = *r.run;
    const std::string* commit = run.identity.find("commit");
    const std::string* device = run.identity.find("device");
    return fmt::format("- {}: `{}` — {} cases, commit {}, {}, {} rounds of {} frame{}, started {}, status {}\n", role,
                       r.path, run.cases.size(), commit ? *commit : "?", device ? *device : "?", run.rounds,
                       run.frames_per_sample, run.frames_per_sample == 1 ? "" : "s", run.started_at, run.status);
}

}  // namespace

std::string comparison_report(const ComparedRun& baseline, const ComparedRun& candidate, const RunComparison& comparison) {
    const ComparisonSettings& s = comparison.settings;
    std::string out = fmt::format("# canopy compare: {}\n\n", baseline.run->experiment);
    out += run_line("baseline", baseline);
    out += run_line("candidate", candidate);
    if (comparison.differences.empty()) {
        out += "- the runs have the same identity (commit, device, build, options): a rerun\n";
    } else {
        out += "- the runs differ in what they ran on (compared all the same, as compare is meant to):\n";
        for (const std::string& d : comparison.differences) out += "  - " + d + "\n";
    }
    out += fmt::format("- time: the change of each case's time ratio to its group's baseline, candidate / baseline - 1, "
                       "[95 % interval]; flagged as a REGRESSION when the whole interval lies above +{:.1f} %{}\n",
                       100.0 * s.threshold, s.time ? "" : " (not compared: --no-time)");
    out += fmt::format("- errors: every error metric within its tolerance (|change| <= absolute + relative x |baseline|){}\n\n",
                       s.errors ? "" : " (not compared: --no-errors)");

    std::vector<std::string> header{"case", "ratio before", "ratio after", "change [95% CI]", "time", "errors"};
    std::vector<bool> right{false, true, true, true, false, false};
    std::vector<std::vector<std::string>> rows;
    for (const CaseComparison& c : comparison.cases) {
        std::string time = to_string(c.time.verdict);
        if (c.failed_candidate && !c.failed_baseline) time = "FAILED (candidate)";
        else if (c.failed_baseline && !c.failed_candidate) time = "failed before, ok now";
        else if (c.failed_baseline) time = "failed in both";
        std::string errors = "-";
        if (!c.errors.empty()) {
            size_t out_of = 0;
            for (const MetricChange& m : c.errors) out_of += m.out_of_tolerance ? 1 : 0;
            errors = out_of ? fmt::format("{} OUT OF TOLERANCE", out_of) : "ok";
        }
        const bool is_baseline = c.time.verdict == TimeVerdict::baseline;
        rows.push_back({c.id, is_baseline ? "1" : ratio_cell(c.time.baseline_ratio),
                        is_baseline ? "1" : ratio_cell(c.time.candidate_ratio),
                        is_baseline ? "GPU ms " + change_cell(c.time.change) : change_cell(c.time.change), time, errors});
    }
    out += render_table(header, rows, right);
    out += fmt::format("\nThe group baseline's own line is the change of its absolute GPU time, for information: on a "
                       "shared machine load moves absolute times between runs, so it is never flagged. Fewer than {} "
                       "rounds on either side (--quick measures 3) judge no time change: \"too few rounds\".\n",
                       kMinComparedRounds);

    std::vector<std::vector<std::string>> metric_rows;
    for (const CaseComparison& c : comparison.cases)
        for (const MetricChange& m : c.errors)
            if (m.out_of_tolerance)
                metric_rows.push_back({c.id, m.metric, metric_cell(m.baseline), metric_cell(m.candidate),
                                       metric_cell(m.candidate - m.baseline), metric_cell(m.allowed)});
    if (!metric_rows.empty()) {
        out += "\n## Error metrics out of tolerance\n\n";
        out += render_table({"case", "metric", "baseline", "candidate", "change", "allowed"}, metric_rows,
                            {false, false, true, true, true, true});
    }
    if (!comparison.only_in_baseline.empty() || !comparison.only_in_candidate.empty()) {
        out += "\n## Cases in one run only (not compared)\n\n";
        for (const std::string& id : comparison.only_in_baseline) out += "- only in the baseline: " + id + "\n";
        for (const std::string& id : comparison.only_in_candidate) out += "- only in the candidate: " + id + "\n";
    }

    out += fmt::format("\n{} compared: {} regression{}, {} improvement{}, {} case{} with errors out of tolerance, {} "
                       "newly failed; {}\n",
                       comparison.cases.size(), comparison.regressions(), comparison.regressions() == 1 ? "" : "s",
                       comparison.improvements(), comparison.improvements() == 1 ? "" : "s",
                       comparison.errors_out_of_tolerance(), comparison.errors_out_of_tolerance() == 1 ? "" : "s",
                       comparison.newly_failed(), comparison.passed() ? "passed (exit code 0)" : "FLAGGED (exit code 1)");
    return out;
}

}  // namespace canopy
