#include "patch_bake.hpp"

#include "grass_population.hpp"

#include "../shaders/btf_interpolation.h"

#include <algorithm>
#include <cmath>

namespace canopy::grass {

namespace {

// ndc = 2 (p - lo) / (hi - lo) - 1 along one axis: scale and offset.
glm::vec2 to_ndc(glm::vec2 r) { return {2.0f / (r.y - r.x), -1.0f - 2.0f * r.x / (r.y - r.x)}; }

}  // namespace

Bounds bake_frame(const Bounds& b) {
    Bounds f;
    f.min = glm::vec3(b.min.x, 0.0f, b.min.z);
    f.max = glm::max(glm::vec3(b.max.x, b.max.y, b.max.z), f.min + glm::vec3(1e-4f));
    return f;
}

Bounds cell_frame(const Bounds& b) {
    Bounds f;
    f.min = glm::vec3(0.0f);
    f.max = glm::vec3(1.0f, std::max(b.max.y, 1e-4f), 1.0f);
    return f;
}

shader::PatchBake ortho_bake(const Bounds& bounds, BakeView view, bool tiled) {
    return ortho_bake_over(baked_frame(bounds, tiled), view, tiled);
}

shader::PatchBake ortho_bake_over(const Bounds& f, BakeView view, bool tiled) {
    const glm::vec2 x(f.min.x, f.max.x), y(f.min.y, f.max.y), z(f.min.z, f.max.z);
    glm::mat4 m(0.0f);  // column-major: m[column][row]
    m[3][3] = 1.0f;
    shader::PatchBake bake;
    const auto set_row = [&](int row, int axis, float scale, float offset) {
        m[axis][row] = scale;
        m[3][row] = offset;
    };
    // Depth 0 at the side nearest the camera, 1 at the farthest.
    if (view == BakeView::along_z) {
        set_row(0, 0, to_ndc(x).x, to_ndc(x).y);
        set_row(1, 1, -2.0f / (y.y - y.x), 1.0f);
        set_row(2, 2, -1.0f / (z.y - z.x), z.y / (z.y - z.x));
        bake.toward_viewer = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);
    } else if (view == BakeView::along_x) {
        set_row(0, 2, to_ndc(z).x, to_ndc(z).y);
        set_row(1, 1, -2.0f / (y.y - y.x), 1.0f);
        set_row(2, 0, -1.0f / (x.y - x.x), x.y / (x.y - x.x));
        bake.toward_viewer = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    } else {
        set_row(0, 0, to_ndc(x).x, to_ndc(x).y);
        set_row(1, 2, to_ndc(z).x, to_ndc(z).y);
        set_row(2, 1, -1.0f / (y.y - y.x), y.y / (y.y - y.x));
        bake.toward_viewer = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    }
    bake.view_proj = m;
    bake.section = glm::vec4(-1e30f, 1e30f, 0.0f, 0.0f);
    bake.tiles = glm::vec4(tiled ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
    return bake;
}

void reverse_bake_depth(shader::PatchBake& bake, int axis) {
    bake.view_proj[axis][2] = -bake.view_proj[axis][2];
    bake.view_proj[3][2] = 1.0f - bake.view_proj[3][2];
    bake.toward_viewer = -bake.toward_viewer;
}

int light_axis(uint32_t row) {
    const glm::vec3 l = shader::btf_light_direction(int(row));
    return l.x != 0.0f ? 0 : l.y != 0.0f ? 1 : 2;
}

Bounds light_frame(const Bounds& bounds, uint32_t row, bool tiled, float margin) {
    if (!tiled) return bake_frame(bounds);
    // An axis-aligned light's rays keep their other two coordinates: only blades over the cell
    // (and the margin the lookup's offsets reach) shadow it, from as far as the neighbours reach
    // along the light.
    const Bounds cell = cell_frame(bounds);
    Bounds f;
    f.min = glm::vec3(-margin, 0.0f, -margin);
    f.max = glm::vec3(1.0f + margin, cell.max.y, 1.0f + margin);
    const int axis = light_axis(row);
    if (axis != 1) {
        f.min[axis] = -1.0f;
        f.max[axis] = 2.0f;
    }
    return f;
}

shader::PatchBake light_bake(const Bounds& bounds, uint32_t row, bool tiled, float margin) {
    const int axis = light_axis(row);
    const BakeView view = axis == 1 ? BakeView::down : axis == 0 ? BakeView::along_x : BakeView::along_z;
    shader::PatchBake bake = ortho_bake_over(light_frame(bounds, row, tiled, margin), view, tiled);
    // A light from the negative side (X-, Z-): looking along +axis, the same image, depth reversed.
    if (shader::btf_light_direction(int(row))[axis] < 0.0f) reverse_bake_depth(bake, axis);
    return bake;
}

glm::mat4 light_lookup(const Bounds& bounds, uint32_t row, bool tiled, float margin, float bias) {
    glm::mat4 m = light_bake(bounds, row, tiled, margin).view_proj;
    const int axis = light_axis(row);
    m[3][2] -= bias * std::abs(m[axis][2]);  // depth per unit along the light, times the bias
    return m;
}

float bake_section_start(const Bounds& frame, int axis, uint32_t k, uint32_t n, bool tiled) {
    if (k == 0 && !tiled) return -1e30f;
    if (k == n && !tiled) return 1e30f;
    return frame.min[axis] + (frame.max[axis] - frame.min[axis]) / float(n) * float(k);
}

const GeneratedPopulation* first_grass(std::span<const GeneratedPopulation> populations) {
    for (const GeneratedPopulation& p : populations)
        if (p.kind == kGrassPopulationKind) return &p;
    return nullptr;
}

bool grass_on_terrain(std::span<const GeneratedPopulation> populations) {
    return std::any_of(populations.begin(), populations.end(), [](const GeneratedPopulation& p) {
        return p.kind == kGrassPopulationKind && p.on_terrain;
    });
}

Bounds prototype_bounds(const GeneratedPopulation* population) {
    Bounds bounds;
    if (population)
        for (const Vertex& v : population->prototype.vertices) bounds.extend(v.position);
    if (bounds.empty()) {
        bounds.extend(glm::vec3(0.0f));
        bounds.extend(glm::vec3(1.0f));
    }
    return bounds;
}

}  // namespace canopy::grass
