// Loads an experiment config (configs/README.md documents the format) and expands it into the
// concrete cases to run. All scene files and technique parameters are validated at load time,
// so every configuration mistake is reported before the GPU is touched.
#pragma once

#include "config/experiment.hpp"
#include "core/registry.hpp"

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace canopy {

// Throws ConfigError naming file:line for any mistake, including those in the scene files it uses.
Experiment load_experiment(const std::filesystem::path& file, const TechniqueRegistry& registry);

// Scene -> resolution -> technique entry -> cartesian product of the entry's sweep (parameters in
// the order the config gives them). Every case gets a unique, file-name-safe id.
std::vector<Case> expand_cases(const Experiment& experiment, const TechniqueRegistry& registry);

// 64-bit FNV-1a, continuing from `state` so several files can be hashed as one stream.
inline constexpr uint64_t kFnv1aOffsetBasis = 0xcbf29ce484222325ull;
uint64_t fnv1a_64(std::string_view bytes, uint64_t state = kFnv1aOffsetBasis);
// Experiment::config_hash: the experiment file's bytes, then each file's (hex).
std::string hash_files(const std::string& experiment_bytes, const std::vector<std::filesystem::path>& files);

}  // namespace canopy
