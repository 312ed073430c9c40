// What one case of an experiment produced, and the record of a whole run.
#pragma once

#include "config/experiment.hpp"
#include "render/frame_renderer.hpp"
#include "run/environment.hpp"
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
    std::string params_summary;
    std::vector<TimingSeries> passes;  // GPU time per pass
    TimingSeries gpu_frame;            // GPU time, first pass start to last pass end
    TimingSeries wall;                 // CPU wall time per frame, submit to completion
    MemoryUse memory;
    size_t triangles = 0;
    std::string shadow_sampler;
    std::string image_exr, image_png;  // relative to the run folder
    long long nonfinite_pixels = 0;
    bool ok = true;
    std::string error;                 // why the case failed, when !ok
};

struct RunRecord {
    std::string experiment;
    std::string description;
    std::string config_file;
    Environment environment;
    int warmup_frames = 0;
    int measured_frames = 0;
    bool quick = false;
    std::string started_at, finished_at;  // ISO 8601, UTC
    std::string status = "running";       // running | complete | interrupted | failed
    size_t planned_cases = 0;
    std::vector<CaseResult> cases;
};

}  // namespace canopy
