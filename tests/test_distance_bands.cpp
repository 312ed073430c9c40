// Error by distance from the eye (metrics/distance_bands.hpp): which band each pixel falls in, the
// per-band FLIP means compute_metrics reports, the [reference] distance_bands key, and a run that
// reports them.
#include "config/experiment_config.hpp"
#include "core/pixel_visibility.hpp"
#include "core/registry.hpp"
#include "metrics/distance_bands.hpp"
#include "metrics/flip.hpp"
#include "metrics/image_metrics.hpp"
#include "report/json_record_reader.hpp"
#include "report/markdown_report.hpp"
#include "support/config_error_of.hpp"
#include "support/quiet_run.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace canopy;
namespace pv = canopy::pixel_visibility;

namespace {

// A camera at the origin looking down -z, 90 degrees vertical field of view.
Camera straight_camera() {
    Camera camera;
    camera.position = glm::vec3(0.0f);
    camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.fov_y_degrees = 90.0f;
    return camera;
}

// The distance to a point at view depth `depth` seen through pixel centre (x, y), written out from
// the pinhole model: the ray's direction is forward + ndc_x tan(fov/2) aspect right + ndc_y
// tan(fov/2) up, whose component along forward is 1, so the distance is depth times its length.
double distance_by_hand(const Camera& camera, int width, int height, int x, int y, double depth) {
    const double tan_half = std::tan(glm::radians(double(camera.fov_y_degrees)) / 2.0);
    const double ndc_x = 2.0 * (x + 0.5) / width - 1.0, ndc_y = 1.0 - 2.0 * (y + 0.5) / height;
    const double a = ndc_x * tan_half * width / height, b = ndc_y * tan_half;
    return depth * std::sqrt(1.0 + a * a + b * b);
}

Image surfaces(int width, int height, float depth) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            p[pv::kVisibility] = pv::kNotLit;
            p[pv::kViewDepth] = depth;
            p[pv::kSurface] = 1.0f;
        }
    return image;
}

}  // namespace

TEST_CASE("distance bands: a pixel's band is the distance along its ray, not its view depth") {
    const Camera camera = straight_camera();
    const int width = 9, height = 5;
    Image image = surfaces(width, height, 10.0f);
    image.at(3, 2)[pv::kSurface] = 0.0f;  // background: no band
    // The centre pixel's ray is the view axis (distance 10); the corner's is longer.
    const double corner = distance_by_hand(camera, width, height, 0, 0, 10.0);
    REQUIRE(corner > 14.0);
    // Bands between the two: the centre lies in the middle, the corners far.
    const std::vector<DistanceBand> bands = classify_distances(image, camera, {9.0, 12.0});
    const auto band = [&](int x, int y) { return bands[size_t(y * width + x)]; };
    CHECK(band(4, 2) == DistanceBand::middle);
    CHECK(band(3, 2) == DistanceBand::none);
    CHECK(band(0, 0) == DistanceBand::far);
    CHECK(band(8, 4) == DistanceBand::far);
    // Every pixel against the hand-written distance, with bands just either side of its own.
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (x == 3 && y == 2) continue;
            const double d = distance_by_hand(camera, width, height, x, y, 10.0);
            CAPTURE(x);
            CAPTURE(y);
            CHECK(classify_distances(image, camera, {d * 1.001, d * 1.002})[size_t(y * width + x)] == DistanceBand::near);
            CHECK(classify_distances(image, camera, {d * 0.999, d * 1.001})[size_t(y * width + x)] == DistanceBand::middle);
            CHECK(classify_distances(image, camera, {d * 0.998, d * 0.999})[size_t(y * width + x)] == DistanceBand::far);
        }
    // Empty bands are allowed: [0, 0] puts every surface far.
    for (size_t i = 0; i < bands.size(); ++i)
        CHECK(classify_distances(image, camera, {0.0, 0.0})[i] == (i == 2 * 9 + 3 ? DistanceBand::none : DistanceBand::far));
    CHECK_THROWS_AS(classify_distances(image, camera, {5.0, 4.0}), std::invalid_argument);
    CHECK_THROWS_AS(classify_distances(image, camera, {-1.0, 4.0}), std::invalid_argument);
    CHECK_THROWS_AS(classify_distances(Image(), camera, {1.0, 4.0}), std::invalid_argument);
}

TEST_CASE("distance bands: means over each band's finite values; an empty band is NaN") {
    using B = DistanceBand;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<float> values{1.0f, 3.0f, 0.5f, nan, 0.25f, 9.0f};
    const std::vector<DistanceBand> bands{B::near, B::near, B::far, B::far, B::far, B::none};
    const BandMeans m = band_means(values, bands);
    CHECK(m.near == doctest::Approx(2.0));
    CHECK(m.near_pixels == 2);
    CHECK(std::isnan(m.middle));
    CHECK(m.middle_pixels == 0);
    CHECK(m.far == doctest::Approx(0.375));
    CHECK(m.far_pixels == 2);
    CHECK_THROWS_AS(band_means(values, {B::near}), std::invalid_argument);
}

TEST_CASE("compute_metrics: FLIP per distance band is the FLIP map's mean over the band's pixels") {
    const int width = 24, height = 16;
    Image reference(width, height), test(width, height);
    std::vector<DistanceBand> bands(size_t(width * height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* r = reference.at(x, y);
            float* t = test.at(x, y);
            r[0] = r[1] = r[2] = 0.4f;
            r[3] = t[3] = 1.0f;
            // The error grows to the right; the bands are columns of 8.
            t[0] = t[1] = t[2] = 0.4f + 0.02f * float(x);
            bands[size_t(y * width + x)] = x < 8 ? DistanceBand::near : x < 16 ? DistanceBand::middle : DistanceBand::far;
        }
    bands[0] = DistanceBand::none;
    std::vector<float> map;
    MetricOptions options;
    options.distance_bands = &bands;
    const ImageMetrics m = compute_metrics(test, reference, nullptr, nullptr, {}, options, &map);
    double sums[4] = {0, 0, 0, 0};
    long long counts[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < map.size(); ++i) sums[size_t(bands[i])] += map[i], ++counts[size_t(bands[i])];
    CHECK(m.near_pixels == 8 * height - 1);
    CHECK(m.middle_pixels == 8 * height);
    CHECK(m.far_pixels == 8 * height);
    CHECK(m.flip_near == doctest::Approx(sums[1] / double(counts[1])));
    CHECK(m.flip_middle == doctest::Approx(sums[2] / double(counts[2])));
    CHECK(m.flip_far == doctest::Approx(sums[3] / double(counts[3])));
    CHECK(m.flip_near < m.flip_middle);
    CHECK(m.flip_middle < m.flip_far);
    const ImageMetrics without = compute_metrics(test, reference, nullptr, nullptr, {});
    CHECK(std::isnan(without.flip_near));
    CHECK(std::isnan(without.flip_far));
    CHECK(without.far_pixels == 0);
}

TEST_CASE("[reference] distance_bands: two distances in order, or an error at its line") {
    test::TempFolder folder;
    folder.write("scene.toml", "[[light]]\ntype = \"directional\"\n");
    const std::string head = "[experiment]\nscenes = [\"scene.toml\"]\n[[technique]]\nname = \"shadow.hard\"\n[reference]\n";
    const auto load = [&](const std::string& line) {
        return load_experiment(folder.write("experiment.toml", head + line + "\n"), TechniqueRegistry::instance());
    };
    const Experiment set = load("distance_bands = [8.3, 30.5]");
    REQUIRE(set.distance_bands);
    CHECK(set.distance_bands->middle_from == 8.3);  // as written, not rounded to a float
    CHECK(set.distance_bands->far_from == 30.5);
    CHECK_FALSE(load("seed = 2").distance_bands);
    for (const char* bad : {"distance_bands = [30, 8]", "distance_bands = [-1, 8]", "distance_bands = 8",
                            "distance_bands = [1, 2, 3]", "distance_bands = \"far\""}) {
        CAPTURE(bad);
        const auto error = test::config_error_of([&] { load(bad); });
        REQUIRE(error);
        CHECK(error->line() == 6);
    }
    // A claim on a band's FLIP needs the bands: an error at the claim, not "not measured" after the run.
    const std::string claim = "\n[paper]\nid = \"x\"\ntitle = \"x\"\nsource = \"x\"\ncolumn_key = \"scene\"\n"
                              "columns = [\"scene\"]\nbaseline = \"a\"\n[[paper.row]]\nlabel = \"a\"\n"
                              "technique = \"shadow.hard\"\nvalues = [1.0]\n[[paper.claim]]\ntext = \"x\"\n"
                              "left = \"a\"\nright = \"a\"\nmetric = \"flip_far\"\noffset = 0.02\n"
                              "states = \"direction\"\nwhy = \"canopy target\"\n";
    CHECK(load("distance_bands = [1, 2]" + claim).paper->claims.size() == 1);
    const auto error = test::config_error_of([&] { load("seed = 2" + claim); });
    REQUIRE(error);
    CHECK(error->line() == 18);  // its [[paper.claim]]
    CHECK(error->what() != std::string());
}

TEST_CASE("a run with distance_bands reports FLIP near, in the middle and far, and results.json keeps them") {
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    Experiment experiment = load_experiment(std::string(CANOPY_TEST_DATA) + "/experiments/tiny.toml", registry);
    experiment.rounds = 1;
    experiment.warmup_frames = 0;
    experiment.techniques.resize(1);  // shadow.hard
    static const test::TempFolder folder("canopy-test-distance-bands");
    const auto run_with = [&](std::optional<DistanceBands> bands, const char* name) {
        experiment.distance_bands = bands;
        return test::quiet_run(experiment, folder.path() / name, folder.path() / "cache");
    };
    // tiny.toml's eye is 7.1 from the floor's centre; the floor reaches from about 5 to 10 away.
    const RunRecord banded = run_with(DistanceBands{6.5, 7.5}, "banded");
    REQUIRE(banded.status == "complete");
    REQUIRE(banded.cases.size() == 1);
    REQUIRE(banded.cases[0].image_error);
    const ImageMetrics& m = *banded.cases[0].image_error;
    CHECK(m.near_pixels > 0);
    CHECK(m.middle_pixels > 0);
    CHECK(m.far_pixels > 0);
    CHECK(m.near_pixels + m.middle_pixels + m.far_pixels <= 96 * 64);
    CHECK(std::isfinite(m.flip_near));
    CHECK(std::isfinite(m.flip_middle));
    CHECK(std::isfinite(m.flip_far));
    CHECK(markdown_table(banded).find("FLIP far") != std::string::npos);
    const RunRecord written = read_json_report(folder.path() / "banded" / "results.json");
    REQUIRE(written.cases.size() == 1);
    CHECK(written.cases[0].image_error->flip_far == doctest::Approx(m.flip_far).epsilon(1e-9));
    CHECK(written.cases[0].image_error->far_pixels == m.far_pixels);
    REQUIRE(written.distance_bands);
    CHECK(written.distance_bands->middle_from == 6.5);
    CHECK(written.distance_bands->far_from == 7.5);

    const RunRecord plain = run_with(std::nullopt, "plain");
    REQUIRE(plain.status == "complete");
    CHECK(std::isnan(plain.cases[0].image_error->flip_far));
    CHECK(plain.cases[0].image_error->far_pixels == 0);
    CHECK_FALSE(read_json_report(folder.path() / "plain" / "results.json").distance_bands);
    CHECK(markdown_table(plain).find("FLIP far") == std::string::npos);
}
