// The volume's vertex stage over macro-cells (grass.volume with macro_cells, and grass.lod's middle
// band under culling = "quadtree"): one carrier cuboid over a macro-cell's cells (fewer at the
// field's far edges), unmirrored, its q space the unit cube over the whole macro-cell. Only the
// faces a ray leaves by are kept, as for one cell (grass_volume_vertex.glsl). Included after the
// technique's parameter block.
//
// With GRASS_MACRO_TERRAIN (a field on a terrain, Lemme eq 6.14 for a macro-cell), the cuboid
// reaches from the lowest grid height under the macro-cell to the patch's height over its
// highest, as one cell's does from its corners (grass_volume_vertex.glsl); the setup or the
// quadtree pass writes that range per drawn macro-cell.
#include "frame_uniforms.glsl"
#include "grass_macro_cells.h"

layout(set = 0, binding = 3, std140) uniform FieldBlock { GrassMacroField field; };
#ifdef GRASS_MACRO_TERRAIN
// Per macro-cell in draw order: its grid vertices' lowest and highest height above the field's origin.
layout(set = 0, binding = 6, std430) readonly buffer MacroRanges { vec2 macro_ranges[]; };
#endif

layout(location = 0) in vec4 corner;      // q space: a corner of the unit cube
layout(location = 1) in vec4 face_plane;  // outward normal xyz; w: dot(normal, q) on the face
layout(location = 2) in uvec4 macro_record;  // per instance: first cell x, z; span x, z

layout(location = 0) out vec3 exit_q;
layout(location = 1) flat out vec3 eye_q;
layout(location = 2) flat out ivec4 macro_cells;
#ifdef GRASS_MACRO_TERRAIN
layout(location = 3) flat out vec2 heights;  // the cuboid's bottom above the field's origin and its height, world
#endif

void main() {
    vec4 macro = vec4(macro_record);
    float size = field.origin_size.w;
    vec3 origin = field.origin_size.xyz + vec3(macro.x, 0.0, macro.y) * size;
    vec3 extent = vec3(macro.z, field.patch_top.x, macro.w) * size;
#ifdef GRASS_MACRO_TERRAIN
    vec2 range = macro_ranges[gl_InstanceIndex];
    origin.y += range.x;
    extent.y += range.y - range.x;
    heights = vec2(range.x, extent.y);
#endif
    exit_q = corner.xyz;
    eye_q = (frame.camera_position.xyz - origin) / extent;
    macro_cells = ivec4(macro);
    bool entry_face = dot(face_plane.xyz, eye_q) > face_plane.w;
    gl_Position = entry_face ? vec4(2.0, 2.0, 2.0, 1.0) : frame.view_proj * vec4(origin + corner.xyz * extent, 1.0);
}
