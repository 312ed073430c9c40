// default_reference_cache_dir (run/reference_provider.hpp): apart from the provider, which a
// timing-only build replaces (timing_only/timing_only.hpp), since every run names the folder.
#include "run/reference_provider.hpp"

#include <cstdlib>

namespace canopy {

std::filesystem::path default_reference_cache_dir() {
    if (const char* dir = std::getenv("CANOPY_CACHE_DIR"); dir && *dir) return std::filesystem::path(dir) / "reference";
    return std::filesystem::path("results") / "cache" / "reference";
}

}  // namespace canopy
