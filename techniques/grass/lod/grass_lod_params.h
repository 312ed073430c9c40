// grass.lod's parameters, written once for C++ and GLSL (harness/shaders/param_block.h). The
// representations' own parameters keep the names they have in grass.geometry, grass.volume and
// grass.image, since grass.lod's shaders are compiled from the same bodies.
#ifndef CANOPY_GRASS_LOD_PARAMS_H
#define CANOPY_GRASS_LOD_PARAMS_H

#include "param_block.h"
#include "../shaders/blade_coverage.h"
#include "../shaders/slice_filtering_params.h"

#define GRASS_LOD_PARAMS(SHADER, PLAN, DERIVED)                                                              \
    SHADER(real, geometry_full, (5.0, 0.0, 1e6),                                                             \
           "distance up to which a cell is all blades (Boulanger's minGeom; Lemme's football field: level 1 begins at 5 m)") \
    SHADER(real, geometry_none, (20.0, 0.0, 1e6),                                                            \
           "distance from which a cell has no blades left (maxGeom; Lemme's level 0 ends at 20 m)")          \
    SHADER(real, image_start, (50.0, 0.0, 1e6),                                                              \
           "distance from which the image takes blades over from the volume (minBTF; Lemme's level 2 begins at 50 m)") \
    SHADER(real, image_full, (80.0, 0.0, 1e6),                                                               \
           "distance from which a cell is all image (maxBTF; Lemme's 8-slice level 1 ends at 80 m)")       \
    SHADER(choice, transition_distance, ("blade", {"blade", "cell"}),                                          \
           "the distance a blade's band is taken at: blade, its root's (both theses: Boulanger Algorithm 4, L1210; Lemme L621; a filtered texel's blades' mean root); cell, the cell's centre's (canopy before issue 37: the split steps once per cell)") \
    PLAN(choice, transition, ("thesis", {"thesis", "boulanger", "lemme", "binary"}),                            \
         "how a blade crosses from one band to the next: over a window of thresholds around the cut, its share moving from the nearer representation to the farther one on complementary pixels (a screen door) - boulanger, Algorithm 1 / eq 4.6's linear ramp whose width shrinks toward the band's ends; lemme, eq 5.26's smoothstep of fixed width; thesis (the default), Boulanger's with middle = slices and Lemme's with the volume; binary, at once (eq 5.25 made complementary)") \
    SHADER(real, transition_width, (0.05, 0.0, 0.25),                                                       \
           "the transition window's half-width in units of the local density: Boulanger's omega_max (not given; canopy's 0.05) or Lemme's epsilon (not given; canopy's 0.05); 0 is the binary cut") \
    DERIVED(integer, transition_window, "the window drawn: 0 binary, 1 linear (Boulanger), 2 smoothstep (Lemme)") \
    SHADER(integer, volume_levels, (1, 1, 3),                                                                \
           "the middle band's volume levels, each its own bake and pass, handing its blades to the next over a ramp as the bands do: 1 (canopy's default, one volume of `slices`) to 3 (Lemme's football field, L930-935: 8, 2 and 1 slices); middle = volume only") \
    SHADER(real, volume_2_start, (50.0, 0.0, 1e6),                                                           \
           "volume_levels >= 2: the distance from which level 2 (slices_2) takes blades over from level 1 (Lemme's level 2 begins at 50 m)") \
    SHADER(real, volume_2_full, (80.0, 0.0, 1e6),                                                            \
           "volume_levels >= 2: the distance from which level 1 has no blades left (Lemme's level 1 ends at 80 m)") \
    SHADER(real, volume_3_start, (100.0, 0.0, 1e6),                                                          \
           "volume_levels = 3: the distance from which level 3 (slices_3) takes blades over from level 2 (Lemme's level 3 begins at 100 m)") \
    SHADER(real, volume_3_full, (160.0, 0.0, 1e6),                                                           \
           "volume_levels = 3: the distance from which level 2 has no blades left (Lemme's level 2 ends at 160 m)") \
    PLAN(integer, slices_2, (2, 1, 64), "volume_levels >= 2: level 2's vertical slices per direction (Lemme: 2)") \
    PLAN(integer, slices_3, (1, 1, 64), "volume_levels = 3: level 3's vertical slices per direction (Lemme: 1)") \
    PLAN(integer, samples, (4, 1, 4), "MSAA samples of every band's pass: 1 or 4 (lavapipe's)")             \
    PLAN(choice, culling, ("gpu", {"none", "gpu", "quadtree"}),                                             \
         "gpu: a compute pass per band keeps the copies whose box may be seen within the distances where that band draws anything (near to geometry_none, middle from geometry_full to image_full, far from image_start; grass.geometry's cull; the image is the same); quadtree: Lemme's quadtree (§6.1-6.2), traversed on the CPU every frame, keeps the same cells and draws the middle and far bands as macro-cells (middle = volume only; the copies stay on the CPU); none: every band draws every copy") \
    PLAN(integer, middle_macro_max, (40, 1, 4096),                                                          \
         "culling = quadtree: the widest macro-cell (cells a side) the middle band draws (Lemme's football field: 40)") \
    PLAN(integer, far_macro_max, (500, 1, 4096),                                                            \
         "culling = quadtree: the widest macro-cell (cells a side) the far band draws (Lemme's football field: 500)") \
    PLAN(integer, macro_capacity, (16384, 1, 16777216),                                                     \
         "culling = quadtree: the most macro-cells (single cells included) each middle or far band may draw in a frame (8 bytes each, 16 on a terrain, on the GPU); a frame that keeps more fails, naming this parameter") \
    PLAN(real, macro_unplanarity, (0.05, 0.0, 1e4),                                                        \
         "culling = quadtree on a terrain: a far-band macro-cell whose ground departs from the bilinear patch of its corners by more than this (world units) is split, down to single cells (grass.image's macro_unplanarity; Lemme L906-908 gives no value)") \
    PLAN(boolean, hilltop_volume, (false),                                                                  \
         "culling = quadtree: Lemme's hilltop silhouettes (§6.4.6, L917-920): the far band's cells whose box reaches above the eye are drawn again by the volume, the image's blades as vertical slices (the last volume level's), in macro-cells of up to middle_macro_max cells a side, so the grass on a crest stands up against the sky") \
    PLAN(integer, near_capacity, (8192, 1, 1048576),                                                        \
         "culling = quadtree: the most cells the near band may draw in a frame (128 bytes each, on the GPU); a frame that keeps more fails, naming this parameter") \
    SHADER(choice, coverage, ("alpha_to_coverage", {"alpha_test", "alpha_to_coverage"}),                    \
           "how the near band's blade outline cuts (grass.geometry's coverage)")                          \
    PLAN(choice, middle, ("volume", {"volume", "slices"}),                                                    \
         "the middle band: Lemme's ray-cast volume (grass.volume) or Boulanger's BTF slices (grass.slices)")     \
    PLAN(boolean, middle_per_sample, (false),                                                                  \
         "the middle band's volume ray-cast once per covered sample instead of once per pixel (the `sample` qualifier on its exit point): anti-aliases the slices' texels as 4x MSAA does the blades' edges, at up to 4 times the band's fragment cost; canopy's addition (Lemme casts once per pixel); needs samples = 4 and middle = volume") \
    SHADER(integer, slices, (8, 1, 64), "the middle band's vertical slices per direction (grass.volume's and grass.slices' slices; with volume_levels, level 1's)") \
    PLAN(integer, resolution, (256, 16, 4096), "texels of a middle-band slice across the patch (grass.volume's and grass.slices' resolution)") \
    PLAN(integer, height_resolution, (64, 4, 4096), "texels of a middle-band slice up the patch's height (grass.volume's and grass.slices')") \
    PLAN(integer, middle_shadow_resolution, (0, 0, 8192), "middle = slices: grass.slices' shadow_resolution, the blades' shadows baked into the slices' rows from one depth view per baked light direction this many texels a side; 0: no shadows in the bake") \
    PLAN(integer, image_resolution, (256, 16, 4096), "texels across the far band's top-view bake (grass.image's resolution)") \
    PLAN(real, slice_height, (0.1, 0.01, 1.0), "the far band's slice height, a fraction of the tallest blade (grass.image's)") \
    GRASS_SLICE_FILTERING_PARAMS(PLAN, "coverage")

CANOPY_BEGIN_NAMESPACE
CANOPY_CONST int GRASS_LOD_DISTANCE_BLADE = 0;
CANOPY_CONST int GRASS_LOD_DISTANCE_CELL = 1;
CANOPY_PARAM_BLOCK(GrassLodParams, GRASS_LOD_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS GrassLodParams
#endif

#endif
