// A patch of grass blades (Lemme 2012 ch. 4, Boulanger 2008 §4.2): roots over the unit square of
// ground, each blade a curved, two-sided quad strip along its spine (shaders/blade_curve.h), with
// a density threshold and a colour modulation of its own. Seeded and deterministic on every
// standard library; pure CPU, so the geometry every grass representation is made from (blades
// drawn, slices baked, the Embree reference) is tested without a device.
#pragma once

#include "density_thresholds.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace canopy::grass {

// Where roots go in the patch's unit square [0, 1)^2 (x and z; y is up).
enum class RootPlacement {
    uniform,     // independent, uniform (Lemme L304: stratified looks regular at low density)
    stratified,  // one per cell of a grid (Boulanger L841), the most square grid of `blades` cells
};

struct BladePatchParams {
    uint32_t blades = 2400;       // Lemme's Table 7.1 patch (L1026)
    uint32_t subdivisions = 4;    // cuts along the blade: subdivisions + 1 segments, 2 triangles each
    RootPlacement roots = RootPlacement::uniform;
    // Tip height above the root, in patch units (the patch is one unit wide); uniform in the range.
    float height_min = 0.15f, height_max = 0.35f;
    // Angle of the launch direction from the vertical, degrees; uniform in the range.
    float tilt_min_degrees = 0.0f, tilt_max_degrees = 25.0f;
    // Gravity's pull as a fraction of the largest that keeps the tip at the top (blade_max_pull).
    float bend_min = 0.2f, bend_max = 1.0f;
    // Strip width, patch units; the blade's outline comes from its alpha mask (Lemme L325).
    float width_min = 0.006f, width_max = 0.012f;
    // Per-blade colour modulation uniform in [1 - v, 1] (Lemme L333, eq 6.8's M_b), and a
    // per-vertex one in [1 - v, 1] on top.
    float blade_colour_variation = 0.3f, vertex_colour_variation = 0.1f;
    ThresholdParams thresholds;
    uint64_t seed = 1;
};

struct Blade {
    glm::vec3 root{0.0f};       // y = 0
    glm::vec3 launch{0.0f};     // b of eq 4.1
    glm::vec3 gravity{0.0f};    // g of eq 4.1, straight down
    glm::vec3 across{0.0f};     // unit, horizontal: the strip's width direction
    float width = 0.0f;
    float threshold = 1.0f;     // in ]0, 1]: drawn where the local density is at least this
    float colour = 1.0f;        // per-blade modulation
};

// One vertex of a blade's strip: two per spine sample, left (u = 0) then right (u = 1).
struct BladeVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};     // unit, orthogonal to the spine's tangent and to `across`
    glm::vec2 uv{0.0f};         // u across, v = t along the blade
    glm::vec3 root{0.0f};       // the blade's root, for height maps and per-blade lookups
    float threshold = 1.0f;
    float colour = 1.0f;        // per-blade times per-vertex modulation
};

struct BladePatch {
    BladePatchParams params;
    std::vector<Blade> blades;
    std::vector<BladeVertex> vertices;  // blade i owns vertices [i * vertices_per_blade(), ...)
    std::vector<uint32_t> indices;      // a triangle list, 6 per segment
    float tallest = 0.0f;               // highest spine point: the patch volume's height
};

constexpr uint32_t segments_per_blade(uint32_t subdivisions) { return subdivisions + 1; }
constexpr uint32_t triangles_per_blade(uint32_t subdivisions) { return 2 * segments_per_blade(subdivisions); }
constexpr uint32_t vertices_per_blade(uint32_t subdivisions) { return 2 * (segments_per_blade(subdivisions) + 1); }

// The stratified grid for `blades` roots: columns x rows == blades, as square as the count
// allows (2400 -> 48 x 50; a prime count gives one row).
glm::uvec2 stratified_grid(uint32_t blades);

// Throws std::invalid_argument naming the first parameter out of its range.
void validate(const BladePatchParams& params);

BladePatch generate_blade_patch(const BladePatchParams& params);

}  // namespace canopy::grass
