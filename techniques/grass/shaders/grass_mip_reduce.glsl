// One mip level of a baked grass slice array from the level above (common/mip_passes.hpp): each
// texel from the 2 x 2 it covers, as Vulkan's mips (an odd side's last texel is dropped, a side of
// one texel read twice), the same arithmetic as common/mip_chain.cpp's reduce:
// - the colour by the filter of choice (mip_filters.h): the box (filter 0) or the alpha-weighted
//   colour with the largest alpha (1: Boulanger's max-alpha; 2: Lemme's, rescaled after by
//   grass_mip_coverage.comp); filter 3 resolves a supersampled bake (mip_resolve: the covered
//   share, the alpha-weighted colour);
// - the blade map by its own rule (blade_texels.h: the threshold range, the roots' mean);
// - with GRASS_MIP_COMPANION, a companion array holding `per_layer` layers per colour layer (a
//   normal; a BTF slice's five lit rows, their alpha the light's visibility): each weighted by
//   the colour's coverage (the four's mean where none is covered).
// Invocation z runs over the colour's layers times per_layer; the first of each layer's writes its
// colour and blade map.
#include "mip_filters.h"
#include "blade_texels.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 1, rgba32f) uniform readonly image2DArray colour_in;
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2DArray colour_out;
layout(set = 0, binding = 5, rgba32f) uniform readonly image2DArray blades_in;
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2DArray blades_out;
#ifdef GRASS_MIP_COMPANION
layout(set = 0, binding = 3, rgba16f) uniform readonly image2DArray companion_in;
layout(set = 0, binding = 4, rgba16f) uniform writeonly image2DArray companion_out;
#endif
// x: filter, y: the colour's layers, z: companion layers per colour layer (1 without one)
layout(push_constant) uniform Reduce { ivec4 filter_layers; } reduce;

void main() {
    ivec2 out_size = imageSize(colour_out).xy;
    ivec3 id = ivec3(gl_GlobalInvocationID);
    int per_layer = max(reduce.filter_layers.z, 1);
    int layer = id.z / per_layer, row = id.z % per_layer;
    if (id.x >= out_size.x || id.y >= out_size.y || layer >= reduce.filter_layers.y) return;
    ivec2 in_size = imageSize(colour_in).xy;
    int x0 = min(2 * id.x, in_size.x - 1), x1 = min(2 * id.x + 1, in_size.x - 1);
    int y0 = min(2 * id.y, in_size.y - 1), y1 = min(2 * id.y + 1, in_size.y - 1);
    vec4 c0 = imageLoad(colour_in, ivec3(x0, y0, layer)), c1 = imageLoad(colour_in, ivec3(x1, y0, layer)),
         c2 = imageLoad(colour_in, ivec3(x0, y1, layer)), c3 = imageLoad(colour_in, ivec3(x1, y1, layer));
    if (row == 0) {
        ivec3 out_at = ivec3(id.xy, layer);
        int filter_kind = reduce.filter_layers.x;
        vec4 colour = filter_kind == 0 ? mip_box(c0, c1, c2, c3)
                    : filter_kind == 3 ? mip_resolve(c0, c1, c2, c3)
                                       : mip_max_alpha(c0, c1, c2, c3);
        imageStore(colour_out, out_at, colour);
        imageStore(blades_out, out_at,
                   blade_map_reduce(imageLoad(blades_in, ivec3(x0, y0, layer)), imageLoad(blades_in, ivec3(x1, y0, layer)),
                                    imageLoad(blades_in, ivec3(x0, y1, layer)), imageLoad(blades_in, ivec3(x1, y1, layer)),
                                    vec4(c0.w, c1.w, c2.w, c3.w)));
    }
#ifdef GRASS_MIP_COMPANION
    vec4 n0 = imageLoad(companion_in, ivec3(x0, y0, id.z)), n1 = imageLoad(companion_in, ivec3(x1, y0, id.z)),
         n2 = imageLoad(companion_in, ivec3(x0, y1, id.z)), n3 = imageLoad(companion_in, ivec3(x1, y1, id.z));
    imageStore(companion_out, id, mip_companion(n0, n1, n2, n3, vec4(c0.w, c1.w, c2.w, c3.w)));
#endif
}
