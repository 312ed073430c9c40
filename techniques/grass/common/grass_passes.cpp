#include "grass_passes.hpp"

#include "shaders/grass/grass_ground_frag.h"
#include "shaders/harness/scene_vert.h"

namespace canopy::grass {

RasterState ground_state() {
    RasterState s;
    s.vertex_spirv = scene_vert;
    s.fragment_spirv = grass_ground_frag;
    return s;
}

}  // namespace canopy::grass
