// How grass.billboard bakes the patch (GLSL and C++): an orthographic view of the patch along z
// (layer 0, the image on the quad in the patch's xy plane) or along x (layer 1, the zy quad),
// framing the prototype's bounds, and the quads that show the images. One struct for the bake
// pass's uniform block and the C++ that fills it.
#ifndef CANOPY_GRASS_BILLBOARD_BAKE_H
#define CANOPY_GRASS_BILLBOARD_BAKE_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

// A baked texel's alpha channel holds the density threshold of the blade it shows; texels that
// show no blade hold this, which no density reaches, so the billboard cuts them away.
CANOPY_CONST float BILLBOARD_EMPTY = 2.0f;

struct BillboardBake {
    mat4 view_proj;      // patch space -> the layer's clip space
    vec4 toward_viewer;  // unit: the side of a two-sided blade the bake sees
};

// One vertex of the billboard quads, patch space: xyz, w = the image layer; uv in the image
// (v = 0 at the top row, the quad's top).
struct BillboardVertex {
    vec4 position;
    vec4 uv;
};

CANOPY_END_NAMESPACE

#endif
