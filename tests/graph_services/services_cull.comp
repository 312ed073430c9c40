#version 450
// Culls quads by their value and appends each survivor's six indices and one
// VkDrawIndexedIndirectCommand; `count` (reset to 0 before the dispatch) ends as the draw count.
layout(local_size_x = 64) in;

struct DrawIndexedIndirect {  // VkDrawIndexedIndirectCommand, 20 bytes in std430
    uint index_count;
    uint instance_count;
    uint first_index;
    int vertex_offset;
    uint first_instance;
};
layout(std430, set = 0, binding = 0) readonly buffer Values { float values[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Arguments { DrawIndexedIndirect arguments[]; };
layout(std430, set = 0, binding = 3) buffer Count { uint count; };
layout(push_constant) uniform Cull { uint quad_count; float threshold; } cull;

void main() {
    const uint quad = gl_GlobalInvocationID.x;
    if (quad >= cull.quad_count || values[quad] < cull.threshold) return;
    const uint slot = atomicAdd(count, 1u);
    const uint first = 6u * slot, v = 4u * quad;
    indices[first + 0u] = v;
    indices[first + 1u] = v + 1u;
    indices[first + 2u] = v + 2u;
    indices[first + 3u] = v;
    indices[first + 4u] = v + 2u;
    indices[first + 5u] = v + 3u;
    arguments[slot] = DrawIndexedIndirect(6u, 1u, first, 0, 0u);
}
