#include "run/experiment_runner.hpp"

#include "config/experiment_config.hpp"
#include "report/csv_report.hpp"
#include "report/image_files.hpp"
#include "report/json_report.hpp"
#include "report/markdown_report.hpp"
#include "run/interrupt.hpp"
#include "run/progress.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <chrono>
#include <cmath>

namespace canopy {

namespace {

std::string utc_now() {
    return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(std::time(nullptr)));
}

const TechniqueEntry* entry_for(const Experiment& experiment, const std::string& technique) {
    for (const auto& entry : experiment.techniques)
        if (entry.name == technique) return &entry;
    return nullptr;
}

long long count_nonfinite(const Image& image) {
    long long count = 0;
    for (size_t i = 0; i < image.pixels.size(); i += 4)
        if (!std::isfinite(image.pixels[i]) || !std::isfinite(image.pixels[i + 1]) || !std::isfinite(image.pixels[i + 2]) ||
            !std::isfinite(image.pixels[i + 3]))
            ++count;
    return count;
}

TimingSeries series(std::string name, std::vector<double> samples) {
    TimingSeries t{std::move(name), std::move(samples), {}};
    t.stats = summarize(t.samples_ms);
    return t;
}

void write_reports(const std::filesystem::path& dir, const RunRecord& run) {
    write_json_report(dir / "results.json", run);
    write_csv_report(dir / "results.csv", run);
    write_markdown_report(dir / "results.md", run);
}

}  // namespace

PreparedExperiment prepare_experiment(const Experiment& experiment, const TechniqueRegistry& registry,
                                      const GpuContext& gpu) {
    PreparedExperiment prepared;
    prepared.experiment = &experiment;
    prepared.cases = expand_cases(experiment, registry);
    for (const Scene& scene : experiment.scenes) prepared.meshes.push_back(build_scene_meshes(scene));
    for (const Case& c : prepared.cases) {
        const Technique* technique = registry.find(c.technique);
        const FramePlan plan = technique->plan(c.params);
        if (auto reason = unsupported_reason(gpu, experiment.scenes[c.scene_index], plan)) {
            const TechniqueEntry* entry = entry_for(experiment, c.technique);
            throw ConfigError(experiment.file, entry ? entry->where.line : 0,
                              fmt::format("case {} cannot run: {}", c.id, *reason),
                              "change the technique's parameters or the scene, or pick another device with --device");
        }
    }
    return prepared;
}

CaseResult measure_case(const Case& c, const Scene& scene, const std::vector<TriangleMesh>& meshes,
                        const Technique& technique, const GpuContext& gpu, int warmup_frames, int measured_frames,
                        Image* image_out) {
    CaseResult result;
    result.id = c.id;
    result.scene = scene.name;
    result.technique = c.technique;
    result.resolution = c.resolution;
    result.params = c.params.values();
    result.params_summary = c.params.summary();

    FrameRenderer renderer(gpu, scene, meshes, uint32_t(c.resolution.width), uint32_t(c.resolution.height),
                           technique.plan(c.params));
    for (int i = 0; i < warmup_frames && !interrupt_requested(); ++i) renderer.render();
    std::vector<std::vector<double>> pass_samples(renderer.pass_names().size());
    std::vector<double> gpu_samples, wall_samples;
    for (int i = 0; i < measured_frames && !interrupt_requested(); ++i) {
        FrameTiming t = renderer.render();
        for (size_t p = 0; p < t.pass_gpu_ms.size(); ++p) pass_samples[p].push_back(t.pass_gpu_ms[p]);
        gpu_samples.push_back(t.gpu_ms);
        wall_samples.push_back(t.wall_ms);
    }
    for (size_t p = 0; p < pass_samples.size(); ++p)
        result.passes.push_back(series(renderer.pass_names()[p], std::move(pass_samples[p])));
    result.gpu_frame = series("gpu_frame", std::move(gpu_samples));
    result.wall = series("wall", std::move(wall_samples));
    result.memory = renderer.memory();
    result.triangles = renderer.triangle_count();
    result.shadow_sampler = renderer.shadow_sampler();

    Image image = renderer.read_color();
    result.nonfinite_pixels = count_nonfinite(image);
    if (result.nonfinite_pixels > 0) {
        result.ok = false;
        result.error = fmt::format("{} pixels are NaN or Inf", result.nonfinite_pixels);
    }
    if (image_out) *image_out = std::move(image);
    return result;
}

RunRecord run_experiment(const PreparedExperiment& prepared, const TechniqueRegistry& registry, const GpuContext& gpu,
                         const RunOptions& options) {
    const Experiment& experiment = *prepared.experiment;
    RunRecord run;
    run.experiment = experiment.name;
    run.description = experiment.description;
    run.config_file = experiment.file.string();
    run.environment = collect_environment(gpu, experiment.config_hash);
    run.quick = options.quick;
    run.warmup_frames = options.quick ? std::min(experiment.warmup_frames, 1) : experiment.warmup_frames;
    run.measured_frames = options.quick ? std::min(experiment.measured_frames, 3) : experiment.measured_frames;
    run.started_at = utc_now();
    run.planned_cases = prepared.cases.size();

    std::filesystem::create_directories(options.out_dir / "images");
    write_reports(options.out_dir, run);

    Progress progress(prepared.cases.size());
    for (size_t i = 0; i < prepared.cases.size() && !interrupt_requested(); ++i) {
        const Case& c = prepared.cases[i];
        const std::string label = fmt::format("{} {}x{} {} {}", experiment.scenes[c.scene_index].name,
                                              c.resolution.width, c.resolution.height, c.technique, c.params.summary());
        if (options.show_progress) progress.start_case(i, label);
        const auto start = std::chrono::steady_clock::now();
        CaseResult result;
        Image image;
        try {
            result = measure_case(c, experiment.scenes[c.scene_index], prepared.meshes[c.scene_index],
                                  *registry.find(c.technique), gpu, run.warmup_frames, run.measured_frames, &image);
        } catch (const GpuError& e) {
            result.id = c.id;
            result.scene = experiment.scenes[c.scene_index].name;
            result.technique = c.technique;
            result.resolution = c.resolution;
            result.params = c.params.values();
            result.params_summary = c.params.summary();
            result.ok = false;
            result.error = e.what();
        }
        if (interrupt_requested()) break;  // this case did not finish: keep only the finished ones
        if (!image.pixels.empty()) {
            result.image_exr = "images/" + c.id + ".exr";
            result.image_png = "images/" + c.id + ".png";
            write_exr(options.out_dir / result.image_exr, image);
            write_png_srgb(options.out_dir / result.image_png, image);
        }
        run.cases.push_back(std::move(result));
        write_reports(options.out_dir, run);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (options.show_progress) progress.finish_case(i, label, seconds, run.cases.back().ok);
    }
    if (options.show_progress) progress.done();

    run.finished_at = utc_now();
    const bool any_failed = std::any_of(run.cases.begin(), run.cases.end(), [](const CaseResult& c) { return !c.ok; });
    run.status = interrupt_requested() ? "interrupted" : any_failed ? "failed" : "complete";
    write_reports(options.out_dir, run);
    return run;
}

}  // namespace canopy
