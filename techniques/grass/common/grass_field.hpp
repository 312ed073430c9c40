// A field of grass: a grid of terrain cells, each showing the one blade patch mirrored its own way
// (shaders/cell_mirroring.h), thinned by a density map. Pure CPU: the reference and the tests
// enumerate exactly the blades every representation must show.
#pragma once

#include "core/image.hpp"
#include "scene/population.hpp"

#include "blade_patch.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace canopy::grass {

// A grey density map over the field, 1 = every blade, 0 = none, sampled bilinearly at texel
// centres with clamped edges (Lemme L797, Boulanger B L918). Empty: density 1 everywhere.
struct DensityMap {
    uint32_t width = 0, height = 0;
    std::vector<float> values;  // row-major, row 0 at field z = 0
    float sample(glm::vec2 field_uv) const;  // field_uv in [0, 1]^2 over the whole field
};

// The density maps a scene can ask for by name (a grass population's `density_map`), sampled at
// `texels` x `texels` over the field: `uniform`, `high` everywhere; `ramp_x`, from `low` at the
// field's first column (x = 0) to `high` at its last; `clearings`, `high` but for clearings of
// `low` where a smooth value noise of `periods` lattice cells across the field (seeded) is below
// its median, with a smooth edge.
enum class DensityPattern { uniform, ramp_x, clearings };
DensityMap density_map(DensityPattern pattern, float low, float high, uint32_t texels, uint32_t periods, uint32_t seed);

// A density map from an image's first channel, each texel v in [0, 1] giving low + (high - low) v,
// its first row at the field's z = 0 edge (-z) and its first column at x = 0 (-x): the image as a
// map seen from above with -z up. Throws std::invalid_argument, naming `file` and the texel, for a
// value outside [0, 1] or not finite, or an empty image.
DensityMap density_map_from_image(const Image& image, float low, float high, const std::string& file);

// The most cells a field has along x or z (the `cells_x` and `cells_z` parameters' range; the
// macro-cells' 16-bit records and grid-height buffers are sized by it).
inline constexpr uint32_t kMaxFieldSide = 4096;

struct GrassField {
    glm::uvec2 cells{32, 32};  // Lemme's Table 7.1 field (L1022)
    float cell_size = 1.0f;    // world units a cell (and a patch) is wide
    glm::vec3 origin{0.0f};    // the corner of cell (0, 0)
    bool mirror = true;        // false: every cell shows the patch as it is
    uint32_t mirror_seed = 1;
    DensityMap density;
    // A terrain under the field (the population's `terrain`), its grid the field's cells
    // (check_terrain_fits): each blade stands on it, `origin.y` above it (shaders/grass_terrain.h).
    PopulationGround ground;
};

// Throws std::invalid_argument, saying what to set, unless the field's terrain (if any) has one
// grid quad a cell: vertices = cells + 1, size = cells x cell_size, centred on the field.
void check_terrain_fits(const GrassField& field);

// The terrain's height at a world (x, z) (0 without one): what a blade rooted there is lifted by.
float terrain_height(const GrassField& field, glm::vec2 world_xz);

// A cell's terrain heights at its corners in world order, (x0, z0), (x1, z0), (x0, z1), (x1, z1);
// zeros without a terrain.
glm::vec4 cell_corner_heights(const GrassField& field, glm::ivec2 cell);

// Where a patch point lands in the world in `cell`: mirrored about the patch centre, then
// scaled and moved to the cell. (A mirrored blade is the same strip seen the other way round:
// blades are two-sided.)
glm::vec3 field_point(const GrassField& field, glm::ivec2 cell, glm::vec3 patch_point);

// The cell's mirror signs (shaders/cell_mirroring.h), or (1, 1) when the field does not mirror.
glm::vec2 mirror_signs(const GrassField& field, glm::ivec2 cell);

// The density map's values at the four corners of `cell`, in world order: (x0, z0), (x1, z0),
// (x0, z1), (x1, z1). Within the cell a blade's density is their bilinear blend at its root
// (shaders/grass_density.h), so a map finer than the cells is seen only at cell corners.
glm::vec4 cell_corner_densities(const GrassField& field, glm::ivec2 cell);

struct FieldBlade {
    glm::ivec2 cell{0};
    uint32_t blade = 0;      // index in the patch
    glm::vec3 root{0.0f};    // world, on the terrain when there is one
    float density = 1.0f;    // at the root: the bilinear blend of the cell's corner densities
};

// Calls `visit` for every blade the field draws (threshold <= density at its world root), cell
// by cell in row order, blades in patch order; returns how many.
uint64_t for_each_drawn_blade(const GrassField& field, const BladePatch& patch,
                              const std::function<void(const FieldBlade&)>& visit = {});

}  // namespace canopy::grass
