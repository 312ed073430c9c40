#include "config/scene_config.hpp"

#include "config/file_name_rules.hpp"
#include "config/toml_reader.hpp"
#include "report/image_files.hpp"
#include "scene/height_field.hpp"
#include "scene/population_kind.hpp"
#include "scene/scene_limits.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace canopy {

glm::vec3 read_direction(TomlReader& reader, std::string_view key, const glm::vec3& fallback,
                         const std::string& zero_message, const std::string& zero_hint) {
    const glm::dvec3 direction(reader.get_vec3(key, fallback, Broadcast::forbidden));
    const double length = glm::length(direction);
    if (!(length >= 1e-6)) throw reader.error(key, zero_message, zero_hint);
    return glm::vec3(direction / length);
}

namespace {

constexpr std::array kLightTypeNames{"directional", "spot", "rect", "sphere"};
constexpr std::array kLightTypes{LightType::directional, LightType::spot, LightType::rect, LightType::sphere};
constexpr std::array kShapeNames{"plane", "box", "sphere", "cylinder", "mesh", "heightfield"};
constexpr std::array kShapes{ShapeType::plane, ShapeType::box, ShapeType::sphere, ShapeType::cylinder,
                             ShapeType::mesh, ShapeType::heightfield};

// Reads a required enum-like string, suggesting the closest name when it is misspelled.
template <typename Enum, size_t N>
Enum read_kind(TomlReader& reader, std::string_view key, const std::array<const char*, N>& names,
               const std::array<Enum, N>& values, const char* what) {
    const std::string text = reader.require_string(key, fmt::format("\"{}\"", names[0]));
    std::vector<std::string> choices(names.begin(), names.end());
    for (size_t i = 0; i < N; ++i)
        if (text == names[i]) return values[i];
    const std::string suggestion = closest_match(text, choices);
    const std::string all = fmt::format("{}", fmt::join(choices, ", "));
    throw reader.error(key, fmt::format("unknown {} '{}'", what, text),
                       suggestion.empty() ? fmt::format("{}s: {}", what, all)
                                          : fmt::format("did you mean '{}'? {}s: {}", suggestion, what, all));
}

// Value checks that name the key's line.
void require_positive(TomlReader& reader, std::string_view key, float value) {
    if (value > 0.0f) return;
    throw reader.error(key, fmt::format("{} must be greater than 0, got {}", reader.describe_key(key), value),
                       "use a positive value");
}

void require_non_negative(TomlReader& reader, std::string_view key, float value) {
    if (value >= 0.0f) return;
    throw reader.error(key, fmt::format("{} must not be negative, got {}", reader.describe_key(key), value),
                       "use a value >= 0");
}

void require_positive(TomlReader& reader, std::string_view key, const glm::vec2& value) {
    if (value.x > 0.0f && value.y > 0.0f) return;
    throw reader.error(key, fmt::format("{} must be greater than 0 in every component, got [{}, {}]",
                                        reader.describe_key(key), value.x, value.y),
                       "use positive sizes");
}

void require_positive(TomlReader& reader, std::string_view key, const glm::vec3& value) {
    if (value.x > 0.0f && value.y > 0.0f && value.z > 0.0f) return;
    throw reader.error(key, fmt::format("{} must be greater than 0 in every component, got [{}, {}, {}]",
                                        reader.describe_key(key), value.x, value.y, value.z),
                       "use positive sizes");
}

void require_in_range(TomlReader& reader, std::string_view key, const glm::vec3& value, float min, float max) {
    for (int i = 0; i < 3; ++i) {
        if (value[i] >= min && value[i] <= max) continue;
        throw reader.error(key, fmt::format("{} must lie in [{}, {}] in every component, got [{}, {}, {}]",
                                            reader.describe_key(key), min, max, value.x, value.y, value.z),
                           fmt::format("use values in [{}, {}]", min, max));
    }
}

void require_non_negative(TomlReader& reader, std::string_view key, const glm::vec3& value) {
    for (int i = 0; i < 3; ++i) {
        if (value[i] >= 0.0f) continue;
        throw reader.error(key, fmt::format("{} must not be negative, got [{}, {}, {}]", reader.describe_key(key),
                                            value.x, value.y, value.z),
                           "use values >= 0");
    }
}

// A value in [min, max]; `why` says what the range protects, for the hint.
void require_between(TomlReader& reader, std::string_view key, float value, double min, double max,
                     const std::string& why) {
    if (value >= float(min) && value <= float(max)) return;  // as floats: near = 1e-6 is allowed
    throw reader.error(key, fmt::format("{} must lie in [{}, {}], got {}", reader.describe_key(key), min, max, value),
                       why);
}

void require_between(TomlReader& reader, std::string_view key, const glm::vec3& value, double min, double max,
                     const std::string& why) {
    for (int i = 0; i < 3; ++i) {
        if (value[i] >= float(min) && value[i] <= float(max)) continue;
        throw reader.error(key, fmt::format("{} must lie in [{}, {}] in every component, got [{}, {}, {}]",
                                            reader.describe_key(key), min, max, value.x, value.y, value.z),
                           why);
    }
}

// A position inside the cube of side 2 * limits::kMaxCoordinate around the origin.
void require_in_scene(TomlReader& reader, std::string_view key, const glm::vec3& value) {
    const double bound = limits::kMaxCoordinate;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(value[i]) <= float(bound)) continue;
        throw reader.error(key, fmt::format("{} = [{}, {}, {}] lies outside the scene's coordinate range [-{}, {}]",
                                            reader.describe_key(key), value.x, value.y, value.z, bound, bound),
                           "canopy computes in single precision: keep every coordinate within 1e6 scene units "
                           "(configs/README.md, \"Limits\"); move the scene closer to the origin or change its units");
    }
}

bool nearly_parallel(const glm::vec3& a, const glm::vec3& b) {
    return std::abs(glm::dot(glm::normalize(a), glm::normalize(b))) > 0.9999f;
}

const std::string kLightRangeWhy =
    "within this range the reference's single-precision sums stay finite (configs/README.md, \"Limits\")";

void read_scene_section(TomlReader& reader, Scene& scene) {
    scene.name = reader.get_string("name", scene.name);
    if (scene.name.empty()) throw reader.error("name", "the scene name must not be empty", "name = \"spheres\"");
    scene.ambient = reader.get_vec3("ambient", scene.ambient);
    require_non_negative(reader, "ambient", scene.ambient);
    require_between(reader, "ambient", scene.ambient, 0.0, limits::kMaxRadiance, kLightRangeWhy);
    scene.background = reader.get_vec3("background", scene.background);
    require_non_negative(reader, "background", scene.background);
    require_between(reader, "background", scene.background, 0.0, limits::kMaxRadiance, kLightRangeWhy);
    reader.finish();
}

void read_camera(TomlReader& reader, Camera& camera) {
    camera.position = reader.get_vec3("position", camera.position, Broadcast::forbidden);
    require_in_scene(reader, "position", camera.position);
    camera.target = reader.get_vec3("target", camera.target, Broadcast::forbidden);
    require_in_scene(reader, "target", camera.target);
    camera.up = read_direction(reader, "up", camera.up, "the camera's 'up' is the zero vector",
                               "use an up vector that is not along target - position, e.g. up = [0, 1, 0]");
    camera.fov_y_degrees = float(reader.get_float("fov", camera.fov_y_degrees));
    camera.near_plane = float(reader.get_float("near", camera.near_plane));
    camera.far_plane = float(reader.get_float("far", camera.far_plane));
    reader.finish();

    if (!(camera.fov_y_degrees > 0.0f && camera.fov_y_degrees < 179.0f))
        throw reader.error("fov", fmt::format("'fov' in [camera] must lie in (0, 179) degrees, got {}", camera.fov_y_degrees),
                           "fov is the vertical field of view in degrees, e.g. fov = 45");
    require_between(reader, "near", camera.near_plane, limits::kMinNear, limits::kMaxFar,
                    "near is the near clip distance in scene units, e.g. near = 0.1");
    require_between(reader, "far", camera.far_plane, limits::kMinNear, limits::kMaxFar,
                    "far is the far clip distance; 1e7 reaches every corner of the scene's coordinate range");
    if (!(camera.far_plane > camera.near_plane))
        throw reader.error(reader.has("far") ? "far" : "near",
                           fmt::format("'far' ({}) must be greater than 'near' ({}) in [camera]", camera.far_plane,
                                       camera.near_plane),
                           "choose near < far, e.g. near = 0.1, far = 100");
    const glm::vec3 view = camera.target - camera.position;
    if (glm::length(view) < 1e-6f)
        throw reader.error("target", "the camera's 'target' equals its 'position'",
                           "the camera looks from position towards target; move one of them");
    if (glm::length(camera.up) < 1e-6f || nearly_parallel(camera.up, view))
        throw reader.error("up", "the camera's 'up' is zero or parallel to its viewing direction",
                           "use an up vector that is not along target - position, e.g. up = [0, 1, 0]");
}

// Which light types use each type-specific key, so a misplaced key gets a precise hint.
struct LightKeyUse {
    const char* key;
    std::vector<LightType> types;
    const char* described;
};

const std::vector<LightKeyUse>& light_key_uses() {
    static const std::vector<LightKeyUse> uses{
        {"position", {LightType::spot, LightType::rect, LightType::sphere}, "spot, rect and sphere lights"},
        {"direction", {LightType::directional, LightType::spot, LightType::rect}, "directional, spot and rect lights"},
        {"size", {LightType::rect}, "rect lights"},
        {"radius", {LightType::sphere}, "sphere lights"},
        {"angle", {LightType::spot}, "spot lights"},
        {"up", {LightType::rect}, "rect lights"},
    };
    return uses;
}

Light read_light(TomlReader& reader) {
    Light light;
    light.where = reader.where();
    light.type = read_kind(reader, "type", kLightTypeNames, kLightTypes, "light type");
    const std::string type_name = kLightTypeNames[size_t(light.type)];

    for (const LightKeyUse& use : light_key_uses()) {
        if (std::find(use.types.begin(), use.types.end(), light.type) == use.types.end())
            reader.reject(use.key, fmt::format("{} lights", type_name), use.described);
    }
    auto applies = [&](const char* key) {
        for (const LightKeyUse& use : light_key_uses())
            if (use.key == std::string_view(key))
                return std::find(use.types.begin(), use.types.end(), light.type) != use.types.end();
        return true;
    };

    if (applies("position")) {
        light.position = reader.get_vec3("position", light.position, Broadcast::forbidden);
        require_in_scene(reader, "position", light.position);
    }
    if (applies("direction"))
        light.direction = read_direction(reader, "direction", light.direction,
                                         fmt::format("{} must not be the zero vector", reader.describe_key("direction")),
                                         "give the direction the light travels in, e.g. direction = [0, -1, 0]");
    light.color = reader.get_vec3("color", light.color);
    require_non_negative(reader, "color", light.color);
    require_between(reader, "color", light.color, 0.0, limits::kMaxColor, kLightRangeWhy + "; set the power with 'intensity'");
    light.intensity = float(reader.get_float("intensity", light.intensity));
    require_non_negative(reader, "intensity", light.intensity);
    require_between(reader, "intensity", light.intensity, 0.0, limits::kMaxIntensity, kLightRangeWhy);
    if (applies("size")) {
        light.rect_size = reader.get_vec2("size", light.rect_size, Broadcast::forbidden);
        require_positive(reader, "size", light.rect_size);
        for (int i = 0; i < 2; ++i)
            require_between(reader, "size", light.rect_size[i], limits::kMinLightSize, limits::kMaxLightSize,
                            kLightRangeWhy + " (radiance is intensity / area)");
    }
    if (applies("radius")) {
        light.sphere_radius = float(reader.get_float("radius", light.sphere_radius));
        require_positive(reader, "radius", light.sphere_radius);
        require_between(reader, "radius", light.sphere_radius, limits::kMinLightSize, limits::kMaxLightSize,
                        kLightRangeWhy + " (radiance is intensity / area)");
    }
    if (applies("angle")) {
        light.spot_angle_degrees = float(reader.get_float("angle", light.spot_angle_degrees));
        if (!(light.spot_angle_degrees > 0.0f && light.spot_angle_degrees <= 89.0f))
            throw reader.error("angle", fmt::format("{} must lie in (0, 89] degrees, got {}", reader.describe_key("angle"),
                                           light.spot_angle_degrees),
                               "angle is the cone's half-angle in degrees, e.g. angle = 30");
    }
    if (applies("up")) {
        const std::string up_hint = "'up' orients the rectangle's height axis; choose one not along 'direction', "
                                    "e.g. up = [0, 0, 1] for a light facing down";
        light.rect_up_hint = read_direction(reader, "up", light.rect_up_hint,
                                            fmt::format("'up' in {} is the zero vector", reader.context()), up_hint);
        if (!reader.has("up") && nearly_parallel(light.rect_up_hint, light.direction))
            throw reader.error("direction",
                               fmt::format("{} is parallel to the default 'up' [0, 0, 1]", reader.describe_key("direction")),
                               "add an 'up' key: " + up_hint);
        if (glm::length(light.rect_up_hint) < 1e-6f || nearly_parallel(light.rect_up_hint, light.direction))
            throw reader.error("up", fmt::format("'up' in {} is zero or parallel to its 'direction'", reader.context()),
                               up_hint);
    }
    light.casts_shadows = reader.get_bool("casts_shadows", light.casts_shadows);
    reader.finish();
    return light;
}

Transform read_transform(TomlReader& reader) {
    Transform transform;
    transform.translate = reader.get_vec3("translate", transform.translate, Broadcast::forbidden);
    require_in_scene(reader, "translate", transform.translate);
    transform.rotate_degrees = reader.get_vec3("rotate", transform.rotate_degrees, Broadcast::forbidden);
    transform.scale = reader.get_vec3("scale", transform.scale);
    if (transform.scale.x == 0.0f || transform.scale.y == 0.0f || transform.scale.z == 0.0f)
        throw reader.error("scale", fmt::format("{} must not be zero in any component", reader.describe_key("scale")),
                           "a zero scale flattens the object away; use e.g. scale = 1");
    for (int i = 0; i < 3; ++i) {
        const float magnitude = std::abs(transform.scale[i]);
        if (magnitude >= float(limits::kMinScale) && magnitude <= float(limits::kMaxScale)) continue;
        const glm::vec3& s = transform.scale;
        throw reader.error("scale",
                           fmt::format("{} = [{}, {}, {}]: every component's magnitude must lie in [{}, {}]",
                                       reader.describe_key("scale"), s.x, s.y, s.z, limits::kMinScale, limits::kMaxScale),
                           "a negative component mirrors the object; for models in other units (millimetres: "
                           "scale = 0.001) stay within this range, or convert the model");
    }
    return transform;
}

// An instance's whole transform must keep some volume: two small scales multiply.
void require_volume(TomlReader& reader, const Transform& transform) {
    const double determinant = glm::determinant(glm::dmat3(glm::mat3(transform.matrix())));
    if (std::abs(determinant) >= limits::kMinVolumeScale) return;
    throw reader.error("scale",
                       fmt::format("{} and its object's transform together scale volumes by {:.3g}, below {}",
                                   reader.context(), determinant, limits::kMinVolumeScale),
                       "the object would be flat; use larger scales on the object or the instance");
}

struct ShapeKeyUse {
    const char* key;
    std::vector<ShapeType> shapes;
    const char* described;
};

const std::vector<ShapeKeyUse>& shape_key_uses() {
    static const std::vector<ShapeKeyUse> uses{
        {"size", {ShapeType::plane, ShapeType::box, ShapeType::heightfield},
         "plane and heightfield ([x, z]) and box ([x, y, z]) shapes"},
        {"radius", {ShapeType::sphere, ShapeType::cylinder}, "sphere and cylinder shapes"},
        {"height", {ShapeType::cylinder}, "cylinder shapes"},
        {"segments", {ShapeType::sphere, ShapeType::cylinder}, "sphere and cylinder shapes"},
        {"file", {ShapeType::mesh}, "mesh shapes"},
        {"height_map", {ShapeType::heightfield}, "heightfield shapes"},
        {"height_map_file", {ShapeType::heightfield}, "heightfield shapes"},
        {"height_scale", {ShapeType::heightfield}, "heightfield shapes"},
        {"vertices", {ShapeType::heightfield}, "heightfield shapes"},
        {"periods", {ShapeType::heightfield}, "heightfield shapes"},
        {"seed", {ShapeType::heightfield}, "heightfield shapes"},
    };
    return uses;
}

// A heightfield's grid: smooth seeded hills, or an image's first channel (one pixel a vertex).
std::shared_ptr<const HeightField> read_height_field(TomlReader& reader, Object& object,
                                                     const std::filesystem::path& config_folder) {
    const glm::vec2 size = object.plane_size;
    const std::string map = reader.get_string("height_map", "hills");
    if (map != "hills" && map != "file")
        throw reader.error("height_map", fmt::format("{} must be \"hills\" or \"file\", got \"{}\"",
                                                     reader.describe_key("height_map"), map),
                           "height_map = \"hills\" (seeded value noise) or \"file\" with height_map_file = \"...\"");
    const float scale = float(reader.get_float("height_scale", 1.0));
    if (!(scale >= 0.0f) || scale > limits::kMaxCoordinate)
        throw reader.error("height_scale", fmt::format("{} must lie in [0, {}], got {}", reader.describe_key("height_scale"),
                                                       limits::kMaxCoordinate, scale),
                           "the world height of a map value of 1, e.g. height_scale = 2");
    if (map == "file") {
        for (const char* key : {"vertices", "periods", "seed"})
            reader.reject(key, "height_map = \"file\" (the image sets the grid)", "height_map = \"hills\"");
        const std::string file = reader.require_string("height_map_file", "\"terrain/heights.png\"");
        std::filesystem::path path(file);
        if (path.is_relative()) path = config_folder / path;
        path = std::filesystem::absolute(path).lexically_normal();
        object.height_map_file = path;
        if (std::filesystem::is_directory(path))
            throw reader.error("height_map_file", fmt::format("height map '{}' is a directory ({}), not an image", file,
                                                              path.string()),
                               "name the image file inside it, e.g. height_map_file = \"terrain/heights.png\"");
        if (!std::filesystem::is_regular_file(path))
            throw reader.error("height_map_file", fmt::format("height map '{}' not found (looked for {})", file, path.string()),
                               fmt::format("relative paths are resolved against the scene config's folder, {}",
                                           config_folder.string()));
        try {
            return std::make_shared<const HeightField>(height_field_from_image(read_image(path), size, scale, file));
        } catch (const std::exception& e) {
            throw reader.error("height_map_file", e.what(), "a greyscale PNG (8 or 16 bits) or OpenEXR image whose values lie in [0, 1]");
        }
    }
    reader.reject("height_map_file", "height_map = \"hills\"", "height_map = \"file\"");
    glm::vec2 vertices = reader.get_vec2("vertices", glm::vec2(65.0f));
    if (vertices != glm::floor(vertices) || vertices.x < 2.0f || vertices.y < 2.0f ||
        vertices.x > float(limits::kMaxHeightFieldVertices) || vertices.y > float(limits::kMaxHeightFieldVertices))
        throw reader.error("vertices", fmt::format("{} must be whole numbers in [2, {}], got [{}, {}]",
                                                   reader.describe_key("vertices"), limits::kMaxHeightFieldVertices,
                                                   vertices.x, vertices.y),
                           "grid vertices along x and z, e.g. vertices = 65 or [129, 65]");
    const long long periods = reader.get_int("periods", 3);
    if (periods < 1 || periods > 1024)
        throw reader.error("periods", fmt::format("{} must lie in [1, 1024], got {}", reader.describe_key("periods"), periods),
                           "noise lattice cells across the field, e.g. periods = 3");
    const long long seed = reader.get_int("seed", 1);
    if (seed < 0 || seed > 0xffffffffll)
        throw reader.error("seed", fmt::format("{} must lie in [0, 4294967295], got {}", reader.describe_key("seed"), seed),
                           "e.g. seed = 1");
    return std::make_shared<const HeightField>(
        hills_height_field(size, glm::uvec2(vertices), uint32_t(periods), uint32_t(seed), scale));
}

Object read_object(TomlReader& reader, size_t index, const std::filesystem::path& config_folder) {
    Object object;
    object.where = reader.where();
    object.shape = read_kind(reader, "shape", kShapeNames, kShapes, "shape");
    const std::string shape_name = kShapeNames[size_t(object.shape)];
    object.name = reader.get_string("name", fmt::format("{}{}", shape_name, index));
    if (object.name.empty()) throw reader.error("name", "an object's name must not be empty", "name = \"floor\"");

    for (const ShapeKeyUse& use : shape_key_uses()) {
        if (std::find(use.shapes.begin(), use.shapes.end(), object.shape) == use.shapes.end())
            reader.reject(use.key, fmt::format("{} shapes", shape_name), use.described);
    }

    switch (object.shape) {
        case ShapeType::plane:
            object.plane_size = reader.get_vec2("size", object.plane_size, Broadcast::forbidden);
            require_positive(reader, "size", object.plane_size);
            break;
        case ShapeType::heightfield:
            object.plane_size = reader.get_vec2("size", object.plane_size, Broadcast::forbidden);
            require_positive(reader, "size", object.plane_size);
            object.height_field = read_height_field(reader, object, config_folder);
            break;
        case ShapeType::box:
            object.box_size = reader.get_vec3("size", object.box_size);
            require_positive(reader, "size", object.box_size);
            break;
        case ShapeType::cylinder:
            object.height = float(reader.get_float("height", object.height));
            require_positive(reader, "height", object.height);
            [[fallthrough]];
        case ShapeType::sphere: {
            object.radius = float(reader.get_float("radius", object.radius));
            require_positive(reader, "radius", object.radius);
            const long long segments = reader.get_int("segments", object.segments);
            if (segments < 3 || segments > 1024)
                throw reader.error("segments", fmt::format("{} must lie in [3, 1024], got {}", reader.describe_key("segments"), segments),
                                   "use e.g. segments = 32");
            object.segments = int(segments);
            break;
        }
        case ShapeType::mesh: {
            const std::string file = reader.require_string("file", "\"meshes/model.glb\"");
            std::filesystem::path path(file);
            if (path.is_relative()) path = config_folder / path;
            object.mesh_file = std::filesystem::absolute(path).lexically_normal();
            std::error_code ignored;
            const auto status = std::filesystem::status(object.mesh_file, ignored);
            const std::string looked = fmt::format("relative paths are resolved against the scene config's folder, {}",
                                                   config_folder.string());
            if (!std::filesystem::exists(status))
                throw reader.error("file", fmt::format("mesh file '{}' not found (looked for {})", file,
                                                       object.mesh_file.string()),
                                   looked);
            if (std::filesystem::is_directory(status))
                throw reader.error("file", fmt::format("mesh file '{}' is a directory ({}), not a model file", file,
                                                       object.mesh_file.string()),
                                   "name the model file inside it, e.g. file = \"meshes/model.glb\"");
            if (!std::filesystem::is_regular_file(status))
                throw reader.error("file", fmt::format("mesh file '{}' is not a regular file ({})", file,
                                                       object.mesh_file.string()),
                                   "name a model file (glTF/GLB, OBJ, PLY, ...), not a device, pipe or socket");
            break;
        }
    }

    object.material.albedo = reader.get_vec3("albedo", object.material.albedo);
    require_in_range(reader, "albedo", object.material.albedo, 0.0f, 1.0f);
    object.casts_shadows = reader.get_bool("casts_shadows", object.casts_shadows);

    const Transform own = read_transform(reader);
    const std::string instance_context = fmt::format("instance of {}", reader.context());
    std::vector<TomlReader> instance_readers = reader.get_tables("instances", instance_context);
    if (reader.has("instances") && instance_readers.empty())
        throw reader.error("instances", fmt::format("{} must not be empty", reader.describe_key("instances")),
                           "remove 'instances' to draw the object once, or list at least one { translate = [...] }");
    object.instances.clear();
    if (instance_readers.empty()) object.instances.push_back(own);
    for (TomlReader& instance_reader : instance_readers) {
        Transform copy = own;
        copy.outer = read_transform(instance_reader).matrix();  // world = instance * object
        require_volume(instance_reader, copy);
        instance_reader.finish();
        object.instances.push_back(copy);
    }
    reader.finish();
    return object;
}

constexpr std::array kAlphaMaskKindNames{"stripes"};
constexpr std::array kAlphaMaskKinds{AlphaMask::Kind::stripes};
constexpr std::array kAxisNames{"x", "y", "z"};
constexpr std::array kAxes{0, 1, 2};

// alpha_mask = { kind = "stripes", axis = "x", period = 0.1, opaque = 0.5 } (harness/shaders/alpha_mask.h).
AlphaMask read_alpha_mask(TomlReader& reader) {
    AlphaMask mask;
    mask.kind = read_kind(reader, "kind", kAlphaMaskKindNames, kAlphaMaskKinds, "alpha mask kind");
    mask.axis = read_kind(reader, "axis", kAxisNames, kAxes, "axis");
    mask.period = float(reader.get_float("period", 0.0));
    mask.opaque = float(reader.get_float("opaque", 0.5));
    reader.finish();
    if (!reader.has("period"))
        throw reader.error("period", fmt::format("{} needs a 'period'", reader.context()),
                           "the length, in the prototype's own units, of one opaque slab and the gap after it, e.g. "
                           "period = 0.1");
    require_between(reader, "period", mask.period, limits::kMinScale, limits::kMaxScale,
                    "a length in the prototype's mesh space, e.g. period = 0.1");
    if (!(mask.opaque > 0.0f && mask.opaque <= 1.0f))
        throw reader.error("opaque", fmt::format("{} must lie in (0, 1], got {}", reader.describe_key("opaque"), mask.opaque),
                           "the fraction of each period that stays; 1 cuts nothing");
    return mask;
}

// A kind a technique family registered (scene/population_kind.hpp): name, material and the
// kind's typed parameters in `params`, checked like a technique's; the copies are generated now.
// The heightfield object a population's `terrain` key names, moved by a translation alone.
PopulationGround population_ground(const TomlReader& reader, const std::string& name, const std::vector<Object>& objects) {
    const auto object = std::find_if(objects.begin(), objects.end(), [&](const Object& o) { return o.name == name; });
    std::vector<std::string> heightfields;
    for (const Object& o : objects)
        if (o.shape == ShapeType::heightfield) heightfields.push_back(o.name);
    const std::string which = heightfields.empty() ? "the scene has no heightfield object: add one ([[object]] with "
                                                     "shape = \"heightfield\") before the population"
                                                   : fmt::format("heightfield objects: {}", fmt::join(heightfields, ", "));
    if (object == objects.end())
        throw reader.error("terrain", fmt::format("terrain = \"{}\" names no object of the scene", name), which);
    if (object->shape != ShapeType::heightfield)
        throw reader.error("terrain", fmt::format("terrain = \"{}\" names a {}, not a heightfield", name,
                                                  kShapeNames[size_t(object->shape)]), which);
    const Transform& t = object->instances.front();
    if (object->instances.size() != 1 || t.rotate_degrees != glm::vec3(0.0f) || t.scale != glm::vec3(1.0f) ||
        t.outer != glm::mat4(1.0f))
        throw reader.error("terrain", fmt::format("the heightfield '{}' is rotated, scaled or copied: a population can "
                                                  "stand only on a heightfield moved by `translate` alone", name),
                           "drop its rotate, scale and instances");
    return {object->height_field, t.translate, name};
}

Population read_family_population(TomlReader& reader, Population population, const PopulationKind& kind,
                                  const std::vector<Object>& objects) {
    if (reader.has("terrain"))
        population.ground = population_ground(reader, reader.get_string("terrain", ""), objects);
    Object& material = population.prototype;
    material.name = population.name;
    material.material.albedo = reader.get_vec3("albedo", material.material.albedo);
    require_in_range(reader, "albedo", material.material.albedo, 0.0f, 1.0f);
    material.casts_shadows = reader.get_bool("casts_shadows", material.casts_shadows);
    std::map<std::string, ParamValue> given;
    std::map<std::string, int> lines;
    const std::string params_context = fmt::format("params of {}", reader.context());
    if (std::optional<TomlReader> params = reader.get_table("params", params_context)) {
        for (auto&& [key, value] : params->table()) {
            if (!is_param_scalar(value))
                throw params->error_at(value, fmt::format("parameter '{}' of population kind '{}' must be a number, "
                                                          "boolean or string, got {}",
                                                          key.str(), kind.name(), describe_node(value)),
                                       "`canopy list` shows each population kind's parameters");
            given.emplace(std::string(key.str()), to_param_value(value));
            lines.emplace(std::string(key.str()), int(key.source().begin.line));
        }
    }
    reader.finish();
    population.params =
        ParamSet::resolve(kind.params(), given, lines, population.where, fmt::format("population kind '{}'", kind.name()));
    try {
        population.family = std::make_shared<const FamilyPopulation>(kind.generate(population.params, population.ground));
    } catch (const std::invalid_argument& e) {
        throw ConfigError(population.where.file, population.where.line,
                          fmt::format("population '{}' (kind '{}') cannot be generated: {}", population.name,
                                      kind.name(), e.what()),
                          "`canopy list` shows the kind's parameters and their ranges");
    }
    return population;
}

Population read_population(TomlReader& reader, size_t index, const std::filesystem::path& config_folder,
                           const std::vector<Object>& objects) {
    Population population;
    population.where = reader.where();
    population.name = reader.get_string("name", fmt::format("population{}", index));
    if (population.name.empty())
        throw reader.error("name", "a population's name must not be empty", "name = \"pebbles\"");
    const std::string kind_name = reader.require_string("kind", "\"scatter\"");
    if (kind_name != population_kinds::kScatter) {
        const PopulationKindRegistry& registry = PopulationKindRegistry::instance();
        if (const PopulationKind* kind = registry.find(kind_name)) {
            population.kind = kind_name;
            return read_family_population(reader, std::move(population), *kind, objects);
        }
        std::vector<std::string> names{population_kinds::kScatter};
        for (const std::string& name : registry.names()) names.push_back(name);
        const std::string suggestion = closest_match(kind_name, names);
        throw reader.error("kind", fmt::format("unknown population kind '{}'", kind_name),
                           fmt::format("{}population kinds: {}",
                                       suggestion.empty() ? "" : fmt::format("did you mean '{}'? ", suggestion),
                                       fmt::join(names, ", ")));
    }
    population.kind = population_kinds::kScatter;

    // Every key is read before the required ones are checked, so that a misspelled required key
    // is reported as misspelled (with the right name), not as missing.
    const long long count = reader.get_int("count", 0);
    population.region_min = reader.get_vec2("region_min", population.region_min, Broadcast::forbidden);
    population.region_max = reader.get_vec2("region_max", population.region_max, Broadcast::forbidden);
    population.ground_y = float(reader.get_float("ground", population.ground_y));
    const long long seed = reader.get_int("seed", 0);
    const glm::vec2 scale = reader.get_vec2("scale", glm::vec2(1.0f));
    population.random_yaw = reader.get_bool("random_yaw", population.random_yaw);
    const std::string prototype_context = fmt::format("prototype of {}", reader.context());
    std::optional<TomlReader> prototype = reader.get_table("prototype", prototype_context);
    std::optional<TomlReader> alpha_mask = reader.get_table("alpha_mask", fmt::format("alpha_mask of {}", reader.context()));
    reader.finish();
    if (alpha_mask) population.alpha_mask = read_alpha_mask(*alpha_mask);

    if (!reader.has("count"))
        throw reader.error("count", fmt::format("{} needs a 'count'", reader.context()),
                           "say how many copies to scatter, e.g. count = 100");
    if (count < 1 || count > limits::kMaxPopulationCount)
        throw reader.error("count", fmt::format("{} must lie in [1, {}], got {}", reader.describe_key("count"),
                                                limits::kMaxPopulationCount, count),
                           "the reference holds one Embree instance per copy (configs/README.md, \"Limits\")");
    population.count = uint32_t(count);

    for (const char* key : {"region_min", "region_max"})
        if (!reader.has(key))
            throw reader.error(key, fmt::format("{} needs 'region_min' and 'region_max'", reader.context()),
                               "the [x, z] corners of the ground rectangle, e.g. region_min = [-2, -2], "
                               "region_max = [2, 2]");
    for (const char* key : {"region_min", "region_max"}) {
        const glm::vec2 corner = std::string_view(key) == "region_min" ? population.region_min : population.region_max;
        require_in_scene(reader, key, glm::vec3(corner.x, 0.0f, corner.y));
    }
    if (!(population.region_max.x > population.region_min.x && population.region_max.y > population.region_min.y))
        throw reader.error("region_max",
                           fmt::format("{} = [{}, {}] must exceed 'region_min' = [{}, {}] in x and in z",
                                       reader.describe_key("region_max"), population.region_max.x,
                                       population.region_max.y, population.region_min.x, population.region_min.y),
                           "region_min is the rectangle's corner with the smaller x and z");
    require_in_scene(reader, "ground", glm::vec3(0.0f, population.ground_y, 0.0f));

    if (seed < 0)
        throw reader.error("seed", fmt::format("{} must not be negative, got {}", reader.describe_key("seed"), seed),
                           "any integer >= 0 picks one arrangement, e.g. seed = 7");
    population.seed = uint64_t(seed);

    for (int i = 0; i < 2; ++i)
        require_between(reader, "scale", scale[i], limits::kMinScale, limits::kMaxScale,
                        "scale = [min, max] draws each copy's uniform scale factor from [min, max]");
    if (!(scale.x <= scale.y))
        throw reader.error("scale", fmt::format("{} = [{}, {}]: min exceeds max", reader.describe_key("scale"), scale.x,
                                                scale.y),
                           "write it as [min, max], or one number for every copy alike");
    population.scale_min = scale.x;
    population.scale_max = scale.y;

    if (!prototype)
        throw reader.error("prototype", fmt::format("{} needs a 'prototype'", reader.context()),
                           "describe the copied shape as an [[object]] is described, e.g. "
                           "prototype = { shape = \"box\", size = 0.2, translate = [0, 0.1, 0] }");
    if (prototype->has("instances"))
        throw prototype->error("instances", fmt::format("a population's prototype has no 'instances' ({})",
                                                        prototype_context),
                               "the population places the copies: use 'count', the region and 'seed'");
    if (prototype->has("name"))
        throw prototype->error("name", fmt::format("a population's prototype has no 'name' ({})", prototype_context),
                               "name the population instead: name = \"...\" in its [[population]] table");
    population.prototype = read_object(*prototype, index, config_folder);
    population.prototype.name = population.name;
    return population;
}

}  // namespace

Scene parse_scene(const std::string& text, const std::filesystem::path& file) {
    const toml::table root = parse_toml(text, file);
    TomlReader top(root, file, "");
    Scene scene;
    scene.file = file;
    scene.name = file.stem().string();

    std::optional<TomlReader> scene_section = top.get_table("scene", "[scene]");
    std::optional<TomlReader> camera_section = top.get_table("camera", "[camera]");
    std::vector<TomlReader> light_sections = top.get_tables("light", "[[light]]");
    std::vector<TomlReader> object_sections = top.get_tables("object", "[[object]]");
    std::vector<TomlReader> population_sections = top.get_tables("population", "[[population]]");
    top.finish();  // a misspelled table name is reported before its absence is

    if (scene_section) read_scene_section(*scene_section, scene);
    if (const auto problem = file_name_problem(scene.name)) {
        const std::string hint = fmt::format("scene names become file names and case ids: use {}, e.g. name = \"spheres-2\"",
                                             kFileNameRule);
        if (scene_section && scene_section->has("name"))
            throw scene_section->error("name", fmt::format("the scene name {} cannot be used: {}",
                                                           printable_name(scene.name), *problem), hint);
        throw ConfigError(file, scene_section ? scene_section->line() : 0,
                          fmt::format("the scene has no name, and its file name {} cannot be used as one: {}",
                                      printable_name(scene.name), *problem),
                          "add [scene] with name = \"...\": " + hint);
    }
    if (camera_section) read_camera(*camera_section, scene.camera);

    if (light_sections.empty())
        throw ConfigError(file, 0, "the scene has no lights",
                          "add at least one light, e.g.\n    [[light]]\n    type = \"directional\"\n    direction = [0, -1, 0]");
    for (TomlReader& section : light_sections) scene.lights.push_back(read_light(section));

    const std::filesystem::path config_folder = std::filesystem::absolute(file).parent_path();
    for (size_t i = 0; i < object_sections.size(); ++i)
        scene.objects.push_back(read_object(object_sections[i], i, config_folder));
    for (size_t i = 0; i < population_sections.size(); ++i) {
        Population population = read_population(population_sections[i], i, config_folder, scene.objects);
        // Techniques draw a population by its name: two of one name would draw the first twice.
        for (const Population& earlier : scene.populations)
            if (earlier.name == population.name)
                throw population_sections[i].error(
                    "name", fmt::format("a second population is named '{}' (the first is at line {})", population.name,
                                        earlier.where.line),
                    "give every [[population]] a name of its own");
        scene.populations.push_back(std::move(population));
    }
    return scene;
}

Scene load_scene(const std::filesystem::path& file) { return parse_scene(read_config_file(file), file); }

void read_scene_camera(TomlReader& reader, Camera& camera) { read_camera(reader, camera); }

}  // namespace canopy
