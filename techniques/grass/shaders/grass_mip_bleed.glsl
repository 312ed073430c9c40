// Lemme's colour bleeding (eq 4.16) on one level of a baked grass slice array, once the level below
// it is bled (common/mip_passes.hpp runs the levels from the smallest up, as mip_chain.cpp does):
// a texel's transparent part takes the next level's colour (nearest texel), and a blade map texel
// that shows no blade the next level's (blade_map_bleed), so trilinear lookups at a blade's edge
// mix blades' colours and thresholds, not the clear colour's. With GRASS_MIP_COMPANION the
// companion layers (grass_mip_reduce.glsl) bleed as the colour does, by its alpha. Push constant
// x: 1 to bleed the colour and companion too, 0 for the blade map alone (mip_bleed = false).
#include "mip_filters.h"
#include "blade_texels.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 1, rgba32f) uniform image2DArray colour;
layout(set = 0, binding = 2, rgba32f) uniform readonly image2DArray colour_next;
layout(set = 0, binding = 5, rgba32f) uniform image2DArray blades;
layout(set = 0, binding = 6, rgba32f) uniform readonly image2DArray blades_next;
#ifdef GRASS_MIP_COMPANION
layout(set = 0, binding = 3, rgba16f) uniform image2DArray companion;
layout(set = 0, binding = 4, rgba16f) uniform readonly image2DArray companion_next;
#endif
// x: bleed the colour, y: the colour's layers, z: companion layers per colour layer (1 without one)
layout(push_constant) uniform Bleed { ivec4 colour_layers; } bleed;

void main() {
    ivec2 size = imageSize(colour).xy;
    ivec3 id = ivec3(gl_GlobalInvocationID);
    int per_layer = max(bleed.colour_layers.z, 1);
    int layer = id.z / per_layer, row = id.z % per_layer;
    if (id.x >= size.x || id.y >= size.y || layer >= bleed.colour_layers.y) return;
    ivec2 next_size = imageSize(colour_next).xy;
    ivec2 q = ivec2(min(id.x / 2, next_size.x - 1), min(id.y / 2, next_size.y - 1));
    ivec3 at = ivec3(id.xy, layer);
    float alpha = imageLoad(colour, at).w;
#ifdef GRASS_MIP_COMPANION
    if (bleed.colour_layers.x != 0)
        imageStore(companion, id, mip_bleed_companion(imageLoad(companion, id), alpha, imageLoad(companion_next, ivec3(q, id.z))));
#endif
    if (row != 0) return;
    if (bleed.colour_layers.x != 0) imageStore(colour, at, mip_bleed(imageLoad(colour, at), imageLoad(colour_next, ivec3(q, layer))));
    imageStore(blades, at, blade_map_bleed(imageLoad(blades, at), imageLoad(blades_next, ivec3(q, layer))));
}
