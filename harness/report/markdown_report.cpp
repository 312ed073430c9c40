#include "report/markdown_report.hpp"

#include "metrics/metric_registry.hpp"
#include "report/atomic_file.hpp"
#include "report/result_columns.hpp"
#include "report/text_table.hpp"
#include "report/timing_sections.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace canopy {

std::string markdown_table(const RunRecord& run) {
    // The columns results.md shows, from the one list (report/result_columns.hpp), in its order.
    std::vector<std::string> header;
    std::vector<bool> right;
    std::vector<ResultColumn::Bound<ResultColumn::MarkdownHeader>> shown;
    for (const ResultColumn& column : result_columns()) {
        if (!column.markdown) continue;
        shown.push_back(column.markdown(run));
        for (const ResultColumn::MarkdownHeader& h : shown.back().headers) {
            header.push_back(h.text);
            right.push_back(h.right);
        }
    }
    std::vector<std::vector<std::string>> rows;
    for (const CaseResult& c : run.cases) {
        std::vector<std::string> row;
        for (const auto& column : shown)
            for (std::string& cell : column.cells(c)) row.push_back(std::move(cell));
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
    out += fmt::format("- heap while measuring: {}\n", e.heap);
    out += fmt::format("- canopy {} ({} build), commit {}, config hash {}\n", e.canopy_version, e.build_type,
                       commit_text(e), e.config_hash);
    if (e.commit_mismatch())
        out += fmt::format("- **the binary was built from {}, not from the checkout's commit {}**: these numbers come "
                           "from the binary's code\n",
                           e.binary_commit, e.git_commit);
    if (!e.binary_older_than.empty())
        out += fmt::format("- **the canopy binary is older than {}**: these numbers may come from other code than the "
                           "commit says\n",
                           e.binary_older_than);
    std::string resumed;
    for (const std::string& at : run.resumed_at) resumed += (resumed.empty() ? ", resumed " : " and ") + at;
    out += fmt::format("- per case {} warm-up frame{}, then {} rounds of {} frame{} (each group's cases interleaved "
                       "round by round){}; started {}{}, finished {}; status: {}\n",
                       run.warmup_frames, run.warmup_frames == 1 ? "" : "s", run.rounds, run.frames_per_sample,
                       run.frames_per_sample == 1 ? "" : "s",
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
           "dominated by: another case of the same scene and resolution that beats it as pareto.md's first front "
           "judges (on the first error its techniques declare as a Pareto axis: not significantly slower nor worse, "
           "and significantly faster or better; none with fewer than 6 rounds, as --quick measures); '-' where none "
           "does. "
           "Errors are against the ray-traced reference. How far the image is from the truth: RMSE, PSNR (peak 1), "
           "SSIM and FLIP over the whole image, in linear radiance (they include aliasing at silhouettes and "
           "shading, which no shadow technique changes). ";
    const auto declared = [&](bool ErrorColumns::*group) {
        return std::any_of(run.cases.begin(), run.cases.end(),
                           [&](const CaseResult& c) { return c.image_error && c.image_error->columns.*group; });
    };
    if (declared(&ErrorColumns::visibility) || declared(&ErrorColumns::shadow_regions))
        out += "How wrong the technique's shadow is: V RMSE, V MAE and V "
               "penumbra RMSE compare the visibility the technique gave the light with the reference's (1024 light "
               "samples) at the same pixel centres, so silhouettes and shading cancel (V excluded %: pixels the light "
               "reaches left out because the raster saw another surface there); bleeding = mean excess luminance over "
               "pixels in full umbra, over-dark = mean missing luminance over fully lit pixels, penumbra RMSE = "
               "luminance RMSE over pixels with 0 < V < 1, the classes from the reference's pixel-centre V, off "
               "silhouettes. ";
    if (declared(&ErrorColumns::coverage))
        out += "Where the blades are: cov MAE, cov tile MAE and cov total % compare the share of each pixel the "
               "population (the grass) covers in the technique (its colour target's alpha) with the share of the "
               "reference's pixel samples that hit it, per pixel (which includes the aliasing of a one-sample "
               "raster), per 8x8-pixel tile (where aliasing averages out) and over the image (grass gained or "
               "lost, as a percentage of the true coverage). ";
    if (std::any_of(run.cases.begin(), run.cases.end(),
                    [](const CaseResult& c) { return c.image_error && std::isfinite(c.image_error->popping_mean); }))
        out += "popping: along the camera path (one more traversal, untimed, the reference ray-traced at every "
               "frame), the mean over consecutive frames of the mean |change of the technique's luminance - change "
               "of the reference's|: what the technique changes that the scene does not (LoD switches, temporal "
               "aliasing, and the reference's re-drawn sample noise, which every technique shares); popping max: "
               "the worst pair of frames. ";
    if (run.distance_bands && std::any_of(run.cases.begin(), run.cases.end(), [](const CaseResult& c) {
            return c.image_error && (c.image_error->near_pixels + c.image_error->middle_pixels + c.image_error->far_pixels) > 0;
        }))
        out += fmt::format("FLIP near, FLIP middle and FLIP far: the mean of the FLIP map over the pixels whose surface "
                           "in the reference (through the pixel's centre) lies nearer than {} scene units from the eye, "
                           "from {} to {}, and {} or farther (distance along the ray; background pixels in none). ",
                           run.distance_bands->middle_from, run.distance_bands->middle_from,
                           run.distance_bands->far_from, run.distance_bands->far_from);
    out += "n/a: the technique's family declares the column meaningless for it. "
           "The papers define no error metric: these columns are canopy's. On lavapipe a GPU time is "
           "CPU time on a shared machine: compare ratios measured in one run, not absolute times across runs.\n";
    return out;
}

void write_markdown_report(const std::filesystem::path& path, const RunRecord& run) {
    write_text_atomically(path, markdown_report(run));
}

}  // namespace canopy
