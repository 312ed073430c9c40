#include "support/bake_truth.hpp"

#include "config/scene_config.hpp"
#include "reference/embree_scene.hpp"
#include "reference/primary_hit.hpp"
#include "scene/geometry.hpp"
#include "scene/population_kind.hpp"
#include "support/reference_hits.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace canopy::grass::test {

Scene one_cell_scene(const std::string& camera, const std::string& extra_params) {
    return parse_scene(std::string("[scene]\nname = \"one-cell\"\nambient = 0.2\n") + camera +
                           "\n[[light]]\ntype = \"directional\"\ndirection = [-0.3, -1, -0.2]\ncasts_shadows = false\n"
                           "[[population]]\nname = \"patch\"\nkind = \"grass\"\nalbedo = [0.1, 0.8, 0.1]\n"
                           "params = { cells_x = 1, cells_z = 1, centre_x = 0.5, centre_z = 0.5, mirror = false, "
                           "blades = 60, subdivisions = 3, width_min = 0.06, width_max = 0.1, " +
                           extra_params + " }\n",
                       "one-cell.toml");
}

std::vector<TexelTruth> traced_bake(const Scene& scene, View view, uint32_t width, uint32_t height, Section section) {
    Bounds b;
    for (const Vertex& v : scene.populations.at(0).family->prototype.vertices) b.extend(v.position);
    return traced_bake_over(scene, b, view, width, height, section);
}

std::vector<TexelTruth> traced_bake_over(const Scene& scene, const Bounds& b, View view, uint32_t width, uint32_t height,
                                         Section section) {
    const EmbreeScene embree(scene, build_scene_meshes(scene));
    const FamilyPopulation& family = *scene.populations.at(0).family;
    const uint32_t per_blade = 2 * (uint32_t(scene.populations[0].params.integer("subdivisions")) + 1);
    // The rays start at the section's far side from the bake's camera, past the camera's near
    // plane (trace_primary clips there).
    const float near = scene.camera.near_plane;
    std::vector<TexelTruth> truth(size_t(width) * height);
    for (uint32_t j = 0; j < height; ++j)
        for (uint32_t i = 0; i < width; ++i) {
            const float u = (float(i) + 0.5f) / float(width), v = (float(j) + 0.5f) / float(height);
            const float y = b.max.y * (1.0f - v);
            Ray ray{};
            if (view == View::along_z) {
                ray.origin = {b.min.x + u * (b.max.x - b.min.x), y, std::min(section.hi, b.max.z + 1.0f) + near};
                ray.direction = {0.0f, 0.0f, -1.0f};
            } else if (view == View::along_x) {
                ray.origin = {std::min(section.hi, b.max.x + 1.0f) + near, y, b.min.z + u * (b.max.z - b.min.z)};
                ray.direction = {-1.0f, 0.0f, 0.0f};
            } else {
                ray.origin = {b.min.x + u * (b.max.x - b.min.x), b.max.y + 1.0f, b.min.z + v * (b.max.z - b.min.z)};
                ray.direction = {0.0f, -1.0f, 0.0f};
            }
            const std::optional<PrimaryHit> hit = trace_primary(embree, scene.camera, ray.direction, ray);
            if (!hit) continue;
            const float along = view == View::along_x ? hit->surface.position.x : hit->surface.position.z;
            if (view != View::down && along < section.lo) continue;
            const uint32_t blade = (hit->primitive % family.prototype.triangle_count()) / per_blade;
            const uint32_t first_vertex = family.prototype.indices[size_t(blade) * per_blade * 3];
            const glm::vec4 root = family.vertex_data[first_vertex].data[1];  // root x, root z, taper
            truth[size_t(j) * width + i] = {family.vertex_data[first_vertex].data[0].z, int64_t(blade), hit->surface.position,
                                            glm::vec2(root.x, root.y)};
        }
    return truth;
}

BakeAgreement compare_bake(const Image& colour, const Image& blades, const std::vector<TexelTruth>& truth, bool flip_u) {
    BakeAgreement a;
    const int width = colour.width, height = colour.height;
    const auto at = [&](int i, int j) -> const TexelTruth& { return truth[size_t(j) * size_t(width) + size_t(i)]; };
    for (int j = 1; j + 1 < height; ++j)
        for (int i = 1; i + 1 < width; ++i) {
            bool edge = false;
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) edge = edge || at(i + di, j + dj).blade != at(i, j).blade;
            if (edge) continue;
            ++a.compared;
            const int u = flip_u ? width - 1 - i : i;
            const bool shown = colour.at(u, j)[3] > 0.5f;
            const float threshold = blades.at(u, j)[0];
            const bool covered = at(i, j).blade >= 0;
            a.covered += covered;
            a.coverage += shown != covered;
            a.threshold += covered && shown && (threshold != at(i, j).threshold || blades.at(u, j)[1] != threshold);
            a.root += covered && shown &&
                      (blades.at(u, j)[2] != at(i, j).root.x || blades.at(u, j)[3] != at(i, j).root.y);
        }
    return a;
}

bool shows_grass(const float* rgb) { return rgb[1] > 2.0f * rgb[0]; }

int grass_pixels(const Image& image) {
    int n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) n += shows_grass(image.at(x, y));
    return n;
}

CoverageAgreement compare_with_reference_hits(const Scene& scene, const Image& image, const Image* visibility,
                                              float depth_tolerance) {
    const EmbreeScene embree(scene, build_scene_meshes(scene));
    const uint32_t width = uint32_t(image.width), height = uint32_t(image.height);
    const auto hits = canopy::test::reference_hits(scene, embree, width, height);
    const uint32_t per_blade = 2 * (uint32_t(scene.populations.at(0).params.integer("subdivisions")) + 1);
    const auto label = [&](int x, int y) -> int64_t {
        const auto& h = hits[size_t(y) * width + size_t(x)];
        if (!h) return -1;
        return h->what.population >= 0 ? int64_t(h->hit.primitive / per_blade) : -2 - int64_t(h->hit.geometry);
    };
    CoverageAgreement a;
    for (int y = 1; y + 1 < int(height); ++y)
        for (int x = 1; x + 1 < int(width); ++x) {
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) edge = edge || label(x + dx, y + dy) != label(x, y);
            if (edge) continue;
            ++a.compared;
            const bool blade = label(x, y) >= 0;
            a.covered += blade;
            a.differ += shows_grass(image.at(x, y)) != blade;
            if (visibility && blade && shows_grass(image.at(x, y))) {
                ++a.depth_compared;
                const float reference_depth = hits[size_t(y) * width + size_t(x)]->hit.view_depth;
                a.depth_off += std::abs(visibility->at(x, y)[1] - reference_depth) > depth_tolerance;
            }
        }
    return a;
}

double tile_coverage_error(const Scene& scene, const Image& image, int tile, int* blade_pixels) {
    const EmbreeScene embree(scene, build_scene_meshes(scene));
    const uint32_t width = uint32_t(image.width), height = uint32_t(image.height);
    const auto hits = canopy::test::reference_hits(scene, embree, width, height);
    double total = 0.0;
    int tiles = 0, blades = 0;
    for (int ty = 0; ty + tile <= int(height); ty += tile)
        for (int tx = 0; tx + tile <= int(width); tx += tile) {
            int shown = 0, hit = 0;
            for (int y = ty; y < ty + tile; ++y)
                for (int x = tx; x < tx + tile; ++x) {
                    shown += shows_grass(image.at(x, y));
                    const auto& h = hits[size_t(y) * width + size_t(x)];
                    hit += h && h->what.population >= 0;
                }
            total += std::abs(shown - hit) / double(tile * tile);
            blades += hit;
            ++tiles;
        }
    if (blade_pixels) *blade_pixels = blades;
    return tiles > 0 ? total / tiles : 0.0;
}

Scene hills_scene(const std::string& camera, double height_scale) {
    return parse_scene(fmt::format("[scene]\nname = \"hills\"\nambient = 0.2\n{}\n"
                                   "[[light]]\ntype = \"directional\"\ndirection = [-0.3, -1, -0.2]\ncasts_shadows = false\n"
                                   "[[object]]\nname = \"ground\"\nshape = \"heightfield\"\nsize = [4, 4]\nvertices = 5\n"
                                   "periods = 1\nseed = 2\nheight_scale = {}\nalbedo = [0.6, 0.3, 0.1]\n"
                                   "[[population]]\nname = \"field\"\nkind = \"grass\"\nterrain = \"ground\"\n"
                                   "albedo = [0.1, 0.8, 0.1]\n"
                                   "params = {{ cells_x = 4, cells_z = 4, blades = 300, subdivisions = 3 }}\n",
                                   camera, height_scale),
                       "hills.toml");
}

FlatAndHills flat_and_hills_coverage_error(const std::string& camera, const std::function<Image(const Scene&)>& render,
                                         double height_scale) {
    FlatAndHills out;
    const Scene flat = hills_scene(camera, 0.0), hills = hills_scene(camera, height_scale);
    out.flat = tile_coverage_error(flat, render(flat), 8, &out.flat_blades);
    out.hills = tile_coverage_error(hills, render(hills), 8, &out.hills_blades);
    return out;
}

void check_follows_terrain(const std::string& camera, double bound, const std::function<Image(const Scene&)>& render,
                           int min_blades, double height_scale) {
    const FlatAndHills e = flat_and_hills_coverage_error(camera, render, height_scale);
    CAPTURE(height_scale);
    CAPTURE(camera);
    CAPTURE(e.flat_blades);
    CAPTURE(e.hills_blades);
    CAPTURE(e.flat);
    CAPTURE(e.hills);
    CHECK(e.flat_blades > min_blades);
    CHECK(e.hills_blades > min_blades);
    CHECK(e.flat > 0.0);
    CHECK(e.hills <= bound * e.flat);
}

}  // namespace canopy::grass::test
