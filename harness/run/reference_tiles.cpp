#include "run/reference_tiles.hpp"

#include "core/error.hpp"
#include "reference/reference_cache.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstring>

namespace canopy {

namespace fs = std::filesystem;

namespace {

PixelVisibilitySettings pixel_visibility_settings(const ReferenceSettings& settings) {
    PixelVisibilitySettings pv;  // its samples and seed stay fixed, as ReferenceProvider's
    pv.threads = settings.threads;
    return pv;
}

// Copies rows [band.begin, band.end) of `from` into `into`.
void copy_rows(const Image& from, Image& into, const RowBand& band) {
    for (int y = band.begin; y < band.end; ++y)
        std::memcpy(into.at(0, y), from.at(0, y), sizeof(float) * 4 * size_t(into.width));
}

}  // namespace

RowBand tile_rows(int height, size_t index, size_t count) {
    return RowBand{int(size_t(height) * index / count), int(size_t(height) * (index + 1) / count)};
}

std::string tile_key(const std::string& key, size_t index, size_t count) {
    return fmt::format("{}.tile-{}-of-{}", key, index + 1, count);
}

uint64_t render_reference_tile(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width, int height,
                               const ReferenceSettings& settings, size_t index, size_t count, const fs::path& dir,
                               const std::function<void(double)>& progress) {
    const RowBand band = tile_rows(height, index, count);
    ReferenceSettings tile_settings = settings;
    tile_settings.rows = band;
    PixelVisibilitySettings pv = pixel_visibility_settings(settings);
    const std::string key = reference_cache_key(scene, meshes, width, height, settings);
    const std::string pv_key = pixel_visibility_cache_key(scene, meshes, width, height, pv);
    pv.rows = band;
    const EmbreeScene embree(scene, meshes);
    ReferenceImages images = render_reference(scene, embree, width, height, tile_settings, [&](double f) {
        if (progress) progress(0.5 * f);
    });
    PixelVisibilityRender visibility = render_pixel_visibility(scene, embree, width, height, pv, [&](double f) {
        if (progress) progress(0.5 + 0.5 * f);
    });
    store_reference(dir, tile_key(key, index, count), images);
    store_pixel_visibility(dir, tile_key(pv_key, index, count), visibility);
    return images.shadow_rays + visibility.shadow_rays;
}

void merge_reference_tiles(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width, int height,
                           const ReferenceSettings& settings, size_t count, const fs::path& dir, const fs::path& cache_dir) {
    const PixelVisibilitySettings pv = pixel_visibility_settings(settings);
    const std::string key = reference_cache_key(scene, meshes, width, height, settings);
    const std::string pv_key = pixel_visibility_cache_key(scene, meshes, width, height, pv);
    ReferenceImages whole;
    whole.radiance = Image(width, height);
    whole.variance = Image(width, height);
    whole.visibility = Image(width, height);
    PixelVisibilityRender whole_visibility;
    whole_visibility.visibility = Image(width, height);
    std::vector<std::string> missing;
    for (size_t i = 0; i < count; ++i) {
        const std::optional<ReferenceImages> tile = load_cached_reference(dir, tile_key(key, i, count));
        const std::optional<PixelVisibilityRender> tile_visibility =
            load_cached_pixel_visibility(dir, tile_key(pv_key, i, count));
        if (!tile || !tile_visibility || tile->radiance.width != width || tile->radiance.height != height ||
            tile_visibility->visibility.width != width || tile_visibility->visibility.height != height) {
            missing.push_back(fmt::format("{}/{}", i + 1, count));
            continue;
        }
        const RowBand band = tile_rows(height, i, count);
        copy_rows(tile->radiance, whole.radiance, band);
        copy_rows(tile->variance, whole.variance, band);
        copy_rows(tile->visibility, whole.visibility, band);
        copy_rows(tile_visibility->visibility, whole_visibility.visibility, band);
        whole.seconds += tile->seconds;
        whole.shadow_rays += tile->shadow_rays;
        whole_visibility.seconds += tile_visibility->seconds;
        whole_visibility.shadow_rays += tile_visibility->shadow_rays;
    }
    if (!missing.empty())
        throw ConfigError(dir, 0,
                          fmt::format("{} of {} tiles of {} {}x{} are missing here or were rendered with other settings: "
                                      "{}",
                                      missing.size(), count, scene.name, width, height, fmt::join(missing, ", ")),
                          fmt::format("render them with `canopy reference SCENE --tile i/{} --out {}` and the same "
                                      "size and sample options",
                                      count, dir.string()));
    store_reference(cache_dir, key, whole);
    store_pixel_visibility(cache_dir, pv_key, whole_visibility);
}

}  // namespace canopy
