// Scenes the raster path used to crash on, and experiments whose cases cannot run: an empty
// scene renders its background, and every refused case is listed with a hint that fits why.
#include "config/experiment_config.hpp"
#include "config/scene_config.hpp"
#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "run/experiment_runner.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <optional>
#include <random>

using namespace canopy;

namespace {

struct TempFolder {
    std::filesystem::path path;
    TempFolder() {
        path = std::filesystem::temp_directory_path() / ("canopy_test_refusals_" + std::to_string(std::random_device()()));
        std::filesystem::create_directories(path);
    }
    ~TempFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
    std::filesystem::path write(const std::string& name, const std::string& text) const {
        std::ofstream(path / name, std::ios::binary) << text;
        return path / name;
    }
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

size_t count(const std::string& text, const std::string& part) {
    size_t n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
    return n;
}

std::optional<ConfigError> prepare_error(const Experiment& experiment) {
    try {
        prepare_experiment(experiment, TechniqueRegistry::instance(), test::gpu());
    } catch (const ConfigError& error) {
        return error;
    }
    return std::nullopt;
}

}  // namespace

TEST_CASE("a scene with no objects renders its background with every kind of shadow map") {
    // Before: a segfault on the zero-size vertex buffer.
    const Scene scene = parse_scene("[scene]\nbackground = [0.25, 0.5, 1]\n[[light]]\ntype = \"sphere\"\n", "empty.toml");
    for (const char* technique : {"shadow.hard", "shadow.pcss", "shadow.vsm", "shadow.ssss"}) {
        CAPTURE(technique);
        const Image image = test::render_technique(scene, technique, {}, 32, 24);
        REQUIRE(image.width == 32);
        bool background = true;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const float* p = &image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
                background = background && p[0] == 0.25f && p[1] == 0.5f && p[2] == 1.0f;
            }
        CHECK(background);
    }
}
