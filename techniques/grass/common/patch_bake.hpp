// The orthographic cameras grass techniques bake their patch with at load (shaders/patch_bake.h,
// shaders/patch_bake.vert), framing the prototype's bounds, and the prototype they bake.
#pragma once

#include "scene/generated_population.hpp"
#include "scene/geometry.hpp"

#include "../shaders/patch_bake.h"

#include <cstdint>
#include <span>

namespace canopy::grass {

// Which way the bake camera looks, and how the image's (u, v) map to patch space (v = 0 is the
// image's first row):
//   along_z: looking along -z; u = x, v = 1 - y / top (the first row at the blades' top)
//   along_x: looking along -x; u = z, v = 1 - y / top
//   down:    looking along -y from above; u = x, v = z
enum class BakeView { along_z, along_x, down };

// What a bake frames of the prototype's `bounds`: y from 0 (the ground) to the top, and every
// side at least 1e-4 long, so a flat prototype still frames. The quads that show a bake span it.
Bounds bake_frame(const Bounds& bounds);

// What a tiled bake frames (PatchBake::tiles): the cell, x and z in [0, 1], y from 0 to the
// prototype's top (at least 1e-4): blades leaning out of the cell are cut at its edges, and those
// of the 8 neighbouring copies leaning in are drawn, so the bake repeats without seams.
Bounds cell_frame(const Bounds& bounds);

// The camera framing bake_frame(bounds) (patch space), or, `tiled`, cell_frame(bounds) with the
// patch's 8 neighbours drawn too.
shader::PatchBake ortho_bake(const Bounds& bounds, BakeView view, bool tiled = false);

// The same camera framing any `frame` (patch space), e.g. a light's (light_frame).
shader::PatchBake ortho_bake_over(const Bounds& frame, BakeView view, bool tiled);

// `bake` seen from the other side along `axis` (0 x, 1 y, 2 z): the same image coordinates, depth
// reversed, toward_viewer turned round.
void reverse_bake_depth(shader::PatchBake& bake, int axis);

// Baked light `row` (btf_light_direction's order: Y+, X+, Z+, X-, Z-): the axis it lies along (0 x,
// 1 y, 2 z).
int light_axis(uint32_t row);

// What a shadowed bake's light view `row` frames: tiled, the cell and `margin` around it across the
// light (its rays keep those coordinates, so no other blade can shadow the cell), and along it as
// far as the 8 neighbours reach (x or z in [-1, 2]; y from 0 to the prototype's top); alone,
// bake_frame(bounds).
Bounds light_frame(const Bounds& bounds, uint32_t row, bool tiled, float margin);

// The camera of baked light `row`: looking along -L over light_frame, depth 0 on the light's side.
// Tiled, it draws the 9 copies.
shader::PatchBake light_bake(const Bounds& bounds, uint32_t row, bool tiled, float margin);

// light_bake's view_proj with its depth moved `bias` (patch units) towards the light: what a bake
// fragment compares its own depth with (bake_shadows.h's lookup).
glm::mat4 light_lookup(const Bounds& bounds, uint32_t row, bool tiled, float margin, float bias);

// Where section k of n along `axis` (0 x, 2 z) of the baked frame begins; k = n is where the last
// ends. Tiled, the sections split the cell exactly: what lies beyond is a neighbouring copy's,
// which that cell's own slices show. Alone, the outer sections reach past the frame (+-1e30), so a
// blade on its edge belongs to one of them.
float bake_section_start(const Bounds& frame, int axis, uint32_t k, uint32_t n, bool tiled);

// What a bake frames: cell_frame(bounds) when tiled, else bake_frame(bounds).
inline Bounds baked_frame(const Bounds& bounds, bool tiled) { return tiled ? cell_frame(bounds) : bake_frame(bounds); }

// The first population of kind "grass" (what the bakes draw), or nullptr.
const GeneratedPopulation* first_grass(std::span<const GeneratedPopulation> populations);

// Whether a grass population stands on a terrain: geometry drawn over every copy that follows the
// ground is then made for it (grass.slices' cut quads), whichever population it is drawn over.
bool grass_on_terrain(std::span<const GeneratedPopulation> populations);

// Its prototype's bounds; the unit cube when there is none, so a scene without grass still bakes
// (an empty image).
Bounds prototype_bounds(const GeneratedPopulation* population);

}  // namespace canopy::grass
