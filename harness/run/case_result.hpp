// What one case of an experiment produced, and the record of a whole run.
#pragma once

#include "config/experiment.hpp"
#include "metrics/image_metrics.hpp"
#include "run/block_bootstrap.hpp"
#include "render/frame_renderer.hpp"
#include "run/environment.hpp"
#include "run/run_identity.hpp"
#include "run/statistics.hpp"
#include "run/timing_check.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace canopy {

struct TimingSeries {
    std::string name;               // pass name, "gpu_frame", "wall" or "cpu"
    std::vector<double> samples_ms; // one per measured round: the mean over the sample's frames
    SampleStats stats;
};

// A case's GPU time relative to its group's baseline (the group's first case), round by round:
// both were measured in the same round, so a load change that lasts longer than a round divides
// out (run/group_measurement.hpp).
struct RatioRecord {
    std::vector<double> per_round;  // GPU time / the baseline's GPU time of the same round
    Estimate estimate;              // median over the rounds, 95 % circular-block-bootstrap interval
    bool measured() const { return !per_round.empty(); }
};

struct CaseResult {
    std::string id;
    std::string scene;
    // The experiment's overrides of the scene's file for this case (Scene::variant: its name,
    // light_casts_shadows, camera, population parameters ...), "" when it renders the file as is.
    std::string scene_variant;
    std::string technique;
    Resolution resolution;
    std::vector<std::pair<std::string, ParamValue>> params;
    std::string params_summary;        // every value
    std::string params_shown;          // swept parameters and values that differ from the defaults ("-" if none)
    std::vector<TimingSeries> passes;  // GPU time per pass
    std::vector<TimingSeries> cpu_passes;  // CPU passes (steady clock), beside the GPU passes
    TimingSeries record_cpu;           // CPU time recording the frame's commands (CPU passes excluded)
    TimingSeries gpu_frame;            // GPU time, first pass start to last pass end
    TimingSeries wall;                 // CPU wall time per frame, submit to completion
    TimingSeries cpu;                  // the process's CPU time per frame (every thread, lavapipe's too)
    std::vector<double> sample_start_s;  // when each sample began, seconds after its chunk's measurement began
    TimingCheck timing_check;          // do the GPU pass times add up to the wall time?
    // With a camera path: per frame of the traversal, its times over the rounds (a sample's series
    // above are the means over the traversal).
    struct PathFrame {
        TimingSeries gpu_frame;
        std::vector<TimingSeries> passes;
    };
    std::vector<PathFrame> path_frames;
    // The load phase (run once, when the renderer is made, before any frame): its GPU passes'
    // times (a bake, an upload), its GPU and wall time and the bytes it uploaded; empty passes
    // for a technique without load passes.
    struct LoadPhase {
        std::vector<std::pair<std::string, double>> pass_gpu_ms;
        double gpu_ms = 0, wall_ms = 0;
        uint64_t uploaded_bytes = 0;
    };
    LoadPhase load;
    size_t group = 0;                  // index into RunRecord::groups
    size_t chunk = 0;                  // the group's chunk whose rounds measured it (the baseline's: the first)
    // The machine that measured it, in a merged run (`canopy merge`: its shard's hostname, a
    // cluster's node); "" in a run of one process, whose environment names the machine.
    std::string node;
    bool group_baseline = false;       // the group's first case, which the others' ratios divide by
    RatioRecord ratio;                 // empty when the group's baseline failed
    MemoryUse memory;
    size_t triangles = 0;  // the scene's, every population copy counted
    // The triangles the technique's frame submitted and rasterised (after clipping), counted in the
    // first warm-up frame (FrameRenderer::render_counting_primitives); empty when not counted.
    std::optional<PrimitiveCounts> primitives;
    // What the technique's CPU passes counted in that same frame (CpuPassContext::count: the cells
    // a CPU cull kept, say), in the order first counted; empty when it counts nothing.
    std::vector<std::pair<std::string, double>> counters;
    // With [camera_path] popping: the popping of each frame pair (k-1, k), k = 1 .. frames - 1, of
    // which image_error's popping_mean and popping_max are the mean and the largest (a spike or a
    // spread); empty otherwise.
    std::vector<double> popping_per_pair;
    std::string shadow_sampler;
    std::string image_exr, image_png;  // relative to the run folder
    std::string visibility_exr;        // the technique's pixel-centre visibility (core/pixel_visibility.hpp)
    long long nonfinite_pixels = 0;
    // Error against the ray-traced reference of the same scene and resolution (when enabled).
    std::optional<ImageMetrics> image_error;
    // Each metric (results.json name) against the reference perturbed by its own noise, replicate
    // by replicate (reference/reference_noise.hpp); the same replicates for every case of one
    // reference. Empty where no reference or no variance was at hand, or in older records.
    std::map<std::string, std::vector<double>> reference_replicates;
    std::string error_map_png, flip_map_png;  // relative to the run folder
    bool ok = true;
    std::string error;                 // why the case failed, when !ok
};

// The reference a run compared its cases with, per scene and resolution.
struct ReferenceRecord {
    std::string scene;
    Resolution resolution;
    std::string key;          // cache key (content hash)
    bool from_cache = false;
    double seconds = 0;       // render time (when it was rendered, possibly in an earlier run)
    uint64_t shadow_rays = 0;
    int light_samples = 0, pixel_samples = 0;
    double error_map_scale = 0;  // luminance error drawn at the top of the heat maps
    // Why it cannot tell techniques apart (metrics/reference_degeneracy.hpp: "no lit pixels",
    // "uniform image", "no penumbra"); empty when it can. Its cases are flagged in every table and
    // no claim's verdict rests on them.
    std::vector<std::string> degenerate;
    std::string image_exr, image_png, visibility_exr;
    // The pixel-centre visibility the technique-isolated error and the shadow masks come from
    // (reference/pixel_visibility.hpp), cached under its own key.
    std::string pixel_visibility_key;
    bool pixel_visibility_from_cache = false;
    double pixel_visibility_seconds = 0;
    uint64_t pixel_visibility_shadow_rays = 0;
    int pixel_visibility_samples = 0;
    std::string pixel_visibility_exr;
};

// One chunk of a group: cases measured together, round after round. A group larger than a
// chunk's limits is measured in several chunks, each with the group's baseline in it.
struct MeasurementChunk {
    std::vector<std::string> cases;            // case ids, the baseline first
    std::string started_at;                    // ISO 8601, UTC
    double seconds = 0;                        // warm-up and rounds
    std::vector<std::vector<size_t>> orders;   // per round: positions in `cases`, in the order they ran
    std::vector<double> baseline_gpu_ms;       // per round: the baseline's sample, which the others are divided by
};

// The cases that share a baseline: one scene at one resolution, in the experiment's order.
struct GroupRecord {
    std::string name;                  // "spheres 640x360"
    std::string scene;
    Resolution resolution;
    std::vector<std::string> cases;    // ids, the baseline first
    std::vector<MeasurementChunk> chunks;
    const std::string& baseline() const { return cases.front(); }
};

// A file the run read, with a hash of its bytes as they were read.
struct InputFile {
    std::string file;  // recorded_path: relative to the run's checkout
    std::string hash;  // FNV-1a 64 of its bytes, hex (the hash config_hash chains)
};

struct RunRecord {
    std::string experiment;
    std::string description;
    std::string config_file;
    // The experiment config, then every file it read (scene files, meshes, height and density
    // maps), as the run read them; a copy of the config's bytes is the run folder's experiment.toml.
    std::vector<InputFile> inputs;
    Environment environment;
    int warmup_frames = 0;         // per case, before the first round of its chunk
    int rounds = 0;                // measured samples per case
    int frames_per_sample = 0;     // frames each sample averages
    int measured_frames() const { return rounds * frames_per_sample; }
    std::optional<CameraPath> camera_path;  // the frames of a sample follow it (then frames_per_sample = its frames)
    std::optional<DistanceBands> distance_bands;  // [reference] distance_bands: FLIP near / middle / far
    bool quick = false;
    // "i/N" when this run measured one shard of the experiment's groups (`canopy run --shard`;
    // `canopy merge` puts the shards together), "" for a whole run.
    std::string shard;
    // A merged run (`canopy merge`): where each shard ran, in shard order; empty otherwise.
    struct MergedShard {
        std::string shard;       // "i/N"
        std::string hostname;    // the machine (a cluster's node) that measured it
        std::string started_at, finished_at;
        size_t cases = 0;
        std::vector<std::string> groups;  // the groups it measured: which node measured which case
    };
    std::vector<MergedShard> merged_from;
    RunIdentity identity;                 // what a run continuing this one must match
    std::string started_at, finished_at;  // ISO 8601, UTC
    std::vector<std::string> resumed_at;  // when it was continued (--resume), ISO 8601, UTC
    std::string status = "running";       // running | complete | interrupted | failed
    std::string error;                    // why the run stopped when it failed as a whole (e.g. a full disk)
    size_t planned_cases = 0;
    bool reference_enabled = false;
    std::vector<ReferenceRecord> references;
    std::vector<GroupRecord> groups;  // those with recorded cases, in the experiment's order
    std::vector<CaseResult> cases;
};

// Whether `r` is the reference of `scene` at `resolution`.
bool same_reference(const ReferenceRecord& r, const std::string& scene, const Resolution& resolution);
// The reference `c` was compared with (same scene and resolution), or null.
const ReferenceRecord* reference_of(const RunRecord& run, const CaseResult& c);
// Why that reference is degenerate (ReferenceRecord::degenerate), empty when it is not or none.
const std::vector<std::string>& degenerate_reasons(const RunRecord& run, const CaseResult& c);

}  // namespace canopy
