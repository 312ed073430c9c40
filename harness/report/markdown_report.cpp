#include "report/markdown_report.hpp"

#include "metrics/metric_registry.hpp"
#include "report/atomic_file.hpp"
#include "report/text_table.hpp"
#include "report/timing_sections.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace canopy {

namespace {

std::string mib(uint64_t bytes) { return fmt::format("{:.2f}", double(bytes) / (1024.0 * 1024.0)); }

}  // namespace

std::string markdown_table(const RunRecord& run) {
    std::vector<std::string> header = {"scene", "resolution", "technique", "parameters", "GPU ms", "± MAD",
                                       "CV %",  "ratio",      "wall ms",   "passes (GPU ms)", "memory MiB"};
    std::vector<bool> right = {false, false, false, false, true, true, true, true, true, false, true};
    const bool errors = std::any_of(run.cases.begin(), run.cases.end(), [](const CaseResult& c) { return c.image_error.has_value(); });
    std::vector<const MetricInfo*> metrics;  // the registered metrics results.md shows
    for (const MetricInfo& metric : registered_metrics())
        if (errors && metric.shown_in(shown_in_markdown)) metrics.push_back(&metric);
    for (const MetricInfo* metric : metrics) {
        header.emplace_back(metric->column);
        right.push_back(true);
    }
    header.push_back("status");
    right.push_back(false);

    std::vector<std::vector<std::string>> rows;
    for (const auto& c : run.cases) {
        std::string passes;
        for (const auto& p : c.passes) passes += fmt::format("{}{} {:.3f}", passes.empty() ? "" : ", ", p.name, p.stats.median);
        const bool timed = c.gpu_frame.stats.count > 0;
        std::vector<std::string> row = {
            c.scene, fmt::format("{}x{}", c.resolution.width, c.resolution.height), c.technique, c.params_shown,
            timed ? fmt::format("{:.3f}", c.gpu_frame.stats.median) : "-",
            timed ? fmt::format("{:.3f}", c.gpu_frame.stats.mad) : "-",
            timed ? fmt::format("{:.1f}", 100.0 * c.gpu_frame.stats.cv) : "-",
            c.ok ? ratio_cell(c.ratio.estimate) : "-",
            timed ? fmt::format("{:.3f}", c.wall.stats.median) : "-", passes.empty() ? "-" : passes,
            mib(c.memory.technique_bytes)};
        for (const MetricInfo* metric : metrics) row.push_back(c.image_error ? table_cell(*metric, *c.image_error) : "-");
        row.push_back(c.ok ? "ok" : "FAILED: " + c.error);
        rows.push_back(std::move(row));
    }
    return render_table(header, rows, right);
}

std::string markdown_report(const RunRecord& run) {
    const Environment& e = run.environment;
    std::string out = fmt::format("# {}\n\n", run.experiment);
    if (!run.description.empty()) out += run.description + "\n\n";
    out += fmt::format("- device: {} ({}, {}), Vulkan {}\n", e.device.name, e.device.type, e.device.driver_info,
                       e.device.api_version);
    out += fmt::format("- CPU: {}, nproc {} (this process may use CPUs {}), LP_NUM_THREADS {}; load average at the "
                       "start {:.2f} {:.2f} {:.2f}\n",
                       e.cpu_model, e.nproc, e.cpus_allowed, e.lp_num_threads, e.load_average[0], e.load_average[1],
                       e.load_average[2]);
    out += fmt::format("- canopy {} ({} build), commit {}{}, config hash {}\n", e.canopy_version, e.build_type,
                       e.git_commit, e.git_dirty ? " (with uncommitted changes)" : "", e.config_hash);
    std::string resumed;
    for (const std::string& at : run.resumed_at) resumed += (resumed.empty() ? ", resumed " : " and ") + at;
    out += fmt::format("- per case {} warm-up frames, then {} rounds of {} frame{} (each group's cases interleaved "
                       "round by round){}; started {}{}, finished {}; status: {}\n",
                       run.warmup_frames, run.rounds, run.frames_per_sample, run.frames_per_sample == 1 ? "" : "s",
                       run.quick ? " (--quick)" : "", run.started_at, resumed,
                       run.finished_at.empty() ? "-" : run.finished_at, run.status);
    if (!run.error.empty()) out += fmt::format("- the run stopped: {}\n", run.error);
    out += "\n";
    out += markdown_table(run);
    if (!run.references.empty()) {
        out += "\nReferences (Embree, same shading model, area lights integrated):\n\n";
        for (const auto& r : run.references)
            out += fmt::format("- {} {}x{}: {} light x {} pixel samples, {} shadow rays, {:.1f} s{}; `{}`\n", r.scene,
                               r.resolution.width, r.resolution.height, r.light_samples, r.pixel_samples, r.shadow_rays,
                               r.seconds, r.from_cache ? " (cached)" : "", r.image_png);
    }
    out += timing_check_section(run);
    out += cpu_time_section(run);
    out += camera_path_section(run);
    out += "\nGPU ms: median over the rounds of a sample's mean frame time, from the first pass's start to the last "
           "pass's end (Vulkan timestamps); CV over the rounds. ratio: GPU time relative to the first row of the same "
           "scene and resolution (the group's baseline), each sample divided by the baseline's samples measured just "
           "before and after it, median over the rounds with its 95 % block-bootstrap interval. "
           "memory: device memory the technique's own resources take (shadow maps, ...). "
           "Errors are against the ray-traced reference. How far the image is from the truth: RMSE, PSNR (peak 1), "
           "SSIM and FLIP over the whole image, in linear radiance (they include aliasing at silhouettes and "
           "shading, which no shadow technique changes). How wrong the technique's shadow is: V RMSE, V MAE and V "
           "penumbra RMSE compare the visibility the technique gave the light with the reference's (1024 light "
           "samples) at the same pixel centres, so silhouettes and shading cancel (V excluded %: pixels the light "
           "reaches left out because the raster saw another surface there); bleeding = mean excess luminance over "
           "pixels in full umbra, over-dark = mean missing luminance over fully lit pixels, penumbra RMSE = "
           "luminance RMSE over pixels with 0 < V < 1, the classes from the reference's pixel-centre V, off "
           "silhouettes. n/a: the technique's family declares the column meaningless for it. "
           "The papers define no error metric: these columns are canopy's. On lavapipe a GPU time is "
           "CPU time on a shared machine: compare ratios measured in one run, not absolute times across runs.\n";
    return out;
}

void write_markdown_report(const std::filesystem::path& path, const RunRecord& run) {
    write_text_atomically(path, markdown_report(run));
}

}  // namespace canopy
