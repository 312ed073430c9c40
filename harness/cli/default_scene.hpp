// The scene `canopy bench` uses when none is given: configs/scenes/spheres.toml of a checkout,
// looked for where a user runs canopy from, then where the executable was built. Nothing is
// compiled in: a binary moved to another machine finds the scene of the checkout it runs in.
#pragma once

#include <filesystem>

namespace canopy {

inline constexpr const char* kDefaultBenchScene = "configs/scenes/spheres.toml";

// `kDefaultBenchScene` in the current directory, else in the folder above the executable's (a
// checkout's build/canopy), else next to the executable. Throws ConfigError, listing where it
// looked, when none exists.
std::filesystem::path find_default_bench_scene(const std::filesystem::path& executable);
// The same search for another checkout-relative scene (a family benchmark's default).
std::filesystem::path find_default_scene(const std::string& relative, const std::filesystem::path& executable);

// This process's executable (/proc/self/exe), or "" when it cannot be read.
std::filesystem::path current_executable();

}  // namespace canopy
