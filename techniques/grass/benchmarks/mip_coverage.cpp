// `canopy bench mip-coverage`: how much of a baked grass slice an alpha test keeps at each mip
// level, for the box filter, Boulanger's max-alpha filter (eq 4.16-4.18) and Lemme's
// coverage-preserving filter (eq 4.9-4.15), on the very slices grass.image and grass.volume bake
// at load. Lemme argues against Boulanger's filter (L439: levels "appear a little over or less
// opaque compared to the base level"); this measures by how much, level by level.
#include "../common/mip_chain.hpp"

#include "core/error.hpp"
#include "core/registry.hpp"
#include "metrics/coverage_error.hpp"
#include "render/frame_renderer.hpp"
#include "run/family_benchmark.hpp"
#include "scene/geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace canopy {
namespace {

// A baked slice's level 0 as colour and alpha (blade_texels.h: alpha 1 where a blade shows, 0
// where none does), whatever the scene's density (a density below 1 would cut some at render time).
grass::RgbaLevel slice_level(const Image& baked) {
    grass::RgbaLevel level;
    level.width = uint32_t(baked.width);
    level.height = uint32_t(baked.height);
    level.texels.resize(size_t(baked.width) * size_t(baked.height));
    for (int y = 0; y < baked.height; ++y)
        for (int x = 0; x < baked.width; ++x) {
            const float* t = baked.at(x, y);
            level.texels[size_t(y) * size_t(baked.width) + size_t(x)] = glm::vec4(t[0], t[1], t[2], t[3]);
        }
    return level;
}

// The slices a technique bakes for `scene` with `params`, read back after its load phase, each
// resolved from `supersampling` x `supersampling` subtexels.
std::vector<grass::RgbaLevel> baked_slices(const GpuContext& gpu, const Scene& scene, const std::string& technique,
                                           const std::map<std::string, ParamValue>& params, const std::string& image,
                                           uint32_t layers, uint32_t supersampling) {
    const Technique* t = TechniqueRegistry::instance().find(technique);
    FrameRenderer renderer(gpu, scene, build_scene_meshes(scene), 16, 16,
                           t->graph(ParamSet::resolve(t->params(), params, {}, {}, technique)));
    renderer.render();
    std::vector<grass::RgbaLevel> slices;
    for (uint32_t layer = 0; layer < layers; ++layer)
        slices.push_back(grass::resolve_supersampled(slice_level(renderer.read_image(image, 0, layer)), supersampling));
    return slices;
}

// One way a representation is baked and filtered (shaders/slice_filtering_params.h).
struct FilterSetting {
    std::string label;
    std::map<std::string, ParamValue> params;
};

std::vector<FilterSetting> filter_settings() {
    const auto setting = [](const char* filter, long long supersampling, bool anisotropic) {
        return std::map<std::string, ParamValue>{{"mip_filter", std::string(filter)},
                                                 {"bake_supersampling", supersampling},
                                                 {"mip_anisotropic", anisotropic}};
    };
    return {{"level 0, NEAREST (before issue 37)", setting("none", 1, false)},
            {"box", setting("box", 2, false)},
            {"max-alpha (Boulanger)", setting("max_alpha", 2, false)},
            {"coverage-preserving (Lemme)", setting("coverage", 2, false)},
            {"coverage-preserving, anisotropic", setting("coverage", 2, true)}};
}

// The scene seen from `elevation` degrees above its ground at `distance` from its camera's target,
// from the side its camera looks from.
Scene seen_from(const Scene& scene, float elevation, float distance) {
    Scene s = scene;
    glm::vec3 across = scene.camera.position - scene.camera.target;
    across.y = 0.0f;
    across = glm::length(across) > 1e-6f ? glm::normalize(across) : glm::vec3(0.0f, 0.0f, 1.0f);
    const float e = glm::radians(elevation);
    s.camera.position = scene.camera.target + distance * (std::cos(e) * across + glm::vec3(0.0f, std::sin(e), 0.0f));
    s.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    return s;
}

// The pixels' coverage (pixel visibility's) of `technique` drawing `scene`.
Image coverage_of(const GpuContext& gpu, const Scene& scene, const std::vector<TriangleMesh>& meshes, const std::string& technique,
                  const std::map<std::string, ParamValue>& params, uint32_t width, uint32_t height) {
    const Technique* t = TechniqueRegistry::instance().find(technique);
    FrameRenderer renderer(gpu, scene, meshes, width, height,
                           t->graph(ParamSet::resolve(t->params(), params, {}, {}, technique)));
    renderer.render();
    return renderer.read_pixel_visibility();
}

struct LevelCoverage {
    uint32_t width = 0, height = 0;
    double coverage = 0;    // eq 4.11 at a_r, over every slice's texels together
    double mean_alpha = 0;  // what blending or alpha-to-coverage would show
};

// Per level, the filter's chains of all `slices` together.
std::vector<LevelCoverage> coverage_per_level(const std::vector<grass::RgbaLevel>& slices, grass::MipFilter filter,
                                              float a_r) {
    std::vector<LevelCoverage> levels;
    for (const grass::RgbaLevel& slice : slices) {
        const std::vector<grass::RgbaLevel> chain = grass::mip_chain(slice, filter, a_r);
        levels.resize(std::max(levels.size(), chain.size()));
        for (size_t l = 0; l < chain.size(); ++l) {
            levels[l].width = chain[l].width;
            levels[l].height = chain[l].height;
            double alpha = 0;
            for (const glm::vec4& t : chain[l].texels) alpha += t.w;
            const double n = double(chain[l].texels.size()) * double(slices.size());
            levels[l].coverage += grass::alpha_coverage(chain[l], a_r) * double(chain[l].texels.size()) / n;
            levels[l].mean_alpha += alpha / n;
        }
    }
    return levels;
}

class MipCoverage final : public FamilyBenchmark {
public:
    std::string name() const override { return "mip-coverage"; }
    std::string summary() const override {
        return "Grass slices' coverage per mip level under the box, max-alpha (Boulanger eq 4.16-4.18) and "
               "coverage-preserving (Lemme eq 4.9-4.15) filters, on the slices grass.image and grass.volume bake.";
    }
    std::string default_scene() const override { return "configs/scenes/lemme-t7.1.toml"; }
    std::vector<ParamSpec> params() const override {
        return {ParamSpec::integer("resolution", 256, 4, 4096, "level 0 of grass.image's top view, texels a side"),
                ParamSpec::integer("slices", 16, 1, 64, "grass.volume's slices per direction (Table 7.1: 16)"),
                ParamSpec::integer("slice_resolution", 256, 4, 4096, "level 0 of grass.volume's slices, texels across"),
                ParamSpec::integer("height_resolution", 32, 4, 4096, "level 0 of grass.volume's slices, texels up"),
                ParamSpec::integer("supersampling", 4, 1, 8,
                                   "each level-0 texel resolved from s x s baked texels (1, 2, 4 or 8; 1: a blade or "
                                   "none per texel; 4 at the defaults bakes Table 7.1's 1024^2 and 1024 x 128)"),
                ParamSpec::real("alpha_reference", 0.5, 0.01, 0.99,
                                "a_r, the alpha test's reference (Lemme: 'a high alpha reference value', not given)"),
                ParamSpec::integer("view_width", 320, 0, 1920,
                                   "the per-view comparison with the blades: image width (height 9/16 of it); 0 skips it"),
                ParamSpec::integer("views", 5, 1, 5,
                                   "the per-view comparison's elevations: the first n of 5, 15, 30, 55 and 80 degrees")};
    }

private:
    void views_against_blades(const GpuContext& gpu, const Scene& scene, const ParamSet& params,
                              FamilyBenchmarkResult& result) const;

public:

    FamilyBenchmarkResult run(const GpuContext& gpu, const Scene& scene, const ParamSet& params) const override {
        const float a_r = float(params.real("alpha_reference"));
        const uint32_t n = uint32_t(params.integer("slices"));
        const uint32_t s = uint32_t(params.integer("supersampling"));
        if ((s & (s - 1)) != 0)
            throw ConfigError({}, 0, fmt::format("--supersampling {}: not a power of 2", s), "use 1, 2, 4 or 8");
        const long long image_bake = params.integer("resolution") * s;
        const long long slice_bake = params.integer("slice_resolution") * s, height_bake = params.integer("height_resolution") * s;
        for (const auto& [name, baked] : {std::pair<const char*, long long>{"resolution", image_bake},
                                          {"slice_resolution", slice_bake},
                                          {"height_resolution", height_bake}})
            if (baked > 4096)
                throw ConfigError({}, 0, fmt::format("--{} x --supersampling = {} texels to bake, more than the 4096 the "
                                                     "techniques bake", name, baked),
                                  fmt::format("lower --{} or --supersampling", name));
        struct Source {
            std::string label;
            std::vector<grass::RgbaLevel> slices;
        };
        const std::vector<Source> sources{
            {fmt::format("grass.image: the top view, baked at {0} x {0}", image_bake),
             baked_slices(gpu, scene, "grass.image", {{"resolution", image_bake}, {"bake_supersampling", 1LL}},
                          "slice_albedo", 1, s)},
            {fmt::format("grass.volume: {} slices baked at {} x {}", 2 * n, slice_bake, height_bake),
             baked_slices(gpu, scene, "grass.volume",
                          {{"slices", (long long)n},
                           {"resolution", slice_bake},
                           {"height_resolution", height_bake},
                           {"bake_supersampling", 1LL}},
                          "slices_albedo", 2 * n, s)},
        };
        FamilyBenchmarkResult result;
        result.markdown = fmt::format(
            "# Grass slices: coverage per mip level\n\n"
            "Coverage: the share of a level's texels an alpha test at a_r = {} keeps (Lemme eq 4.11). Level 0 is "
            "the bake resolved from {} x {} baked texels (mean alpha, alpha-weighted colour), as an anti-aliased "
            "bake would hold it (at 1: a blade or none per texel). In brackets: the level's coverage minus level 0's, in "
            "percentage points. Mean alpha: what blending or alpha-to-coverage shows (the box filter keeps it "
            "exactly).\n",
            a_r, s, s);
        for (const Source& source : sources) {
            std::map<grass::MipFilter, std::vector<LevelCoverage>> by_filter;
            for (grass::MipFilter f : grass::kMipFilters) by_filter[f] = coverage_per_level(source.slices, f, a_r);
            const double base = by_filter[grass::MipFilter::box].at(0).coverage;
            result.markdown += fmt::format("\n## {}\n\n| level | texels | box | max-alpha | coverage-preserving | mean alpha: box | max-alpha | coverage-preserving |\n|---:|---|---:|---:|---:|---:|---:|---:|\n",
                                           source.label);
            nlohmann::json levels = nlohmann::json::array();
            std::map<grass::MipFilter, double> worst, sum;
            const size_t count = by_filter[grass::MipFilter::box].size();
            for (size_t l = 0; l < count; ++l) {
                const LevelCoverage& shape = by_filter[grass::MipFilter::box][l];
                std::string row = fmt::format("| {} | {} x {} |", l, shape.width, shape.height);
                std::string alpha_cells;
                nlohmann::json level{{"level", l}, {"width", shape.width}, {"height", shape.height}};
                for (grass::MipFilter f : grass::kMipFilters) {
                    const LevelCoverage& c = by_filter[f][l];
                    const double error = 100.0 * (c.coverage - base);
                    row += fmt::format(" {:.1f} % ({:+.1f}) |", 100.0 * c.coverage, error);
                    alpha_cells += fmt::format(" {:.3f} |", c.mean_alpha);
                    level[to_string(f)] = {{"coverage", c.coverage}, {"mean_alpha", c.mean_alpha}};
                    if (l > 0) {
                        worst[f] = std::max(worst[f], std::abs(error));
                        sum[f] += std::abs(error);
                    }
                }
                result.markdown += row + alpha_cells + "\n";
                levels.push_back(level);
            }
            result.markdown += "\n| over levels 1-" + std::to_string(count - 1) + " | box | max-alpha | coverage-preserving |\n|---|---:|---:|---:|\n";
            std::string mean_row = "| mean coverage error (points) |", worst_row = "| largest coverage error (points) |";
            for (grass::MipFilter f : grass::kMipFilters) {
                mean_row += fmt::format(" {:.1f} |", sum[f] / double(std::max<size_t>(count - 1, 1)));
                worst_row += fmt::format(" {:.1f} |", worst[f]);
            }
            result.markdown += mean_row + "\n" + worst_row + "\n";
            result.numbers[source.label] = {{"base_coverage", base}, {"levels", levels}};
        }
        result.numbers["alpha_reference"] = a_r;
        if (params.integer("view_width") > 0) views_against_blades(gpu, scene, params, result);
        return result;
    }
};

// The filters judged by what the blades show (issue 37): each representation drawn as its
// technique draws it, under each filter, at each elevation, its pixels' coverage against
// grass.geometry's (one sample a pixel, alpha-tested: an unbiased estimate of the blades'
// coverage, test_grass_coverage) at the same view; tile MAE over 8 x 8 tiles and bias (the
// share of the blades' coverage gained or lost).
void MipCoverage::views_against_blades(const GpuContext& gpu, const Scene& scene, const ParamSet& params,
                                       FamilyBenchmarkResult& result) const {
    const uint32_t width = uint32_t(params.integer("view_width")), height = (width * 9 + 8) / 16;
    const float distance = glm::length(scene.camera.position - scene.camera.target);
    std::vector<float> elevations{5.0f, 15.0f, 30.0f, 55.0f, 80.0f};
    elevations.resize(size_t(params.integer("views")));
    const std::vector<TriangleMesh> meshes = build_scene_meshes(scene);
    const long long n = params.integer("slices");
    const std::vector<std::pair<std::string, std::map<std::string, ParamValue>>> techniques{
        {"grass.image", {{"resolution", params.integer("resolution")}}},
        {"grass.volume", {{"slices", n}, {"resolution", params.integer("slice_resolution")},
                          {"height_resolution", params.integer("height_resolution")}}},
        {"grass.slices", {{"slices", n}, {"resolution", params.integer("slice_resolution")},
                          {"height_resolution", params.integer("height_resolution")}}},
        {"grass.billboard", {{"resolution", params.integer("resolution")}}}};
    std::vector<Image> blades;
    for (float e : elevations)
        blades.push_back(coverage_of(gpu, seen_from(scene, e, distance), meshes, "grass.geometry",
                                     {{"samples", 1LL}, {"coverage", std::string("alpha_test")}}, width, height));
    result.markdown += fmt::format(
        "\n# Against the blades, from grazing to top-down\n\nEach representation as its technique draws it, baked "
        "and filtered as the row says (2x supersampled bakes but the first row; trilinear lookups but the last; "
        "alpha-tested at 0.5), its pixels' coverage against grass.geometry's (one sample a pixel, alpha-tested: "
        "an unbiased estimate of the blades' coverage) at the same view: {} x {} pixels, the scene's target seen "
        "from {:.1f} m at each elevation. Each cell: bias (the share of the blades' coverage gained or lost), "
        "then the tile MAE over 8 x 8 tiles.\n",
        width, height, distance);
    nlohmann::json views = nlohmann::json::object();
    for (const auto& [technique, base] : techniques) {
        result.markdown += fmt::format("\n## {}\n\n| filter |", technique);
        for (float e : elevations) result.markdown += fmt::format(" {:.0f}° |", e);
        result.markdown += "\n|---|";
        for (size_t i = 0; i < elevations.size(); ++i) result.markdown += "---:|";
        result.markdown += "\n";
        for (const FilterSetting& setting : filter_settings()) {
            std::map<std::string, ParamValue> values = base;
            values.insert(setting.params.begin(), setting.params.end());
            std::string row = "| " + setting.label + " |";
            nlohmann::json cells = nlohmann::json::array();
            for (size_t i = 0; i < elevations.size(); ++i) {
                const CoverageError err = compute_coverage_error(
                    coverage_of(gpu, seen_from(scene, elevations[i], distance), meshes, technique, values, width, height),
                    blades[i]);
                row += fmt::format(" {:+.2f} ({:.3f}) |", err.bias, err.tile_mae);
                cells.push_back({{"elevation", elevations[i]}, {"bias", err.bias}, {"tile_mae", err.tile_mae},
                                 {"pixels", err.pixels}});
            }
            result.markdown += row + "\n";
            views[technique][setting.label] = cells;
        }
    }
    result.numbers["views_against_blades"] = views;
}

RegisterFamilyBenchmark<MipCoverage> registered;

}  // namespace
}  // namespace canopy
