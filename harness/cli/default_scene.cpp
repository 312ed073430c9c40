#include "cli/default_scene.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace canopy {

std::filesystem::path find_default_bench_scene(const std::filesystem::path& executable) {
    return find_default_scene(kDefaultBenchScene, executable);
}

std::filesystem::path find_default_scene(const std::string& relative, const std::filesystem::path& executable) {
    namespace fs = std::filesystem;
    std::vector<fs::path> candidates{fs::path(relative)};
    if (!executable.empty()) {
        const fs::path folder = executable.parent_path();
        candidates.push_back((folder / ".." / relative).lexically_normal());
        candidates.push_back((folder / relative).lexically_normal());
    }
    std::vector<fs::path> looked;
    for (const fs::path& candidate : candidates) {
        std::error_code ignored;
        if (fs::is_regular_file(candidate, ignored)) return candidate;
        const fs::path absolute = fs::absolute(candidate, ignored).lexically_normal();
        if (std::find(looked.begin(), looked.end(), absolute) == looked.end()) looked.push_back(absolute);
    }
    std::string places;
    for (const fs::path& place : looked) places += fmt::format("{}{}", places.empty() ? "" : ", ", place.string());
    throw ConfigError({}, 0, fmt::format("no scene given, and the default scene {} was not found; looked for {}", relative, places),
                      fmt::format("give the scene file as the command's argument, e.g. path/to/canopy/{}", relative));
}

std::filesystem::path current_executable() {
    std::error_code error;
    std::filesystem::path path = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : path;
}

}  // namespace canopy
