#include "report/timing_sections.hpp"

#include "run/statistics.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace canopy {

namespace {

std::string disagreement(const CaseResult& c) {
    const TimingCheck& t = c.timing_check;
    return fmt::format("{}: GPU passes sum to {:.3f} ms, wall {:.3f} ms, median gap {:+.3f} ms (tolerance {:.3f} ms)",
                       c.id, t.pass_sum_ms, t.wall_ms, t.gap_ms, t.tolerance_ms);
}

}  // namespace

std::vector<std::string> timing_check_warnings(const RunRecord& run) {
    std::vector<std::string> lines;
    for (const CaseResult& c : run.cases)
        if (c.ok && !c.timing_check.agrees()) lines.push_back(disagreement(c));
    return lines;
}

std::string timing_check_section(const RunRecord& run) {
    size_t checked = 0;
    for (const CaseResult& c : run.cases) checked += c.timing_check.checked ? 1 : 0;
    if (checked == 0) return {};
    std::string out = fmt::format(
        "\nTiming cross-check: per round, the sum of a case's GPU pass times beside its fence-to-fence wall time; the "
        "median gap must lie within max({:.0f} % of the wall time, {} ms).",
        100 * kTimingCheckRelative, kTimingCheckAbsoluteMs);
    const std::vector<std::string> flagged = timing_check_warnings(run);
    if (flagged.empty()) return out + fmt::format(" All {} cases agree.\n", checked);
    out += fmt::format(" **{} of {} cases disagree** (their GPU times do not account for the frame: read them with "
                       "care):\n\n",
                       flagged.size(), checked);
    for (const std::string& line : flagged) out += "- " + line + "\n";
    return out;
}

std::string cpu_time_section(const RunRecord& run) {
    const bool any = std::any_of(run.cases.begin(), run.cases.end(),
                                 [](const CaseResult& c) { return c.record_cpu.stats.count > 0; });
    if (!any) return {};
    std::string out =
        "\nCPU side of a frame (steady clock, median over the rounds, ms): recording the frame's commands (every frame "
        "is recorded anew), and each CPU pass the technique declares. Neither is in the GPU times above.\n\n"
        "| case | record ms | CPU passes |\n|---|---:|---|\n";
    for (const CaseResult& c : run.cases) {
        if (c.record_cpu.stats.count == 0) continue;
        std::string passes;
        for (const TimingSeries& p : c.cpu_passes)
            passes += fmt::format("{}{} {:.3f}", passes.empty() ? "" : ", ", p.name, p.stats.median);
        out += fmt::format("| {} | {:.3f} | {} |\n", c.id, c.record_cpu.stats.median, passes.empty() ? "-" : passes);
    }
    return out;
}

std::string camera_path_section(const RunRecord& run) {
    if (!run.camera_path) return {};
    std::string out = fmt::format(
        "\nCamera path: {} frames through {} poses, every sample one traversal (the times above are means over it; "
        "images and errors are rendered at the scene's camera after it). Per pass, its median time at each frame of "
        "the path, then the least, median and greatest of those over the frames (ms):\n\n"
        "| case | pass | min | median | max | slowest frame |\n|---|---|---:|---:|---:|---:|\n",
        run.camera_path->frames, run.camera_path->poses.size());
    for (const CaseResult& c : run.cases) {
        if (c.path_frames.empty()) continue;
        const auto row = [&](const std::string& name, auto&& value_of) {
            std::vector<double> medians;
            for (const CaseResult::PathFrame& f : c.path_frames) medians.push_back(value_of(f));
            const SampleStats s = summarize(medians);
            const size_t slowest = size_t(std::max_element(medians.begin(), medians.end()) - medians.begin());
            out += fmt::format("| {} | {} | {:.3f} | {:.3f} | {:.3f} | {} |\n", c.id, name, s.min, s.median, s.max, slowest);
        };
        row("gpu_frame", [](const CaseResult::PathFrame& f) { return f.gpu_frame.stats.median; });
        for (size_t p = 0; p < c.passes.size(); ++p)
            row(c.passes[p].name, [p](const CaseResult::PathFrame& f) {
                return p < f.passes.size() ? f.passes[p].stats.median : 0.0;
            });
    }
    return out;
}

}  // namespace canopy
