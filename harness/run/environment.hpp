// Where a run happened: device, driver, threads, CPU, build, commit. Recorded with every result.
#pragma once

#include "gpu/context.hpp"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>

namespace canopy {

struct Environment {
    DeviceInfo device;
    std::string mesa_version;      // "22.3.6" for Mesa drivers, "" otherwise
    unsigned nproc = 0;            // hardware threads available to this process
    std::string lp_num_threads;    // LP_NUM_THREADS as set, or "unset" (lavapipe then uses nproc)
    std::string cpu_model;
    std::string build_type;        // CMAKE_BUILD_TYPE of this binary
    std::string canopy_version;
    std::string git_commit;        // "unknown" outside a git checkout
    bool git_dirty = false;        // uncommitted changes in the source tree
    std::string hostname;
    std::string config_hash;
};

Environment collect_environment(const GpuContext& gpu, const std::string& config_hash);
// The checkout this binary was built from, and its commit ("unknown" outside a git checkout).
std::filesystem::path source_checkout();
std::string source_commit();
std::string canopy_build_type();  // CMAKE_BUILD_TYPE of this binary
void to_json(nlohmann::json& j, const Environment& e);

}  // namespace canopy
