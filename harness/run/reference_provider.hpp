// The ray-traced reference of each (scene, resolution) an experiment needs, and its pixel-centre
// visibility: each loaded from the content-keyed cache when an identical one was rendered
// before, otherwise rendered and stored. The pixel-centre visibility is the same for every
// experiment's [reference] settings (its own fixed sample count and seed), so it is shared.
#pragma once

#include "reference/pixel_visibility.hpp"
#include "reference/reference_renderer.hpp"
#include "scene/geometry.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <string>

namespace canopy {

struct ReferenceEntry {
    ReferenceImages images;
    std::string key;
    bool from_cache = false;
    PixelVisibilityRender pixel_visibility;  // at the pixel centres, kPixelVisibilitySamples light samples
    std::string pixel_visibility_key;
    bool pixel_visibility_from_cache = false;
};

class ReferenceProvider {
public:
    // An empty cache_dir disables the cache (every reference is rendered).
    ReferenceProvider(std::filesystem::path cache_dir, ReferenceSettings settings);

    // `started` learns where a reference not yet in memory comes from (true: the cache, false:
    // ray-traced now, in part or whole), before any rendering; `progress` gets the fraction done
    // while a reference or its pixel visibility is rendered (not called on a cache hit).
    const ReferenceEntry& get(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width, int height,
                              const std::function<void(double)>& progress = {},
                              const std::function<void(bool from_cache)>& started = {});
    // The reference images alone, without the pixel-centre visibility (which would cost its 1024
    // light samples a pixel for area lights): e.g. one per frame of a camera path for popping.
    // Shares the cache and get()'s entries.
    const ReferenceImages& images(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width, int height,
                                  const std::function<void(double)>& progress = {});
    const ReferenceSettings& settings() const { return settings_; }
    const PixelVisibilitySettings& pixel_visibility_settings() const { return pixel_visibility_settings_; }

private:
    std::filesystem::path cache_dir_;
    ReferenceSettings settings_;
    PixelVisibilitySettings pixel_visibility_settings_;
    std::map<std::string, ReferenceEntry> entries_;  // by cache key
    std::map<std::string, ReferenceImages> images_;  // images() not also in entries_, by cache key
};

// Default cache folder: $CANOPY_CACHE_DIR, else results/cache/reference in the working directory.
std::filesystem::path default_reference_cache_dir();
// Before any work: throws ConfigError (exit 2) naming the path when the cache folder, or the
// nearest of its folders that exists, is a file (e.g. $CANOPY_CACHE_DIR set to one), not a folder.
void check_reference_cache_dir(const std::filesystem::path& dir);

}  // namespace canopy
