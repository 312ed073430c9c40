// Per-draw push constants of scene passes. Must match canopy::DrawConstants.
layout(push_constant) uniform DrawBlock {
    mat4 model;
    vec4 normal_matrix[3];     // columns of the inverse-transpose of mat3(model)
    vec4 albedo;               // rgb; w: the surface's transmission (FamilyPopulation::transmission; 0 for objects)
} draw;
