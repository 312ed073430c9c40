#version 450
// TEST-ONLY ballast (run/test_ballast.hpp): a known amount of GPU work, `iterations` dependent
// multiply-adds per invocation, one invocation per pixel, written out so nothing is optimised away.
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) buffer Sink { float values[]; } sink;
layout(push_constant) uniform Work { uint iterations; uint count; } work;

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= work.count) return;
    float x = float(i & 1023u) * 1e-3;
    for (uint k = 0u; k < work.iterations; ++k) x = x * 0.999 + 0.001;
    sink.values[i] = x;
}
