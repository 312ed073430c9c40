#include "reference/reference_cache.hpp"

#include "report/atomic_file.hpp"
#include "report/exr_file.hpp"
#include "scene/population_kind.hpp"

#include <fmt/format.h>

#include <atomic>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <type_traits>
#include <unistd.h>

namespace canopy {

// The key must cover every field that changes the image. These fail when a struct gains a
// field: hash it in reference_cache_key (or decide it does not matter), then update the size.
static_assert(sizeof(Camera) == 48, "Camera changed: update reference_cache_key");
static_assert(sizeof(Material) == 12, "Material changed: update reference_cache_key");
static_assert(sizeof(Light) == 80 + sizeof(SourceLocation), "Light changed: update reference_cache_key");
static_assert(sizeof(Transform) == 36 + 64, "Transform changed: update reference_cache_key (it hashes matrix())");

namespace {

// FNV-1a, 64 bit.
class Fnv1a64 {
public:
    void bytes(const void* data, size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) {
            hash_ ^= p[i];
            hash_ *= 0x100000001b3ull;
        }
    }
    template <class T>
    void add(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&value, sizeof(T));
    }
    void add_string(const std::string& text) {
        add(uint64_t(text.size()));
        bytes(text.data(), text.size());
    }
    uint64_t value() const { return hash_; }

private:
    uint64_t hash_ = 0xcbf29ce484222325ull;
};

void hash_vec(Fnv1a64& hash, glm::vec3 v) {
    hash.add(v.x);
    hash.add(v.y);
    hash.add(v.z);
}

const char* kImageNames[3] = {"radiance", "variance", "visibility"};
const char* kPixelVisibilityName = "pixel_visibility";

std::filesystem::path image_path(const std::filesystem::path& dir, const std::string& key, const char* name) {
    return dir / fmt::format("{}.{}.exr", key, name);
}

// What the radiance and pixel-visibility files record about their render.
struct RenderStats {
    double seconds = 0;
    uint64_t shadow_rays = 0;
};

void store_cached_exr(const std::filesystem::path& path, const Image& image, const std::string& key,
                      const RenderStats* stats) {
    ExrAttributes attributes;
    attributes.strings["canopy:key"] = key;
    if (stats) {
        attributes.numbers["canopy:seconds"] = stats->seconds;
        attributes.strings["canopy:shadow_rays"] = std::to_string(stats->shadow_rays);
    }
    // Unique per process and call: two threads may store the same reference. Not
    // write_bytes_atomically's name, nor its test hook: the cache is not a run's output.
    static std::atomic<uint64_t> counter{0};
    write_bytes_through(path.parent_path() / fmt::format(".{}.tmp-{}-{}.exr", path.stem().string(), ::getpid(), counter++),
                        path, encode_exr(image, attributes));
}

// Reads an RGBA float image written by store_cached_exr; nullopt when it is missing or does not fit.
std::optional<Image> load_cached_exr(const std::filesystem::path& path, const std::string& key, RenderStats* stats) {
    std::error_code ignored;
    if (!std::filesystem::is_regular_file(path, ignored)) return std::nullopt;
    ExrAttributes attributes;
    Image image;
    try {
        image = read_exr(path, &attributes);
    } catch (const std::runtime_error&) {
        return std::nullopt;  // unreadable (e.g. cut short): a miss, rendered again
    }
    const auto stored_key = attributes.strings.find("canopy:key");
    if (stored_key == attributes.strings.end() || stored_key->second != key) return std::nullopt;
    if (stats) {
        const auto seconds = attributes.numbers.find("canopy:seconds");
        stats->seconds = seconds == attributes.numbers.end() ? 0.0 : seconds->second;
        const auto rays = attributes.strings.find("canopy:shadow_rays");
        stats->shadow_rays = rays == attributes.strings.end() ? 0 : std::strtoull(rays->second.c_str(), nullptr, 10);
    }
    return image;
}

}  // namespace

namespace {

void hash_mesh(Fnv1a64& hash, const TriangleMesh* mesh) {
    hash.add(uint64_t(mesh ? mesh->vertices.size() : 0));
    hash.add(uint64_t(mesh ? mesh->indices.size() : 0));
    if (!mesh) return;
    for (const Vertex& vertex : mesh->vertices) {
        hash_vec(hash, vertex.position);
        hash_vec(hash, vertex.normal);
    }
    hash.bytes(mesh->indices.data(), mesh->indices.size() * sizeof(uint32_t));
}

// Every input of the scene that changes an image: the camera, ambient, background, every light
// (all fields but `where`), every object's material, casts_shadows, world matrix per instance
// and mesh vertices and indices, and every population's kind, prototype material, casts_shadows
// and mesh, and its generated copies' matrices (which cover count, region, ground, seed, scale,
// yaw, the prototype's own transform and the generator itself).
void hash_scene(Fnv1a64& hash, const Scene& scene, const std::vector<TriangleMesh>& meshes) {
    const Camera& camera = scene.camera;
    hash_vec(hash, camera.position);
    hash_vec(hash, camera.target);
    hash_vec(hash, camera.up);
    hash.add(camera.fov_y_degrees);
    hash.add(camera.near_plane);
    hash.add(camera.far_plane);
    hash_vec(hash, scene.ambient);
    hash_vec(hash, scene.background);

    hash.add(uint64_t(scene.lights.size()));
    for (const Light& light : scene.lights) {
        hash.add(int32_t(light.type));
        hash_vec(hash, light.position);
        hash_vec(hash, light.direction);
        hash_vec(hash, light.color);
        hash.add(light.intensity);
        hash.add(light.spot_angle_degrees);
        hash.add(light.rect_size.x);
        hash.add(light.rect_size.y);
        hash.add(light.sphere_radius);
        hash_vec(hash, light.rect_up_hint);
        hash.add(uint8_t(light.casts_shadows));
    }

    hash.add(uint64_t(scene.objects.size()));
    for (size_t index = 0; index < scene.objects.size(); ++index) {
        const Object& object = scene.objects[index];
        hash_vec(hash, object.material.albedo);
        hash.add(uint8_t(object.casts_shadows));
        hash.add(uint64_t(object.instances.size()));
        for (const Transform& instance : object.instances) {
            const glm::mat4 matrix = instance.matrix();
            hash.bytes(&matrix[0][0], sizeof(matrix));
        }
        hash_mesh(hash, index < meshes.size() ? &meshes[index] : nullptr);
    }

    hash.add(uint64_t(scene.populations.size()));
    for (size_t index = 0; index < scene.populations.size(); ++index) {
        const Population& population = scene.populations[index];
        hash.add_string(population.kind);
        hash_vec(hash, population.prototype.material.albedo);
        hash.add(uint8_t(population.prototype.casts_shadows));
        const auto shared_copies = generate_instances(population);
        const std::vector<PopulationInstance>& copies = *shared_copies;
        hash.add(uint64_t(copies.size()));
        for (const PopulationInstance& copy : copies) {
            hash.bytes(&copy.model[0][0], sizeof(copy.model));
            hash.bytes(&copy.data[0], sizeof(copy.data));
        }
        const glm::vec4 mask = population.alpha_mask.packed();
        for (int c = 0; c < 4; ++c) hash.add(mask[c]);
        if (population.family) {
            // The kind's alpha test and albedo scale are code: its version and parameters stand for them.
            const PopulationKind* kind = PopulationKindRegistry::instance().find(population.kind);
            hash.add(int32_t(kind ? kind->version() : -1));
            hash.add_string(population.params.summary());
            const auto& data = population.family->vertex_data;
            hash.add(uint64_t(data.size()));
            if (!data.empty()) hash.bytes(data.data(), data.size() * sizeof(PopulationVertexData));
        }
        const size_t mesh_index = scene.objects.size() + index;
        hash_mesh(hash, mesh_index < meshes.size() ? &meshes[mesh_index] : nullptr);
    }
}

}  // namespace

std::string reference_cache_key(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width, int height,
                                const ReferenceSettings& settings) {
    Fnv1a64 hash;
    hash.add_string("canopy reference");
    hash.add(int32_t(kReferenceShadingVersion));
    hash.add(int32_t(width));
    hash.add(int32_t(height));
    hash.add(int32_t(settings.light_samples));
    hash.add(int32_t(settings.pixel_samples));
    hash.add(uint64_t(settings.seed));
    hash_scene(hash, scene, meshes);
    return fmt::format("{:016x}", hash.value());
}

std::string pixel_visibility_cache_key(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width,
                                       int height, const PixelVisibilitySettings& settings) {
    Fnv1a64 hash;
    hash.add_string("canopy pixel visibility");
    hash.add(int32_t(kPixelVisibilityVersion));
    hash.add(int32_t(width));
    hash.add(int32_t(height));
    hash.add(int32_t(settings.light_samples));
    hash.add(uint64_t(settings.seed));
    hash.add(settings.position_in_pixel_x);
    hash.add(settings.position_in_pixel_y);
    hash_scene(hash, scene, meshes);
    return fmt::format("{:016x}", hash.value());
}

std::optional<ReferenceImages> load_cached_reference(const std::filesystem::path& dir, const std::string& key) {
    ReferenceImages images;
    RenderStats stats;
    std::optional<Image> radiance = load_cached_exr(image_path(dir, key, kImageNames[0]), key, &stats);
    std::optional<Image> variance = load_cached_exr(image_path(dir, key, kImageNames[1]), key, nullptr);
    std::optional<Image> visibility = load_cached_exr(image_path(dir, key, kImageNames[2]), key, nullptr);
    if (!radiance || !variance || !visibility) return std::nullopt;
    const auto same_size = [&](const Image& image) {
        return image.width == radiance->width && image.height == radiance->height;
    };
    if (!same_size(*variance) || !same_size(*visibility)) return std::nullopt;
    images.seconds = stats.seconds;
    images.shadow_rays = stats.shadow_rays;
    images.radiance = std::move(*radiance);
    images.variance = std::move(*variance);
    images.visibility = std::move(*visibility);
    return images;
}

namespace {

void create_cache_folder(const std::filesystem::path& dir) {
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error)
        throw std::runtime_error(fmt::format("cannot create the reference cache folder '{}': {}", dir.string(),
                                             error.message()));
}

}  // namespace

void store_reference(const std::filesystem::path& dir, const std::string& key, const ReferenceImages& images) {
    create_cache_folder(dir);
    const RenderStats stats{images.seconds, images.shadow_rays};
    store_cached_exr(image_path(dir, key, kImageNames[0]), images.radiance, key, &stats);
    store_cached_exr(image_path(dir, key, kImageNames[1]), images.variance, key, nullptr);
    store_cached_exr(image_path(dir, key, kImageNames[2]), images.visibility, key, nullptr);
}

std::optional<PixelVisibilityRender> load_cached_pixel_visibility(const std::filesystem::path& dir,
                                                                  const std::string& key) {
    RenderStats stats;
    std::optional<Image> visibility = load_cached_exr(image_path(dir, key, kPixelVisibilityName), key, &stats);
    if (!visibility) return std::nullopt;
    return PixelVisibilityRender{std::move(*visibility), stats.seconds, stats.shadow_rays};
}

void store_pixel_visibility(const std::filesystem::path& dir, const std::string& key,
                            const PixelVisibilityRender& render) {
    create_cache_folder(dir);
    const RenderStats stats{render.seconds, render.shadow_rays};
    store_cached_exr(image_path(dir, key, kPixelVisibilityName), render.visibility, key, &stats);
}

}  // namespace canopy
