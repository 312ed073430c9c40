// `canopy merge`: the shards of one experiment (`canopy run --shard i/N`, each a run folder of some
// of its groups) put together into the run a single process would have written: every group in
// the experiment's order, every case with its samples, ratios and errors as measured, the
// references, and where each shard ran. A group is measured whole inside one shard, so every
// ratio keeps the baseline it was paired with.
#pragma once

#include "config/experiment.hpp"
#include "core/registry.hpp"
#include "run/case_result.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace canopy {

struct MergedRun {
    RunRecord run;
    std::vector<std::string> missing;  // ids of the experiment's cases no shard recorded, in its order
};

// Shards of `experiment` (its cases as expand_cases gives them) into one record. Throws
// ConfigError naming the shard folder and the difference when shards come from other configs,
// commits, devices or settings, are whole runs, or repeat a shard; `folders[k]` is where
// `shards[k]` was read from.
MergedRun merge_shards(const std::vector<RunRecord>& shards, const std::vector<std::filesystem::path>& folders,
                       const Experiment& experiment, const std::vector<Case>& cases, const TechniqueRegistry& registry);

// The images the merged record names, copied from the shard folders into `out`, each renamed into
// place over what was there (merging the same shards twice writes the same folder). Returns the
// count copied.
size_t copy_shard_images(const MergedRun& merged, const std::vector<RunRecord>& shards,
                         const std::vector<std::filesystem::path>& folders, const std::filesystem::path& out);

}  // namespace canopy
