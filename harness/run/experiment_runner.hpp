// Runs an experiment group by group (the cases of one scene at one resolution, measured together
// round by round: run/group_measurement.hpp), saves each case's image and error, records every
// finished chunk of a group in results.json and rewrites every report after each group, so an
// interrupted run keeps every finished chunk and --resume goes on after it.
#pragma once

#include "core/registry.hpp"
#include "run/case_result.hpp"
#include "run/group_measurement.hpp"
#include "run/test_ballast.hpp"

#include <filesystem>

namespace canopy {

enum class ImageOutput { all, png, none };  // EXR + PNG + error maps, PNGs only, nothing

struct RunOptions {
    std::filesystem::path out_dir;
    bool quick = false;          // 1 warm-up frame, 3 rounds of 1 frame per case
    bool show_progress = true;
    ImageOutput images = ImageOutput::all;
    bool reference = true;                        // ray-trace references and compute errors (if the experiment enables it)
    std::filesystem::path reference_cache_dir;    // empty: no cache
    // The run this one continues (read from out_dir's results.json, same identity): its finished
    // cases whose files exist are kept, the others are run. Null: a new run.
    const RunRecord* previous = nullptr;
    ChunkLimits chunk_limits;
    std::optional<BallastSpec> ballast;  // TEST-ONLY (run/test_ballast.hpp)
    // This run measures one shard of the experiment's groups (`canopy run --shard i/N`,
    // run/run_plan.hpp): "i/N", or "" for the whole experiment. The cases given are the shard's.
    std::string shard;
};

// The measurement an experiment gets with these options (--quick shortens it).
MeasurementSettings measurement_settings(const Experiment& experiment, const RunOptions& options);

// The cases that share a baseline: one scene at one resolution, in the order of the cases.
struct PlannedGroup {
    std::string name;           // "spheres 640x360"
    size_t scene_index = 0;
    Resolution resolution;
    std::vector<size_t> cases;  // indices into the experiment's cases, the baseline first
};
std::vector<PlannedGroup> plan_groups(const std::vector<Case>& cases, const std::vector<Scene>& scenes);

// An experiment checked against the device: every case's plan fits its scene and the device,
// every mesh loaded. Nothing is written before this succeeds.
struct PreparedExperiment {
    const Experiment* experiment = nullptr;
    std::vector<Case> cases;
    std::vector<std::vector<TriangleMesh>> meshes;  // per scene
};

// Throws ConfigError naming the experiment's file:line when a case cannot run here.
PreparedExperiment prepare_experiment(const Experiment& experiment, const TechniqueRegistry& registry,
                                      const GpuContext& gpu);

// The same refusal for what no device decides (check_scene_supported): `canopy plan` on a machine
// that may have no device refuses the cases no device could run.
void refuse_cases_scenes_cannot_run(const Experiment& experiment, const std::vector<Case>& cases,
                                    const TechniqueRegistry& registry);

// Writes a run's reports into `dir`: results.json, results.csv, results.md, results.gbench.json,
// pareto.md, and paper.md and paper.json for an experiment with a [paper] table.
void write_run_reports(const std::filesystem::path& dir, const RunRecord& run, const Experiment& experiment);

// How many chunks measuring `cases` cases of a group (the baseline among them) takes at least:
// the progress lines' "chunk k/n".
size_t planned_chunks(size_t cases, const ChunkLimits& limits);

// Writes results.json, results.csv, results.md, results.gbench.json and images/ under
// options.out_dir, recording each finished chunk and rewriting the reports after every group. A failure to write (a full disk, ...) ends the run with status
// "failed" and the reason in RunRecord::error, recorded in results.json where the disk allows.
RunRecord run_experiment(const PreparedExperiment& prepared, const TechniqueRegistry& registry, const GpuContext& gpu,
                         const RunOptions& options);

}  // namespace canopy
