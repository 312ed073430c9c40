#version 450
// State carried from frame to frame in a persistent buffer: frames seen, and the sum of their indices.
layout(local_size_x = 1) in;
layout(std430, set = 0, binding = 0) buffer Counter { uint frames; uint index_sum; } counter;
layout(push_constant) uniform Frame { uint index; } this_frame;

void main() {
    counter.frames += 1u;
    counter.index_sum += this_frame.index;
}
