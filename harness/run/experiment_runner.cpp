#include "run/experiment_runner.hpp"

#include "config/experiment_config.hpp"
#include "metrics/comparable_pair.hpp"
#include "metrics/error_maps.hpp"
#include "report/csv_report.hpp"
#include "report/image_files.hpp"
#include "report/json_report.hpp"
#include "report/markdown_report.hpp"
#include "report/paper_report.hpp"
#include "run/interrupt.hpp"
#include "run/progress.hpp"
#include "run/reference_provider.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace canopy {

namespace {

std::string utc_now() { return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(std::time(nullptr))); }

const TechniqueEntry* entry_for(const Experiment& experiment, const std::string& technique) {
    for (const auto& entry : experiment.techniques)
        if (entry.name == technique) return &entry;
    return nullptr;
}

TimingSeries series(std::string name, std::vector<double> samples) {
    TimingSeries t{std::move(name), std::move(samples), {}};
    t.stats = summarize(t.samples_ms);
    return t;
}

// "kernel=5 pattern=poisson": the values that differ from the technique's defaults.
std::string changed_params(const Technique& technique, const ParamSet& params) {
    std::string out;
    const auto specs = technique.params();
    for (const auto& [name, value] : params.values()) {
        auto spec = std::find_if(specs.begin(), specs.end(), [&name = name](const ParamSpec& s) { return s.name == name; });
        if (spec != specs.end() && to_string(spec->default_value) == to_string(value)) continue;
        out += fmt::format("{}{}={}", out.empty() ? "" : " ", name, to_string(value));
    }
    return out.empty() ? "-" : out;
}

CaseResult case_header(const Case& c, const Scene& scene, const Technique& technique) {
    CaseResult result;
    result.id = c.id;
    result.scene = scene.name;
    result.technique = c.technique;
    result.resolution = c.resolution;
    result.params = c.params.values();
    result.params_summary = c.params.summary();
    result.params_changed = changed_params(technique, c.params);
    return result;
}

// Heat maps of every case of one reference share one scale: half the reference's 99th
// percentile luminance, so they can be compared side by side.
double error_map_scale(const Image& reference) {
    std::vector<float> luminance;
    luminance.reserve(size_t(reference.width) * size_t(reference.height));
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) luminance.push_back(reference.luminance(x, y));
    if (luminance.empty()) return 1.0;
    const size_t k = size_t(0.99 * double(luminance.size() - 1));
    std::nth_element(luminance.begin(), luminance.begin() + std::ptrdiff_t(k), luminance.end());
    const double scale = 0.5 * double(luminance[k]);
    return scale > 0.0 ? scale : 1.0;
}

std::string reference_stem(const Scene& scene, const Resolution& r) {
    return fmt::format("reference_{}_{}x{}", scene.name, r.width, r.height);
}

void write_reports(const std::filesystem::path& dir, const RunRecord& run, const Experiment& experiment) {
    write_json_report(dir / "results.json", run);
    write_csv_report(dir / "results.csv", run);
    write_markdown_report(dir / "results.md", run);
    if (experiment.paper) write_paper_report(dir / "paper.md", *experiment.paper, run);
}

}  // namespace

PreparedExperiment prepare_experiment(const Experiment& experiment, const TechniqueRegistry& registry,
                                      const GpuContext& gpu) {
    PreparedExperiment prepared;
    prepared.experiment = &experiment;
    prepared.cases = expand_cases(experiment, registry);
    for (const Scene& scene : experiment.scenes) prepared.meshes.push_back(build_scene_meshes(scene));

    // Every case that cannot run, so one attempt shows them all.
    struct Refused {
        const Case* c;
        Unsupported why;
    };
    std::vector<Refused> refused;
    for (const Case& c : prepared.cases) {
        const Technique* technique = registry.find(c.technique);
        if (auto why = check_supported(gpu, experiment.scenes[c.scene_index], technique->plan(c.params)))
            refused.push_back({&c, std::move(*why)});
    }
    if (refused.empty()) return prepared;

    constexpr size_t kListed = 20;  // more lines than this would scroll the cause off the screen
    std::string message = refused.size() == 1
                              ? "1 case cannot run:"
                              : fmt::format("{} of {} cases cannot run:", refused.size(), prepared.cases.size());
    std::vector<std::string> hints;
    for (size_t i = 0; i < refused.size(); ++i) {
        const Refused& r = refused[i];
        if (i < kListed) message += fmt::format("\n    {}: {}", r.c->id, r.why.reason);
        if (std::find(hints.begin(), hints.end(), r.why.hint) == hints.end()) hints.push_back(r.why.hint);
    }
    if (refused.size() > kListed) message += fmt::format("\n    ... and {} more", refused.size() - kListed);
    std::string hint;
    for (const std::string& h : hints) hint += (hint.empty() ? "" : "\n  hint: ") + h;
    const TechniqueEntry* entry = entry_for(experiment, refused.front().c->technique);
    throw ConfigError(experiment.file, entry ? entry->where.line : 0, message, hint);
}

CaseResult measure_case(const Case& c, const Scene& scene, const std::vector<TriangleMesh>& meshes,
                        const Technique& technique, const GpuContext& gpu, int warmup_frames, int measured_frames,
                        Image* image_out) {
    CaseResult result = case_header(c, scene, technique);
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
    result.nonfinite_pixels = count_nonfinite_pixels(image);
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
    run.reference_enabled = options.reference && experiment.reference_enabled;

    const std::filesystem::path& out = options.out_dir;
    std::filesystem::create_directories(out / "images");
    write_reports(out, run, experiment);

    ReferenceProvider references(options.reference_cache_dir, experiment.reference);
    Progress progress(prepared.cases.size());
    for (size_t i = 0; i < prepared.cases.size() && !interrupt_requested(); ++i) {
        const Case& c = prepared.cases[i];
        const Scene& scene = experiment.scenes[c.scene_index];
        const Technique& technique = *registry.find(c.technique);
        const std::string label = fmt::format("{} {}x{} {} {}", scene.name, c.resolution.width, c.resolution.height,
                                              c.technique, changed_params(technique, c.params));
        const auto start = std::chrono::steady_clock::now();

        // The reference first, so a case's record is complete when it is written.
        const ReferenceEntry* reference = nullptr;
        if (run.reference_enabled) {
            const std::string stem = reference_stem(scene, c.resolution);
            const bool first_use = std::none_of(run.references.begin(), run.references.end(), [&](const ReferenceRecord& r) {
                return r.scene == scene.name && r.resolution.width == c.resolution.width &&
                       r.resolution.height == c.resolution.height;
            });
            if (options.show_progress && first_use) progress.start_case(i, "ray-tracing " + stem);
            reference = &references.get(scene, prepared.meshes[c.scene_index], c.resolution.width, c.resolution.height,
                                        [&](double fraction) {
                                            if (options.show_progress)
                                                progress.update_label(i, fmt::format("ray-tracing {} {:.0f}%", stem, 100.0 * fraction));
                                        });
            const bool recorded = std::any_of(run.references.begin(), run.references.end(),
                                              [&](const ReferenceRecord& r) { return r.key == reference->key; });
            if (!recorded) {
                ReferenceRecord record;
                record.scene = scene.name;
                record.resolution = c.resolution;
                record.key = reference->key;
                record.from_cache = reference->from_cache;
                record.seconds = reference->images.seconds;
                record.shadow_rays = reference->images.shadow_rays;
                record.light_samples = references.settings().light_samples;
                record.pixel_samples = references.settings().pixel_samples;
                record.error_map_scale = error_map_scale(reference->images.radiance);
                if (options.images != ImageOutput::none) {
                    record.image_png = "images/" + stem + ".png";
                    write_png_srgb(out / record.image_png, reference->images.radiance);
                }
                if (options.images == ImageOutput::all) {
                    record.image_exr = "images/" + stem + ".exr";
                    record.visibility_exr = "images/" + stem + ".visibility.exr";
                    write_exr(out / record.image_exr, reference->images.radiance);
                    write_exr(out / record.visibility_exr, reference->images.visibility);
                }
                run.references.push_back(record);
            }
        }

        if (options.show_progress) progress.start_case(i, label);
        CaseResult result;
        Image image;
        try {
            result = measure_case(c, scene, prepared.meshes[c.scene_index], technique, gpu, run.warmup_frames,
                                  run.measured_frames, &image);
        } catch (const GpuError& e) {
            result = case_header(c, scene, technique);
            result.ok = false;
            result.error = e.what();
        }
        if (interrupt_requested()) break;  // this case did not finish: keep only the finished ones

        if (!image.pixels.empty()) {
            const bool pngs = options.images != ImageOutput::none;
            if (options.images == ImageOutput::all) {
                result.image_exr = "images/" + c.id + ".exr";
                write_exr(out / result.image_exr, image);
            }
            if (pngs) {
                result.image_png = "images/" + c.id + ".png";
                write_png_srgb(out / result.image_png, image);
            }
            if (reference) {
                const Image& truth = reference->images.radiance;
                std::vector<float> flip_map;
                result.image_error = compute_metrics(image, truth, &reference->images.visibility, {}, &flip_map);
                if (pngs) {
                    const auto record = std::find_if(run.references.begin(), run.references.end(),
                                                     [&](const ReferenceRecord& r) { return r.key == reference->key; });
                    result.error_map_png = "images/" + c.id + ".error.png";
                    result.flip_map_png = "images/" + c.id + ".flip.png";
                    write_png_display(out / result.error_map_png,
                                      absolute_error_heatmap(image, truth, record->error_map_scale));
                    write_png_display(out / result.flip_map_png, flip_heatmap(flip_map, image.width, image.height));
                }
            }
        }
        run.cases.push_back(std::move(result));
        write_reports(out, run, experiment);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (options.show_progress) progress.finish_case(i, label, seconds, run.cases.back().ok);
    }
    if (options.show_progress) progress.done();

    run.finished_at = utc_now();
    const bool any_failed = std::any_of(run.cases.begin(), run.cases.end(), [](const CaseResult& c) { return !c.ok; });
    run.status = interrupt_requested() ? "interrupted" : any_failed ? "failed" : "complete";
    write_reports(out, run, experiment);
    return run;
}

}  // namespace canopy
