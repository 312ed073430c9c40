// default_reference_cache_dir (run/reference_provider.hpp): apart from the provider, which a
// timing-only build replaces (timing_only/timing_only.hpp), since every run names the folder.
#include "run/reference_provider.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <cstdlib>

namespace canopy {

std::filesystem::path default_reference_cache_dir() {
    if (const char* dir = std::getenv("CANOPY_CACHE_DIR"); dir && *dir) return std::filesystem::path(dir) / "reference";
    return std::filesystem::path("results") / "cache" / "reference";
}

void check_reference_cache_dir(const std::filesystem::path& dir) {
    for (std::filesystem::path folder = dir; !folder.empty(); folder = folder.parent_path()) {
        std::error_code ec;
        const std::filesystem::file_status status = std::filesystem::status(folder, ec);
        if (!std::filesystem::exists(status)) {
            if (folder == folder.parent_path()) break;
            continue;
        }
        if (std::filesystem::is_directory(status)) return;
        const char* variable = std::getenv("CANOPY_CACHE_DIR");
        const bool from_variable = variable && *variable && dir == default_reference_cache_dir();
        throw ConfigError(folder, 0,
                          fmt::format("is a file, not a folder: the reference cache ({}) cannot be made there{}",
                                      dir.string(), from_variable ? " (CANOPY_CACHE_DIR names it)" : ""),
                          from_variable ? "set CANOPY_CACHE_DIR to a folder (or unset it for results/cache), or give "
                                          "--reference-cache DIR"
                                        : "give --reference-cache a folder, or --no-cache");
    }
}

}  // namespace canopy
