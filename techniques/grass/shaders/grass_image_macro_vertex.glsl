// The image's vertex stage over macro-cells (grass.image with macro_cells, and grass.lod's far
// band under culling = "quadtree"; Lemme §6.2): one horizontal quad over a macro-cell's cells
// (fewer at the field's far edges), unmirrored; the fragment stage finds each point's cell.
// Included after the technique's parameter block.
#include "frame_uniforms.glsl"
#include "grass_macro_cells.h"

layout(set = 0, binding = 3, std140) uniform FieldBlock { GrassMacroField field; };

layout(location = 0) in vec4 quad_position;  // x, z: the corner in [0, 1]; y: the slice's height (patch units)
layout(location = 1) in vec4 quad_uv;
layout(location = 2) in uvec4 macro_record;  // per instance: first cell x, z; span x, z

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec2 field_uv;        // field coordinates: one unit a cell
layout(location = 2) flat out ivec4 macro_cells;  // first cell x, z; span x, z

void main() {
    vec4 macro = vec4(macro_record);
    vec2 u = macro.xy + quad_position.xz * macro.zw;
    vec3 world = field.origin_size.xyz + vec3(u.x, quad_position.y, u.y) * field.origin_size.w;
    world_position = world;
    field_uv = u;
    macro_cells = ivec4(macro);
    gl_Position = frame.view_proj * vec4(world, 1.0);
}
