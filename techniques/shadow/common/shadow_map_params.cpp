#include "shadow_map_params.hpp"

namespace canopy {

std::vector<ParamSpec> shadow_map_params() {
    return {
        ParamSpec::integer("resolution", 1024, 16, 8192, "shadow-map width and height in texels"),
        ParamSpec::choice("depth_format", "d32f", {"d32f", "d16"}, "shadow-map depth format: 32-bit float or 16-bit unorm"),
        ParamSpec::real("bias_constant", 0.0005, 0.0, 0.05,
                        "constant depth bias as a fraction of the light's depth range"),
        ParamSpec::real("bias_slope", 1.0, 0.0, 16.0,
                        "slope-scaled bias: multiples of the receiver plane's depth change across one texel"),
    };
}

ShadowMapNeeds shadow_map_needs(const ParamSet& params) {
    ShadowMapNeeds needs;
    needs.resolution = uint32_t(params.integer("resolution"));
    needs.format = params.choice("depth_format") == "d16" ? DepthFormat::d16 : DepthFormat::d32f;
    return needs;
}

void write_bias_params(const ParamSet& params, ShaderParams& shader) {
    shader.values[0] = float(params.real("bias_constant"));
    shader.values[1] = float(params.real("bias_slope"));
}

}  // namespace canopy
