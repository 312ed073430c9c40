// `canopy run --references-only`: the references a run (or one shard of it) will compare with,
// rendered into the reference cache beforehand and nothing else written, so that a cluster renders
// each scene and resolution's reference in a job of its own before the timing jobs start
// (scripts/slurm/submit). The same calls as the runner's (ReferenceProvider, the experiment's
// [reference] settings, the camera path's frames when it measures popping): the same cache keys.
#pragma once

#include "run/experiment_runner.hpp"

#include <functional>
#include <string>

namespace canopy {

struct PrefetchedReference {
    std::string group;   // "spheres 640x360"
    bool from_cache = false;
    double seconds = 0;
    int path_frames = 0;  // camera-path frames also rendered (popping)
};

// Every group's reference of `prepared` (its cases: a shard's when sharded), into `cache_dir`.
// Throws ConfigError when the experiment has no reference or the cache is off.
std::vector<PrefetchedReference> prefetch_references(const PreparedExperiment& prepared, const RunOptions& options,
                                                     const std::function<void(const std::string&)>& starting = {});

}  // namespace canopy
