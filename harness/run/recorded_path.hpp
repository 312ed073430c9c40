// Paths written into results name files relative to the checkout (configs/scenes/spheres.toml),
// not where the checkout happens to be on the machine that ran them: committed results must read
// the same on every machine.
#pragma once

#include <filesystem>
#include <string>

namespace canopy {

// Relative to the run's checkout (run_checkout()) when `path` is inside it; otherwise absolute.
// Forward slashes.
std::string recorded_path(const std::filesystem::path& path);

}  // namespace canopy
