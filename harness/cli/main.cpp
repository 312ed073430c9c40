// canopy: runs rendering techniques over configured scenes and tabulates time and error.
#include "cli/default_scene.hpp"
#include "config/experiment_config.hpp"
#include "config/scene_config.hpp"
#include "reference/shadow_ray_benchmark.hpp"
#include "report/image_files.hpp"
#include "timing_only/timing_only.hpp"
#include "run/reference_provider.hpp"
#include "core/registry.hpp"
#include "scene/population_kind.hpp"
#include "gpu/context.hpp"
#include "report/markdown_report.hpp"
#include "report/paper_report.hpp"
#include "run/experiment_runner.hpp"
#include "run/family_benchmark_run.hpp"
#include "run/interrupt.hpp"
#include "run/kernel_scaling.hpp"
#include "report/atomic_file.hpp"
#include "report/comparison_report.hpp"
#include "report/console_table.hpp"
#include "report/timing_sections.hpp"
#include "report/json_record_reader.hpp"
#include "report/metric_list.hpp"
#include "run/run_comparison.hpp"
#include "run/stability_bench.hpp"
#include "report/stability_report.hpp"
#include "core/graph_requirements.hpp"
#include "graph/frame_graph.hpp"
#include "config/paper_table_change.hpp"
#include "run/environment.hpp"
#include "run/heap_settings.hpp"
#include "run/output_folder.hpp"
#include "report/gbench_report.hpp"
#include "report/html_report.hpp"
#include "report/text_table.hpp"
#include "run/run_merge.hpp"
#include "run/run_plan.hpp"
#include "run/reference_tiles.hpp"
#include "run/reference_prefetch.hpp"
#include "metrics/image_metrics.hpp"
#include "metrics/metric_registry.hpp"
#include "run/run_identity.hpp"

#include <CLI/CLI.hpp>
#include <fmt/chrono.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <list>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace canopy;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailedCases = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitInterrupted = 130;   // 128 + SIGINT
constexpr int kExitTerminated = 143;    // 128 + SIGTERM

int list_techniques() {
    // One column width for every technique, so long names do not push the columns apart.
    size_t name_width = 0, type_width = 0, default_width = 0;
    // (and every population kind's, printed after the techniques in the same columns).
    const auto widen = [&](const std::vector<ParamSpec>& specs) {
        for (const ParamSpec& p : specs) {
            name_width = std::max(name_width, p.name.size());
            type_width = std::max(type_width, p.type_and_range().size());
            default_width = std::max(default_width, default_text(p).size());
        }
    };
    for (const Technique* t : TechniqueRegistry::instance().all()) widen(t->params());
    for (const PopulationKind* kind : PopulationKindRegistry::instance().all()) widen(kind->params());
    for (const Technique* t : TechniqueRegistry::instance().all()) {
        fmt::print("{}\n  {}\n  from: {}\n", t->name(), t->summary(), t->paper());
        const std::vector<ParamSpec> specs = t->params();
        const ParamSet defaults = ParamSet::resolve(specs, {}, {}, {}, t->name());
        std::string requires_text;
        for (const std::string& need : graph_requirements(t->graph(defaults)))
            requires_text += (requires_text.empty() ? "" : "; ") + need;
        fmt::print("  requires: {}\n  parameters:\n", requires_text.empty() ? "nothing beyond the scene" : requires_text);
        for (const ParamSpec& p : specs)
            fmt::print("    {:<{}}  {:<{}}  default {:<{}}  {}\n", p.name, name_width, p.type_and_range(), type_width,
                       default_text(p), default_width, p.doc);
        fmt::print("\n");
    }
    // The population kinds families define, with the parameters a scene's [[population]] gives
    // them in `params = { ... }` (the harness's own "scatter" is described in configs/README.md).
    for (const PopulationKind* kind : PopulationKindRegistry::instance().all()) {
        fmt::print("population kind \"{}\"\n  {}\n  parameters (in a [[population]]'s params = {{ ... }}):\n",
                   kind->name(), kind->summary());
        for (const ParamSpec& p : kind->params())
            fmt::print("    {:<{}}  {:<{}}  default {:<{}}  {}\n", p.name, name_width, p.type_and_range(), type_width,
                       default_text(p), default_width, p.doc);
        fmt::print("\n");
    }
    return kExitOk;
}

// The frame graph a technique declares at its default parameters, as describe() prints it.
int print_graph(const std::string& name) {
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    const Technique* technique = registry.find(name);
    if (!technique) {
        std::vector<std::string> names;
        for (const Technique* t : registry.all()) names.push_back(t->name());
        const std::string near = closest_match(name, names);
        throw ConfigError("", 0, fmt::format("unknown technique '{}'", name),
                          near.empty() ? "run `canopy list` to see every technique"
                                       : fmt::format("did you mean '{}'? (`canopy list` shows every technique)", near));
    }
    const ParamSet defaults = ParamSet::resolve(technique->params(), {}, {}, {}, technique->name());
    fmt::print("{} at its defaults ({}):\n{}", technique->name(), defaults.summary(), describe(technique->graph(defaults)));
    return kExitOk;
}

int list_devices() {
    for (const DeviceInfo& d : GpuContext::list_devices())
        fmt::print("{}: {}  [{}]  driver {} ({}), Vulkan {}\n", d.index, d.name, d.type, d.driver_name, d.driver_info,
                   d.api_version);
    return kExitOk;
}

fs::path default_out_dir(const std::string& experiment) {
    return fs::path("results") / "runs" / fmt::format("{:%Y-%m-%d-%H%M%S}-{}", fmt::localtime(std::time(nullptr)), experiment);
}

struct ReferenceOptions {
    int width = 640, height = 360;
    ReferenceSettings settings{64, 4, 1, 0};
    std::string cache_dir;  // "" = default
    bool no_cache = false;
    std::string tile;        // `canopy reference --tile i/N`: render one row band into --out
    size_t merge_tiles = 0;  // `--merge-tiles N`: put --out's N tiles together into the cache
};

// The reference cache folder, checked (a file where the folder should be is refused, exit 2).
fs::path cache_dir(const ReferenceOptions& o) {
    if (o.no_cache) return {};
    const fs::path dir = o.cache_dir.empty() ? default_reference_cache_dir() : fs::path(o.cache_dir);
    check_reference_cache_dir(dir);
    return dir;
}

// Before anything is read or written: what a timing-only build lacks, as bad input (exit 2).
void refuse_in_timing_only_build(bool wants_reference, bool writes_images) {
    if (const auto refusal = timing_only_refusal(kTimingOnlyBuild, wants_reference, writes_images)) throw ConfigError({}, 0, *refusal);
}

int reference(const fs::path& scene_file, const std::string& out, const ReferenceOptions& o) {
    refuse_in_timing_only_build(true, true);
    if (o.tile.empty()) cache_dir(o);  // checked before anything is ray-traced
    const Scene scene = load_scene(scene_file);
    const auto meshes = build_scene_meshes(scene);
    install_interrupt_handler();  // Ctrl-C stops the ray-trace within a row of pixels (exit 130)
    if (!o.tile.empty() && o.merge_tiles > 0)
        throw ConfigError(fs::path(), 0, "--tile and --merge-tiles together", "render the tiles first, then merge them");
    if (!o.tile.empty()) {
        ShardSpec tile;
        try {
            tile = parse_shard(o.tile, "--tile");
        } catch (const std::invalid_argument& e) {
            throw ConfigError(fs::path(), 0, e.what(), "give --tile i/N, 1 <= i <= N: row band i of N");
        }
        if (out.empty())
            throw ConfigError(fs::path(), 0, "--tile needs --out", "give the folder every tile of this reference goes to");
        const RowBand rows = tile_rows(o.height, tile.index, tile.count);
        const uint64_t rays = render_reference_tile(scene, meshes, o.width, o.height, o.settings, tile.index, tile.count, out);
        fmt::print("reference {} {}x{}: tile {} (rows {} to {}), {} shadow rays, in {}\n  when every tile is there: canopy "
                   "reference {} --merge-tiles {} --out {} (same size and sample options)\n",
                   scene.name, o.width, o.height, tile.text(), rows.begin, rows.end - 1, rays, out, scene_file.string(),
                   tile.count, out);
        return kExitOk;
    }
    if (o.merge_tiles > 0) {
        if (out.empty()) throw ConfigError(fs::path(), 0, "--merge-tiles needs --out", "give the folder holding the tiles");
        if (cache_dir(o).empty())
            throw ConfigError(fs::path(), 0, "--merge-tiles puts the reference into the cache", "drop --no-cache");
        merge_reference_tiles(scene, meshes, o.width, o.height, o.settings, o.merge_tiles, out, cache_dir(o));
        fmt::print(stderr, "canopy: {} tiles of {} {}x{} merged into the reference cache ({})\n", o.merge_tiles, scene.name,
                   o.width, o.height, cache_dir(o).string());
    }
    ReferenceProvider provider(cache_dir(o), o.settings);
    const bool terminal = isatty(STDERR_FILENO);
    const ReferenceEntry& entry = provider.get(scene, meshes, o.width, o.height, [&](double fraction) {
        if (terminal) fmt::print(stderr, "\rray-tracing {} {}x{}: {:3.0f}%", scene.name, o.width, o.height, 100.0 * fraction);
    });
    if (terminal) fmt::print(stderr, "\r\033[K");
    const fs::path dir = out.empty() ? fs::path("results") / "reference" : fs::path(out);
    fs::create_directories(dir);
    const std::string stem = fmt::format("{}_{}x{}", scene.name, o.width, o.height);
    write_exr(dir / (stem + ".exr"), entry.images.radiance);
    write_png_srgb(dir / (stem + ".png"), entry.images.radiance);
    write_exr(dir / (stem + ".variance.exr"), entry.images.variance);
    write_exr(dir / (stem + ".visibility.exr"), entry.images.visibility);
    write_exr(dir / (stem + ".pixel_visibility.exr"), entry.pixel_visibility.visibility);
    fmt::print("reference {} {}x{}: {} light x {} pixel samples, {} shadow rays, {:.2f} s{}\n", scene.name, o.width,
               o.height, o.settings.light_samples, o.settings.pixel_samples, entry.images.shadow_rays,
               entry.images.seconds, entry.from_cache ? " (from cache, key " + entry.key + ")" : "");
    fmt::print("pixel-centre visibility: {} light samples, {} shadow rays, {:.2f} s{}\n",
               provider.pixel_visibility_settings().light_samples, entry.pixel_visibility.shadow_rays,
               entry.pixel_visibility.seconds, entry.pixel_visibility_from_cache ? " (from cache, key " + entry.pixel_visibility_key + ")" : "");
    fmt::print("images: {}/{}.{{exr,png,variance.exr,visibility.exr,pixel_visibility.exr}}\n", fs::absolute(dir).string(),
               stem);
    return kExitOk;
}

int bench_reference(const fs::path& scene_file, const ReferenceOptions& o) {
    refuse_in_timing_only_build(true, false);
    const Scene scene = load_scene(scene_file);
    const auto meshes = build_scene_meshes(scene);
    fmt::print(stderr, "benchmarking shadow rays on {} at {}x{} ({} light x {} pixel samples)...\n", scene.name, o.width,
               o.height, o.settings.light_samples, o.settings.pixel_samples);
    const ShadowRayBenchmark b = benchmark_shadow_rays(scene, meshes, o.width, o.height, o.settings);
    fmt::print("| renderer | shadow rays/s |\n|---|---:|\n");
    fmt::print("| canopy reference | {:.3e} |\n| bare rtcOccluded1 loop | {:.3e} |\n", b.reference_rays_per_second,
               b.bare_rays_per_second);
    fmt::print("\nratio reference / bare: {:.3f} (target >= 0.80), over {} shadow rays, {} threads\n", b.ratio, b.rays,
               std::thread::hardware_concurrency());
    return kExitOk;
}

int bench_scaling(const ScalingOptions& options, const std::string& device, const std::string& out) {
    GpuContext gpu(device);
    const auto series = run_kernel_scaling(TechniqueRegistry::instance(), gpu, options);
    const std::string report = kernel_scaling_report(series, collect_environment(gpu, ""), options);
    fmt::print("{}", report);
    if (!out.empty()) {
        write_text_atomically(out, report);
        fmt::print("\nwritten to {}\n", fs::absolute(out).string());
    }
    return kExitOk;
}

struct StabilityCommand {
    StabilityOptions options;
    std::string out;
    std::vector<std::string> from;
    bool force = false;
};

int bench_stability(StabilityCommand command) {
    if (!command.from.empty()) {
        std::vector<fs::path> folders(command.from.begin(), command.from.end());
        const StabilityResult result = analyse_run_folders(folders);
        fmt::print("{}", stability_markdown(result));
        if (!command.out.empty()) {
            fs::create_directories(command.out);
            write_stability_report(command.out, result);
            fmt::print("\nwritten to {}/stability.md and stability.json\n", fs::absolute(command.out).string());
        }
        return kExitOk;
    }
    if (command.options.experiment.empty())
        throw ConfigError(fs::path(), 0, "bench stability needs an experiment (or --from run folders)",
                          "canopy bench stability configs/experiments/stability.toml --runs 5");
    // The experiment is checked here, so a bad config fails before any run starts.
    const Experiment experiment = load_experiment(command.options.experiment, TechniqueRegistry::instance());
    fs::path out = command.out.empty()
                       ? fs::path("results") / "runs" /
                             fmt::format("{:%Y-%m-%d-%H%M%S}-stability-{}", fmt::localtime(std::time(nullptr)), experiment.name)
                       : fs::path(command.out);
    if (fs::exists(out) && !fs::is_empty(out)) {
        if (!command.force)
            throw ConfigError(out, 0, "the folder is not empty",
                              "give a new folder with --out, or --force to replace an earlier stability benchmark there");
        for (const char* name : {"stability.md", "stability.json"}) fs::remove(out / name);
        fs::remove_all(out / "runs");
    }
    fs::create_directories(out);
    command.options.out = out;
    const StabilityResult result = run_stability_bench(current_executable(), command.options);
    write_stability_report(out, result);
    fmt::print("{}\nwritten to {}/stability.md and stability.json (the runs in runs/)\n", stability_markdown(result),
               fs::absolute(out).string());
    return kExitOk;
}

// "5%" or "0.05" -> 0.05; throws ConfigError for anything else.
double parse_threshold(const std::string& text) {
    try {
        size_t used = 0;
        const bool percent = !text.empty() && text.back() == '%';
        const double value = std::stod(percent ? text.substr(0, text.size() - 1) : text, &used);
        if (used != text.size() - (percent ? 1 : 0)) throw std::invalid_argument(text);
        const double fraction = percent ? value / 100.0 : value;
        if (!(fraction >= 0.0 && fraction < 1.0) || (!percent && value >= 1.0)) throw std::out_of_range(text);
        return fraction;
    } catch (const std::logic_error&) {
        throw ConfigError(fs::path(), 0, fmt::format("--threshold '{}' is not a relative change", text),
                          "give a percentage or a fraction below 1, e.g. --threshold 5% or --threshold 0.05");
    }
}

// The folder of a run given as its folder or its results.json.
fs::path run_folder(const std::string& where) {
    return fs::is_directory(where) ? fs::path(where) : fs::path(where).parent_path();
}

// Committed results (results/paper/, results/baselines/) are written only with --force.
void refuse_committed(const fs::path& dir, bool force, const std::string& hint) {
    if (is_committed_results_folder(dir.empty() ? fs::path(".") : dir) && !force)
        throw ConfigError(dir, 0, "this folder holds committed results; canopy does not write there unless told to", hint);
}

// The experiment config a run names (relative to its checkout, as results record paths): the
// checkout holding the run folder `dir`, else the run's checkout (run_checkout()). That checkout
// becomes the run's, for the paths and commit of what is written next.
fs::path recorded_config(const RunRecord& run, const fs::path& dir) {
    const fs::path config = run.config_file;
    if (!config.is_relative()) return config;
    const fs::path holding = checkout_of(dir);
    if (!holding.empty()) set_run_checkout_of(holding);
    return run_checkout() / config;
}

// A run folder or its results.json.
RunRecord read_run(const std::string& where) {
    const fs::path path = fs::is_directory(where) ? fs::path(where) / "results.json" : fs::path(where);
    try {
        return read_json_report(path);
    } catch (const std::runtime_error& e) {
        throw ConfigError(fs::path(), 0, e.what(),
                          "give a run folder (holding results.json) or a results.json written by this canopy version");
    }
}

struct CompareCommand {
    std::string baseline, candidate, threshold = "5%", out;
    bool no_time = false, no_errors = false;
};

// `canopy compare`'s exit codes: 0 nothing flagged, 1 a regression (kExitFailedCases), 2 bad input,
// and this when its report could not be written (or it failed otherwise): 1 always means a regression.
constexpr int kExitCompareFailed = 3;

int compare(const CompareCommand& command) {
    const fs::path out = command.out.empty() ? fs::path() : output_file(command.out, "compare.md");
    const RunRecord baseline = read_run(command.baseline);
    const RunRecord candidate = read_run(command.candidate);
    ComparisonSettings settings;
    settings.threshold = parse_threshold(command.threshold);
    settings.time = !command.no_time;
    settings.errors = !command.no_errors;
    RunComparison comparison;
    try {
        comparison = compare_runs(baseline, candidate, settings);
    } catch (const ComparisonRefused& e) {
        throw ConfigError(fs::path(), 0, e.what(), "canopy compare compares two runs of one experiment and config");
    }
    const std::string report =
        comparison_report({command.baseline, &baseline}, {command.candidate, &candidate}, comparison);
    fmt::print("{}", report);
    if (!out.empty()) {
        try {
            if (!out.parent_path().empty()) fs::create_directories(out.parent_path());  // as `canopy run` creates its folder
            write_text_atomically(out, report);
        } catch (const std::exception& e) {  // WriteError, or a folder that cannot be made
            fmt::print(stderr, "canopy compare: the report could not be written: {}\n", e.what());
            return kExitCompareFailed;
        }
        fmt::print("\nwritten to {}\n", fs::absolute(out).string());
    }
    return comparison.passed() ? kExitOk : kExitFailedCases;
}

// `canopy image-error TEST REFERENCE`: every whole-image metric of one image against another (EXR
// or PNG), e.g. a reference of N samples against one of 4N: how converged it is.
int image_error(const std::string& test_path, const std::string& reference_path, bool json) {
    const Image test = read_image(test_path), reference = read_image(reference_path);
    if (test.width != reference.width || test.height != reference.height)
        throw ConfigError(fs::path(test_path), 0,
                          fmt::format("is {}x{}, the reference {}x{}", test.width, test.height, reference.width,
                                      reference.height),
                          "compare images of one size");
    const ImageMetrics m = compute_metrics(test, reference, nullptr, nullptr, ErrorColumns{});
    nlohmann::json values = nlohmann::json::object();
    std::vector<std::vector<std::string>> rows;
    for (const MetricInfo& metric : registered_metrics()) {
        const double v = metric.meaningful_value(m);
        if (std::isnan(v)) continue;
        values[std::string(metric.name)] = std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
        rows.push_back({std::string(metric.name), format_metric_value(v), std::string(metric.title)});
    }
    if (json) fmt::print("{}\n", values.dump(1));
    else fmt::print("{}", render_table({"metric", "value", "what"}, rows, {false, true, false}));
    return kExitOk;
}

// Writes results.gbench.json of recorded runs from their results.json (e.g. runs made before
// canopy wrote it, or before its context named the commit and device).
int export_gbench(const std::vector<std::string>& runs, bool force) {
    for (const std::string& where : runs) {
        const RunRecord run = read_run(where);
        const fs::path dir = run_folder(where);
        refuse_committed(dir, force, "add --force to rewrite its results.gbench.json (then review `git diff`)");
        write_gbench_report(dir / "results.gbench.json", run);
        fmt::print("{}\n", (dir / "results.gbench.json").string());
    }
    return kExitOk;
}

// paper.md and paper.json of recorded paper runs, from their results.json and the experiment
// config they name: unchanged since the run, or (--rejudge) changed only in its [paper] table,
// shown against the run's commit's config (config/paper_table_change.hpp).
int export_paper(const std::vector<std::string>& runs, bool force, bool rejudge) {
    for (const std::string& where : runs) {
        const RunRecord run = read_run(where);
        const fs::path dir = run_folder(where);
        refuse_committed(dir, force, "add --force to write its paper.md and paper.json (then review `git diff`)");
        const fs::path config = recorded_config(run, dir);
        const Experiment experiment = load_experiment(config, TechniqueRegistry::instance());
        if (!experiment.paper)
            throw ConfigError(config, 0, "this experiment has no [paper] table", "export-paper is for paper experiments");
        if (experiment.config_hash != run.environment.config_hash) {
            if (!rejudge)
                throw ConfigError(config, 0,
                                  fmt::format("the config hashes to {}, the run recorded {}: it changed since the run",
                                              experiment.config_hash, run.environment.config_hash),
                                  "rerun the experiment (scripts/reproduce --only ID), check out the run's commit, or, "
                                  "when only its [paper] table changed, add --rejudge");
            const std::optional<std::string> text_at_run = checkout_file_at(run.environment.git_commit, run.config_file);
            if (!text_at_run)
                throw ConfigError(config, 0,
                                  fmt::format("the run's commit {} has no {} in this checkout",
                                              run.environment.git_commit.substr(0, 9), run.config_file),
                                  "rerun the experiment: --rejudge needs the config the run measured");
            if (const std::string differs = paper_table_only_change(experiment, config, *text_at_run,
                                                                     run.environment.config_hash);
                !differs.empty())
                throw ConfigError(config, 0, "cannot judge the run again: " + differs,
                                  "rerun the experiment (scripts/reproduce --only ID)");
        }
        const RunToRunNoise noise = run_to_run_noise_for(run, dir);
        write_paper_report(dir / "paper.md", *experiment.paper, run, noise);
        write_paper_data(dir / "paper.json", *experiment.paper, run, noise);
        fmt::print("{}\n{}\n", (dir / "paper.md").string(), (dir / "paper.json").string());
    }
    return kExitOk;
}

// `canopy plan`: the cases, their keys and estimated costs, the groups and (with --shards) the split.
int plan(const fs::path& config, size_t shards, bool quick) {
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    const Experiment experiment = load_experiment(config, registry);
    const std::vector<Case> cases = expand_cases(experiment, registry);
    refuse_cases_scenes_cannot_run(experiment, cases, registry);  // what `canopy run` would refuse, bar the device's
    RunOptions options;
    options.quick = quick;
    const RunPlan plan = plan_run(experiment, cases, registry, measurement_settings(experiment, options));
    const std::vector<size_t> shard_of = assign_shards(plan.group_cost, std::max<size_t>(shards, 1));
    double total = 0;
    for (double c : plan.group_cost) total += c;
    fmt::print("{}: {} case{} in {} group{}, estimated cost {:.1f} megapixel-frames{}\n\n", experiment.name,
               cases.size(), cases.size() == 1 ? "" : "s", plan.groups.size(), plan.groups.size() == 1 ? "" : "s", total,
               quick ? " (--quick)" : "");
    std::vector<std::vector<std::string>> rows;
    for (size_t g = 0; g < plan.groups.size(); ++g)
        for (size_t k = 0; k < plan.groups[g].cases.size(); ++k) {
            const size_t i = plan.groups[g].cases[k];
            rows.push_back({plan.keys[i], cases[i].id, plan.groups[g].name, k == 0 ? "baseline" : "",
                            fmt::format("{:.2f}", plan.case_cost[i]),
                            shards > 1 ? fmt::format("{}/{}", shard_of[g] + 1, shards) : std::string("-")});
        }
    fmt::print("{}", render_table({"key", "case", "group", "", "cost", "shard"}, rows, {false, false, false, false, true, false}));
    if (shards > 1) {
        std::vector<double> load(shards, 0.0);
        std::vector<size_t> count(shards, 0);
        for (size_t g = 0; g < plan.groups.size(); ++g) {
            load[shard_of[g]] += plan.group_cost[g];
            count[shard_of[g]] += plan.groups[g].cases.size();
        }
        fmt::print("\nShards (whole groups, the most costly first to the least loaded shard):\n");
        for (size_t s = 0; s < shards; ++s)
            fmt::print("  --shard {}/{}: {} cases, cost {:.1f} ({:.0f} %)\n", s + 1, shards, count[s], load[s],
                       total > 0 ? 100.0 * load[s] / total : 0.0);
    }
    fmt::print("\nCost: frames rendered x pixels the frame's passes cover, in millions; a ranking to balance shards "
               "with, not seconds (geometry and the reference are left out).\n");
    return kExitOk;
}

// `canopy merge`: shards' folders into one run folder.
int merge(const std::vector<std::string>& shard_dirs, const std::string& out_dir, bool force) {
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    std::vector<RunRecord> shards;
    std::vector<fs::path> folders;
    for (const std::string& where : shard_dirs) {
        shards.push_back(read_run(where));
        folders.push_back(run_folder(where));
    }
    // An input is never the output: merging into a shard's folder would overwrite the shard, and a
    // second merge would find it gone. Checked before anything is read further or written.
    std::error_code ec;
    for (const fs::path& folder : folders)
        if (fs::exists(out_dir, ec) && fs::equivalent(folder, out_dir, ec))
            throw ConfigError(fs::path(out_dir), 0, fmt::format("--out is one of the shards being merged ({}), with or without --force",
                                                                folder.string()),
                              "merge into a new or empty folder (e.g. results/runs/<name>-merged)");
    const Experiment experiment = load_experiment(recorded_config(shards.front(), folders.front()), registry);
    const std::vector<Case> cases = expand_cases(experiment, registry);
    const MergedRun merged = merge_shards(shards, folders, experiment, cases, registry);

    const fs::path out = out_dir;
    refuse_committed(out, force, "merge into results/runs/..., or add --force");
    if (fs::exists(out / "results.json") && !force) {
        // Merging the same shards again rewrites the same folder; anything else is refused.
        const RunRecord there = read_run(out.string());
        if (there.experiment != merged.run.experiment || there.environment.config_hash != merged.run.environment.config_hash ||
            there.merged_from.empty())
            throw ConfigError(out, 0, fmt::format("this folder holds another run ({}, config hash {})", there.experiment,
                                                  there.environment.config_hash),
                              "merge into a new or empty folder, or add --force to replace it");
    }
    const OutputFolderLock lock(out);
    const size_t copied = copy_shard_images(merged, shards, folders, out);
    write_run_reports(out, merged.run, experiment);
    fmt::print("{}: {} of {} cases from {} shards ({} images copied)\n", out.string(), merged.run.cases.size(),
               cases.size(), shards.size(), copied);
    for (const RunRecord::MergedShard& m : merged.run.merged_from)
        fmt::print("  shard {}: {} cases on {} ({} to {})\n", m.shard, m.cases, m.hostname, m.started_at, m.finished_at);
    if (!merged.missing.empty()) {
        fmt::print(stderr, "canopy merge: {} cases are in no shard given:\n", merged.missing.size());
        for (const std::string& id : merged.missing) fmt::print(stderr, "    {}\n", id);
        fmt::print(stderr, "  hint: run the missing shards (canopy plan --shards N says which groups each has), then merge "
                           "again\n");
        return kExitFailedCases;
    }
    return merged.run.status == "complete" ? kExitOk : kExitFailedCases;
}

struct ReportCommand {
    std::string run, out;
    std::vector<std::string> pareto;
    bool link_images = false, force = false;
};

// The run folder's HTML report; its path.
fs::path write_report(const ReportCommand& command) {
    const fs::path dir = run_folder(command.run);
    const fs::path out = command.out.empty() ? dir / "report.html" : output_file(command.out, "report.html");
    if (!fs::exists(dir / "results.json"))
        throw ConfigError(dir, 0, "no results.json here", "give a run folder that `canopy run` wrote (or its results.json)");
    refuse_committed(out.parent_path(), command.force, "write the page elsewhere (--out /tmp/report.html), or add --force");
    HtmlReportOptions options;
    options.embed_images = !command.link_images;
    options.pareto_metrics = command.pareto;
    for (const std::string& metric : command.pareto)
        if (!find_metric(metric))
            throw ConfigError(fs::path(), 0, fmt::format("--pareto {}: no such error metric", metric),
                              "give a results.json name from `canopy metrics`, e.g. --pareto flip_mean --pareto rmse");
    if (command.link_images && fs::absolute(out).parent_path() != fs::absolute(dir))
        throw ConfigError(out, 0, "--link-images links the images relative to the run folder, so the page must be in it",
                          "drop --out, or drop --link-images to embed the images");
    if (!out.parent_path().empty()) fs::create_directories(out.parent_path());  // as `canopy run` creates its folder
    write_html_report(dir, out, options);
    return out;
}

int report(const ReportCommand& command) {
    const fs::path out = write_report(command);
    fmt::print("{}\n  open it in a browser (file://{}); nothing else is needed{}\n", out.string(), fs::absolute(out).string(),
               command.link_images ? " but the run folder's images/" : "");
    return kExitOk;
}

struct RunCommand {
    fs::path config;
    std::string out, device, shard;
    bool quick = false, progress = true, with_reference = true, resume = false, force = false, report = false;
    bool references_only = false;
    ImageOutput images = ImageOutput::all;
    int runs = 1;  // --runs N: N - 1 more runs into <out>/runs/run-<k>/, for the spread between runs
};

int exit_code_for_interrupt() {
    const int signal = interrupt_signal();
    return signal == SIGTERM ? kExitTerminated : kExitInterrupted;
}

// --runs N: runs 2..N of the experiment, each its own process (a new heap, new threads: what
// moves a ratio between runs), timing only, into <out>/runs/run-<k>/; a finished one is kept, one
// cut short resumed. Throws when one fails.
void run_repeats(const RunCommand& command, const fs::path& out_dir) {
    for (int k = 2; k <= command.runs; ++k) {
        const fs::path folder = repeated_run_folder(out_dir, k);
        std::error_code ec;
        if (!command.force && fs::is_regular_file(folder / "results.json", ec)) {
            try {
                if (read_json_report(folder / "results.json").status == "complete") continue;
            } catch (const std::exception&) {
            }
        }
        fs::create_directories(folder.parent_path());
        std::vector<std::string> argv{current_executable().string(), "run", command.config.string(), "--out",
                                      folder.string(), "--no-reference", "--images", "none", "--no-progress"};
        if (command.quick) argv.push_back("--quick");
        if (!command.device.empty()) argv.insert(argv.end(), {"--device", command.device});
        if (command.force) argv.push_back("--force");
        else if (fs::exists(folder / "results.json", ec)) argv.push_back("--resume");
        fmt::print(stderr, "canopy: run {} of {} (timing only) into {} ...\n", k, command.runs, folder.string());
        const fs::path log = folder.parent_path() / fmt::format("run-{}.log", k);
        const int status = run_process(argv, log);
        if (status != 0)
            throw std::runtime_error(fmt::format("run {} of {} exited {}; its output is in {}; run the same command "
                                                 "again to resume",
                                                 k, command.runs, status, log.string()));
    }
}

int run(const RunCommand& command, const ReferenceOptions& reference_options) {
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    // Everything is checked (config, scenes, meshes, device support, the output folder) before
    // anything is written.
    refuse_in_timing_only_build(command.with_reference, command.images != ImageOutput::none);
    // The run is in the config's checkout: its commit is the run's, its paths are recorded from it.
    set_run_checkout_of(command.config);
    const Experiment experiment = load_experiment(command.config, registry);
    const fs::path reference_cache = command.with_reference ? cache_dir(reference_options) : fs::path();
    std::optional<ShardSpec> shard;
    if (!command.shard.empty()) try {
            shard = parse_shard(command.shard);
        } catch (const std::invalid_argument& e) {
            throw ConfigError(fs::path(), 0, e.what(), "give --shard i/N, 1 <= i <= N; `canopy plan EXPERIMENT --shards N` "
                                                       "shows the split");
        }
    GpuContext gpu(command.device);
    PreparedExperiment prepared = prepare_experiment(experiment, registry, gpu);

    RunOptions options;
    options.out_dir = command.out.empty() ? default_out_dir(experiment.name) : fs::path(command.out);
    options.quick = command.quick;
    options.show_progress = command.progress;
    options.reference = command.with_reference;
    options.images = command.images;
    options.reference_cache_dir = reference_cache;
    options.ballast = ballast_from_environment();  // TEST-ONLY (run/test_ballast.hpp)
    if (shard) {
        // Whole groups, balanced by estimated cost (run/run_plan.hpp): this shard's cases alone.
        const RunPlan plan = plan_run(experiment, prepared.cases, registry, measurement_settings(experiment, options));
        const std::vector<size_t> shard_of = assign_shards(plan.group_cost, shard->count);
        std::vector<bool> in_shard(prepared.cases.size(), false);
        for (size_t g = 0; g < plan.groups.size(); ++g)
            if (shard_of[g] == shard->index)
                for (size_t i : plan.groups[g].cases) in_shard[i] = true;
        std::vector<Case> kept;  // in the experiment's order
        for (size_t i = 0; i < prepared.cases.size(); ++i)
            if (in_shard[i]) kept.push_back(prepared.cases[i]);
        if (kept.empty())
            throw ConfigError(command.config, 0,
                              fmt::format("shard {} has no group: the experiment has {} groups", shard->text(), plan.groups.size()),
                              "use fewer shards (canopy plan --shards N shows the split)");
        prepared.cases = std::move(kept);
        options.shard = shard->text();
    }
    if (command.references_only) {
        if (!command.with_reference)
            throw ConfigError(fs::path(), 0, "--references-only with --no-reference", "drop one of them");
        for (const PrefetchedReference& r : prefetch_references(prepared, options, [](const std::string& group) {
                 fmt::print(stderr, "canopy: reference of {}...\n", group);
             }))
            fmt::print("reference {}: {} ({:.1f} s{})\n", r.group, r.from_cache ? "already in the cache" : "rendered",
                       r.seconds, r.path_frames ? fmt::format(", {} camera-path frames", r.path_frames) : "");
        fmt::print("reference cache: {}\n", options.reference_cache_dir.string());
        return kExitOk;
    }
    const Environment environment = collect_environment(gpu, experiment.config_hash);
    if (!environment.binary_older_than.empty())
        fmt::print(stderr, "canopy: warning: this canopy binary is older than {} (changed after it was linked): rebuild "
                           "(scripts/build) before trusting the numbers; results.json records it\n",
                   environment.binary_older_than);
    if (environment.commit_mismatch())
        fmt::print(stderr, "canopy: warning: this binary was built from commit {} but the run is in {} at commit {}: "
                           "results.json records both; build canopy in this checkout (scripts/build) to measure its "
                           "code\n",
                   environment.binary_commit.substr(0, 12), run_checkout().string(), environment.git_commit.substr(0, 12));
    const RunIdentity identity = make_run_identity(experiment, options, environment);
    const OutputFolderPlan folder = plan_output_folder(options.out_dir, identity, command.force, command.resume);
    const OutputFolderLock lock(options.out_dir);  // one canopy process per folder
    if (folder.replace) {
        const size_t removed = remove_run_outputs(options.out_dir, *folder.previous);
        fmt::print(stderr, "canopy: --force: replacing {} ({} files of the earlier run removed)\n",
                   options.out_dir.string(), removed);
    }
    options.previous = folder.previous && !folder.replace ? &*folder.previous : nullptr;
    if (options.previous)
        fmt::print(stderr, "canopy: resuming the run in {} (status {}, {} of {} cases recorded)\n",
                   options.out_dir.string(), options.previous->status, options.previous->cases.size(),
                   prepared.cases.size());
    fmt::print(stderr, "canopy: {} cases on {} ({}); writing to {}\n", prepared.cases.size(), gpu.info().name,
               gpu.info().driver_info, options.out_dir.string());
    install_interrupt_handler();
    const RunRecord record = run_experiment(prepared, registry, gpu, options);

    fmt::print("{}\n", console_table(record));
    for (const std::string& line : timing_check_warnings(record))
        fmt::print(stderr, "canopy: timing cross-check failed (results.md, \"Timing cross-check\"): {}\n", line);
    fmt::print("results: {}\n", fs::absolute(options.out_dir).string());
    const char* images = options.images == ImageOutput::all   ? "  images in images/ (EXR linear, PNG sRGB)\n"
                         : options.images == ImageOutput::png ? "  images in images/ (PNG sRGB)\n"
                                                              : "";
    fmt::print("  results.json, results.csv, results.md (every column), results.gbench.json{}\n{}",
               experiment.paper ? ", paper.md, paper.json" : "", images);
    if (fs::exists(options.out_dir / "pareto.md"))
        fmt::print("  pareto.md: the Pareto fronts of time against error (`canopy report` draws them)\n");
    if (command.report && record.status == "complete") {
        ReportCommand report_command;
        report_command.run = options.out_dir.string();
        report_command.force = command.force;
        fmt::print("  report.html (canopy report): {}\n", write_report(report_command).string());
    }
    if (command.runs > 1 && record.status == "complete") {
        run_repeats(command, options.out_dir);
        if (experiment.paper) {
            const RunToRunNoise noise = run_to_run_noise_for(record, options.out_dir);
            write_paper_report(options.out_dir / "paper.md", *experiment.paper, record, noise);
            write_paper_data(options.out_dir / "paper.json", *experiment.paper, record, noise);
            fmt::print("  paper.md and paper.json: timing intervals hold the spread between runs, {}\n", noise.source);
        }
    }
    if (experiment.paper) {
        fmt::print("\n{} ({}): claims\n", experiment.paper->id, experiment.paper->source);
        for (const ClaimVerdict& v : judge_claims(*experiment.paper, record, run_to_run_noise_for(record, options.out_dir)))
            fmt::print("  {:<15} {}{}\n", v.outcome, v.text,
                       v.magnitude_stated ? fmt::format(" [magnitude: {}]", v.magnitude_outcome) : std::string());
    }
    if (!record.error.empty()) {
        fmt::print(stderr, "canopy: the run failed: {}\n  hint: fix the cause (free space, permissions), then run the "
                           "same command again: it resumes, keeping the finished groups results.json records\n",
                   record.error);
        return kExitFailedCases;
    }
    if (record.status == "interrupted") {
        fmt::print(stderr, "canopy: interrupted after {} of {} cases; the finished ones are saved. Run the same "
                           "command again (or add --resume) to continue\n",
                   record.cases.size(), record.planned_cases);
        return exit_code_for_interrupt();
    }
    if (record.status == "failed") {
        for (const auto& c : record.cases)
            if (!c.ok) fmt::print(stderr, "canopy: case {} FAILED: {}\n", c.id, c.error);
        return kExitFailedCases;
    }
    return kExitOk;
}

// `canopy frobnicate` (or `canopy bench frobnicate`): CLI11 would say only "A subcommand is
// required". Throws ConfigError naming the word and listing the commands.
void refuse_unknown_command(CLI::App& app, int argc, char** argv) {
    CLI::App* level = &app;
    std::string prefix;  // the commands before the word: "" or "bench "
    for (int i = 1; i < argc; ++i) {
        const std::vector<CLI::App*> commands = level->get_subcommands([](CLI::App*) { return true; });
        const std::string word = argv[i];
        if (commands.empty() || word.empty() || word[0] == '-') return;
        std::vector<std::string> names;
        for (CLI::App* command : commands) names.push_back(command->get_name());
        const auto known = std::find(names.begin(), names.end(), word);
        if (known == names.end()) {
            const std::string near = closest_match(word, names);
            throw ConfigError(fs::path(), 0,
                              fmt::format("unknown command {}{}; the commands are: {}", prefix, word, fmt::join(names, ", ")),
                              fmt::format("{}`canopy {}--help` describes each",
                                          near.empty() ? "" : fmt::format("did you mean {}{}? ", prefix, near), prefix));
        }
        level = commands[size_t(known - names.begin())];
        prefix += word + " ";
    }
}

}  // namespace

int main(int argc, char** argv) {
    hold_heap_still();  // before any driver allocates: see run/heap_settings.hpp
    CLI::App app{"canopy: benchmark real-time rendering techniques for nature scenes against a ray-traced reference.\n"
                 "Measures how long each technique takes and how far its image is from the truth."};
    app.require_subcommand(1);
    app.set_version_flag("--version", [] {
        return fmt::format("canopy {} ({} build, commit {})", CANOPY_VERSION, canopy_build_type(), source_commit());
    });
    app.footer("Exit codes: 0 success, 1 a case failed (e.g. NaN pixels) or a file could not be written, 2 bad input\n"
               "(the message names file:line, or the output folder), 130 interrupted by Ctrl-C, 143 by SIGTERM\n"
               "(finished groups of cases are kept; the same command resumes). `canopy compare`: 1 a regression, 3 its\n"
               "report could not be written (its --help). Set CANOPY_VALIDATION=1 for Vulkan validation layers.");

    std::string config_path, out_dir, device, scene_path, shard_text;
    bool report_after_run = false, references_only = false;
    bool quick = false, no_progress = false, no_reference = false, resume = false, force = false;
    int run_count = 1;
    std::string images = "all";
    ReferenceOptions reference_options;
    auto add_reference_options = [&](CLI::App* cmd, bool with_size) {
        if (with_size) {
            cmd->add_option("--width", reference_options.width, "image width")->capture_default_str()->check(CLI::Range(1, 8192));
            cmd->add_option("--height", reference_options.height, "image height")->capture_default_str()->check(CLI::Range(1, 8192));
            cmd->add_option("--light-samples", reference_options.settings.light_samples,
                            "shadow rays per pixel sample towards an area light")->capture_default_str()->check(CLI::Range(1, 65536));
            cmd->add_option("--pixel-samples", reference_options.settings.pixel_samples, "sub-pixel samples per pixel")
                ->capture_default_str()->check(CLI::Range(1, 1024));
            cmd->add_option("--seed", reference_options.settings.seed,
                            "the sample patterns' seed: another seed gives an independent reference of the same noise")
                ->capture_default_str();
        }
        cmd->add_option("--reference-cache", reference_options.cache_dir,
                        "reference cache folder (default $CANOPY_CACHE_DIR/reference or results/cache/reference)");
        cmd->add_flag("--no-cache", reference_options.no_cache, "neither read nor write the reference cache");
    };
    CLI::App* run_cmd = app.add_subcommand("run", "Run an experiment: scenes x techniques x parameters x resolutions.");
    run_cmd->add_option("experiment", config_path, "experiment TOML, e.g. configs/experiments/default.toml")->required();
    run_cmd->add_option("--out", out_dir, "output folder (default results/runs/<date>-<experiment>/)");
    run_cmd->add_flag("--quick", quick, "1 warm-up frame and 3 measured rounds of 1 frame per case, for smoke tests "
                                         "(too few to judge timing claims or compare times)");
    run_cmd->add_option("--runs", run_count,
                        "run the experiment N times, each a separate process (runs 2..N timing only, into "
                        "<out>/runs/run-<k>/): paper.md's timing intervals then hold this experiment's own spread "
                        "between runs (at least 5), instead of the committed bench stability runs'")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    run_cmd->add_option("--device", device, "Vulkan device: index or part of its name (default: lavapipe)");
    run_cmd->add_flag("--no-progress", no_progress, "no progress bar or lines on stderr");
    run_cmd->add_flag("--no-reference", no_reference, "skip the ray-traced reference and the error columns");
    run_cmd->add_option("--images", images, "which images to write: all (EXR, PNG, error maps), png, none")
        ->check(CLI::IsMember({"all", "png", "none"}))
        ->capture_default_str();
    run_cmd->add_flag("--resume", resume,
                      "continue the run in --out (stopped by Ctrl-C, SIGTERM, a kill or a full disk): its finished groups "
                      "are kept, the rest run; the config and options must be the same");
    run_cmd->add_flag("--force", force,
                      "write into a folder that holds another run (its canopy files are removed first) or into "
                      "committed results (results/paper/, results/baselines/)");
    run_cmd->add_flag("--report", report_after_run, "write report.html at the end (as `canopy report` does)");
    run_cmd->add_flag("--references-only", references_only,
                      "render the references the run (or its --shard) compares with into the reference cache, and "
                      "nothing else (a cluster's reference jobs, before the timing jobs)");
    run_cmd->add_option("--shard", shard_text,
                        "run one shard i/N of the experiment's groups, balanced by estimated cost (`canopy plan "
                        "--shards N` shows the split; `canopy merge` puts the shards' folders together)");
    add_reference_options(run_cmd, false);
    run_cmd->footer("Timing: the cases of one scene at one resolution (a group) are measured together, round by round;\n"
                    "each sample (frames_per_sample frames) sits between two samples of the group's first case (the\n"
                    "baseline) and its ratio is taken against their mean; a case's ratio is the median over the rounds\n"
                    "with a 95 % block-bootstrap interval (README, Timing). With a [camera_path], a sample is one\n"
                    "traversal of the path, and every frame of it keeps its own times. A case whose GPU pass times do\n"
                    "not add up to its wall time (max(10 %, 0.5 ms)) is flagged: the timing cross-check.\n"
                    "Writes results.json (every sample, per-round ratios, statistics, parameters, groups, environment,\n"
                    "errors), results.csv, results.md (every column; stdout gets a compact table), results.gbench.json\n"
                    "(Google Benchmark's JSON format), paper.md for experiments with a [paper] table, and in images/ per\n"
                    "case an EXR (linear float), a PNG (sRGB), the technique's pixel-centre visibility (EXR), an\n"
                    "absolute-error heat map and a FLIP map with colour bars, plus the reference images. Errors:\n"
                    "whole-image (RMSE, PSNR, SSIM, FLIP: how far the image is from the truth) and technique-isolated\n"
                    "(visibility RMSE/MAE: how wrong the technique's shadow is, at the same pixel centres as a\n"
                    "1024-light-sample reference); `canopy metrics` lists them all. The reference's sample counts\n"
                    "come from the experiment's [reference] table; references are cached by content.\n"
                    "Output folder: a new or empty one starts a run; one holding a run of the same experiment, config\n"
                    "(content hash), options (--quick, --images, --no-reference), measurement settings, device, build\n"
                    "and thread count continues it, keeping its finished groups; anything else, and results/paper/ or\n"
                    "results/baselines/, is refused (exit 2) unless --force. One canopy process at a time writes into a\n"
                    "folder.");

    CLI::App* reference_cmd = app.add_subcommand("reference", "Ray-trace the ground-truth image of a scene with Embree.");
    reference_cmd->add_option("scene", scene_path, "scene TOML, e.g. configs/scenes/spheres.toml")->required();
    reference_cmd->add_option("--out", out_dir, "output folder (default results/reference/)");
    reference_cmd->add_option("--tile", reference_options.tile,
                              "render only row band i of N into --out (no cache), for a reference too large for one job");
    reference_cmd->add_option("--merge-tiles", reference_options.merge_tiles,
                              "put the N tiles in --out together into the reference cache (bit for bit a whole "
                              "render), then write the reference as without tiles")
        ->check(CLI::Range(1, 100000));
    add_reference_options(reference_cmd, true);

    CLI::App* bench_cmd = app.add_subcommand("bench", "Benchmarks (not timed tests).");
    bench_cmd->require_subcommand(1);
    CLI::App* bench_reference_cmd = bench_cmd->add_subcommand(
        "reference", "Shadow-ray throughput of the reference renderer vs a bare Embree rtcOccluded1 loop, same rays.");
    const std::string default_scene_doc =
        fmt::format("scene TOML (default: {0} in the current directory, else in the checkout the canopy executable "
                    "was built in, i.e. ../{0} from its folder)",
                    kDefaultBenchScene);
    bench_reference_cmd->add_option("scene", scene_path, default_scene_doc);
    add_reference_options(bench_reference_cmd, true);
    ScalingOptions scaling;
    CLI::App* bench_scaling_cmd = bench_cmd->add_subcommand(
        "scaling", "Time vs kernel width per shadow technique, fitted exponent (separable ~1, K x K ~2).");
    bench_scaling_cmd->add_option("scene", scaling.scene_file, default_scene_doc);
    bench_scaling_cmd->add_option("--width", scaling.width, "image width")->capture_default_str()->check(CLI::Range(1, 8192));
    bench_scaling_cmd->add_option("--height", scaling.height, "image height")->capture_default_str()->check(CLI::Range(1, 8192));
    bench_scaling_cmd->add_option("--measured", scaling.measured, "measured rounds per point (each width of a technique renders one frame per round, interleaved)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000000));
    bench_scaling_cmd->add_option("--out", out_dir, "also write the Markdown report to this file");
    bench_scaling_cmd->add_option("--device", device, "Vulkan device: index or part of its name (default: lavapipe)");

    CompareCommand compare_command;
    CLI::App* compare_cmd = app.add_subcommand(
        "compare", "Compare two runs of one experiment: time ratios (with intervals) and errors, case by case.");
    compare_cmd->add_option("baseline", compare_command.baseline, "the earlier run: its folder or its results.json")->required();
    compare_cmd->add_option("candidate", compare_command.candidate, "the run to check: its folder or its results.json")->required();
    compare_cmd->add_option("--threshold", compare_command.threshold,
                            "a time ratio's change counts as a regression only when its whole 95 % interval lies above "
                            "this (e.g. 5% or 0.05)")
        ->capture_default_str();
    compare_cmd->add_flag("--no-time", compare_command.no_time,
                          "compare errors only (e.g. against a baseline run on another machine)");
    compare_cmd->add_flag("--no-errors", compare_command.no_errors, "compare time ratios only");
    compare_cmd->add_option("--out", compare_command.out,
                            "also write the report to this file, or into this folder as compare.md (an existing one, or "
                            "a path ending in /); its folder is created");
    compare_cmd->footer(
        "Cases are matched by id; cases in one run only are listed. Time: per case, the relative change of its time\n"
        "ratio to its group's baseline (both measured in the same rounds), candidate / baseline - 1, with a 95 %\n"
        "interval from resampling each run's rounds (block bootstrap). Errors: every metric within |change| <=\n"
        "absolute + relative x |baseline| (each metric's tolerance: `canopy metrics`). Runs of different\n"
        "experiments or configs are refused (exit 2); different commits, devices or builds are compared and named.\n"
        "The interval sees only each run's own rounds: on a shared machine a ratio also moves by a few % from one\n"
        "run to the next, so use a threshold at least twice the spread `canopy bench stability` reports there\n"
        "(README, Timing).\n"
        "Exit codes: 0 nothing flagged, 1 a regression, an error out of tolerance or a case that failed only in\n"
        "the candidate, 2 bad input (a run that cannot be read, runs that cannot be compared, a bad option),\n"
        "3 an I/O failure: --out could not be written (or compare failed otherwise), whatever was flagged.");

    StabilityCommand stability;
    CLI::App* bench_stability_cmd = bench_cmd->add_subcommand(
        "stability", "The instrument's own benchmark: run an experiment N times; within-run CV and run-to-run spread "
                     "of every ratio.");
    bench_stability_cmd->add_option("experiment", stability.options.experiment,
                                    "experiment TOML, e.g. configs/experiments/stability.toml");
    bench_stability_cmd->add_option("--from", stability.from,
                                    "analyse these run folders of one experiment instead of running it (e.g. runs "
                                    "interleaved with other settings by scripts/measurement-study)");
    bench_stability_cmd->add_option("--runs", stability.options.runs, "separate `canopy run` processes")
        ->capture_default_str()
        ->check(CLI::Range(2, 1000));
    bench_stability_cmd->add_option("--out", stability.out,
                                    "report folder (default results/runs/<date>-stability-<experiment>/)");
    bench_stability_cmd->add_flag("--quick", stability.options.quick, "pass --quick to every run (a smoke test)");
    bench_stability_cmd->add_flag("--force", stability.force, "replace an earlier stability benchmark in --out");
    bench_stability_cmd->add_option("--device", stability.options.device,
                                    "Vulkan device: index or part of its name (default: lavapipe)");
    bench_stability_cmd->footer(
        "Each run is `canopy run EXPERIMENT --no-reference --images none` into OUT/runs/run-<k>/, with this\n"
        "process's environment (LP_NUM_THREADS, taskset, ...). Writes OUT/stability.md and OUT/stability.json:\n"
        "per case its within-run CV (samples of one run), the run-to-run spread of its ratio to the group's\n"
        "baseline ((max - min) / median and std / mean over the runs), whether it reaches the targets (spread\n"
        "<= 5 % for cases over 20 ms, CV <= 5 %), and the load average before and after every run.\n"
        "scripts/measurement-study runs it under several settings (README, Timing).");

    // The families' own benchmarks, each with its parameters as options (--name value).
    struct FamilyBenchmarkCommand {
        const FamilyBenchmark* benchmark;
        CLI::App* command;
        std::string scene, out, device;
        std::map<std::string, std::string> given;
    };
    std::list<FamilyBenchmarkCommand> family_benchmarks;  // stable addresses for CLI11's references
    for (const FamilyBenchmark* b : FamilyBenchmarkRegistry::instance().all()) {
        FamilyBenchmarkCommand& c = family_benchmarks.emplace_back();
        c.benchmark = b;
        c.command = bench_cmd->add_subcommand(b->name(), b->summary());
        c.command->add_option("scene", c.scene, fmt::format("scene TOML (default: {} in the checkout)", b->default_scene()));
        for (const ParamSpec& spec : b->params())
            c.command->add_option_function<std::string>(
                "--" + spec.name, [&c, name = spec.name](const std::string& v) { c.given[name] = v; },
                fmt::format("{} ({}, default {})", spec.doc, spec.type_and_range(), default_text(spec)));
        c.command->add_option("--out", c.out, "also write <name>.md and <name>.json (numbers, parameters, environment) into this folder");
        c.command->add_option("--device", c.device, "Vulkan device: index or part of its name (default: lavapipe)");
    }

    std::vector<std::string> export_runs;
    bool export_force = false;
    CLI::App* export_cmd = app.add_subcommand(
        "export-gbench", "Write results.gbench.json (Google Benchmark's JSON format) of recorded runs from their "
                         "results.json.");
    export_cmd->add_option("runs", export_runs, "run folders or their results.json")->required();
    export_cmd->add_flag("--force", export_force, "also into committed results (results/paper/, results/baselines/)");

    ReportCommand report_command;
    CLI::App* report_cmd = app.add_subcommand(
        "report", "Write a run as one HTML page: environment, sortable tables, Pareto fronts, the paper comparison, "
                  "and every case's image, reference, error and FLIP maps side by side (zoomed together).");
    report_cmd->add_option("run", report_command.run, "a run folder or its results.json")->required();
    report_cmd->add_option("--out", report_command.out,
                           "the page (default RUN/report.html); a folder (an existing one, or a path ending in /) gets "
                           "report.html in it, and is created");
    report_cmd->add_option("--pareto", report_command.pareto,
                           "an error axis of the Pareto fronts (a results.json name from `canopy metrics`; repeat for "
                           "more); default: the axes the techniques' families declare");
    report_cmd->add_flag("--link-images", report_command.link_images,
                         "link the run's PNGs instead of embedding them (a smaller page that must stay in the run folder)");
    report_cmd->add_flag("--force", report_command.force, "also into committed results (results/paper/, results/baselines/)");
    report_cmd->footer(
        "The page is self-contained (images embedded as data: URIs, no network, no external script): open it in any\n"
        "browser. Pareto fronts: per scene and resolution, on the error axes the techniques' families declare\n"
        "(shadows: visibility RMSE and penumbra RMSE; grass: FLIP, RMSE, coverage tile MAE); a configuration is\n"
        "dominated only by one that is neither significantly worse in error nor significantly slower, and is\n"
        "significantly better in one of the two (pareto.md beside results.md has the same tables).");

    std::string plan_config;
    size_t plan_shards = 1;
    bool plan_quick = false;
    CLI::App* plan_cmd = app.add_subcommand(
        "plan", "List an experiment's cases with stable keys (a hash of scene, technique, parameters and resolution), "
                "their groups and estimated cost, and with --shards N how `canopy run --shard i/N` splits them.");
    plan_cmd->add_option("experiment", plan_config, "experiment TOML")->required();
    plan_cmd->add_option("--shards", plan_shards, "split the groups into this many shards")->check(CLI::Range(1, 10000));
    plan_cmd->add_flag("--quick", plan_quick, "cost of a --quick run");

    std::vector<std::string> merge_dirs;
    std::string merge_out;
    bool merge_force = false;
    CLI::App* merge_cmd = app.add_subcommand(
        "merge", "Merge the folders of `canopy run --shard i/N` runs into one run folder: the same files one run writes, "
                 "groups in the experiment's order; lists the cases no shard has.");
    merge_cmd->add_option("shards", merge_dirs, "the shards' run folders")->required();
    merge_cmd->add_option("--out", merge_out, "the merged run's folder")->required();
    merge_cmd->add_flag("--force", merge_force, "replace a folder holding another run, or write into committed results");
    merge_cmd->footer("Refused (exit 2): shards of another experiment or config, commit, build, device or settings, a\n"
                      "shard given twice, a folder that is not a shard. Merging the same shards again rewrites the same\n"
                      "folder. Exit 1 when cases are missing (they are listed) or a case failed.");

    std::vector<std::string> paper_runs;
    bool paper_force = false, paper_rejudge = false;
    CLI::App* export_paper_cmd = app.add_subcommand(
        "export-paper", "Write paper.md and paper.json (its numbers as data, for plots) of recorded paper runs from "
                        "their results.json and the experiment config, which must be unchanged since the run.");
    export_paper_cmd->add_option("runs", paper_runs, "run folders or their results.json")->required();
    export_paper_cmd->add_flag("--force", paper_force, "also into committed results (results/paper/)");
    export_paper_cmd->add_flag("--rejudge", paper_rejudge,
                               "judge the run's claims again under a [paper] table changed since the run: refused unless "
                               "the config at the run's commit hashes to what the run recorded and differs from today's "
                               "only in [paper]");

    std::string image_test, image_reference;
    bool image_json = false;
    CLI::App* image_error_cmd = app.add_subcommand(
        "image-error", "Every whole-image error metric (canopy metrics) of one image against another, EXR or PNG: "
                       "e.g. a reference of N samples a pixel against one of 4N.");
    image_error_cmd->add_option("test", image_test, "the image to score")->required();
    image_error_cmd->add_option("reference", image_reference, "the image taken as the truth")->required();
    image_error_cmd->add_flag("--json", image_json, "print the values as JSON (results.json's names)");

    CLI::App* list_cmd = app.add_subcommand("list", "List every technique with its parameters (type, range, default), then the population kinds technique families define for scenes.");
    std::string graph_technique;
    CLI::App* graph_cmd = app.add_subcommand(
        "graph", "Print the frame graph a technique declares at its default parameters: its images, buffers and "
                 "passes with every use (what the harness allocates, binds, barriers and times).");
    graph_cmd->add_option("technique", graph_technique, "a technique name, e.g. shadow.pcss")->required();
    CLI::App* devices_cmd = app.add_subcommand("devices", "List the Vulkan devices canopy can run on.");
    CLI::App* metrics_cmd = app.add_subcommand(
        "metrics", "List every error metric: its names in results and [paper] claims, unit, better direction, group, "
                   "compare tolerance.");
    // The commands that only read and print (or write a file) run no case: their exit codes are these.
    for (CLI::App* quick_cmd : {list_cmd, graph_cmd, devices_cmd, metrics_cmd, plan_cmd, export_cmd, export_paper_cmd,
                               image_error_cmd})
        quick_cmd->footer("Exit codes: 0 success, 1 a file could not be written, 2 bad input (the message names file:line).");

    try {
        refuse_unknown_command(app, argc, argv);
        app.parse(argc, argv);
    } catch (const ConfigError& e) {
        fmt::print(stderr, "{}\n", e.formatted());
        return kExitBadInput;
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kExitOk : kExitBadInput;
    }

    try {
        for (const FamilyBenchmarkCommand& c : family_benchmarks)
            if (*c.command)
                return run_family_benchmark(*c.benchmark,
                                            c.scene.empty() ? find_default_scene(c.benchmark->default_scene(), current_executable())
                                                            : fs::path(c.scene),
                                            c.given, c.device, c.out);
        if (*list_cmd) return list_techniques();
        if (*graph_cmd) return print_graph(graph_technique);
        if (*devices_cmd) return list_devices();
        if (*metrics_cmd) {
            fmt::print("{}", metric_list());
            return kExitOk;
        }
        if (*run_cmd) {
            RunCommand command;
            command.config = config_path;
            command.out = out_dir;
            command.device = device;
            command.quick = quick;
            command.progress = !no_progress;
            command.with_reference = !no_reference;
            command.resume = resume;
            command.force = force;
            command.report = report_after_run;
            command.shard = shard_text;
            command.references_only = references_only;
            command.images = images == "none" ? ImageOutput::none : images == "png" ? ImageOutput::png : ImageOutput::all;
            command.runs = run_count;
            if (run_count > 1 && !shard_text.empty())
                throw ConfigError(fs::path(), 0, "--runs with --shard", "repeat the whole experiment, not one shard");
            return run(command, reference_options);
        }
        if (*reference_cmd) return reference(scene_path, out_dir, reference_options);
        if (*compare_cmd) try {
                return compare(compare_command);
            } catch (const ConfigError&) {
                throw;
            } catch (const std::exception& e) {
                fmt::print(stderr, "canopy: error: {}\n", e.what());
                return kExitCompareFailed;  // not 1, which means a regression
            }
        if (*report_cmd) return report(report_command);
        if (*export_cmd) return export_gbench(export_runs, export_force);
        if (*export_paper_cmd) return export_paper(paper_runs, paper_force, paper_rejudge);
        if (*image_error_cmd) return image_error(image_test, image_reference, image_json);
        if (*plan_cmd) return plan(plan_config, plan_shards, plan_quick);
        if (*merge_cmd) return merge(merge_dirs, merge_out, merge_force);
        if (*bench_stability_cmd) return bench_stability(stability);
        if (*bench_reference_cmd)
            return bench_reference(scene_path.empty() ? find_default_bench_scene(current_executable()) : fs::path(scene_path),
                                   reference_options);
        if (*bench_scaling_cmd) {
            if (scaling.scene_file.empty()) scaling.scene_file = find_default_bench_scene(current_executable()).string();
            return bench_scaling(scaling, device, out_dir);
        }
    } catch (const ConfigError& e) {
        fmt::print(stderr, "{}\n", e.formatted());
        return kExitBadInput;
    } catch (const Interrupted&) {
        fmt::print(stderr, "canopy: interrupted; the image being ray-traced was dropped\n");
        return exit_code_for_interrupt();
    } catch (const GpuError& e) {
        fmt::print(stderr, "canopy: Vulkan error: {}\n", e.what());
        return kExitFailedCases;
    } catch (const std::exception& e) {
        fmt::print(stderr, "canopy: error: {}\n", e.what());
        return kExitFailedCases;
    }
    return kExitOk;
}
