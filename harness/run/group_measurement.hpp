// Measures a group of cases — those that share a baseline: one scene at one resolution — so that
// a change of load on the machine hits every case of the group alike. Every case's renderer is
// built and warmed up, then each measured round takes one sample of every case (F frames each),
// and each sample is divided by a baseline sample taken as close to it in time as can be:
//   adjacent (the default): B X B Y B Z B — each case between two baseline samples, divided by
//            their mean; the cases' order changes per round (round_order.hpp), and every case
//            follows the baseline, so none inherits another case's state;
//   round:   X Y B Z (a Williams order of all cases) — each case divided by the baseline's one
//            sample of the round.
// The median of those per-round ratios, with a block-bootstrap interval, is the case's ratio: a
// load shift that lasts longer than a sample divides out, where the ratio of two medians measured
// minutes apart would carry it. README "Timing" has the measurements behind the choice.
//
// A group whose renderers would hold more than ChunkLimits allows is measured in chunks, each
// with the baseline in it (re-measured, so every chunk's rounds are paired with it too).
#pragma once

#include "config/experiment.hpp"
#include "core/technique.hpp"
#include "run/case_result.hpp"

#include <functional>
#include <optional>

namespace canopy {

struct MeasurementSettings {
    int warmup_frames = 5;      // per case, before the first round of its chunk
    int rounds = 20;            // samples per case
    int frames_per_sample = 1;  // frames one sample averages
    BaselinePairing pairing = BaselinePairing::adjacent;
    // Frames follow it (a sample is one traversal: frames_per_sample is its frames); none: the
    // scene's camera.
    std::optional<CameraPath> camera_path;
};

struct ChunkLimits {
    // Cases measured together, the baseline included. More makes a round longer, and the samples
    // a case is paired with further apart in time.
    size_t max_cases = 16;
    // Device memory of the chunk's renderers together (targets, scene and technique resources;
    // lavapipe's is host memory).
    uint64_t max_bytes = uint64_t(4) << 30;
};

struct GroupCase {
    const Case* c = nullptr;
    const Technique* technique = nullptr;
    uint32_t ballast_iterations = 0;  // TEST-ONLY extra work per frame (run/test_ballast.hpp), 0: none
};

struct GroupInput {
    std::string name;  // "spheres 640x360"
    const Scene* scene = nullptr;
    const std::vector<TriangleMesh>* meshes = nullptr;
    std::vector<GroupCase> cases;  // the baseline first
    // A group cut short earlier and now continued (--resume): the chunks it recorded, and per case
    // whether they measured it (the baseline is in every chunk). Those cases are neither built nor
    // measured again; the baseline is, to pair the new chunks with, but not finished again. Both
    // empty: the whole group is measured.
    std::vector<MeasurementChunk> chunks_done;
    std::vector<bool> recorded;
};

struct GroupCallbacks {
    // A case is measured (its chunk's rounds are done, or it failed): `result` holds its timings,
    // `image` its last frame and `visibility` that frame's pixel-centre visibility
    // (FrameRenderer::read_pixel_visibility; both empty when it failed before rendering). Called in
    // group order within a chunk; the callee may set `result`'s image and error fields.
    std::function<void(size_t index, CaseResult& result, Image&& image, Image&& visibility)> case_measured;
    // With [camera_path] popping = true: after case_measured, the case's frames of one more
    // traversal (untimed, in path order; not called for a failed case, or when this is unset).
    std::function<void(size_t index, CaseResult& result, std::vector<Image>&& frames)> path_rendered;
    // Case `index` is about to render `state` (warm-up, measured and the final untimed frame):
    // which frame of the run it is and where the camera is, for tests and tools that trace it.
    std::function<void(size_t index, const FrameState& state)> frame_rendered;
    // A chunk is done: `finished` (group indices) are the cases it measured and those that failed
    // to build before it, each already through case_measured, their results final; `record` holds
    // the chunks so far, this one last. What the caller records here survives an interrupt.
    std::function<void(const GroupRecord& record, const std::vector<std::pair<size_t, const CaseResult*>>& finished)>
        chunk_finished;
    // Progress: round `round` (1-based) of `rounds` of a chunk of `cases` cases starts.
    std::function<void(size_t chunk, size_t cases, int round, int rounds)> round_started;
};

// Returns the group's record and its cases' results (group order; a case `recorded` before is
// left as a bare result with its id), or nullopt when an interrupt was requested before the group
// finished: then the chunks already passed to chunk_finished are the part of it that is valid. A
// case that cannot be built or rendered (GpuError) fails alone; the group goes on without it.
struct MeasuredGroup {
    GroupRecord record;
    std::vector<CaseResult> cases;
};
std::optional<MeasuredGroup> measure_group(const GpuContext& gpu, const GroupInput& group,
                                           const MeasurementSettings& settings, const ChunkLimits& limits,
                                           const GroupCallbacks& callbacks);

// The per-round ratios of `series` to `baseline` (same rounds, same length: paired) and their
// median with its interval; rounds where either is missing or not positive are left out.
RatioRecord paired_ratio(const std::vector<double>& series, const std::vector<double>& baseline, const std::string& label);

}  // namespace canopy
