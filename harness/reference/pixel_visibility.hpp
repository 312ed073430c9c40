// The reference's side of the technique-isolated error: per pixel, one camera ray through the
// pixel's centre (the rasteriser's sample point, scene/camera.hpp) and, at the surface it hits,
// the shadow light's irradiance-weighted visibility  V = integral(E V) / integral(E)  over the
// light (light_integrator.hpp), from a fixed, high number of stratified light samples. V is the
// quantity a raster technique's visibility stands for: the lit pass multiplies it into the
// light's irradiance. It does not depend on an experiment's [reference] sample counts, so masks
// drawn from it (umbra, penumbra, lit) hold still when those change.
#pragma once

#include "core/pixel_visibility.hpp"
#include "reference/embree_scene.hpp"
#include "reference/reference_settings.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <functional>

namespace canopy {

// Light samples per pixel for area lights: 32 x 32 strata. Across a straight edge's penumbra V is
// within 1.4e-3 RMS (6e-3 at most) of the closed form, an order below the techniques' visibility
// errors; the umbra (V <= 1e-3) is where no sample sees the light; the umbra, penumbra and lit
// classes change at 0.03 % of the pixels between 256 and 1024 samples (tests/test_pixel_visibility.cpp).
inline constexpr int kPixelVisibilitySamples = 1024;

struct PixelVisibilitySettings {
    int light_samples = kPixelVisibilitySamples;  // towards an area light (point-like lights: one ray)
    uint64_t seed = 1;
    int threads = 0;  // 0 = all cores; the image does not depend on it
    // Where each ray crosses its pixel, in pixel units from the pixel's top-left corner. The
    // rasteriser samples (0.5, 0.5); anything else is for showing that the two must agree.
    float position_in_pixel_x = 0.5f, position_in_pixel_y = 0.5f;
    RowBand rows;  // the whole image unless rendering a tile (reference_settings.hpp)
};

struct PixelVisibilityRender {
    Image visibility;  // core/pixel_visibility.hpp's layout: R = V or kNotLit, G = view depth, A = surface
    double seconds = 0;
    uint64_t shadow_rays = 0;
};

// Throws ConfigError for a camera or lights the reference cannot represent, std::invalid_argument
// for an empty size or fewer than one light sample. Without a shadow-casting light every V is
// kNotLit. `progress` as render_reference's.
PixelVisibilityRender render_pixel_visibility(const Scene& scene, const EmbreeScene& embree, int width, int height,
                                              const PixelVisibilitySettings& settings,
                                              const std::function<void(double)>& progress = {});

}  // namespace canopy
