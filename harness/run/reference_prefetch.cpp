#include "run/reference_prefetch.hpp"

#include "core/error.hpp"
#include "run/reference_provider.hpp"

#include <chrono>

namespace canopy {

std::vector<PrefetchedReference> prefetch_references(const PreparedExperiment& prepared, const RunOptions& options,
                                                     const std::function<void(const std::string&)>& starting) {
    const Experiment& experiment = *prepared.experiment;
    if (!experiment.reference_enabled)
        throw ConfigError(experiment.file, 0, "this experiment compares with no reference ([reference] is off)",
                          "run it without --references-only");
    if (options.reference_cache_dir.empty())
        throw ConfigError(experiment.file, 0, "--references-only renders into the reference cache, which is off",
                          "drop --no-cache; give the shared folder with --reference-cache or $CANOPY_CACHE_DIR");
    const MeasurementSettings settings = measurement_settings(experiment, options);
    ReferenceProvider references(options.reference_cache_dir, experiment.reference);
    std::vector<PrefetchedReference> done;
    for (const PlannedGroup& planned : plan_groups(prepared.cases, experiment.scenes)) {
        if (starting) starting(planned.name);
        const Scene& scene = experiment.scenes[planned.scene_index];
        const auto& meshes = prepared.meshes[planned.scene_index];
        const auto start = std::chrono::steady_clock::now();
        PrefetchedReference record;
        record.group = planned.name;
        const ReferenceEntry& entry = references.get(scene, meshes, planned.resolution.width, planned.resolution.height);
        record.from_cache = entry.from_cache && entry.pixel_visibility_from_cache;
        if (settings.camera_path && settings.camera_path->popping)
            for (int k = 0; k < settings.camera_path->frames; ++k) {
                Scene at = scene;
                at.camera = settings.camera_path->at(scene.camera, k);
                references.images(at, meshes, planned.resolution.width, planned.resolution.height);
                ++record.path_frames;
            }
        record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        done.push_back(record);
    }
    return done;
}

}  // namespace canopy
