// The interface of a separable filter pass (FilterPass): one 1D pass over a 2D image.
// A filter shader includes this file and defines `vec4 filter_texel(ivec2 xy)`, reading its
// neighbours with `fetch`; edges clamp. Runs in 8x8 workgroups. Coarse-map filters may also
// read the frame uniforms; screen-space filters the frame uniforms, the depth shadow map and an
// auxiliary image (techniques/shadow/common/shadow_graph.hpp, FilterChainInputs); they must not use what their pass
// was not given.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D src;          // NEAREST
layout(set = 0, binding = 1) writeonly uniform image2D dst;  // no format qualifier: any float format

layout(push_constant) uniform FilterBlock {
    ivec2 direction;   // (1, 0) horizontal or (0, 1) vertical
    int radius;        // texels on each side
    int downsample;    // input texels per output texel in each axis (1: same size)
    ivec2 extent;      // output width, height
    ivec2 src_extent;  // input width, height
} filter_pass;

// The input texel `offset` steps along the pass's direction from output texel `xy` (for
// same-size passes), clamped to the input.
vec4 fetch(ivec2 xy, int offset) {
    ivec2 p = clamp(xy + offset * filter_pass.direction, ivec2(0), filter_pass.src_extent - 1);
    return texelFetch(src, p, 0);
}

// Input texel (dx, dy) of the block that output texel `xy` covers when downsampling.
vec4 fetch_block(ivec2 xy, int dx, int dy) {
    ivec2 p = clamp(xy * filter_pass.downsample + ivec2(dx, dy), ivec2(0), filter_pass.src_extent - 1);
    return texelFetch(src, p, 0);
}

vec4 filter_texel(ivec2 xy);

void main() {
    ivec2 xy = ivec2(gl_GlobalInvocationID.xy);
    if (xy.x >= filter_pass.extent.x || xy.y >= filter_pass.extent.y) return;
    imageStore(dst, xy, filter_texel(xy));
}
