// The image's vertex stage over macro-cells (grass.image with macro_cells, and grass.lod's far
// band under culling = "quadtree"; Lemme §6.2): one horizontal quad over a macro-cell's cells
// (fewer at the field's far edges), unmirrored; the fragment stage finds each point's cell.
// Included after the technique's parameter block.
//
// With GRASS_MACRO_TERRAIN (grass.image's macro-cells on a terrain), Lemme's displacement of
// image-based patches (L902): the quad's four corners are lifted onto the field's grid heights
// and the height between them is interpolated; the setup split the macro-cells whose ground is
// not flat enough (macro_instances_on_terrain). The quad is then split along the ground's own
// diagonal ((1, 0)-(0, 1), height_field.h), so a one-cell macro-cell runs parallel to its
// ground's two triangles as grass.image's per-cell quad does. A flat field draws as before.
#include "frame_uniforms.glsl"
#include "grass_macro_cells.h"

layout(set = 0, binding = 3, std140) uniform FieldBlock { GrassMacroField field; };
#ifdef GRASS_MACRO_TERRAIN
#include "height_field.h"
#include "grass_field_heights.glsl"
#endif

layout(location = 0) in vec4 quad_position;  // x, z: the corner in [0, 1]; y: the slice's height (patch units)
layout(location = 1) in vec4 quad_uv;
layout(location = 2) in uvec4 macro_record;  // per instance: first cell x, z; span x, z

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec2 field_uv;        // field coordinates: one unit a cell
layout(location = 2) flat out ivec4 macro_cells;  // first cell x, z; span x, z

void main() {
    vec4 macro = vec4(macro_record);
    vec2 corner = quad_position.xz;
    float lift = 0.0;
#ifdef GRASS_MACRO_TERRAIN
    ivec2 first = ivec2(macro_record.xy), last = first + ivec2(macro_record.zw);
    vec4 heights = vec4(grid_height(first), grid_height(ivec2(last.x, first.y)), grid_height(ivec2(first.x, last.y)),
                        grid_height(last));
    if (heights != vec4(0.0)) corner.x = 1.0 - corner.x;  // the buffer's (0, 0)-(1, 1) split reflected
    lift = mix(mix(heights.x, heights.y, corner.x), mix(heights.z, heights.w, corner.x), corner.y);
#endif
    vec2 u = macro.xy + corner * macro.zw;
    vec3 world = field.origin_size.xyz + vec3(u.x, quad_position.y, u.y) * field.origin_size.w + vec3(0.0, lift, 0.0);
    world_position = world;
    field_uv = u;
    macro_cells = ivec4(macro);
    gl_Position = frame.view_proj * vec4(world, 1.0);
}
