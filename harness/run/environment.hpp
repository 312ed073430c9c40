// Where a run happened: device, driver, threads, CPU, build, commit. Recorded with every result.
#pragma once

#include "gpu/context.hpp"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <optional>
#include <array>
#include <string>
#include <vector>

namespace canopy {

// One CPU cache level as the kernel describes it (/sys/devices/system/cpu/cpu0/cache).
struct CpuCache {
    std::string type;  // "Data", "Instruction", "Unified"
    int level = 0;
    long long size_bytes = 0;
    int num_sharing = 0;  // CPUs sharing it
};

struct Environment {
    DeviceInfo device;
    std::string mesa_version;      // "22.3.6" for Mesa drivers, "" otherwise
    unsigned nproc = 0;            // hardware threads available to this process
    std::string lp_num_threads;    // LP_NUM_THREADS as set, or "unset" (lavapipe then uses nproc)
    std::string heap;              // the C heap's settings while measuring (run/heap_settings.hpp)
    std::string cpu_model;
    double cpu_mhz = 0;            // /proc/cpuinfo's "cpu MHz" of the first CPU, 0 if unknown
    bool cpu_scaling = false;      // a cpufreq governor other than "performance" is active
    std::vector<CpuCache> caches;
    std::string cpus_allowed;      // the CPUs this process may run on ("0-1"), e.g. after taskset
    std::array<double, 3> load_average{};  // 1, 5 and 15 minutes, when the environment was collected
    std::string build_type;        // CMAKE_BUILD_TYPE of this binary
    std::string canopy_version;
    // The checkout the run is in (run_checkout(): the experiment config's), read without taking
    // git's lock: its commit ("unknown" outside a git checkout), whether it has uncommitted changes
    // to anything but results/, and which files those are.
    std::string git_commit;
    bool git_dirty = false;
    std::vector<std::string> dirty_files;
    // The commit this binary was built from (source_commit()), recorded apart: a build copied or
    // moved from another checkout, or older than the checkout's commit, runs other code than
    // `git_commit` says. "" in records older than this field.
    std::string binary_commit;
    bool binary_dirty = false;
    // The binary's commit is known and is not the checkout's (commit_mismatch_text says how).
    bool commit_mismatch() const;
    // A source file changed after this binary was linked (run/binary_freshness.hpp), or "": the
    // numbers then come from other code than `git_commit` says.
    std::string binary_older_than;
    std::string hostname;
    std::string config_hash;
};

Environment collect_environment(const GpuContext& gpu, const std::string& config_hash);
// "6153c3b… (with uncommitted changes: a.cpp, b.toml)", and when the binary was built from another
// commit, "; the binary was built from <commit>, not this checkout's commit": how every report
// names the code a run measured.
std::string commit_text(const Environment& e);
// The checkout this binary was built from, and its commit ("unknown" outside a git checkout).
std::filesystem::path source_checkout();
std::string source_commit();
// The git checkout holding `path` (the nearest folder above it with a .git), or "" when none does.
std::filesystem::path checkout_of(const std::filesystem::path& path);
// The checkout a run is in: where set_run_checkout put it (the experiment config's checkout), else
// the working directory's checkout, else the binary's own (source_checkout()). Results record their
// paths relative to it (recorded_path.hpp) and collect_environment reads its commit.
std::filesystem::path run_checkout();
// Makes `path`'s checkout (checkout_of) the run's, when it is in one; otherwise changes nothing.
void set_run_checkout_of(const std::filesystem::path& path);
// A file of the run's checkout as `commit` had it (path relative to the checkout), read without
// taking git's lock; nothing when the commit or the file is not there.
std::optional<std::string> checkout_file_at(const std::string& commit, const std::string& relative_path);
std::string canopy_build_type();  // CMAKE_BUILD_TYPE of this binary
std::array<double, 3> current_load_average();  // /proc/loadavg: 1, 5 and 15 minutes; zeros if unknown
void to_json(nlohmann::json& j, const Environment& e);
// Reads back what to_json wrote; fields a record lacks keep their defaults.
void from_json(const nlohmann::json& j, Environment& e);

// Now as results record times: ISO 8601, UTC ("2026-12-04T05:10:31Z").
std::string utc_now();

}  // namespace canopy
