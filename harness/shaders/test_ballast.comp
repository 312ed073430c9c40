#version 450
// TEST-ONLY ballast (run/test_ballast.hpp): a known amount of GPU work, `iterations` rounds of a
// xorshift generator per invocation, one invocation per pixel, written out. (A float
// multiply-add chain is folded away by the shader compiler; a xorshift cannot be.)
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) buffer Sink { uint values[]; } sink;
layout(push_constant) uniform Work { uint iterations; uint count; } work;

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= work.count) return;
    uint h = i * 2654435761u + 1u;
    for (uint k = 0u; k < work.iterations; ++k) {
        h ^= h << 13;
        h ^= h >> 17;
        h ^= h << 5;
    }
    sink.values[i] = h;
}
