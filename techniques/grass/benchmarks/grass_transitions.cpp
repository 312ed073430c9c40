// `canopy bench grass-transitions`: where the blades that change representation lie when the eye
// moves a little (issue 10, "Popping": "the depth spread of the blades that switch representation
// between two nearby eyes"). For two eyes `step` apart along the scene camera's line of sight,
// every blade the field draws is given its representation at each eye by grass.lod's cuts
// (shaders/lod_selection.h, from its root's distance or its cell's centre's, as the shaders cut
// it under transition_distance); the blades
// whose representation differs are the ones that can pop, and their distances from the first eye
// say whether a transition spreads them over a band (Boulanger's density thresholds) or gathers
// them on a line. No rendering: the selection is the shaders' own header, run on the CPU.
#include "../common/blade_patch.hpp"
#include "../common/grass_field.hpp"
#include "../common/grass_population.hpp"
#include "../shaders/lod_selection.h"

#include "core/error.hpp"
#include "run/family_benchmark.hpp"
#include "run/statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace canopy {
namespace {

struct Bands {
    std::string label;
    float geometry_full, geometry_none, image_start, image_full;
};

// The representation grass.lod draws a blade of threshold `t` with, where the cell's local
// density is `density`, at distance `d` of the cell's centre; -1 where none (thinned).
int representation(const Bands& b, float d, float t, float density) {
    const glm::vec2 cuts = shader::lod_cuts(d, b.geometry_full, b.geometry_none, b.image_start, b.image_full);
    for (int r : {shader::GRASS_LOD_GEOMETRY, shader::GRASS_LOD_VOLUME, shader::GRASS_LOD_IMAGE}) {
        const glm::vec2 band = shader::lod_band(r, cuts);
        if (t > band.x * density && t <= band.y * density) return r;
    }
    return -1;
}

class GrassTransitions final : public FamilyBenchmark {
public:
    std::string name() const override { return "grass-transitions"; }
    std::string summary() const override {
        return "grass: the blades that change representation between two nearby eyes, and how far they spread in depth";
    }
    std::string default_scene() const override { return "configs/scenes/grass-field.toml"; }
    std::vector<ParamSpec> params() const override {
        return {ParamSpec::real("step", 0.25, 0.001, 100.0,
                                "how far the second eye stands behind the first, along the camera's line of sight (m)"),
                ParamSpec::choice("transition_distance", "blade", {"blade", "cell"},
                                  "where a blade's band is taken: at its root (grass.lod's default) or its cell's centre"),
                ParamSpec::real("eye_distance", 4.0, 0.0, 1e5,
                                "the first eye's distance from the camera's target, along the same line (m)")};
    }

    FamilyBenchmarkResult run(const GpuContext&, const Scene& scene, const ParamSet& params) const override {
        const Population* population = nullptr;
        for (const Population& p : scene.populations)
            if (p.kind == grass::kGrassPopulationKind && !population) population = &p;
        if (!population)
            throw ConfigError({}, 0, fmt::format("scene '{}' has no grass population", scene.name),
                              "use a scene with a [[population]] of kind = \"grass\", e.g. configs/scenes/grass-field.toml");
        const grass::GrassPopulationSpec spec = grass::grass_population_spec(population->params);
        const grass::BladePatch patch = grass::generate_blade_patch(spec.patch);
        const glm::vec3 target = scene.camera.target;
        const glm::vec3 back = glm::normalize(scene.camera.position - target);
        const float step = float(params.real("step"));
        const bool by_root = params.choice("transition_distance") == "blade";
        const glm::vec3 eye = target + float(params.real("eye_distance")) * back, eye2 = eye + step * back;
        // grass.lod's defaults, and the smooth and sharp bands of configs/experiments/grass/popping.toml.
        const std::vector<Bands> configurations{{"grass.lod's defaults (5-20 m, 50-80 m)", 5, 20, 50, 80},
                                                {"smooth (4-10 m, 14-20 m)", 4, 10, 14, 20},
                                                {"sharp (9.5-10 m, 19.5-20 m)", 9.5f, 10, 19.5f, 20}};
        FamilyBenchmarkResult result;
        result.markdown = fmt::format(
            "# grass.lod: the blades that change representation between two eyes {} m apart\n\nScene '{}', its field "
            "of {} x {} cells of {} blades; the first eye {} m from the camera's target along its line of sight, the "
            "second {} m farther. A blade's representation at each eye is grass.lod's cut of its threshold at its "
            "{} distance (lod_selection.h); depth: the blade's root's distance from the first eye. One row "
            "per transition: blades to the volume (near/middle), volume to image (middle/far).\n\n"
            "| bands | transition | blades drawn | switching | depth 5 % | median | 95 % | spread (5-95 %) | cells switching |\n"
            "|---|---|---:|---:|---:|---:|---:|---:|---:|\n",
            step, scene.name, spec.field.cells.x, spec.field.cells.y, patch.blades.size(), params.real("eye_distance"),
            step, by_root ? "root's" : "cell's centre");
        nlohmann::json rows = nlohmann::json::array();
        const char* transition_names[2] = {"near/middle", "middle/far"};
        for (const Bands& b : configurations) {
            std::vector<double> depths[2];
            std::vector<int> cell_switches[2];
            for (auto& c : cell_switches) c.assign(size_t(spec.field.cells.x) * spec.field.cells.y, 0);
            uint64_t drawn = 0, other = 0;
            grass::for_each_drawn_blade(spec.field, patch, [&](const grass::FieldBlade& blade) {
                ++drawn;
                const glm::vec3 at = by_root ? blade.root
                                             : grass::field_point(spec.field, blade.cell, glm::vec3(0.5f, 0.0f, 0.5f));
                const float t = patch.blades[blade.blade].threshold;
                const int a = representation(b, glm::length(at - eye), t, blade.density);
                const int c = representation(b, glm::length(at - eye2), t, blade.density);
                if (a == c) return;
                // A step back sends a blade to the next band: from the blades (0) or from the volume (1).
                if (c != a + 1 || a < 0 || a > 1) {
                    ++other;
                    return;
                }
                depths[a].push_back(glm::length(blade.root - eye));
                cell_switches[a][size_t(blade.cell.y) * spec.field.cells.x + size_t(blade.cell.x)] = 1;
            });
            for (int k = 0; k < 2; ++k) {
                std::sort(depths[k].begin(), depths[k].end());
                const double p5 = quantile_of_sorted(depths[k], 0.05), p50 = quantile_of_sorted(depths[k], 0.5),
                             p95 = quantile_of_sorted(depths[k], 0.95);
                size_t cells = 0;
                for (int sw : cell_switches[k]) cells += size_t(sw);
                const auto m = [](double v) { return std::isnan(v) ? std::string("-") : fmt::format("{:.2f}", v); };
                result.markdown += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", b.label, transition_names[k],
                                               drawn, depths[k].size(), m(p5), m(p50), m(p95), m(p95 - p5), cells);
                rows.push_back({{"bands", b.label},
                                {"transition", transition_names[k]},
                                {"distances", {b.geometry_full, b.geometry_none, b.image_start, b.image_full}},
                                {"blades_drawn", drawn},
                                {"switching", depths[k].size()},
                                {"other_switches", other},
                                {"depth_p5", p5},
                                {"depth_median", p50},
                                {"depth_p95", p95},
                                {"cells_switching", cells}});
            }
        }
        uint64_t others = 0;
        for (const nlohmann::json& r : rows) others += r.at("other_switches").get<uint64_t>();
        result.markdown += fmt::format(
            "\nA step back moves every cell's cuts towards the farther representation, so each switching blade should "
            "go to the next band: {} did not (summed over the settings; `other_switches` in the JSON). Boulanger's "
            "density thresholds spread a transition's switches over its depth, a few blades in many cells; sharp bands "
            "gather them on a line of cells, each switching many of its blades at once.\n",
            others);
        result.numbers["eye"] = {eye.x, eye.y, eye.z};
        result.numbers["step"] = step;
        result.numbers["configurations"] = rows;
        return result;
    }
};

RegisterFamilyBenchmark<GrassTransitions> registered;

}  // namespace
}  // namespace canopy
