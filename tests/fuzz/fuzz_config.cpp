// libFuzzer target: the config loader. An input is an experiment file and a scene file
// separated by a line "#%scene" (without the line: a scene file only). Both are written to a
// scratch folder as experiment.toml and scene.toml (an experiment names its scenes by path, so
// scenes = ["scene.toml"] loads the second part), then loaded as canopy does: parse_scene,
// load_experiment, expand_cases, and the primitive objects' meshes. Mesh files are fuzzed by
// fuzz_mesh. A ConfigError is a clean rejection; anything else (a crash, a sanitizer report,
// another exception, or a loaded config that breaks a documented limit) is a finding.
#include "config/experiment_config.hpp"
#include "config/file_name_rules.hpp"
#include "config/scene_config.hpp"
#include "core/error.hpp"
#include "core/registry.hpp"
#include "scene/geometry.hpp"
#include "scene/scene_limits.hpp"
#include "scratch_folder.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <string_view>

using namespace canopy;

namespace {

constexpr std::string_view kSceneMarker = "#%scene\n";
constexpr size_t kMaxBuiltVertices = 1u << 16;  // per object, over its instances: keeps each run fast

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool within(const glm::vec3& v, double bound) {
    return std::abs(v.x) <= bound && std::abs(v.y) <= bound && std::abs(v.z) <= bound;
}

using fuzz::property_violated;

// What every scene that loads must satisfy (configs/README.md, "Limits").
void check_scene(const Scene& scene) {
    if (file_name_problem(scene.name)) property_violated("scene name " + printable_name(scene.name) + " was accepted");
    const Camera& c = scene.camera;
    if (!within(c.position, limits::kMaxCoordinate) || !within(c.target, limits::kMaxCoordinate))
        property_violated("camera outside the coordinate range");
    if (!finite(c.up) || std::abs(glm::length(c.up) - 1.0f) > 1e-4f) property_violated("camera up not a unit vector");
    if (!(c.near_plane > 0.0f && c.far_plane > c.near_plane && c.far_plane <= float(limits::kMaxFar)))
        property_violated("camera clip range");
    if (!(c.fov_y_degrees > 0.0f && c.fov_y_degrees < 179.0f)) property_violated("camera fov");
    for (const Light& light : scene.lights) {
        if (!within(light.position, limits::kMaxCoordinate)) property_violated("light outside the coordinate range");
        if (!finite(light.direction) || std::abs(glm::length(light.direction) - 1.0f) > 1e-4f)
            property_violated("light direction not a unit vector");
        if (!(light.intensity >= 0.0f && light.intensity <= float(limits::kMaxIntensity))) property_violated("intensity");
        if (!finite(light.color) || !within(light.color, limits::kMaxColor)) property_violated("color");
        if (light.type == LightType::rect &&
            !(light.rect_size.x >= float(limits::kMinLightSize) && light.rect_size.y >= float(limits::kMinLightSize)))
            property_violated("rect size");
        if (light.type == LightType::sphere && !(light.sphere_radius >= float(limits::kMinLightSize)))
            property_violated("sphere radius");
    }
    if (!finite(scene.ambient) || !finite(scene.background)) property_violated("ambient or background");
}

// Builds the meshes of the primitive objects (mesh files are fuzz_mesh's) that stay small,
// and checks that every vertex is finite and inside the coordinate range.
void build_primitives(const Scene& scene) {
    Scene primitives = scene;
    std::erase_if(primitives.objects, [](const Object& object) {
        const size_t segments = size_t(object.segments) + 1;
        const size_t vertices = object.shape == ShapeType::mesh ? SIZE_MAX
                              : object.shape == ShapeType::sphere ? segments * (segments / 2 + 1)
                                                                  : 4 * segments + 24;
        return vertices == SIZE_MAX || vertices * object.instances.size() > kMaxBuiltVertices;
    });
    const std::vector<TriangleMesh> meshes = build_scene_meshes(primitives);
    const auto check = [](const glm::mat4& matrix, const Vertex& vertex) {
        const glm::vec3 world(matrix * glm::vec4(vertex.position, 1.0f));
        if (!finite(world) || !within(world, limits::kMaxCoordinate * 1.0001))
            property_violated("a world-space vertex outside the coordinate range was accepted");
        if (!finite(vertex.normal)) property_violated("a non-finite normal");
    };
    // meshes: the objects', then the populations' prototypes (build_scene_meshes).
    for (size_t i = 0; i < primitives.objects.size(); ++i)
        for (const Transform& instance : primitives.objects[i].instances)
            for (const Vertex& vertex : meshes[i].vertices) check(instance.matrix(), vertex);
    for (size_t p = 0; p < primitives.populations.size(); ++p) {
        const TriangleMesh& prototype = meshes[primitives.objects.size() + p];
        size_t checked = 0;  // every copy's placement, a bounded number of vertices in all
        const size_t stride = 1 + prototype.vertices.size() / 64;
        const auto copies = generate_instances(primitives.populations[p]);
        for (const PopulationInstance& copy : *copies)
            for (size_t v = 0; v < prototype.vertices.size() && checked < kMaxBuiltVertices; v += stride, ++checked)
                check(copy.model, prototype.vertices[v]);
    }
}

void check_case_ids(const std::vector<Case>& cases) {
    for (const Case& c : cases) {
        // The longest file written per case is "<id>.error.png"; file names hold 255 bytes.
        if (c.id.size() + std::string_view(".error.png").size() > 255)
            property_violated(fmt::format("case id of {} bytes is too long for a file name", c.id.size()));
        if (file_name_safe(c.id) != c.id || c.id.find("..") != std::string::npos || c.id.front() == '.' ||
            c.id.front() == '-')
            property_violated("case id " + printable_name(c.id) + " is not a safe file name");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const fuzz::ScratchFolder folder("canopy-fuzz-config");
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const size_t marker = input.find(kSceneMarker);
    const std::string_view experiment_text = marker == std::string_view::npos ? std::string_view() : input.substr(0, marker);
    const std::string_view scene_text =
        marker == std::string_view::npos ? input : input.substr(marker + kSceneMarker.size());

    const std::filesystem::path scene_file = folder.write("scene.toml", scene_text);
    try {
        const Scene scene = parse_scene(std::string(scene_text), scene_file);
        check_scene(scene);
        build_primitives(scene);
    } catch (const ConfigError&) {
    }
    if (experiment_text.empty()) return 0;

    const std::filesystem::path experiment_file = folder.write("experiment.toml", experiment_text);
    try {
        const TechniqueRegistry& registry = TechniqueRegistry::instance();
        const Experiment experiment = load_experiment(experiment_file, registry);
        if (file_name_problem(experiment.name)) property_violated("experiment name accepted");
        for (const Scene& scene : experiment.scenes) check_scene(scene);
        check_case_ids(expand_cases(experiment, registry));
    } catch (const ConfigError&) {
    }
    return 0;
}
