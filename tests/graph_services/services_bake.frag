#version 450
// The load phase's pattern for mip 0 of one layer, integers the test recomputes exactly
// (bake_texel in tests/test_graph_services.cpp).
layout(push_constant) uniform Bake { uint layer; } bake;
layout(location = 0) out vec4 color;

void main() {
    const uvec2 p = uvec2(gl_FragCoord.xy);
    color = vec4(float(p.x) + 100.0 * float(bake.layer), float(p.y), float((p.x * p.y) % 7u), 1.0 + float(bake.layer));
}
