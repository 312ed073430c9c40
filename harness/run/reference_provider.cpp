#include "run/reference_provider.hpp"

#include "reference/reference_cache.hpp"

#include <cstdlib>

namespace canopy {

ReferenceProvider::ReferenceProvider(std::filesystem::path cache_dir, ReferenceSettings settings)
    : cache_dir_(std::move(cache_dir)), settings_(settings) {}

const ReferenceEntry& ReferenceProvider::get(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width,
                                             int height, const std::function<void(double)>& progress,
                                             const std::function<void(bool from_cache)>& started) {
    const std::string key = reference_cache_key(scene, meshes, width, height, settings_);
    if (auto it = entries_.find(key); it != entries_.end()) return it->second;

    ReferenceEntry entry;
    entry.key = key;
    if (!cache_dir_.empty()) {
        if (auto cached = load_cached_reference(cache_dir_, key)) {
            entry.images = std::move(*cached);
            entry.from_cache = true;
        }
    }
    if (started) started(entry.from_cache);
    if (!entry.from_cache) {
        entry.images = render_reference(scene, meshes, width, height, settings_, progress);
        if (!cache_dir_.empty()) {
            std::filesystem::create_directories(cache_dir_);
            store_reference(cache_dir_, key, entry.images);
        }
    }
    return entries_.emplace(key, std::move(entry)).first->second;
}

std::filesystem::path default_reference_cache_dir() {
    if (const char* dir = std::getenv("CANOPY_CACHE_DIR"); dir && *dir) return std::filesystem::path(dir) / "reference";
    return std::filesystem::path("results") / "cache" / "reference";
}

}  // namespace canopy
