// Reference images are expensive, so they are cached on disk under a key that hashes every
// input that changes them. Files: <dir>/<key>.radiance.exr, <key>.variance.exr and
// <key>.visibility.exr for a reference, <key>.pixel_visibility.exr for a pixel-centre visibility
// (its own key: it does not depend on the reference's sample counts), 32-bit float RGBA EXR; the
// radiance and pixel-visibility files also record the key, the render's seconds and shadow-ray
// count as attributes (canopy:key, canopy:seconds, canopy:shadow_rays).
#pragma once

#include "reference/pixel_visibility.hpp"
#include "reference/reference_renderer.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace canopy {

// Bump whenever the reference's shading, sampling or image definitions change, so that stale
// cached images are never reused.
inline constexpr int kReferenceShadingVersion = 3;  // 3: visibility B = population coverage
// Likewise for the pixel-centre visibility (pixel_visibility.hpp).
inline constexpr int kPixelVisibilityVersion = 1;

// 16 hex digits: FNV-1a 64 over kReferenceShadingVersion, the resolution, light and pixel sample
// counts, seed, the camera, ambient, background, every light (all fields but `where`), and every
// object's material, casts_shadows, world matrix per instance and mesh vertices and indices.
// Names, file paths, source locations and the thread count do not change the image and are left out.
std::string reference_cache_key(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width, int height,
                                const ReferenceSettings& settings);

// The cached images for `key`, or nullopt when any file is missing, unreadable, of another key
// or of mismatched sizes (a miss, never an error).
std::optional<ReferenceImages> load_cached_reference(const std::filesystem::path& dir, const std::string& key);

// Writes the three images atomically: each goes to a temporary .exr in `dir` first and is then
// renamed into place, so readers never see a partial file. Creates `dir` if needed; throws
// std::runtime_error when writing fails.
void store_reference(const std::filesystem::path& dir, const std::string& key, const ReferenceImages& images);

// 16 hex digits: FNV-1a 64 over kPixelVisibilityVersion, the resolution, light sample count, seed,
// position in the pixel and the same scene content as reference_cache_key.
std::string pixel_visibility_cache_key(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width,
                                       int height, const PixelVisibilitySettings& settings);

// As load_cached_reference and store_reference, for a pixel-centre visibility.
std::optional<PixelVisibilityRender> load_cached_pixel_visibility(const std::filesystem::path& dir,
                                                                  const std::string& key);
void store_pixel_visibility(const std::filesystem::path& dir, const std::string& key,
                            const PixelVisibilityRender& render);

}  // namespace canopy
