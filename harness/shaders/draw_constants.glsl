// Per-draw push constants of scene passes. Must match canopy::DrawConstants.
layout(push_constant) uniform DrawBlock {
    mat4 model;
    vec4 normal_matrix[3];     // columns of the inverse-transpose of mat3(model)
    vec4 albedo;               // rgb
} draw;
