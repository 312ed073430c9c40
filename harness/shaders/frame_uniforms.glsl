// The per-frame uniform block and per-draw push constants every pass sees.
// Must match canopy::FrameUniforms and canopy::DrawConstants (render/frame_uniforms.hpp).
layout(set = 0, binding = 0, std140) uniform FrameBlock {
    mat4 view_proj;            // world -> camera clip
    mat4 light_view;           // world -> light view space (looking down -z)
    mat4 light_proj;           // light view -> light clip
    vec4 camera_position;      // xyz
    vec4 light_position;       // xyz; w = light type (LIGHT_* in shading.h)
    vec4 light_axis;           // xyz = direction the light travels / faces; w = cos of spot half-angle
    vec4 light_intensity;      // rgb = colour * intensity (W/sr, or W/m^2 for directional)
    vec4 light_size;           // x = size in world units (rect diagonal, sphere diameter), y = width, z = height/radius
    vec4 ambient;              // rgb
    vec4 shadow_depth_range;   // x = near, y = far, z = 1 / (far - near), w = 1 perspective / 0 orthographic
    vec4 shadow_texel;         // x = resolution, y = 1 / resolution, z = world texel size at view depth 1 (persp.) or absolute (ortho)
    vec4 technique_params[4];  // technique-defined (ShaderParams::values)
    vec4 sample_offsets[64];   // technique-defined vec2 table, two per vec4 (ShaderParams::offsets)
} frame;

layout(push_constant) uniform DrawBlock {
    mat4 model;
    vec4 normal_matrix[3];     // columns of the inverse-transpose of mat3(model)
    vec4 albedo;               // rgb
} draw;
