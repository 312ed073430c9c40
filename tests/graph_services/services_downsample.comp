#version 450
// One mip of every layer from the mip above it: the mean of each 2x2 block.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba32f) uniform readonly image2DArray source;
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2DArray target;

void main() {
    const ivec3 size = imageSize(target);
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    const int layer = int(gl_GlobalInvocationID.z);
    if (any(greaterThanEqual(p, size.xy)) || layer >= size.z) return;
    const ivec2 s = 2 * p;
    const vec4 sum = imageLoad(source, ivec3(s, layer)) + imageLoad(source, ivec3(s + ivec2(1, 0), layer)) +
                     imageLoad(source, ivec3(s + ivec2(0, 1), layer)) + imageLoad(source, ivec3(s + ivec2(1, 1), layer));
    imageStore(target, ivec3(p, layer), 0.25 * sum);
}
