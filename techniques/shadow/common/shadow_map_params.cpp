#include "shadow_map_params.hpp"

namespace canopy {

ShadowMapNeeds shadow_map_needs(const ParamSet& params) {
    ShadowMapNeeds needs;
    needs.resolution = uint32_t(params.integer("resolution"));
    needs.format = params.choice("depth_format") == "d16" ? DepthFormat::d16 : DepthFormat::d32f;
    return needs;
}

}  // namespace canopy
