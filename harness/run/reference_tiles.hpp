// A reference too large for one job, rendered as row bands ("tiles") by separate processes
// (`canopy reference --tile i/N`) and put together (`--merge-tiles N`) into the reference cache,
// where runs then find it. Every pixel is computed from its own rays and samples
// (reference_settings.hpp, RowBand), so the merged images equal a whole render's bit for bit.
#pragma once

#include "reference/reference_settings.hpp"
#include "scene/geometry.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace canopy {

// Tile `index` (from 0) of `count`: rows [index * height / count, (index + 1) * height / count).
RowBand tile_rows(int height, size_t index, size_t count);

// The name a tile's files take in its folder: "<cache key>.tile-<i>-of-<N>" (i from 1).
std::string tile_key(const std::string& key, size_t index, size_t count);

// Renders the reference and the pixel-centre visibility of tile `index` of `count` (only its rows)
// and writes them into `dir` as the cache would (reference_cache.hpp) under tile_key names.
// Returns the shadow rays traced.
uint64_t render_reference_tile(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width, int height,
                               const ReferenceSettings& settings, size_t index, size_t count,
                               const std::filesystem::path& dir, const std::function<void(double)>& progress = {});

// Reads the `count` tiles from `dir`, puts each one's rows in place and stores the whole images in
// `cache_dir` under their cache keys. Throws ConfigError naming the tiles that are missing or of
// other settings (their keys differ).
void merge_reference_tiles(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width, int height,
                           const ReferenceSettings& settings, size_t count, const std::filesystem::path& dir,
                           const std::filesystem::path& cache_dir);

}  // namespace canopy
