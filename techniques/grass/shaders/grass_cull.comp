#version 450
#extension GL_GOOGLE_include_directive : require
// The grass GPU cull (common/grass_cull.hpp), grass.geometry's and each of grass.lod's bands': one
// invocation per copy of the first grass population; a copy that may be seen within its block's
// distances (grass_culling.h) is appended to the survivors, and the draw's instance count grows by
// one (atomically). The arguments buffer was zeroed by a fill in this pass before the dispatch;
// invocation 0 writes the draw's other fields, which no other invocation touches.
#define FRAME_BINDING 0
#include "frame_uniforms.glsl"
#include "grass_culling.h"

layout(local_size_x = 64) in;

struct Copy {
    mat4 model;
    vec4 normal_matrix[3];
    vec4 data;
};

layout(set = 0, binding = 1, std140) uniform CullBlock { GrassCull cull; };
layout(set = 0, binding = 2, std430) readonly buffer Copies { Copy copies[]; };
layout(set = 0, binding = 3, std430) writeonly buffer Survivors { Copy survivors[]; };
layout(set = 0, binding = 4, std430) buffer Arguments {
    uint index_count;
    uint instance_count;
    uint first_index;
    int vertex_offset;
    uint first_instance;
} arguments;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i == 0u) {
        arguments.index_count = cull.draw.x;
        arguments.first_index = cull.draw.y;
        arguments.vertex_offset = int(cull.draw.z);
        arguments.first_instance = 0u;
    }
    if (i >= cull.draw.w) return;
    if (!grass_cell_visible(frame.view_proj, frame.camera_position.xyz, copies[i].model, cull.box_min.xyz,
                            cull.box_max.xyz, cull.distances.x, cull.distances.y))
        return;
    uint slot = atomicAdd(arguments.instance_count, 1u);
    survivors[slot] = copies[i];
}
