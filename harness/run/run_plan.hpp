// What a run of an experiment will do before it does it: its groups (the cases measured together,
// experiment_runner.hpp), each case's stable key and estimated cost, and how the groups split into
// shards balanced by that cost (`canopy plan`, `canopy run --shard i/N`, `canopy merge`).
#pragma once

#include "config/experiment.hpp"
#include "core/registry.hpp"
#include "run/experiment_runner.hpp"

#include <string>
#include <vector>

namespace canopy {

// 16 hex digits of a 64-bit FNV-1a hash of the scene's name, the technique, every parameter value
// and the resolution: the same case of any experiment, in any order, has the same key.
std::string case_key(const Case& c, const Scene& scene);

// A case's work in megapixel-frames: every frame it renders (warm-up, rounds; a non-baseline case
// also makes its group's baseline render beside each sample) times the pixels its frame-phase
// passes cover (each pass: the largest image it uses; a pass that uses no image counts a tenth of
// the screen). A ranking to balance shards with, not a prediction of seconds: it leaves out
// geometry (a population's blades) and the reference, which runs before the shards.
double estimated_case_cost(const Case& c, const Technique& technique, const MeasurementSettings& settings,
                           bool group_baseline);

struct RunPlan {
    std::vector<PlannedGroup> groups;   // in the experiment's order
    std::vector<std::string> keys;      // per case (the experiment's cases' order)
    std::vector<double> case_cost;      // per case
    std::vector<double> group_cost;     // per group: its cases' sum
};
RunPlan plan_run(const Experiment& experiment, const std::vector<Case>& cases, const TechniqueRegistry& registry,
                 const MeasurementSettings& settings);

// Which shard (0 .. shards - 1) measures each group: whole groups, the most costly first, each to
// the shard with the least cost so far (ties: the lowest index). Deterministic.
std::vector<size_t> assign_shards(const std::vector<double>& group_cost, size_t shards);

// "i/N" (1 <= i <= N) -> {i - 1, N}; throws std::invalid_argument saying what is wrong, in the
// words of the option that gave it (`flag`: "--shard", or "--tile" for `canopy reference`).
struct ShardSpec {
    size_t index = 0;  // from 0
    size_t count = 1;
    std::string text() const;  // "2/4"
};
ShardSpec parse_shard(const std::string& text, const std::string& flag = "--shard");

}  // namespace canopy
