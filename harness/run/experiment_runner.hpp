// Runs an experiment's cases: for each, builds the technique's frame, warms up, measures,
// saves the image, and rewrites the reports so an interrupted run keeps every finished case.
#pragma once

#include "core/registry.hpp"
#include "run/case_result.hpp"

#include <filesystem>

namespace canopy {

enum class ImageOutput { all, png, none };  // EXR + PNG + error maps, PNGs only, nothing

struct RunOptions {
    std::filesystem::path out_dir;
    bool quick = false;          // 1 warm-up and 3 measured frames per case
    bool show_progress = true;
    ImageOutput images = ImageOutput::all;
    bool reference = true;                        // ray-trace references and compute errors (if the experiment enables it)
    std::filesystem::path reference_cache_dir;    // empty: no cache
    // The run this one continues (read from out_dir's results.json, same identity): its finished
    // cases whose files exist are kept, the others are run. Null: a new run.
    const RunRecord* previous = nullptr;
};

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

// Writes results.json, results.csv, results.md and images/ under options.out_dir, rewriting the
// reports after every case. A failure to write (a full disk, ...) ends the run with status
// "failed" and the reason in RunRecord::error, recorded in results.json where the disk allows.
RunRecord run_experiment(const PreparedExperiment& prepared, const TechniqueRegistry& registry, const GpuContext& gpu,
                         const RunOptions& options);

// Renders one case and measures it (no files written). Used by the runner and by tests.
// `image_out` receives the last frame, `visibility_out` its pixel-centre visibility
// (FrameRenderer::read_pixel_visibility).
CaseResult measure_case(const Case& c, const Scene& scene, const std::vector<TriangleMesh>& meshes,
                        const Technique& technique, const GpuContext& gpu, int warmup_frames, int measured_frames,
                        Image* image_out, Image* visibility_out = nullptr);

}  // namespace canopy
