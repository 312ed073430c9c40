#include "reference/reference_noise.hpp"
#include "reference/parallel_for.hpp"
#include "run/environment.hpp"
#include "run/experiment_runner.hpp"

#include "config/experiment_config.hpp"
#include "metrics/colour_bar.hpp"
#include "metrics/comparable_pair.hpp"
#include "metrics/error_maps.hpp"
#include "metrics/metric_registry.hpp"
#include "metrics/popping.hpp"
#include "metrics/reference_degeneracy.hpp"
#include "report/atomic_file.hpp"
#include "report/csv_report.hpp"
#include "report/gbench_report.hpp"
#include "report/image_files.hpp"
#include "report/json_report.hpp"
#include "report/markdown_report.hpp"
#include "report/paper_report.hpp"
#include "report/pareto_report.hpp"
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
#include <fstream>
#include <functional>
#include <map>
#include <optional>

namespace canopy {

namespace {


const TechniqueEntry* entry_for(const Experiment& experiment, const std::string& technique) {
    for (const auto& entry : experiment.techniques)
        if (entry.name == technique) return &entry;
    return nullptr;
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

// Every metric against each of the reference's noisy replicates (reference/reference_noise.hpp), the
// replicates computed in parallel; nothing when the reference has no variance image.
std::map<std::string, std::vector<double>> metrics_against_noisy_references(
    const Image& image, const ReferenceImages& reference, const PixelVisibilityPair* visibility,
    const CoveragePair* coverage, ErrorColumns columns, const MetricOptions& options) {
    std::map<std::string, std::vector<double>> replicates;
    if (reference.variance.width != reference.radiance.width || reference.variance.height != reference.radiance.height)
        return replicates;
    std::vector<ImageMetrics> metrics(kReferenceReplicates);
    parallel_for(metrics.size(), 0, [&](size_t k, int) {
        metrics[k] = compute_metrics(image, perturbed_reference(reference.radiance, reference.variance, int(k)),
                                     visibility, coverage, columns, options);
    });
    for (const MetricInfo& metric : registered_metrics()) {
        std::vector<double> values;
        bool any = false;
        for (const ImageMetrics& m : metrics) {
            values.push_back(metric.meaningful_value(m));
            any = any || std::isfinite(values.back());
        }
        if (any) replicates[std::string(metric.name)] = std::move(values);
    }
    return replicates;
}

// The experiment config, then the files it read, each once.
std::vector<std::filesystem::path> inputs_of(const Experiment& experiment) {
    std::vector<std::filesystem::path> files{experiment.file};
    for (const std::filesystem::path& f : experiment.hashed_files)
        if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(f);
    return files;
}

std::string file_bytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string reference_stem(const Scene& scene, const Resolution& r) {
    return fmt::format("reference_{}_{}x{}", scene.name, r.width, r.height);
}

}  // namespace

void write_run_reports(const std::filesystem::path& dir, const RunRecord& run, const Experiment& experiment) {
    write_json_report(dir / "results.json", run);
    write_csv_report(dir / "results.csv", run);
    write_markdown_report(dir / "results.md", run);
    write_gbench_report(dir / "results.gbench.json", run);
    if (experiment.paper) {
        const RunToRunNoise noise = run_to_run_noise_for(run, dir);
        write_paper_report(dir / "paper.md", *experiment.paper, run, noise);
        write_paper_data(dir / "paper.json", *experiment.paper, run, noise);
    }
    write_pareto_report(dir / "pareto.md", run);
}

namespace {

// Throws ConfigError naming the experiment's file:line and every case that `check` refuses, or
// whose scene lacks the population its technique renders (check_population_present), so one
// attempt shows them all.
void refuse_unrunnable(const Experiment& experiment, const std::vector<Case>& cases, const TechniqueRegistry& registry,
                       const std::function<std::optional<Unsupported>(const Scene&, const FrameGraph&)>& check) {
    struct Refused {
        const Case* c;
        Unsupported why;
    };
    std::vector<Refused> refused;
    for (const Case& c : cases) {
        const Technique* technique = registry.find(c.technique);
        const Scene& scene = experiment.scenes[c.scene_index];
        const FrameGraph graph = technique->graph(c.params);
        std::optional<Unsupported> why = check_population_present(scene, graph);
        if (!why) why = check(scene, graph);
        if (why) refused.push_back({&c, std::move(*why)});
    }
    if (refused.empty()) return;

    constexpr size_t kListed = 20;  // more lines than this would scroll the cause off the screen
    std::string message = refused.size() == 1 ? "1 case cannot run:"
                                              : fmt::format("{} of {} cases cannot run:", refused.size(), cases.size());
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

}  // namespace

PreparedExperiment prepare_experiment(const Experiment& experiment, const TechniqueRegistry& registry,
                                      const GpuContext& gpu) {
    PreparedExperiment prepared;
    prepared.experiment = &experiment;
    prepared.cases = expand_cases(experiment, registry);
    for (const Scene& scene : experiment.scenes) prepared.meshes.push_back(build_scene_meshes(scene));
    refuse_unrunnable(experiment, prepared.cases, registry,
                      [&](const Scene& scene, const FrameGraph& graph) { return check_supported(gpu, scene, graph); });
    return prepared;
}

void refuse_cases_scenes_cannot_run(const Experiment& experiment, const std::vector<Case>& cases,
                                    const TechniqueRegistry& registry) {
    refuse_unrunnable(experiment, cases, registry, check_scene_supported);
}

namespace {

// Which of the previous run's cases (and references) this run keeps: finished, recorded, and with
// every file they name still on disk. A case that failed is run again.
struct KeptResults {
    std::map<std::string, CaseResult> cases;  // by case id
    std::vector<ReferenceRecord> references;
};

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

MeasurementSettings measurement_settings(const Experiment& experiment, const RunOptions& options) {
    MeasurementSettings m;
    m.warmup_frames = options.quick ? std::min(experiment.warmup_frames, 1) : experiment.warmup_frames;
    m.rounds = options.quick ? std::min(experiment.rounds, 3) : experiment.rounds;
    m.frames_per_sample = options.quick ? 1 : experiment.frames_per_sample;
    m.pairing = experiment.pairing;
    m.camera_path = experiment.camera_path;
    if (m.camera_path) m.frames_per_sample = m.camera_path->frames;  // a sample is one traversal
    return m;
}

std::vector<PlannedGroup> plan_groups(const std::vector<Case>& cases, const std::vector<Scene>& scenes) {
    std::vector<PlannedGroup> groups;
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        auto same = [&](const PlannedGroup& g) {
            return g.scene_index == c.scene_index && g.resolution.width == c.resolution.width &&
                   g.resolution.height == c.resolution.height;
        };
        auto it = std::find_if(groups.begin(), groups.end(), same);
        if (it == groups.end()) {
            PlannedGroup g;
            g.name = fmt::format("{} {}x{}", scenes[c.scene_index].name, c.resolution.width, c.resolution.height);
            g.scene_index = c.scene_index;
            g.resolution = c.resolution;
            groups.push_back(std::move(g));
            it = groups.end() - 1;
        }
        it->cases.push_back(i);
    }
    return groups;
}

size_t planned_chunks(size_t cases, const ChunkLimits& limits) {
    // The baseline is in every chunk: each holds up to max_cases - 1 others (memory may split more).
    const size_t per_chunk = std::max<size_t>(limits.max_cases, 2) - 1;
    return std::max<size_t>(1, (cases > 1 ? cases - 1 + per_chunk - 1 : per_chunk) / per_chunk);
}

RunRecord run_experiment(const PreparedExperiment& prepared, const TechniqueRegistry& registry, const GpuContext& gpu,
                         const RunOptions& options) {
    const Experiment& experiment = *prepared.experiment;
    const std::filesystem::path& out = options.out_dir;
    const MeasurementSettings settings = measurement_settings(experiment, options);
    RunRecord run;
    run.experiment = experiment.name;
    run.description = experiment.description;
    run.config_file = recorded_path(experiment.file);
    std::string config_bytes;
    for (const std::filesystem::path& file : inputs_of(experiment)) {
        const std::string bytes = file_bytes(file);
        if (config_bytes.empty() && file == experiment.file) config_bytes = bytes;
        run.inputs.push_back({recorded_path(file), fmt::format("{:016x}", fnv1a_64(bytes))});
    }
    run.environment = collect_environment(gpu, experiment.config_hash);
    run.identity = make_run_identity(experiment, options, run.environment);
    run.quick = options.quick;
    run.shard = options.shard;
    run.warmup_frames = settings.warmup_frames;
    run.rounds = settings.rounds;
    run.frames_per_sample = settings.frames_per_sample;
    run.camera_path = settings.camera_path;
    run.started_at = utc_now();
    run.planned_cases = prepared.cases.size();
    run.reference_enabled = options.reference && experiment.reference_enabled;
    if (run.reference_enabled) run.distance_bands = experiment.distance_bands;  // the bands need the reference

    const std::vector<PlannedGroup> groups = plan_groups(prepared.cases, experiment.scenes);
    for (const PlannedGroup& g : groups) {
        GroupRecord record;
        record.name = g.name;
        record.scene = experiment.scenes[g.scene_index].name;
        record.resolution = g.resolution;
        for (size_t i : g.cases) record.cases.push_back(prepared.cases[i].id);
        run.groups.push_back(std::move(record));
    }

    // A continued run keeps the groups the previous one finished whole; the rest run in the planned order.
    const KeptResults kept = kept_results(options.previous, out);
    if (options.previous) {
        run.started_at = options.previous->started_at;
        run.resumed_at = options.previous->resumed_at;
        run.resumed_at.push_back(utc_now());
        run.references = kept.references;
    }
    const CaseLabels labels(prepared.cases, registry);
    std::vector<std::optional<CaseResult>> slots(prepared.cases.size());  // planned order
    std::vector<bool> group_kept(groups.size(), false);
    // Per group, per case: recorded by the chunks of a group the previous run cut short (those
    // chunks are kept, the group continues after them); empty for a group measured afresh.
    std::vector<std::vector<bool>> recorded_in_chunks(groups.size());
    for (size_t g = 0; g < groups.size() && options.previous; ++g) {
        const auto previous_group = std::find_if(options.previous->groups.begin(), options.previous->groups.end(),
                                                 [&](const GroupRecord& r) { return r.name == run.groups[g].name; });
        if (previous_group == options.previous->groups.end() || previous_group->cases != run.groups[g].cases ||
            previous_group->chunks.empty())
            continue;
        // The cases its finished chunks measured (the baseline in each): kept when every one of
        // them is; a lost file redoes the whole group, as a changed baseline would have to.
        std::vector<bool> in_chunks(groups[g].cases.size(), false);
        for (const MeasurementChunk& chunk : previous_group->chunks)
            for (const std::string& id : chunk.cases)
                for (size_t k = 0; k < groups[g].cases.size(); ++k)
                    if (prepared.cases[groups[g].cases[k]].id == id) in_chunks[k] = true;
        bool all_kept = in_chunks[0];
        for (size_t k = 0; k < in_chunks.size(); ++k)
            if (in_chunks[k] && !kept.cases.count(prepared.cases[groups[g].cases[k]].id)) all_kept = false;
        if (!all_kept) continue;
        const bool whole = std::all_of(groups[g].cases.begin(), groups[g].cases.end(),
                                       [&](size_t i) { return kept.cases.count(prepared.cases[i].id) > 0; });
        group_kept[g] = whole;
        if (!whole) recorded_in_chunks[g] = in_chunks;
        run.groups[g].chunks = previous_group->chunks;
        for (size_t k = 0; k < groups[g].cases.size(); ++k) {
            if (!in_chunks[k] && !whole) continue;
            const size_t i = groups[g].cases[k];
            const Case& c = prepared.cases[i];
            CaseResult result = kept.cases.at(c.id);  // measurements as recorded, labels from this run's cases
            result.params = c.params.values();
            result.params_summary = c.params.summary();
            result.params_shown = labels.parameters(c);
            result.group = g;
            slots[i] = std::move(result);
        }
    }
    auto record_cases = [&] {
        run.cases.clear();
        for (const auto& slot : slots)
            if (slot) run.cases.push_back(*slot);
    };
    record_cases();

    // References the groups still to run need, for the ETA.
    size_t references_needed = 0;
    for (size_t g = 0; g < groups.size(); ++g) references_needed += group_kept[g] ? 0 : 1;
    Progress progress(prepared.cases.size(), run.reference_enabled ? references_needed : 0);
    ReferenceProvider references(options.reference_cache_dir, experiment.reference);
    size_t groups_measured = 0;  // groups this process measured
    size_t chunks_recorded = 0;  // chunks this process measured and recorded
    try {
        std::filesystem::create_directories(out / "images");
        if (options.previous) remove_temporary_files(out);
        write_run_reports(out, run, experiment);
        // The config as it was run, beside its results (a later edit of the file changes nothing here).
        write_text_atomically(out / "experiment.toml", config_bytes);

        for (size_t g = 0; g < groups.size() && !interrupt_requested(); ++g) {
            const PlannedGroup& planned = groups[g];
            const Scene& scene = experiment.scenes[planned.scene_index];
            const Resolution& resolution = planned.resolution;
            const size_t first = planned.cases.front();
            auto label_of = [&](size_t i) {
                const Case& c = prepared.cases[i];
                return planned.name + " " + case_name(c.technique, labels.parameters(c));
            };
            if (options.show_progress)
                for (size_t k = 0; k < planned.cases.size(); ++k)
                    if (group_kept[g] || (!recorded_in_chunks[g].empty() && recorded_in_chunks[g][k]))
                        progress.kept_case(planned.cases[k], label_of(planned.cases[k]));
            if (group_kept[g]) continue;
            // The reference first, so a case's record is complete when it is written.
            const ReferenceEntry* reference = nullptr;
            if (run.reference_enabled) {
                const std::string stem = reference_stem(scene, resolution);
                bool obtained_now = false;
                bool source_from_cache = false;
                const auto reference_start = std::chrono::steady_clock::now();
                reference = &references.get(
                    scene, prepared.meshes[planned.scene_index], resolution.width, resolution.height,
                    [&](double fraction) {
                        if (options.show_progress) progress.reference_progress(first, planned.name, fraction);
                    },
                    [&](bool from_cache) {
                        obtained_now = true;
                        source_from_cache = from_cache;
                        if (options.show_progress) progress.reference_started(first, planned.name, from_cache);
                    });
                if (obtained_now && options.show_progress)
                    progress.reference_finished(
                        first, planned.name,
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - reference_start).count(),
                        source_from_cache);
                const bool recorded = std::any_of(run.references.begin(), run.references.end(),
                                                  [&](const ReferenceRecord& r) { return same_reference(r, scene.name, resolution); });
                if (!recorded) {
                    ReferenceRecord record;
                    record.scene = scene.name;
                    record.resolution = resolution;
                    record.key = reference->key;
                    record.from_cache = reference->from_cache;
                    record.seconds = reference->images.seconds;
                    record.shadow_rays = reference->images.shadow_rays;
                    record.light_samples = references.settings().light_samples;
                    record.pixel_samples = references.settings().pixel_samples;
                    record.error_map_scale = error_map_scale(reference->images.radiance);
                    const Light* light = scene.shadow_light();
                    record.degenerate = degenerate_reference(reference->images.radiance, reference->images.visibility,
                                                             {light != nullptr, light && light->is_area()});
                    if (!record.degenerate.empty())
                        fmt::print(stderr, "canopy: warning: the reference of {} is degenerate ({}): every technique "
                                           "scores near perfect against it; its cases are flagged and no claim rests "
                                           "on them\n",
                                   planned.name, degenerate_reference_text(record.degenerate).substr(22));
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

            // Distance bands: the reference's surface at each pixel centre decides, for every case alike.
            std::vector<DistanceBand> distance_bands;
            if (reference && experiment.distance_bands)
                distance_bands = classify_distances(reference->pixel_visibility.visibility, scene.camera, *experiment.distance_bands);

            // Popping: the reference at every frame of the path (cached like any other), before
            // the group is measured so no case waits on it.
            std::vector<const Image*> path_references;
            if (reference && settings.camera_path && settings.camera_path->popping) {
                const CameraPath& path = *settings.camera_path;
                for (int k = 0; k < path.frames && !interrupt_requested(); ++k) {
                    Scene at = scene;
                    at.camera = path.at(scene.camera, k);
                    path_references.push_back(&references.images(
                        at, prepared.meshes[planned.scene_index], resolution.width, resolution.height,
                        [&](double fraction) {
                            if (options.show_progress)
                                progress.reference_progress(first, planned.name, (double(k) + fraction) / double(path.frames));
                        }).radiance);
                }
                if (interrupt_requested()) break;
            }

            // The group's time leaves its reference out: Progress estimates the time left from case
            // times and reference times separately (a reference is obtained once per scene and size).
            const auto start = std::chrono::steady_clock::now();
            GroupInput input;
            input.name = planned.name;
            input.scene = &scene;
            input.meshes = &prepared.meshes[planned.scene_index];
            for (size_t i : planned.cases) {
                const Case& c = prepared.cases[i];
                GroupCase gc{&c, registry.find(c.technique), 0};
                if (options.ballast && options.ballast->technique == c.technique) gc.ballast_iterations = options.ballast->iterations;
                input.cases.push_back(gc);
            }
            input.chunks_done = run.groups[g].chunks;
            input.recorded = recorded_in_chunks[g];
            const size_t to_measure =
                size_t(std::count(input.recorded.begin(), input.recorded.end(), false)) + (input.recorded.empty() ? planned.cases.size() : 0);
            if (options.show_progress)
                progress.start_group(first, planned.name, to_measure, settings.rounds,
                                     planned_chunks(to_measure, options.chunk_limits));

            GroupCallbacks callbacks;
            callbacks.round_started = [&](size_t chunk, size_t cases, int round, int rounds) {
                if (options.show_progress) progress.group_round(planned.name, chunk, cases, round, rounds);
            };
            callbacks.case_measured = [&](size_t k, CaseResult& result, Image&& image, Image&& visibility) {
                const Case& c = prepared.cases[planned.cases[k]];
                result.params_shown = labels.parameters(c);
                result.group = g;
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
                        // The population coverage: the technique's alpha against the reference's
                        // pixel samples (metrics/coverage_error.hpp).
                        const CoveragePair coverage{visibility, reference->images.visibility};
                        MetricOptions metric_options;
                        if (!distance_bands.empty()) metric_options.distance_bands = &distance_bands;
                        result.image_error = compute_metrics(image, truth, &pixel_visibility, &coverage,
                                                             input.cases[k].technique->error_columns(), metric_options,
                                                             &flip_map);
                        result.reference_replicates =
                            metrics_against_noisy_references(image, reference->images, &pixel_visibility, &coverage,
                                                             input.cases[k].technique->error_columns(), metric_options);
                        if (pngs) {
                            const auto record = std::find_if(run.references.begin(), run.references.end(),
                                                             [&](const ReferenceRecord& r) { return same_reference(r, scene.name, resolution); });
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
                test_hooks::case_images_written(groups_measured);
            };
            if (!path_references.empty())
                callbacks.path_rendered = [&](size_t, CaseResult& result, std::vector<Image>&& frames) {
                    if (!result.image_error) return;
                    const PoppingError popping = compute_popping(frames, path_references);
                    result.image_error->popping_mean = popping.mean;
                    result.image_error->popping_max = popping.max;
                    result.popping_per_pair = popping.per_pair;
                };
            // Each finished chunk is recorded (its cases with the baseline they were paired with),
            // so an interrupted group keeps its finished chunks and --resume goes on after them.
            // results.json is rewritten after a chunk when the last write took under a tenth of
            // the time since (a large run's record takes a while to write); an interrupt writes it
            // anyway, before the process stops.
            auto chunk_start = start;
            auto last_write = std::chrono::steady_clock::now();
            double last_write_seconds = 0;
            callbacks.chunk_finished = [&](const GroupRecord& so_far,
                                           const std::vector<std::pair<size_t, const CaseResult*>>& finished) {
                run.groups[g].chunks = so_far.chunks;
                for (const auto& [k, result] : finished) slots[planned.cases[k]] = *result;
                record_cases();
                const auto now = std::chrono::steady_clock::now();
                if (std::chrono::duration<double>(now - last_write).count() >= 10.0 * last_write_seconds) {
                    write_json_report(out / "results.json", run);
                    last_write = std::chrono::steady_clock::now();
                    last_write_seconds = std::chrono::duration<double>(last_write - now).count();
                }
                ++chunks_recorded;
                test_hooks::chunk_recorded(chunks_recorded);
                const double seconds = std::chrono::duration<double>(now - chunk_start).count();
                chunk_start = now;
                if (options.show_progress)
                    for (const auto& [k, result] : finished)
                        progress.finish_case(planned.cases[k], label_of(planned.cases[k]),
                                             seconds / double(finished.size()), result->ok);
            };
            std::optional<MeasuredGroup> measured = measure_group(gpu, input, settings, options.chunk_limits, callbacks);
            if (!measured || interrupt_requested()) break;  // this group did not finish: its finished chunks are kept
            ++groups_measured;
            write_run_reports(out, run, experiment);
            test_hooks::group_recorded(groups_measured);
        }
    } catch (const Interrupted&) {
        // Ctrl-C or SIGTERM while a reference was ray-traced: it is dropped, the run is interrupted below.
    } catch (const std::exception& e) {
        // The run cannot go on (a full disk, an unwritable folder, a reference that cannot be
        // rendered): record why, if the disk still takes it.
        if (options.show_progress) progress.done();
        run.finished_at = utc_now();
        run.status = "failed";
        run.error = e.what();
        try {
            write_run_reports(out, run, experiment);
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
        write_run_reports(out, run, experiment);
    } catch (const std::exception& e) {
        run.status = "failed";
        run.error = e.what();
    }
    return run;
}

}  // namespace canopy
