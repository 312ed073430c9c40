// The technique-isolated error measures the technique's shadow and nothing else (issue 8):
// - on a shadow-free variant of every committed scene (configs/experiments/checks/shadow-free.toml,
//   run through the runner) it reads about 0 for every technique, below 10 % of the whole-image
//   error, which aliasing and shading keep well above 0;
// - on the committed scenes it rises when a technique is broken on purpose: its shadow shifted
//   (the shadow map rendered from a light moved sideways), its footprint widened (PCF with an
//   absurd kernel over a coarse map), or its visibility buffer shifted by a few pixels.
#include "config/experiment_config.hpp"
#include "config/scene_config.hpp"
#include "core/pixel_visibility.hpp"
#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "run/experiment_runner.hpp"
#include "run/reference_provider.hpp"
#include "support/temp_folder.hpp"
#include "support/test_gpu.hpp"

#include "support/technique_variants.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>

using namespace canopy;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 160, kHeight = 90;
const fs::path kSource(CANOPY_SOURCE_DIR);

struct Render {
    Image image, visibility;
};

Render render(const Scene& scene, const std::vector<TriangleMesh>& meshes, const std::string& technique,
              const std::map<std::string, ParamValue>& params = {}) {
    FrameRenderer renderer(test::gpu(), scene, meshes, kWidth, kHeight, test::technique_graph(technique, params));
    renderer.render();
    return {renderer.read_color(), renderer.read_pixel_visibility()};
}

ImageMetrics errors(const Render& r, const ReferenceEntry& reference, const std::string& technique) {
    const PixelVisibilityPair pair{r.visibility, reference.pixel_visibility.visibility};
    return compute_metrics(r.image, reference.images.radiance, &pair, nullptr,
                           TechniqueRegistry::instance().find(technique)->error_columns());
}

// `image` moved `dx` pixels to the right, the first columns repeating the first.
Image shifted(const Image& image, int dx) {
    Image out = image;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* from = image.at(std::max(x - dx, 0), y);
            std::copy(from, from + 4, out.at(x, y));
        }
    return out;
}

}  // namespace

TEST_CASE("shadow-free scenes: every technique's isolated error is ~0, below 10 % of its whole-image error") {
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    Experiment experiment = load_experiment(kSource / "configs/experiments/checks/shadow-free.toml", registry);
    experiment.resolutions = {{kWidth, kHeight}};  // the committed size takes minutes on two cores
    experiment.warmup_frames = 0;
    experiment.rounds = 1;
    experiment.frames_per_sample = 1;
    const PreparedExperiment prepared = prepare_experiment(experiment, registry, test::gpu());
    const test::TempFolder folder("canopy-test-isolated");
    RunOptions options;
    options.out_dir = folder.path() / "run";
    options.show_progress = false;
    options.images = ImageOutput::none;
    options.reference_cache_dir = folder.path() / "cache";
    const RunRecord run = run_experiment(prepared, registry, test::gpu(), options);
    REQUIRE(run.status == "complete");
    REQUIRE(run.cases.size() == 4 * test::family_techniques("shadow").size());
    for (const CaseResult& c : run.cases) {
        CAPTURE(c.id);
        REQUIRE(c.image_error);
        const ImageMetrics& m = *c.image_error;
        INFO("whole image: RMSE " << m.rmse << ", MAE " << m.mae << "; isolated: visibility RMSE " << m.visibility_rmse
                                  << ", MAE " << m.visibility_mae << " over " << m.visibility_pixels
                                  << " pixels, excluded " << m.visibility_excluded);
        CHECK(m.columns.visibility);
        // Aliasing and shading alone keep the whole-image error well above 0 ...
        CHECK(m.rmse > 2e-3);
        // ... while the technique's visibility matches the truth's 1 wherever the light reaches.
        CHECK(m.visibility_pixels > kWidth * kHeight / 4);
        CHECK(m.visibility_rmse < 0.1 * m.rmse);
        CHECK(m.visibility_mae < 0.1 * m.mae);
        CHECK(m.visibility_rmse < 1e-4);
        CHECK(m.visibility_excluded < 0.01);
        CHECK(m.umbra_pixels == 0);
        CHECK(m.penumbra_pixels == 0);
    }
}

TEST_CASE("committed scenes: the isolated error rises when a technique's shadow is shifted or widened") {
    for (const char* name : {"spheres", "chairs", "car", "at-at"}) {
        CAPTURE(name);
        const Scene scene = load_scene(kSource / "configs/scenes" / (std::string(name) + ".toml"));
        const auto meshes = build_scene_meshes(scene);
        ReferenceProvider references({}, ReferenceSettings{64, 4, 1, 0});
        const ReferenceEntry& reference = references.get(scene, meshes, kWidth, kHeight);

        const Render hard = render(scene, meshes, "shadow.hard");
        const ImageMetrics hard_errors = errors(hard, reference, "shadow.hard");
        // A hard shadow under an area light is wrong in every penumbra: never 0.
        CHECK(hard_errors.visibility_rmse > 0.01);

        // Shifted: the shadow map rendered from the light moved sideways by 15 % of its distance
        // to what the camera looks at; the reference keeps the real light.
        Scene moved = scene;
        Light& light = moved.lights.front();
        const float distance = glm::length(light.position - scene.camera.target);
        light.position += 0.15f * distance * glm::normalize(glm::cross(light.direction, glm::vec3(0, 0, 1)));
        const ImageMetrics shifted_shadow = errors(render(moved, meshes, "shadow.hard"), reference, "shadow.hard");

        // Widened: PCF with its widest kernel over a 64-texel map, against PCF's defaults.
        const ImageMetrics pcf = errors(render(scene, meshes, "shadow.pcf"), reference, "shadow.pcf");
        const ImageMetrics wide = errors(render(scene, meshes, "shadow.pcf", {{"kernel", 11LL}, {"resolution", 64LL}}),
                                         reference, "shadow.pcf");

        // Shifted after the fact: hard's own visibility buffer moved 5 pixels.
        const ImageMetrics moved_buffer =
            errors(Render{hard.image, shifted(hard.visibility, 5)}, reference, "shadow.hard");

        INFO("visibility RMSE: hard " << hard_errors.visibility_rmse << ", shadow shifted "
                                      << shifted_shadow.visibility_rmse << ", buffer shifted "
                                      << moved_buffer.visibility_rmse << "; PCF " << pcf.visibility_rmse
                                      << ", widened " << wide.visibility_rmse);
        CHECK(shifted_shadow.visibility_rmse > 1.4 * hard_errors.visibility_rmse);
        CHECK(moved_buffer.visibility_rmse > 1.4 * hard_errors.visibility_rmse);
        CHECK(wide.visibility_rmse > 2.0 * pcf.visibility_rmse);
        CHECK(wide.visibility_mae > 2.0 * pcf.visibility_mae);
    }
}
