#include "run/experiment_runner.hpp"

#include "config/experiment_config.hpp"
#include "metrics/colour_bar.hpp"
#include "metrics/comparable_pair.hpp"
#include "metrics/error_maps.hpp"
#include "report/csv_report.hpp"
#include "report/image_files.hpp"
#include "report/json_report.hpp"
#include "report/markdown_report.hpp"
#include "report/paper_report.hpp"
#include "run/interrupt.hpp"
#include "run/case_labels.hpp"
#include "run/output_folder.hpp"
#include "run/progress.hpp"
#include "run/recorded_path.hpp"
#include "run/reference_provider.hpp"
#include "run/run_identity.hpp"
#include "run/test_hooks.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <set>

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

CaseResult case_header(const Case& c, const Scene& scene) {
    CaseResult result;
    result.id = c.id;
    result.scene = scene.name;
    result.technique = c.technique;
    result.resolution = c.resolution;
    result.params = c.params.values();
    result.params_summary = c.params.summary();
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
                        Image* image_out, Image* visibility_out) {
    CaseResult result = case_header(c, scene);
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
    if (visibility_out) *visibility_out = renderer.read_pixel_visibility();
    return result;
}

namespace {

// Which of the previous run's cases (and references) this run keeps: finished, recorded, and with
// every file they name still on disk. A case that failed is run again.
struct KeptResults {
    std::map<std::string, CaseResult> cases;  // by case id
    std::vector<ReferenceRecord> references;
};

bool same_reference(const ReferenceRecord& r, const std::string& scene, const Resolution& resolution) {
    return r.scene == scene && r.resolution.width == resolution.width && r.resolution.height == resolution.height;
}

bool files_exist(const std::filesystem::path& dir, std::initializer_list<const std::string*> files) {
    return std::all_of(files.begin(), files.end(),
                       [&](const std::string* f) { return f->empty() || std::filesystem::is_regular_file(dir / *f); });
}

KeptResults kept_results(const RunRecord* previous, const std::filesystem::path& out) {
    KeptResults kept;
    if (!previous) return kept;
    for (const ReferenceRecord& r : previous->references)
        if (files_exist(out, {&r.image_exr, &r.image_png, &r.visibility_exr, &r.pixel_visibility_exr}))
            kept.references.push_back(r);
    for (const CaseResult& c : previous->cases) {
        const bool reference_kept =
            !c.image_error || std::any_of(kept.references.begin(), kept.references.end(),
                                          [&](const ReferenceRecord& r) { return same_reference(r, c.scene, c.resolution); });
        if (c.ok && reference_kept &&
            files_exist(out, {&c.image_exr, &c.image_png, &c.visibility_exr, &c.error_map_png, &c.flip_map_png}))
            kept.cases.emplace(c.id, c);
    }
    return kept;
}

}  // namespace

RunRecord run_experiment(const PreparedExperiment& prepared, const TechniqueRegistry& registry, const GpuContext& gpu,
                         const RunOptions& options) {
    const Experiment& experiment = *prepared.experiment;
    const std::filesystem::path& out = options.out_dir;
    RunRecord run;
    run.experiment = experiment.name;
    run.description = experiment.description;
    run.config_file = recorded_path(experiment.file);
    run.environment = collect_environment(gpu, experiment.config_hash);
    run.identity = make_run_identity(experiment, options, run.environment);
    run.quick = options.quick;
    run.warmup_frames = options.quick ? std::min(experiment.warmup_frames, 1) : experiment.warmup_frames;
    run.measured_frames = options.quick ? std::min(experiment.measured_frames, 3) : experiment.measured_frames;
    run.started_at = utc_now();
    run.planned_cases = prepared.cases.size();
    run.reference_enabled = options.reference && experiment.reference_enabled;

    // A continued run keeps what the previous one finished; the rest is run in the planned order.
    const KeptResults kept = kept_results(options.previous, out);
    if (options.previous) {
        run.started_at = options.previous->started_at;
        run.resumed_at = options.previous->resumed_at;
        run.resumed_at.push_back(utc_now());
        run.references = kept.references;
    }
    const CaseLabels labels(prepared.cases, registry);
    std::vector<std::optional<CaseResult>> slots(prepared.cases.size());  // planned order
    for (size_t i = 0; i < prepared.cases.size(); ++i) {
        const Case& c = prepared.cases[i];
        if (auto it = kept.cases.find(c.id); it != kept.cases.end()) {
            CaseResult result = it->second;  // measurements as recorded, labels from this run's cases
            result.params = c.params.values();
            result.params_summary = c.params.summary();
            result.params_shown = labels.parameters(c);
            slots[i] = std::move(result);
        }
    }
    auto record_cases = [&] {
        run.cases.clear();
        for (const auto& slot : slots)
            if (slot) run.cases.push_back(*slot);
    };
    record_cases();

    // References the cases still to run need, for the ETA.
    std::set<std::string> references_needed;
    for (size_t i = 0; i < prepared.cases.size(); ++i)
        if (!slots[i])
            references_needed.insert(fmt::format("{}@{}x{}", prepared.cases[i].scene_index, prepared.cases[i].resolution.width,
                                                 prepared.cases[i].resolution.height));
    Progress progress(prepared.cases.size(), run.reference_enabled ? references_needed.size() : 0);
    ReferenceProvider references(options.reference_cache_dir, experiment.reference);
    size_t measured = 0;  // cases this process measured
    try {
        std::filesystem::create_directories(out / "images");
        if (options.previous) remove_temporary_files(out);
        write_reports(out, run, experiment);

        for (size_t i = 0; i < prepared.cases.size() && !interrupt_requested(); ++i) {
            const Case& c = prepared.cases[i];
            const Scene& scene = experiment.scenes[c.scene_index];
            const Technique& technique = *registry.find(c.technique);
            const std::string label = fmt::format("{} {}x{} {} {}", scene.name, c.resolution.width, c.resolution.height,
                                                  c.technique, labels.parameters(c));
            if (slots[i]) {
                if (options.show_progress) progress.kept_case(i, label);
                continue;
            }
            // The reference first, so a case's record is complete when it is written.
            const ReferenceEntry* reference = nullptr;
            if (run.reference_enabled) {
                const std::string stem = reference_stem(scene, c.resolution);
                const std::string name = fmt::format("{} {}x{}", scene.name, c.resolution.width, c.resolution.height);
                bool obtained_now = false;
                bool source_from_cache = false;
                const auto reference_start = std::chrono::steady_clock::now();
                reference = &references.get(
                    scene, prepared.meshes[c.scene_index], c.resolution.width, c.resolution.height,
                    [&](double fraction) {
                        if (options.show_progress) progress.reference_progress(i, name, fraction);
                    },
                    [&](bool from_cache) {
                        obtained_now = true;
                        source_from_cache = from_cache;
                        if (options.show_progress) progress.reference_started(i, name, from_cache);
                    });
                if (obtained_now && options.show_progress)
                    progress.reference_finished(
                        i, name, std::chrono::duration<double>(std::chrono::steady_clock::now() - reference_start).count(),
                        source_from_cache);
                const bool recorded = std::any_of(run.references.begin(), run.references.end(),
                                                  [&](const ReferenceRecord& r) { return same_reference(r, scene.name, c.resolution); });
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
                    record.pixel_visibility_key = reference->pixel_visibility_key;
                    record.pixel_visibility_from_cache = reference->pixel_visibility_from_cache;
                    record.pixel_visibility_seconds = reference->pixel_visibility.seconds;
                    record.pixel_visibility_shadow_rays = reference->pixel_visibility.shadow_rays;
                    record.pixel_visibility_samples = references.pixel_visibility_settings().light_samples;
                    if (options.images != ImageOutput::none) {
                        record.image_png = "images/" + stem + ".png";
                        write_png_srgb(out / record.image_png, reference->images.radiance);
                    }
                    if (options.images == ImageOutput::all) {
                        record.image_exr = "images/" + stem + ".exr";
                        record.visibility_exr = "images/" + stem + ".visibility.exr";
                        write_exr(out / record.image_exr, reference->images.radiance);
                        write_exr(out / record.visibility_exr, reference->images.visibility);
                        record.pixel_visibility_exr = "images/" + stem + ".pixel_visibility.exr";
                        write_exr(out / record.pixel_visibility_exr, reference->pixel_visibility.visibility);
                    }
                    run.references.push_back(record);
                }
            }

            // The case's time leaves its reference out: Progress estimates the time left from case
            // times and reference times separately (a reference is obtained once per scene and size).
            const auto start = std::chrono::steady_clock::now();
            if (options.show_progress) progress.start_case(i, label);
            CaseResult result;
            Image image, visibility;
            try {
                result = measure_case(c, scene, prepared.meshes[c.scene_index], technique, gpu, run.warmup_frames,
                                      run.measured_frames, &image, &visibility);
            } catch (const GpuError& e) {
                result = case_header(c, scene);
                result.ok = false;
                result.error = e.what();
            }
            if (interrupt_requested()) break;  // this case did not finish: keep only the finished ones
            result.params_shown = labels.parameters(c);
            ++measured;

            if (!image.pixels.empty()) {
                const bool pngs = options.images != ImageOutput::none;
                if (options.images == ImageOutput::all) {
                    result.image_exr = "images/" + c.id + ".exr";
                    write_exr(out / result.image_exr, image);
                    result.visibility_exr = "images/" + c.id + ".visibility.exr";
                    write_exr(out / result.visibility_exr, visibility);
                }
                if (pngs) {
                    result.image_png = "images/" + c.id + ".png";
                    write_png_srgb(out / result.image_png, image);
                }
                if (reference) {
                    const Image& truth = reference->images.radiance;
                    std::vector<float> flip_map;
                    // The pixel-centre visibility of the technique and of the reference: the
                    // technique-isolated error and the shadow regions (metrics/pixel_classes.hpp).
                    const PixelVisibilityPair pixel_visibility{visibility, reference->pixel_visibility.visibility};
                    result.image_error =
                        compute_metrics(image, truth, &pixel_visibility, technique.error_columns(), {}, &flip_map);
                    if (pngs) {
                        const auto record = std::find_if(run.references.begin(), run.references.end(),
                                                         [&](const ReferenceRecord& r) { return same_reference(r, scene.name, c.resolution); });
                        result.error_map_png = "images/" + c.id + ".error.png";
                        result.flip_map_png = "images/" + c.id + ".flip.png";
                        // Each with its scale drawn beside it.
                        write_png_display(out / result.error_map_png,
                                          with_colour_bar(absolute_error_heatmap(image, truth, record->error_map_scale),
                                                          viridis_colormap(), record->error_map_scale));
                        write_png_display(out / result.flip_map_png,
                                          with_colour_bar(flip_heatmap(flip_map, image.width, image.height),
                                                          magma_colormap(), 1.0));
                    }
                }
            }
            test_hooks::case_images_written(measured);
            slots[i] = std::move(result);
            record_cases();
            write_reports(out, run, experiment);
            test_hooks::case_recorded(measured);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (options.show_progress) progress.finish_case(i, label, seconds, slots[i]->ok);
        }
    } catch (const std::exception& e) {
        // The run cannot go on (a full disk, an unwritable folder, a reference that cannot be
        // rendered): record why, if the disk still takes it.
        if (options.show_progress) progress.done();
        run.finished_at = utc_now();
        run.status = "failed";
        run.error = e.what();
        try {
            write_reports(out, run, experiment);
        } catch (const std::exception& again) {
            run.error += fmt::format(" (results.json could not record this either: {})", again.what());
        }
        return run;
    }
    if (options.show_progress) progress.done();

    run.finished_at = utc_now();
    const bool any_failed = std::any_of(run.cases.begin(), run.cases.end(), [](const CaseResult& c) { return !c.ok; });
    run.status = interrupt_requested() ? "interrupted" : any_failed ? "failed" : "complete";
    try {
        write_reports(out, run, experiment);
    } catch (const std::exception& e) {
        run.status = "failed";
        run.error = e.what();
    }
    return run;
}

}  // namespace canopy
