// The image the technique-isolated error compares: per pixel, what the surface seen through the
// pixel's centre receives from the shadow light. The raster lit pass (FrameRenderer::
// read_pixel_visibility) and the reference (render_pixel_visibility) each produce one, so a
// technique's visibility is compared with the truth at the same primary hits.
#pragma once

#include "core/image.hpp"
#include "lit_pass_output.h"

namespace canopy::pixel_visibility {

// Channels of a pixel-visibility Image.
inline constexpr int kVisibility = 0;  // R: the shadow light's visibility in [0, 1], or kNotLit
inline constexpr int kViewDepth = 1;   // G: the surface's distance along the camera's view axis; 0 without one
inline constexpr int kSurface = 3;     // A: 1 where the pixel centre sees a surface, 0 where it sees the background
// B: the population coverage, the fraction of the pixel the scene's populations (grass blades)
// cover. The raster's is its colour target's alpha, which means coverage for a family that
// declares ErrorColumns::coverage (and visibility, R, for one that declares visibility: a family's
// alpha carries one or the other). The reference's pixel-centre image holds 0 here; its coverage
// over the pixel's samples is ReferenceImages::visibility's B (metrics/coverage_error.hpp).
inline constexpr int kCoverage = 2;

// Where the light does not reach the surface (it faces away, lies outside a spot's cone) or
// there is none. The raster's test is at the light's centre (the lit pass's); the reference's is
// "any of the light's samples carries irradiance".
inline constexpr float kNotLit = shader::VISIBILITY_NOT_LIT;

inline bool has_surface(const Image& image, int x, int y) { return image.at(x, y)[kSurface] >= 0.5f; }
inline bool is_lit(const Image& image, int x, int y) { return image.at(x, y)[kVisibility] >= 0.0f; }

}  // namespace canopy::pixel_visibility
