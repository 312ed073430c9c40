#include "grass_population.hpp"

#include "../shaders/blade_alpha.h"
#include "../shaders/cell_mirroring.h"
#include "../shaders/grass_density.h"
#include "../shaders/grass_terrain.h"

#include "report/image_files.hpp"
#include "scene/scene_limits.hpp"

#include <fmt/format.h>

#include <memory>
#include <stdexcept>

namespace canopy::grass {

namespace {

// Two ParamSpecs for one [min, max] range of BladePatchParams.
void add_range(std::vector<ParamSpec>& specs, const std::string& name, double lo, double hi, double min, double max,
               const std::string& doc) {
    specs.push_back(ParamSpec::real(name + "_min", lo, min, max, doc + ": lower end"));
    specs.push_back(ParamSpec::real(name + "_max", hi, min, max, doc + ": upper end"));
}

class GrassPopulation final : public PopulationKind {
public:
    std::string name() const override { return kGrassPopulationKind; }
    std::string summary() const override {
        return "a field of grass cells, each a mirrored copy of one seeded blade patch (Lemme 2012, Boulanger 2008)";
    }
    int version() const override { return 1; }
    std::vector<ParamSpec> params() const override { return grass_population_params(); }
    FamilyPopulation generate(const ParamSet& params, const PopulationGround& ground) const override {
        return generate_grass_population(grass_population_spec(params, ground));
    }
};

const RegisterPopulationKind<GrassPopulation> registered;

}  // namespace

std::vector<ParamSpec> grass_population_params() {
    const BladePatchParams d;
    std::vector<ParamSpec> s;
    s.push_back(ParamSpec::integer("cells_x", 4, 1, kMaxFieldSide, "terrain cells along x (Lemme Table 7.1: 32)"));
    s.push_back(ParamSpec::integer("cells_z", 4, 1, kMaxFieldSide, "terrain cells along z (Lemme Table 7.1: 32)"));
    s.push_back(ParamSpec::real("cell_size", 1.0, 1e-3, 1e4, "world units a cell, and so the patch, is wide"));
    s.push_back(ParamSpec::real("centre_x", 0.0, -1e5, 1e5, "world x of the field's centre"));
    s.push_back(ParamSpec::real("centre_z", 0.0, -1e5, 1e5, "world z of the field's centre"));
    s.push_back(ParamSpec::real("ground", 0.0, -1e5, 1e5, "world y of the blades' roots (on a terrain: their height above it)"));
    s.push_back(ParamSpec::boolean("mirror", true, "mirror each cell's patch in x and/or z by a hash of the cell (eq 6.4-6.7)"));
    s.push_back(ParamSpec::integer("mirror_seed", 1, 0, 0xffffffffll, "seed of the cells' mirror signs"));
    s.push_back(ParamSpec::real("density", 1.0, 0.0, 1.0,
                                "the field's density: a blade is drawn when its threshold is at most this"));
    s.push_back(ParamSpec::choice("density_map", "uniform", {"uniform", "ramp_x", "clearings", "file"},
                                  "uniform: `density` everywhere; ramp_x: from `density_low` at the field's first column to "
                                  "`density` at its last; clearings: `density` but for clearings of `density_low` (Lemme §6.4.1); "
                                  "file: `density_map_file`, from `density_low` where it is 0 to `density` where it is 1"));
    s.push_back(ParamSpec::real("density_low", 0.0, 0.0, 1.0, "ramp_x, clearings and file: the low end, at most `density`"));
    s.push_back(ParamSpec::path("density_map_file",
                                "density_map = file: a greyscale image over the whole field (PNG of 8 or 16 bits, or OpenEXR; its first channel, "
                                "in [0, 1]), its first row along the field's -z edge and its first column along -x, "
                                "relative to the scene file"));
    s.push_back(ParamSpec::integer("density_map_texels", 64, 2, 4096, "ramp_x and clearings: the map's texels a side over the field"));
    s.push_back(ParamSpec::integer("density_map_periods", 4, 1, 1024, "clearings: noise lattice cells across the field"));
    s.push_back(ParamSpec::integer("density_map_seed", 1, 0, 0xffffffffll, "clearings: the noise's seed"));
    s.push_back(ParamSpec::integer("blades", d.blades, 1, 1 << 20, "blades in the patch (Lemme Table 7.1: 2400)"));
    s.push_back(ParamSpec::integer("subdivisions", d.subdivisions, 0, 64,
                                   "cuts along a blade: subdivisions + 1 segments of 2 triangles (Lemme: 4)"));
    s.push_back(ParamSpec::choice("roots", "uniform", {"uniform", "stratified"},
                                  "root placement: independent uniform (Lemme) or one per grid cell (Boulanger)"));
    // 2^53: ParamSpec's range is a double, exact up to there.
    s.push_back(ParamSpec::integer("seed", int64_t(d.seed), 0, 1ll << 53, "seed of the patch's blades"));
    add_range(s, "height", d.height_min, d.height_max, 1e-4, 10.0, "tip height above the root, patch units");
    add_range(s, "tilt", d.tilt_min_degrees, d.tilt_max_degrees, 0.0, 80.0, "launch angle from the vertical, degrees");
    add_range(s, "bend", d.bend_min, d.bend_max, 0.0, 1.0, "gravity's pull, a fraction of the most that keeps the tip on top");
    add_range(s, "width", d.width_min, d.width_max, 1e-5, 1.0, "strip width, patch units");
    s.push_back(ParamSpec::real("taper", 2.0, 0.05, 64.0,
                                "outline taper exponent k: |u - 1/2| <= (1 - v^k)/2 covers k/(k+1) of the strip"));
    s.push_back(ParamSpec::real("blade_colour_variation", d.blade_colour_variation, 0.0, 1.0,
                                "per-blade albedo factor uniform in [1 - v, 1]"));
    s.push_back(ParamSpec::real("vertex_colour_variation", d.vertex_colour_variation, 0.0, 1.0,
                                "per-vertex albedo factor uniform in [1 - v, 1], on top"));
    s.push_back(ParamSpec::choice("thresholds", "uniform", {"uniform", "clustered"},
                                  "density thresholds: independent uniform (eq 4.3) or clustered (eq 4.4-4.6)"));
    s.push_back(ParamSpec::real("sigma", d.thresholds.sigma, 0.0, 10.0, "clustered: spread around the noise (Fig 4.3: 0.12)"));
    s.push_back(ParamSpec::integer("noise_periods", d.thresholds.noise_periods, 1, 256,
                                   "clustered: noise lattice cells across the patch"));
    s.push_back(ParamSpec::boolean("equalise", false, "replace the thresholds by their ranks: exactly uniform"));
    s.push_back(ParamSpec::real("transmission", 0.0, 0.0, 1.0,
                                "Boulanger eq 4.1's gamma: the share of the light from behind a blade that passes through "
                                "(every representation and the reference add gamma times the far side's irradiance)"));
    return s;
}

GrassField grass_field_placement(const ParamSet& params) {
    GrassField f;
    f.cells = {uint32_t(params.integer("cells_x")), uint32_t(params.integer("cells_z"))};
    f.cell_size = float(params.real("cell_size"));
    const glm::vec2 extent = f.cell_size * glm::vec2(f.cells);
    f.origin = glm::vec3(float(params.real("centre_x")) - 0.5f * extent.x, float(params.real("ground")),
                         float(params.real("centre_z")) - 0.5f * extent.y);
    f.mirror = params.boolean("mirror");
    f.mirror_seed = uint32_t(params.integer("mirror_seed"));
    return f;
}

GrassPopulationSpec grass_population_spec(const ParamSet& params, const PopulationGround& ground) {
    GrassPopulationSpec spec;
    BladePatchParams& p = spec.patch;
    p.blades = uint32_t(params.integer("blades"));
    p.subdivisions = uint32_t(params.integer("subdivisions"));
    p.roots = params.choice("roots") == "stratified" ? RootPlacement::stratified : RootPlacement::uniform;
    p.seed = uint64_t(params.integer("seed"));
    p.height_min = float(params.real("height_min"));
    p.height_max = float(params.real("height_max"));
    p.tilt_min_degrees = float(params.real("tilt_min"));
    p.tilt_max_degrees = float(params.real("tilt_max"));
    p.bend_min = float(params.real("bend_min"));
    p.bend_max = float(params.real("bend_max"));
    p.width_min = float(params.real("width_min"));
    p.width_max = float(params.real("width_max"));
    p.blade_colour_variation = float(params.real("blade_colour_variation"));
    p.vertex_colour_variation = float(params.real("vertex_colour_variation"));
    p.thresholds.distribution =
        params.choice("thresholds") == "clustered" ? ThresholdDistribution::clustered : ThresholdDistribution::uniform;
    p.thresholds.sigma = float(params.real("sigma"));
    p.thresholds.noise_periods = uint32_t(params.integer("noise_periods"));
    p.thresholds.equalise = params.boolean("equalise");
    validate(p);  // min <= max

    spec.field = grass_field_placement(params);
    GrassField& f = spec.field;
    f.ground = ground;
    check_terrain_fits(f);
    const std::string& pattern = params.choice("density_map");
    const float low = float(params.real("density_low")), high = float(params.real("density"));
    if (pattern != "uniform" && low > high)
        throw std::invalid_argument(fmt::format("density_low = {} is above density = {}: the map's low end must be at most its high end",
                                                low, high));
    const std::string& map_file = params.path("density_map_file");
    if (pattern == "file" && map_file.empty())
        throw std::invalid_argument("density_map = \"file\" needs density_map_file = \"...\", the image to read");
    if (pattern != "file" && !map_file.empty())
        throw std::invalid_argument(fmt::format("density_map_file is given but density_map is \"{}\": set density_map = \"file\" "
                                                "to read it, or remove it",
                                                pattern));
    if (pattern == "file") {
        Image map;
        try {
            map = read_image(map_file);
        } catch (const std::runtime_error& e) {  // the reader's reason: not PNG or OpenEXR, truncated, ...
            throw std::invalid_argument(fmt::format("density_map_file: {}", e.what()));
        }
        f.density = density_map_from_image(map, low, high, map_file);
    }
    else
        f.density = density_map(pattern == "ramp_x"      ? DensityPattern::ramp_x
                                : pattern == "clearings" ? DensityPattern::clearings
                                                         : DensityPattern::uniform,
                                low, high, uint32_t(params.integer("density_map_texels")),
                                uint32_t(params.integer("density_map_periods")), uint32_t(params.integer("density_map_seed")));
    spec.taper = float(params.real("taper"));
    spec.transmission = float(params.real("transmission"));
    return spec;
}

FamilyPopulation generate_grass_population(const GrassPopulationSpec& spec) {
    // Refuse what the reference cannot hold before generating anything: one Embree instance per
    // cell, the patch stored once.
    const double cell_count = double(spec.field.cells.x) * double(spec.field.cells.y);
    const double triangles = double(spec.patch.blades) * double(triangles_per_blade(spec.patch.subdivisions));
    if (cell_count > double(limits::kMaxPopulationCount))
        throw std::invalid_argument(fmt::format("cells_x x cells_z = {:.0f} cells, more than the {} copies a population "
                                                "may have (configs/README.md, \"Limits\")",
                                                cell_count, limits::kMaxPopulationCount));
    if (triangles > limits::kMaxPrototypeTriangles)
        throw std::invalid_argument(fmt::format("a patch of {} blades of {} triangles has {:.3g} triangles, more than the "
                                                "{:.3g} a prototype may have: fewer blades or subdivisions",
                                                spec.patch.blades, triangles_per_blade(spec.patch.subdivisions),
                                                triangles, limits::kMaxPrototypeTriangles));
    if (spec.field.ground.terrain && cell_count * triangles > limits::kMaxPrototypeTriangles)
        throw std::invalid_argument(fmt::format("on a terrain the reference stores every cell's blades apart: {:.0f} cells of "
                                                "{:.3g} triangles are {:.3g}, more than the {:.3g} it may hold; use fewer "
                                                "cells, blades or subdivisions",
                                                cell_count, triangles, cell_count * triangles, limits::kMaxPrototypeTriangles));
    const BladePatch patch = generate_blade_patch(spec.patch);
    const GrassField& field = spec.field;
    FamilyPopulation out;
    out.transmission = spec.transmission;
    out.prototype.vertices.reserve(patch.vertices.size());
    out.vertex_data.reserve(patch.vertices.size());
    for (const BladeVertex& v : patch.vertices) {
        out.prototype.vertices.push_back({v.position, v.normal});
        PopulationVertexData d;
        d.data[0] = glm::vec4(v.uv, v.threshold, v.colour);
        d.data[1] = glm::vec4(v.root.x, v.root.z, spec.taper, 0.0f);
        out.vertex_data.push_back(d);
    }
    out.prototype.indices = patch.indices;

    const size_t cells = size_t(field.cells.x) * field.cells.y;
    out.instances.resize(cells);
    for (uint32_t z = 0; z < field.cells.y; ++z)
        for (uint32_t x = 0; x < field.cells.x; ++x) {
            const glm::ivec2 cell{int(x), int(z)};
            const glm::vec2 s = mirror_signs(field, cell);
            // world = origin + size (cell + mirror(p)), mirror(p) = (p - 0.5) s + 0.5 in x and z (eq 6.7).
            const float size = field.cell_size;
            glm::mat4 m(0.0f);
            m[0] = glm::vec4(size * s.x, 0.0f, 0.0f, 0.0f);
            m[1] = glm::vec4(0.0f, size, 0.0f, 0.0f);
            m[2] = glm::vec4(0.0f, 0.0f, size * s.y, 0.0f);
            const glm::vec4 heights = cell_corner_heights(field, cell);  // world order; zeros on flat ground
            m[3] = glm::vec4(field.origin.x + size * (float(x) + 0.5f - 0.5f * s.x), field.origin.y + heights.x,
                             field.origin.z + size * (float(z) + 0.5f - 0.5f * s.y), 1.0f);
            PopulationInstance& copy = out.instances[size_t(z) * field.cells.x + x];
            copy.model = m;
            copy.normal_matrix[0] = glm::vec4(1.0f / (size * s.x), 0.0f, 0.0f, heights.y - heights.x);
            copy.normal_matrix[1] = glm::vec4(0.0f, 1.0f / size, 0.0f, heights.z - heights.x);
            copy.normal_matrix[2] = glm::vec4(0.0f, 0.0f, 1.0f / (size * s.y), heights.w - heights.x);
            copy.data = shader::grass_patch_corner_densities(cell_corner_densities(field, cell), s);
        }

    // The reference's cut and colour, from the same per-vertex data the shaders interpolate.
    struct Shared {
        std::vector<PopulationVertexData> vertex_data;
        std::vector<uint32_t> indices;
        std::vector<glm::vec4> corners;  // per copy
    };
    auto shared = std::make_shared<Shared>();
    shared->vertex_data = out.vertex_data;
    shared->indices = out.prototype.indices;
    for (const PopulationInstance& copy : out.instances) shared->corners.push_back(copy.data);
    // Per blade (constant over its strip) from its first vertex, so the reference thins exactly
    // the blades the vertex shader does; u, v and the colour interpolated, as the raster does.
    const auto interpolate = [](const Shared& sh, uint32_t triangle, float u, float v) {
        const uint32_t* t = sh.indices.data() + size_t(triangle) * 3;
        return (1.0f - u - v) * sh.vertex_data[t[0]].data[0] + u * sh.vertex_data[t[1]].data[0] +
               v * sh.vertex_data[t[2]].data[0];
    };
    out.opaque = [shared, interpolate](uint32_t copy, uint32_t triangle, float u, float v) {
        const PopulationVertexData& first = shared->vertex_data[shared->indices[size_t(triangle) * 3]];
        const float density =
            shader::grass_root_density(shared->corners[copy], glm::vec2(first.data[1].x, first.data[1].y));
        if (!shader::grass_blade_drawn(first.data[0].z, density)) return false;
        const glm::vec4 a = interpolate(*shared, triangle, u, v);
        return shader::blade_opaque(glm::vec2(a.x, a.y), first.data[1].z);
    };
    out.albedo_scale = [shared, interpolate](uint32_t, uint32_t triangle, float u, float v) {
        return interpolate(*shared, triangle, u, v).w;
    };
    if (field.ground.terrain) {
        // Each blade lifted by the ground under its root, as grass_blades_vertex.glsl lifts it: in
        // the prototype's space, where a world unit up is 1 / cell_size.
        struct Lifts {
            std::vector<glm::vec2> roots;  // per prototype vertex, patch x and z
            std::vector<glm::vec3> lifts;  // per copy
            std::vector<glm::vec2> signs;  // per copy
            float cell_size;
        };
        auto lifts = std::make_shared<Lifts>();
        for (const PopulationVertexData& d : out.vertex_data) lifts->roots.emplace_back(d.data[1].x, d.data[1].y);
        for (const PopulationInstance& copy : out.instances) {
            lifts->lifts.emplace_back(copy.normal_matrix[0].w, copy.normal_matrix[1].w, copy.normal_matrix[2].w);
            lifts->signs.emplace_back(glm::sign(copy.model[0][0]), glm::sign(copy.model[2][2]));
        }
        lifts->cell_size = field.cell_size;
        out.vertex_offset = [lifts](uint32_t copy, uint32_t vertex) {
            const float lift = shader::grass_terrain_lift(lifts->lifts[copy], lifts->roots[vertex], lifts->signs[copy]);
            return glm::vec3(0.0f, lift / lifts->cell_size, 0.0f);
        };
    }
    return out;
}

}  // namespace canopy::grass
