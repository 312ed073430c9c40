// What every technique of the shadow family shares: it keeps the scene's surfaces (the camera
// sees the same primary hits as the reference's pixel-centre rays) and computes only the shadow
// light's visibility, which canopy's lit pass multiplies into the light's irradiance. So the
// technique-isolated visibility error and the shadow-region errors both measure its shadow.
#pragma once

#include "core/error_columns.hpp"

namespace canopy {

inline constexpr ErrorColumns kShadowErrorColumns{.visibility = true, .shadow_regions = true};

}  // namespace canopy
