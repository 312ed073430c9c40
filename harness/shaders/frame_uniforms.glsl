// The per-frame uniform block every pass sees (binding 0 in scene passes; compute filters
// define FRAME_BINDING to where they bind it). Must match canopy::FrameUniforms.
#ifndef FRAME_BINDING
#define FRAME_BINDING 0
#endif
// The technique's parameter struct (harness/shaders/param_block.h); its params header names it.
#ifndef TECHNIQUE_PARAMS
struct NoTechniqueParams { float unused; };  // passes that read no technique parameters
#define TECHNIQUE_PARAMS NoTechniqueParams
#endif
layout(set = 0, binding = FRAME_BINDING, std140) uniform FrameBlock {
    mat4 view_proj;            // world -> camera clip
    mat4 view;                 // world -> camera view space (looking down -z)
    mat4 inverse_view_proj;    // camera clip -> world
    mat4 light_view;           // world -> light view space (looking down -z)
    mat4 light_proj;           // light view -> light clip
    vec4 camera_position;      // xyz
    vec4 viewport;             // x = width, y = height (pixels), z = vertical focal length in pixels
    vec4 light_position;       // xyz; w = light type (LIGHT_* in shading.h)
    vec4 light_axis;           // xyz = direction the light travels / faces; w = cos of spot half-angle
    vec4 light_intensity;      // rgb = colour * intensity (W/sr, or W/m^2 for directional)
    vec4 light_size;           // x = size in world units (rect diagonal, sphere diameter), y = width, z = height/radius
    vec4 ambient;              // rgb
    vec4 shadow_depth_range;   // x = near, y = far, z = 1 / (far - near), w = 1 perspective / 0 orthographic
    vec4 shadow_texel;         // x = resolution, y = 1 / resolution, z = world texel size at view depth 1 (persp.) or absolute (ortho)
    vec4 sample_offsets[64];   // technique-defined vec2 table, two per vec4 (ShaderParams::offsets)
    TECHNIQUE_PARAMS technique;  // ShaderParams::block; last, so each technique's size may differ
} frame;
