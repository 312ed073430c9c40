// `canopy bench grass-scale`: what a field costs as it grows (issue 10, "Scale and performance";
// a benchmark, not a timed test):
//   - memory per field cell: each technique's GPU memory (its resources and the scene's buffers,
//     MemoryLedger) and the process heap on the CPU, on the scene's field and on one with a quarter
//     of its cells; the slope is the bytes per cell, the rest is the patch (Lemme's structure holds
//     about 164 bytes a quadtree node, 42 MB for the football field: about 208 bytes a cell, L676);
//   - cost exponents: grass.geometry, grass.volume and grass.image on a small field at 1/8, 1/4,
//     1/2 and all of the patch's blades, fitted as t = a + b n^p (blades: p near 1; the volume and
//     the image, whose cost follows their pixels, near 0: their time ratio over the counts);
//   - the blades alone on the whole field, projected from that fit: the cells the view's frustum
//     keeps (the quadtree's count) times the blades a patch, never rendered (about 10^10 triangles).
#include "../common/grass_population.hpp"
#include "../common/patch_bake.hpp"
#include "../common/quadtree_selection.hpp"
#include "../shaders/lod_selection.h"

#include "config/population_overrides.hpp"
#include "core/error.hpp"
#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "run/family_benchmark.hpp"
#include "run/kernel_scaling.hpp"
#include "run/statistics.hpp"
#include "scene/camera.hpp"
#include "scene/geometry.hpp"

#include <fmt/format.h>

#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace canopy {
namespace {

using Values = std::map<std::string, ParamValue>;

Population& field_population(Scene& scene) {
    for (Population& p : scene.populations)
        if (p.kind == grass::kGrassPopulationKind) return p;
    throw ConfigError({}, 0, fmt::format("scene '{}' has no grass population", scene.name),
                      "use a scene with a [[population]] of kind = \"grass\", e.g. configs/scenes/football-field.toml");
}

// `scene` with its field's population parameters replaced.
Scene with_field(const Scene& scene, const Values& overrides) {
    Scene copy = scene;
    override_population_params(field_population(copy), overrides, {}, SourceLocation{"grass-scale", 0});
    return copy;
}

size_t heap_bytes() {
    const struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
}

struct Footprint {
    uint64_t cells = 0;
    uint64_t gpu = 0;   // the technique's resources and the scene's buffers (no camera targets)
    int64_t heap = 0;   // the process heap grown while the field was generated (its copies and per-copy data)
};

const Technique& technique(const std::string& name) {
    const Technique* t = TechniqueRegistry::instance().find(name);
    if (!t) throw std::logic_error("grass-scale: no technique " + name);
    return *t;
}

ParamSet resolved(const std::string& name, const Values& values) {
    const Technique& t = technique(name);
    return ParamSet::resolve(t.params(), values, {}, {}, name);
}

Footprint footprint(const GpuContext& gpu, const Scene& scene, glm::uvec2 cells, const std::string& name,
                    const Values& values) {
    Footprint f;
    f.cells = uint64_t(cells.x) * cells.y;
    const size_t before = heap_bytes();
    const Scene sized = with_field(scene, {{"cells_x", (long long)cells.x}, {"cells_z", (long long)cells.y}});
    f.heap = int64_t(heap_bytes()) - int64_t(before);
    FrameRenderer renderer(gpu, sized, build_scene_meshes(sized), 64, 64, technique(name).graph(resolved(name, values)));
    const MemoryUse m = renderer.memory();
    f.gpu = m.technique_bytes + m.scene_bytes;
    return f;
}

// A technique and its parameters.
struct Timed {
    std::string name;
    Values values;
};

}  // namespace

class GrassScale final : public FamilyBenchmark {
public:
    std::string name() const override { return "grass-scale"; }
    std::string summary() const override {
        return "grass: memory per field cell, cost exponents in blades, the blades alone on the whole field projected";
    }
    std::string default_scene() const override { return "configs/scenes/football-field.toml"; }
    std::vector<ParamSpec> params() const override {
        return {ParamSpec::integer("width", 512, 16, 4096, "image width of the timed frames"),
                ParamSpec::integer("height", 384, 16, 4096, "image height of the timed frames"),
                ParamSpec::integer("rounds", 5, 1, 100, "measured rounds (each renders every technique at every count once)"),
                ParamSpec::integer("small_cells", 16, 1, 256,
                                   "the timed field's side in cells, centred where the scene's camera looks")};
    }

    FamilyBenchmarkResult run(const GpuContext& gpu, const Scene& scene, const ParamSet& params) const override {
        Scene base = scene;
        const Population& population = field_population(base);
        const glm::uvec2 cells(uint32_t(population.params.integer("cells_x")), uint32_t(population.params.integer("cells_z")));
        const long long blades = population.params.integer("blades");
        if (blades < 8)
            throw ConfigError({}, 0, fmt::format("a patch of {} blades cannot be cut to 1/8, 1/4 and 1/2", blades),
                              "use a scene whose grass patch has at least 8 blades");
        FamilyBenchmarkResult result;
        result.markdown = fmt::format("# Grass at scale: scene '{}', {} x {} cells of {} blades\n", scene.name, cells.x,
                                      cells.y, blades);
        memory_part(gpu, base, cells, result);
        timing_part(gpu, base, cells, blades, params, result);
        return result;
    }

private:
    static void memory_part(const GpuContext& gpu, const Scene& scene, glm::uvec2 cells, FamilyBenchmarkResult& result) {
        const glm::uvec2 quarter((cells.x + 1) / 2, (cells.y + 1) / 2);
        if (uint64_t(quarter.x) * quarter.y == uint64_t(cells.x) * cells.y)
            throw ConfigError({}, 0, fmt::format("a field of {} x {} cells has no smaller quarter to compare with", cells.x, cells.y),
                              "use a field of at least 2 cells along one side");
        const std::vector<std::pair<std::string, Timed>> cases{
            {"grass.lod, culling = quadtree", {"grass.lod", {{"culling", std::string("quadtree")}}}},
            {"grass.lod, culling = quadtree, Lemme's five levels",
             {"grass.lod",
              {{"culling", std::string("quadtree")}, {"volume_levels", 3LL}, {"image_start", 200.0}, {"image_full", 300.0}}}},
            {"grass.lod, culling = gpu", {"grass.lod", {{"culling", std::string("gpu")}}}},
            {"grass.geometry, culling = gpu", {"grass.geometry", {{"culling", std::string("gpu")}}}},
        };
        result.markdown += fmt::format(
            "\n## Memory per field cell\n\nThe field at {} x {} and {} x {} cells; bytes per cell = the difference "
            "over the difference in cells, the rest the patch's (its triangles, bakes and fixed buffers). GPU: the "
            "technique's resources and the scene's buffers (canopy's memory ledger). CPU: the process heap grown while "
            "the field was generated (its copies, and what the Embree reference reads per copy), measured with "
            "mallinfo2; the renderer shares those copies (GeneratedPopulation) and the quadtree is implicit, so neither "
            "adds per cell (the heap grown while a renderer is made mixes in lavapipe's caches and is not counted). Lemme's quadtree: about 164 bytes a node, 42 MB for his "
            "380 x 532 field, about 208 bytes a cell (L676).\n\n"
            "| technique | GPU bytes per cell | GPU patch MiB | CPU bytes per cell | CPU + GPU bytes per cell |\n"
            "|---|---:|---:|---:|---:|\n",
            quarter.x, quarter.y, cells.x, cells.y);
        nlohmann::json rows = nlohmann::json::array();
        for (const auto& [label, c] : cases) {
            const Footprint small = footprint(gpu, scene, quarter, c.name, c.values);
            const Footprint large = footprint(gpu, scene, cells, c.name, c.values);
            const double dc = double(large.cells) - double(small.cells);
            const double gpu_per_cell = (double(large.gpu) - double(small.gpu)) / dc;
            const double gpu_patch = double(large.gpu) - gpu_per_cell * double(large.cells);
            const double cpu_per_cell = (double(large.heap) - double(small.heap)) / dc;
            result.markdown += fmt::format("| {} | {:.0f} | {:.2f} | {:.0f} | {:.0f} |\n", label, gpu_per_cell,
                                           gpu_patch / (1024.0 * 1024.0), cpu_per_cell, cpu_per_cell + gpu_per_cell);
            rows.push_back({{"technique", label},
                            {"cells", {small.cells, large.cells}},
                            {"gpu_bytes", {small.gpu, large.gpu}},
                            {"heap_bytes", {small.heap, large.heap}},
                            {"gpu_bytes_per_cell", gpu_per_cell},
                            {"cpu_bytes_per_cell", cpu_per_cell}});
        }
        result.numbers["memory"] = rows;
    }

    static void timing_part(const GpuContext& gpu, const Scene& scene, glm::uvec2 cells, long long blades,
                            const ParamSet& params, FamilyBenchmarkResult& result) {
        const uint32_t width = uint32_t(params.integer("width")), height = uint32_t(params.integer("height"));
        const int rounds = int(params.integer("rounds"));
        const uint32_t side = uint32_t(params.integer("small_cells"));
        // The small field: side x side cells centred under the point the camera looks at.
        const glm::vec3 target = scene.camera.target;
        const std::vector<long long> counts{std::max(1LL, blades / 8), std::max(1LL, blades / 4), std::max(1LL, blades / 2),
                                            blades};
        const std::vector<Timed> techniques{
            {"grass.geometry", {{"culling", std::string("gpu")}}}, {"grass.volume", {}}, {"grass.image", {}}};
        std::vector<std::unique_ptr<FrameRenderer>> renderers;  // technique-major, then count
        std::vector<Scene> scenes;
        for (long long n : counts)
            scenes.push_back(with_field(scene, {{"cells_x", (long long)side},
                                                {"cells_z", (long long)side},
                                                {"centre_x", double(target.x)},
                                                {"centre_z", double(target.z)},
                                                {"blades", n}}));
        for (const Timed& t : techniques)
            for (const Scene& s : scenes)
                renderers.push_back(std::make_unique<FrameRenderer>(gpu, s, build_scene_meshes(s), width, height,
                                                                    technique(t.name).graph(resolved(t.name, t.values))));
        // Every renderer once to warm up, then `rounds` rounds, each renderer once a round.
        std::vector<std::vector<double>> times(renderers.size());
        for (auto& r : renderers) r->render();
        for (int round = 0; round < rounds; ++round)
            for (size_t i = 0; i < renderers.size(); ++i) {
                const size_t k = (i + size_t(round)) % renderers.size();  // a different first renderer each round
                times[k].push_back(renderers[k]->render().gpu_ms);
            }
        result.markdown += fmt::format(
            "\n## Cost against the blades a patch holds\n\n{0} x {0} cells centred under the camera's target, {1} x {2} "
            "pixels, the frame's GPU time, the ground's pass included (median of {3} rounds, every case once a round). 'ratio': the time at {4} blades over the "
            "time at {5}, 1 for a cost that does not follow the blades; 'slope': log(ratio) / log({4} / {5}), the "
            "exponent between the two ends; for the blades, also the fit t = a + b n^p over the four counts (least "
            "squares, p in [0.2, 3.5], a >= 0: a fixed cost such as the ground's).\n\n| technique |",
            side, width, height, rounds, counts.back(), counts.front());
        for (long long n : counts) result.markdown += fmt::format(" {} blades, ms |", n);
        result.markdown += " ratio | slope | fit p |\n|---|";
        for (size_t i = 0; i < counts.size(); ++i) result.markdown += "---:|";
        result.markdown += "---:|---:|---:|\n";
        nlohmann::json series = nlohmann::json::array();
        PowerFit geometry_fit;
        double geometry_small_ms = 0;
        for (size_t t = 0; t < techniques.size(); ++t) {
            std::vector<double> n, median;
            std::string row = "| " + techniques[t].name + " |";
            for (size_t c = 0; c < counts.size(); ++c) {
                const double m = summarize(times[t * counts.size() + c]).median;
                n.push_back(double(counts[c]));
                median.push_back(m);
                row += fmt::format(" {:.2f} |", m);
            }
            const PowerFit fit = fit_power_law(n, median);
            const double ratio = median.back() / median.front();
            const double slope = std::log(ratio) / std::log(n.back() / n.front());
            // A fit to a flat series picks any exponent: shown for the blades, whose cost grows.
            row += fmt::format(" {:.2f} | {:.2f} | {} |", ratio, slope, t == 0 ? fmt::format("{:.2f}", fit.exponent) : "-");
            result.markdown += row + "\n";
            series.push_back({{"technique", techniques[t].name}, {"blades", n}, {"median_ms", median},
                              {"ratio", ratio}, {"slope", slope},
                              {"fit", {{"offset", fit.offset}, {"scale", fit.scale}, {"exponent", fit.exponent},
                                       {"r_squared", fit.r_squared}}}});
            if (t == 0) {
                geometry_fit = fit;
                geometry_small_ms = median.back();
            }
        }
        result.numbers["cost"] = series;

        // The blades alone on the whole field from the scene's camera: the cells in view (the
        // quadtree with one band over every distance), each a full patch.
        const Population& field = field_population(const_cast<Scene&>(scene));
        const grass::GrassField placement = grass::grass_field_placement(field.params);
        Bounds box{glm::vec3(0.0f), glm::vec3(1.0f, float(field.params.real("height_max")), 1.0f)};
        const grass::QuadtreeField qf{placement.cells, placement.origin, placement.cell_size, box};
        const grass::QuadtreeSelection in_view = grass::select_cells(
            qf, {{0.0f, shader::LOD_NO_DISTANCE, 1}}, scene.camera.position, view_projection(scene.camera, width, height));
        const double view_cells = double(in_view.bands[0].size());
        const grass::QuadtreeSelection small_view = grass::select_cells(
            grass::QuadtreeField{{side, side},
                                 glm::vec3(target.x - 0.5f * float(side) * placement.cell_size, placement.origin.y,
                                           target.z - 0.5f * float(side) * placement.cell_size),
                                 placement.cell_size, box},
            {{0.0f, shader::LOD_NO_DISTANCE, 1}}, scene.camera.position, view_projection(scene.camera, width, height));
        const double small_cells = double(small_view.bands[0].size());
        const long long triangles_per_blade = 2 * (field.params.integer("subdivisions") + 1);
        // The blades' cost per drawn blade, from the fit at the full patch, scaled by the field's
        // blades in view: t = a + b (n_view / n_small)^p, as the fit says cost follows blades.
        const double drawn_small = small_cells * double(blades), drawn_field = view_cells * double(blades);
        const double scale = drawn_field / std::max(drawn_small, 1.0);
        const double projected_ms =
            geometry_fit.offset + (geometry_small_ms - geometry_fit.offset) * std::pow(scale, geometry_fit.exponent);
        const double linear_ms = geometry_small_ms * scale;
        result.markdown += fmt::format(
            "\n## The blades alone on the whole field (projected, not rendered)\n\nFrom the scene's camera the frustum "
            "keeps {:.0f} of the field's {} cells ({:.3g} blades, {:.3g} triangles a frame); the timed field showed "
            "{:.0f} cells of {} blades in {:.1f} ms. With the fitted exponent p = {:.2f}, the blades alone would take about "
            "{:.3g} s a frame here; in proportion to the blades (p = 1), {:.3g} s. Both extrapolate {:.0f} times beyond "
            "what was rendered.\n",
            view_cells, uint64_t(cells.x) * cells.y, drawn_field, drawn_field * double(triangles_per_blade), small_cells,
            blades, geometry_small_ms, geometry_fit.exponent, projected_ms / 1000.0, linear_ms / 1000.0, scale);
        result.numbers["projection"] = {{"cells_in_view", view_cells},
                                        {"blades_in_view", drawn_field},
                                        {"triangles_in_view", drawn_field * double(triangles_per_blade)},
                                        {"timed_cells_in_view", small_cells},
                                        {"timed_ms", geometry_small_ms},
                                        {"exponent", geometry_fit.exponent},
                                        {"projected_ms", projected_ms},
                                        {"proportional_ms", linear_ms}};
    }
};

namespace {
RegisterFamilyBenchmark<GrassScale> registered;
}  // namespace

}  // namespace canopy
