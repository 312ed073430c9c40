// What the grass family's image-based tests compare a load-phase bake with: one unmirrored cell
// whose copy sits at the origin (patch space is world space), Embree's orthographic rays through
// each texel of a bake (which blade they hit, its density threshold), and the texel-by-texel
// agreement away from the edges between blades. The mapping from texels to rays is written here
// again, apart from the techniques' bake cameras, so a wrong camera shows.
#pragma once

#include <functional>

#include "core/image.hpp"
#include "scene/geometry.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace canopy::grass::test {

// A scene of one 1 x 1 cell at [0, 1]^2, `camera` a [camera] table, `extra_params` more
// population parameters (e.g. "density = 0.5"); 60 wide blades, no ground.
Scene one_cell_scene(const std::string& camera, const std::string& extra_params);

// The view a bake looks along, and its texel (i, j) -> patch mapping (v = j / size from the first row):
//   along_z: u = x, v = 1 - y / top, rays along -z;  along_x: u = z, v = 1 - y / top, rays along -x;
//   down: u = x, v = z, rays along -y.  Over the prototype's bounds (y from 0).
enum class View { along_z, along_x, down };

struct TexelTruth {
    float threshold = 2.0f;  // the hit blade's, or the bakes' "empty" (2)
    int64_t blade = -1;      // -1: no blade
    glm::vec3 position{0.0f};  // where the ray meets it
    glm::vec2 root{0.0f};      // the hit blade's root, patch x and z
};

// A section of the patch along the axis a bake looks along (x for along_x, z for along_z): what a
// slice of grass.volume holds, the blades in [lo, hi).
struct Section {
    float lo = -1e30f, hi = 1e30f;
};

// Row-major, width x height texels; a ray that first meets a blade outside `section` sees none.
std::vector<TexelTruth> traced_bake(const Scene& scene, View view, uint32_t width, uint32_t height,
                                    Section section = {});
// The same over `frame` (patch space) instead of the prototype's bounds: a tiled bake's, the cell
// (x and z in [0, 1]) of a field whose copy at the origin is unmirrored.
std::vector<TexelTruth> traced_bake_over(const Scene& scene, const Bounds& frame, View view, uint32_t width,
                                         uint32_t height, Section section = {});
inline std::vector<TexelTruth> traced_bake(const Scene& scene, View view, uint32_t size) {
    return traced_bake(scene, view, size, size);
}

struct BakeAgreement {
    int compared = 0;   // texels off the edges between blades
    int covered = 0;    // of those, where a ray hits a blade
    int coverage = 0;   // where the bake and the rays disagree on whether a blade is there
    int threshold = 0;  // where both show one but the bake's threshold is not the blade's
    int root = 0;       // where both show one but the bake's root is not the blade's
};

// A bake's level 0 against the rays (shaders/blade_texels.h): a blade where its colour's alpha is
// above 0.5, its threshold range the blade's one threshold; `flip_u` reads the bake mirrored (to
// show the check can fail).
BakeAgreement compare_bake(const Image& colour, const Image& blades, const std::vector<TexelTruth>& truth,
                           bool flip_u = false);

// Pixels showing grass (green above twice the red: the grounds and backgrounds of the grass
// tests are brown or black).
int grass_pixels(const Image& image);
bool shows_grass(const float* rgb);

// A technique's image against the reference's primary rays from the scene's camera, at every
// pixel centre off the edges where the blade the rays hit changes. With `visibility` (the
// renderer's pixel-centre visibility, G = view depth), also where both show a blade: how many
// drawn depths lie more than `depth_tolerance` from the reference's hit.
struct CoverageAgreement {
    int compared = 0, covered = 0, differ = 0;
    int depth_compared = 0, depth_off = 0;
};
CoverageAgreement compare_with_reference_hits(const Scene& scene, const Image& image, const Image* visibility = nullptr,
                                              float depth_tolerance = 0.0f);

// Per `tile` x `tile` block of pixels, the share showing grass against the share whose reference
// ray hits a blade; the mean absolute difference over the blocks (blades thinner than a pixel make
// a pixel-by-pixel comparison mostly noise). `blade_pixels`: how many reference rays hit a blade.
double tile_coverage_error(const Scene& scene, const Image& image, int tile = 8, int* blade_pixels = nullptr);

// A 4 x 4-cell field of 300-blade patches standing on hills up to `height_scale` high (one grid
// quad a cell, grass_terrain.h), seen from `camera`; height_scale 0 is the same field flat.
Scene hills_scene(const std::string& camera, double height_scale);

// tile_coverage_error of a representation over hills_scene(camera, 0) (flat) and (camera, 1.2)
// (hills), `render` drawing each scene; with the blade pixels the reference found in each.
struct FlatAndHills {
    double flat = 0.0, hills = 0.0;
    int flat_blades = 0, hills_blades = 0;
};
FlatAndHills flat_and_hills_coverage_error(const std::string& camera, const std::function<Image(const Scene&)>& render,
                                         double height_scale = 1.2);

// A representation follows the terrain: with flat_and_hills_coverage_error's fields, the reference
// finds more than `min_blades` blade pixels in each, the flat field's error is above 0 and the
// hills' at most `bound` times it. Reports the errors when a check fails. `height_scale`: the
// hills' height (hills_scene's).
void check_follows_terrain(const std::string& camera, double bound, const std::function<Image(const Scene&)>& render,
                           int min_blades = 1000, double height_scale = 1.2);

}  // namespace canopy::grass::test
