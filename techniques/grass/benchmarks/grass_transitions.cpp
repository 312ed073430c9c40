// `canopy bench grass-transitions`: where the blades that change representation lie when the eye
// moves a little (issue 10, "Popping": "the depth spread of the blades that switch representation
// between two nearby eyes"). For two eyes `step` apart along the scene camera's line of sight,
// every blade the field draws is given its representation at each eye by grass.lod's cuts
// (shaders/lod_selection.h, from its root's distance or its cell's centre's, as the shaders cut
// it under transition_distance); the blades
// whose representation differs are the ones that can pop, and their distances from the first eye
// say whether a transition spreads them over a band (Boulanger's density thresholds) or gathers
// them on a line. With a smooth `transition` (grass.lod's default window) a blade moves a share at
// a time: the share moved is summed. A second table measures what a filtered texel, which knows
// only its blades' mean root, makes of the split: the share of the blades drawn twice or never
// where the blades cut at their own root meet a texel cutting at the mean (issue 37, item 2). No
// rendering: the selection is the shaders' own header, run on the CPU.
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

// How grass.lod crosses a cut (its `transition`): the window and its half-width.
struct Window {
    int kind = shader::GRASS_LOD_WINDOW_BINARY;
    float width = 0.0f;
};

// The share of a blade of threshold `t` (local density `density`, at distance d) beyond each of
// grass.lod's two cuts (lod_beyond: drawn farther than the blades, farther than the volume);
// (-1, -1) where the density thins it.
glm::vec2 beyond_cuts(const Bands& b, const Window& w, float d, float t, float density) {
    if (!(density > 0.0f) || t > density) return glm::vec2(-1.0f);
    const glm::vec2 cuts = shader::lod_cuts(d, b.geometry_full, b.geometry_none, b.image_start, b.image_full);
    return {shader::lod_beyond(t / density, cuts.x, w.kind, w.width), shader::lod_beyond(t / density, cuts.y, w.kind, w.width)};
}

// A filtered texel knows only its blades' mean root (blade_texels.h), so where the blades, cut at
// their own roots, meet a texel cut at the mean, some of a blade's share may be drawn twice or
// never. Modelled here with a texel of a `resolution`-texel bake at mip level L showing the blades
// whose roots share a square of the level's footprint (2^L / resolution of the cell): a proxy. The
// image's top-view texels gather blades so (leaning a little across their edges); a volume
// slice's texel gathers them along its section's depth as well (1/8 of a cell with 8 slices: the
// 32-texel row of a 256-texel bake), and the bench does not read a texel's thresholds as spread
// over their range, as the shaders do. At each eye along the camera's line, the share of the
// drawn blades' worth that differs between their own root's cut and their square's mean root's, at
// the near/middle cut (blades against texels); at the middle/far cut two texels meet, the
// volume's and the image's, each off its blades' roots: twice the same model's figure, an
// estimate (their footprints differ), not a bound.
nlohmann::json filtered_roots(const grass::GrassField& field, const grass::BladePatch& patch,
                              const std::vector<Bands>& configurations, const Window& window, glm::vec3 target,
                              glm::vec3 back, uint32_t resolution, int eyes, std::string& markdown) {
    constexpr int kLevels = 6;  // levels 1 to 6: footprints of 2 to 64 texels
    const float spacing = 120.0f / float(eyes);  // eyes from the target out to 120 m
    // Each level's mean root (patch x, z) of the blades in each square, all the patch's blades
    // (the bake draws them all; the density thins them at run time).
    std::vector<std::vector<glm::vec2>> means(kLevels + 1);
    std::vector<std::vector<uint32_t>> square_of(kLevels + 1);
    for (int level = 1; level <= kLevels; ++level) {
        const uint32_t squares = std::max(1u, resolution >> level);
        std::vector<glm::dvec3> sums(size_t(squares) * squares, glm::dvec3(0.0));
        square_of[size_t(level)].resize(patch.blades.size());
        for (size_t i = 0; i < patch.blades.size(); ++i) {
            const glm::vec3 r = patch.blades[i].root;
            const uint32_t sx = std::min(squares - 1, uint32_t(std::max(0.0f, r.x) * float(squares)));
            const uint32_t sz = std::min(squares - 1, uint32_t(std::max(0.0f, r.z) * float(squares)));
            const uint32_t sq = sz * squares + sx;
            square_of[size_t(level)][i] = sq;
            sums[sq] += glm::dvec3(r.x, r.z, 1.0);
        }
        means[size_t(level)].resize(sums.size());
        for (size_t q = 0; q < sums.size(); ++q)
            means[size_t(level)][q] = sums[q].z > 0.0 ? glm::vec2(sums[q].x / sums[q].z, sums[q].y / sums[q].z) : glm::vec2(0.5f);
    }
    markdown += fmt::format(
        "\n## Filtered texels: blades drawn twice or never where a texel cuts at its blades' mean root\n\n"
        "A texel of a {}-texel bake at mip level L shows the blades of a square 2^L / {} of a cell wide and cuts them "
        "at their mean root (blade_texels.h), while the blades cut at their own. At {} eyes every {:.3g} m along the "
        "camera's line (from the target out to 120 m), the share of the drawn blades' worth whose cut at the "
        "near/middle transition differs between the two (drawn twice, or never); the largest over the eyes, and "
        "at the middle/far transition twice the same figure (two texels meet there: an estimate, not a bound). "
        "Blades grouped by root square: a proxy for the blades a texel shows (an image texel's blades lean a "
        "little across its edges; a volume slice's texel also gathers them along its section's depth, 1/8 of a "
        "cell with 8 slices: the 0.125 row).\n\n"
        "| bands | level | footprint (cell) | near/middle: worst eye | middle/far: estimate, worst eye |\n|---|---:|---:|---:|---:|\n",
        resolution, resolution, eyes, spacing);
    nlohmann::json rows = nlohmann::json::array();
    for (const Bands& b : configurations)
        for (int level = 1; level <= kLevels; ++level) {
            double worst[2] = {0.0, 0.0};
            for (int e = 0; e < eyes; ++e) {
                const glm::vec3 eye = target + (spacing * float(e)) * back;
                double off[2] = {0.0, 0.0};
                uint64_t drawn = 0;
                grass::for_each_drawn_blade(field, patch, [&](const grass::FieldBlade& blade) {
                    ++drawn;
                    const glm::vec2 mean = means[size_t(level)][square_of[size_t(level)][blade.blade]];
                    glm::vec3 at_mean = grass::field_point(field, blade.cell, glm::vec3(mean.x, 0.0f, mean.y));
                    at_mean.y = blade.root.y;  // on the blade's own ground (flat within a square)
                    const float t = patch.blades[blade.blade].threshold;
                    const glm::vec2 own = beyond_cuts(b, window, glm::length(blade.root - eye), t, blade.density);
                    const glm::vec2 texel = beyond_cuts(b, window, glm::length(at_mean - eye), t, blade.density);
                    off[0] += std::abs(double(own.x - texel.x));
                    off[1] += 2.0 * std::abs(double(own.y - texel.y));
                });
                if (drawn == 0) continue;
                for (int k = 0; k < 2; ++k) worst[k] = std::max(worst[k], off[k] / double(drawn));
            }
            markdown += fmt::format("| {} | {} | {:.4f} | {:.3f} % | {:.3f} % |\n", b.label, level,
                                    double(1u << level) / double(resolution), 100.0 * worst[0], 100.0 * worst[1]);
            rows.push_back({{"bands", b.label},
                            {"level", level},
                            {"footprint_cells", double(1u << level) / double(resolution)},
                            {"near_middle_worst_share", worst[0]},
                            {"middle_far_estimate_worst_share", worst[1]}});
        }
    return rows;
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
                                "the first eye's distance from the camera's target, along the same line (m)"),
                ParamSpec::choice("transition", "lemme", {"binary", "boulanger", "lemme"},
                                  "how a blade crosses a cut (grass.lod's `transition`): at once, or over Boulanger's "
                                  "linear window or Lemme's smoothstep (grass.lod's default with the volume)"),
                ParamSpec::real("transition_width", 0.05, 0.0, 0.25, "the window's half-width (grass.lod's)"),
                ParamSpec::integer("resolution", 256, 16, 4096,
                                   "texels across a cell of the filtered bakes the second table models "
                                   "(grass.lod's resolution and image_resolution)"),
                ParamSpec::integer("filtered_eyes", 48, 0, 1000,
                                   "eyes of the second table, evenly from the camera's target out to 120 m "
                                   "(48: every 2.5 m); 0 leaves the table out")};
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
        const std::string& transition = params.choice("transition");
        const Window window{.kind = transition == "binary"      ? shader::GRASS_LOD_WINDOW_BINARY
                                    : transition == "boulanger" ? shader::GRASS_LOD_WINDOW_LINEAR
                                                                : shader::GRASS_LOD_WINDOW_SMOOTHSTEP,
                            .width = float(params.real("transition_width"))};
        const std::string window_label =
            window.kind == shader::GRASS_LOD_WINDOW_BINARY
                ? "a binary cut"
                : fmt::format("{} window of half-width {}", transition == "boulanger" ? "Boulanger's linear" : "Lemme's smoothstep",
                              window.width);
        FamilyBenchmarkResult result;
        result.markdown = fmt::format(
            "# grass.lod: the blades that change representation between two eyes {} m apart\n\nScene '{}', its field "
            "of {} x {} cells of {} blades; the first eye {} m from the camera's target along its line of sight, the "
            "second {} m farther. A blade's representation at each eye is grass.lod's cut of its threshold at its "
            "{} distance, crossed over {} (lod_selection.h); depth: the blade's root's distance from the first eye. "
            "One row per transition: blades to the volume (near/middle), volume to image (middle/far). A blade "
            "switches when any share of it moves across the cut; `share moved` sums the shares (blades' worth).\n\n"
            "| bands | transition | blades drawn | switching | share moved | depth 5 % | median | 95 % | spread (5-95 %) | cells switching |\n"
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
            step, scene.name, spec.field.cells.x, spec.field.cells.y, patch.blades.size(), params.real("eye_distance"),
            step, by_root ? "root's" : "cell's centre", window_label);
        nlohmann::json rows = nlohmann::json::array();
        const char* transition_names[2] = {"near/middle", "middle/far"};
        for (const Bands& b : configurations) {
            std::vector<double> depths[2];
            double moved[2] = {0.0, 0.0};
            std::vector<int> cell_switches[2];
            for (auto& c : cell_switches) c.assign(size_t(spec.field.cells.x) * spec.field.cells.y, 0);
            uint64_t drawn = 0, other = 0;
            grass::for_each_drawn_blade(spec.field, patch, [&](const grass::FieldBlade& blade) {
                ++drawn;
                const glm::vec3 at = by_root ? blade.root
                                             : grass::field_point(spec.field, blade.cell, glm::vec3(0.5f, 0.0f, 0.5f));
                const float t = patch.blades[blade.blade].threshold;
                const glm::vec2 a = beyond_cuts(b, window, glm::length(at - eye), t, blade.density);
                const glm::vec2 c = beyond_cuts(b, window, glm::length(at - eye2), t, blade.density);
                // A step back moves a blade's shares across each cut towards the farther band only.
                if (c.x < a.x || c.y < a.y) {
                    ++other;
                    return;
                }
                for (int k = 0; k < 2; ++k) {
                    if (!(c[k] > a[k])) continue;
                    depths[k].push_back(glm::length(blade.root - eye));
                    moved[k] += double(c[k] - a[k]);
                    cell_switches[k][size_t(blade.cell.y) * spec.field.cells.x + size_t(blade.cell.x)] = 1;
                }
            });
            for (int k = 0; k < 2; ++k) {
                std::sort(depths[k].begin(), depths[k].end());
                const double p5 = quantile_of_sorted(depths[k], 0.05), p50 = quantile_of_sorted(depths[k], 0.5),
                             p95 = quantile_of_sorted(depths[k], 0.95);
                size_t cells = 0;
                for (int sw : cell_switches[k]) cells += size_t(sw);
                const auto m = [](double v) { return std::isnan(v) ? std::string("-") : fmt::format("{:.2f}", v); };
                result.markdown += fmt::format("| {} | {} | {} | {} | {:.1f} | {} | {} | {} | {} | {} |\n", b.label,
                                               transition_names[k], drawn, depths[k].size(), moved[k], m(p5), m(p50),
                                               m(p95), m(p95 - p5), cells);
                rows.push_back({{"bands", b.label},
                                {"transition", transition_names[k]},
                                {"distances", {b.geometry_full, b.geometry_none, b.image_start, b.image_full}},
                                {"blades_drawn", drawn},
                                {"switching", depths[k].size()},
                                {"share_moved", moved[k]},
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
            "\nA step back moves every cell's cuts towards the farther representation, so each blade's shares should "
            "move to the farther band only: {} did not (summed over the settings; `other_switches` in the JSON). "
            "Boulanger's density thresholds spread a transition's switches over its depth, a few blades in many cells; "
            "sharp bands gather them on a line of cells, each switching many of its blades at once.\n",
            others);
        if (const int eyes = int(params.integer("filtered_eyes")); eyes > 0)
            result.numbers["filtered_roots"] = filtered_roots(spec.field, patch, configurations, window, target, back,
                                                              uint32_t(params.integer("resolution")), eyes,
                                                              result.markdown);
        result.numbers["eye"] = {eye.x, eye.y, eye.z};
        result.numbers["step"] = step;
        result.numbers["configurations"] = rows;
        return result;
    }
};

RegisterFamilyBenchmark<GrassTransitions> registered;

}  // namespace
}  // namespace canopy
