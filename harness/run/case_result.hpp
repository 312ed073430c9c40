// What one case of an experiment produced, and the record of a whole run.
#pragma once

#include "config/experiment.hpp"
#include "metrics/image_metrics.hpp"
#include "render/frame_renderer.hpp"
#include "run/environment.hpp"
#include "run/run_identity.hpp"
#include "run/statistics.hpp"

#include <optional>
#include <string>
#include <vector>

namespace canopy {

struct TimingSeries {
    std::string name;               // pass name, "gpu_frame" or "wall"
    std::vector<double> samples_ms; // one per measured frame
    SampleStats stats;
};

struct CaseResult {
    std::string id;
    std::string scene;
    std::string technique;
    Resolution resolution;
    std::vector<std::pair<std::string, ParamValue>> params;
    std::string params_summary;        // every value
    std::string params_shown;          // swept parameters and values that differ from the defaults ("-" if none)
    std::vector<TimingSeries> passes;  // GPU time per pass
    TimingSeries gpu_frame;            // GPU time, first pass start to last pass end
    TimingSeries wall;                 // CPU wall time per frame, submit to completion
    MemoryUse memory;
    size_t triangles = 0;
    std::string shadow_sampler;
    std::string image_exr, image_png;  // relative to the run folder
    std::string visibility_exr;        // the technique's pixel-centre visibility (core/pixel_visibility.hpp)
    long long nonfinite_pixels = 0;
    // Error against the ray-traced reference of the same scene and resolution (when enabled).
    std::optional<ImageMetrics> image_error;
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

struct RunRecord {
    std::string experiment;
    std::string description;
    std::string config_file;
    Environment environment;
    int warmup_frames = 0;
    int measured_frames = 0;
    bool quick = false;
    RunIdentity identity;                 // what a run continuing this one must match
    std::string started_at, finished_at;  // ISO 8601, UTC
    std::vector<std::string> resumed_at;  // when it was continued (--resume), ISO 8601, UTC
    std::string status = "running";       // running | complete | interrupted | failed
    std::string error;                    // why the run stopped when it failed as a whole (e.g. a full disk)
    size_t planned_cases = 0;
    bool reference_enabled = false;
    std::vector<ReferenceRecord> references;
    std::vector<CaseResult> cases;
};

}  // namespace canopy
