// What every technique of the shadow family shares: it keeps the scene's surfaces (the camera
// sees the same primary hits as the reference's pixel-centre rays) and computes only the shadow
// light's visibility, which canopy's lit pass multiplies into the light's irradiance. So the
// technique-isolated visibility error and the shadow-region errors both measure its shadow.
#pragma once

#include "core/error_columns.hpp"

#include <string>
#include <vector>

namespace canopy {

inline constexpr ErrorColumns kShadowErrorColumns{.visibility = true, .shadow_regions = true};

// The Pareto fronts' default error axes (report/pareto.hpp): the technique-isolated visibility
// error (the shadow alone, silhouettes and shading left out) and the luminance error in the
// reference's penumbrae, where the filters differ.
inline std::vector<std::string> shadow_pareto_errors() { return {"visibility_rmse", "penumbra_rmse"}; }

}  // namespace canopy
