// An experiment: scenes x techniques x parameter values x resolutions, with timing settings.
#pragma once

#include "config/paper_comparison.hpp"
#include "core/param.hpp"
#include "metrics/distance_bands.hpp"
#include "reference/reference_settings.hpp"
#include "scene/camera_path.hpp"
#include "scene/scene.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace canopy {

// Frames one timing sample averages unless an experiment says otherwise (README, "Timing").
inline constexpr int kDefaultFramesPerSample = 1;

// How a case's samples are paired with the baseline's (run/group_measurement.hpp).
enum class BaselinePairing { adjacent, round };
const char* to_string(BaselinePairing pairing);

struct Resolution {
    int width = 640;
    int height = 360;
};

// One [[technique]] entry. Each parameter may list several values; the experiment runs the
// cartesian product of all lists (a sweep).
struct TechniqueEntry {
    std::string name;                                     // registry name, already checked to exist
    std::map<std::string, std::vector<ParamValue>> sweep; // parameter -> values
    std::map<std::string, int> param_lines;               // parameter -> line in the config
    std::vector<std::string> param_order;                 // parameters in the order the config gives them
    SourceLocation where;
};

struct Experiment {
    std::string name;
    std::filesystem::path file;
    std::string description;
    std::vector<Scene> scenes;
    std::vector<Resolution> resolutions{{640, 360}};
    std::vector<TechniqueEntry> techniques;
    // Timing (run/group_measurement.hpp): warm-up frames per case, then `rounds` measured rounds,
    // each one sample of every case of a group, a sample the mean of `frames_per_sample` frames.
    int warmup_frames = 5;
    int rounds = 30;  // the `repetitions` key
    int frames_per_sample = kDefaultFramesPerSample;
    BaselinePairing pairing = BaselinePairing::adjacent;  // the `pairing` key
    // [camera_path]: the camera moves along it, every sample one traversal of its frames (each
    // scene's camera gives up vector and clip planes); none: every frame at the scene's camera.
    std::optional<CameraPath> camera_path;
    // The ray-traced reference every case's image is compared with ([reference] table).
    bool reference_enabled = true;
    ReferenceSettings reference{64, 4, 1, 0};  // 64 light samples x 4 pixel samples = 256 shadow rays per pixel
    // [reference] distance_bands: FLIP is also reported near, in the middle and far (metrics/distance_bands.hpp).
    std::optional<DistanceBands> distance_bands;
    // The paper table this experiment reproduces ([paper]), if any.
    std::optional<PaperComparison> paper;
    // Hash of the experiment file and every scene file it uses (hex), for the results record.
    std::string config_hash;
    // The files hashed after the experiment's own bytes, in order (scenes, meshes, maps).
    std::vector<std::filesystem::path> hashed_files;
};

// One thing to run: one scene, one resolution, one technique with concrete parameters.
struct Case {
    size_t scene_index = 0;
    Resolution resolution;
    std::string technique;
    ParamSet params;
    std::string id;  // unique, file-name safe: "spheres_640x360_shadow.pcf_kernel-5_pattern-grid"
};

}  // namespace canopy
