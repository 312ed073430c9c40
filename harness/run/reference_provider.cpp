#include "run/reference_provider.hpp"

#include "reference/reference_cache.hpp"

#include <chrono>
#include <cstdlib>
#include <optional>

namespace canopy {

ReferenceProvider::ReferenceProvider(std::filesystem::path cache_dir, ReferenceSettings settings)
    : cache_dir_(std::move(cache_dir)), settings_(settings) {
    pixel_visibility_settings_.threads = settings.threads;  // its samples and seed stay fixed
}

const ReferenceEntry& ReferenceProvider::get(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width,
                                             int height, const std::function<void(double)>& progress,
                                             const std::function<void(bool from_cache)>& started) {
    const std::string key = reference_cache_key(scene, meshes, width, height, settings_);
    if (auto it = entries_.find(key); it != entries_.end()) return it->second;

    ReferenceEntry entry;
    entry.key = key;
    entry.pixel_visibility_key =
        pixel_visibility_cache_key(scene, meshes, width, height, pixel_visibility_settings_);
    if (!cache_dir_.empty()) {
        if (auto cached = load_cached_reference(cache_dir_, key)) {
            entry.images = std::move(*cached);
            entry.from_cache = true;
        }
        if (auto cached = load_cached_pixel_visibility(cache_dir_, entry.pixel_visibility_key);
            cached && cached->visibility.width == width && cached->visibility.height == height) {
            entry.pixel_visibility = std::move(*cached);
            entry.pixel_visibility_from_cache = true;
        }
    }
    if (started) started(entry.from_cache && entry.pixel_visibility_from_cache);
    if (!entry.from_cache || !entry.pixel_visibility_from_cache) {
        const auto start = std::chrono::steady_clock::now();
        const EmbreeScene embree(scene, meshes);  // one BVH for both renders
        const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        // Progress over both renders, weighted by the light samples each takes per pixel.
        const double reference_share =
            entry.from_cache ? 0.0
            : entry.pixel_visibility_from_cache
                ? 1.0
                : double(settings_.light_samples) * settings_.pixel_samples /
                      (double(settings_.light_samples) * settings_.pixel_samples + pixel_visibility_settings_.light_samples);
        if (!entry.from_cache) {
            entry.images = render_reference(scene, embree, width, height, settings_, [&](double fraction) {
                if (progress) progress(reference_share * fraction);
            });
            entry.images.seconds += build_seconds;
            if (!cache_dir_.empty()) store_reference(cache_dir_, key, entry.images);
        }
        if (!entry.pixel_visibility_from_cache) {
            entry.pixel_visibility = render_pixel_visibility(
                scene, embree, width, height, pixel_visibility_settings_,
                [&](double fraction) {
                    if (progress) progress(reference_share + (1.0 - reference_share) * fraction);
                });
            if (!cache_dir_.empty()) store_pixel_visibility(cache_dir_, entry.pixel_visibility_key, entry.pixel_visibility);
        }
    }
    return entries_.emplace(key, std::move(entry)).first->second;
}

const ReferenceImages& ReferenceProvider::images(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width,
                                                 int height, const std::function<void(double)>& progress) {
    const std::string key = reference_cache_key(scene, meshes, width, height, settings_);
    if (auto it = entries_.find(key); it != entries_.end()) return it->second.images;
    if (auto it = images_.find(key); it != images_.end()) return it->second;
    std::optional<ReferenceImages> cached;
    if (!cache_dir_.empty()) cached = load_cached_reference(cache_dir_, key);
    if (!cached) {
        cached = render_reference(scene, meshes, width, height, settings_, progress);
        if (!cache_dir_.empty()) store_reference(cache_dir_, key, *cached);
    }
    return images_.emplace(key, std::move(*cached)).first->second;
}

}  // namespace canopy
