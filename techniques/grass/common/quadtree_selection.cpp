#include "quadtree_selection.hpp"

#include "macro_cells.hpp"

#include "../shaders/grass_culling.h"
#include "../shaders/lod_selection.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace canopy::grass {

namespace {

// Distances are compared with this much slack (relative), so a cell the shaders place a rounding
// error inside a band is never discarded: a node kept by mistake costs a draw of nothing.
constexpr float kSlack = 1e-4f;

class Traversal {
public:
    Traversal(const QuadtreeField& field, const std::vector<QuadtreeBand>& bands, glm::vec3 eye,
              const glm::mat4& view_proj, std::span<const float> grid)
        : field_(field), bands_(bands), eye_(eye), view_proj_(view_proj), grid_(grid) {
        // world = origin + cell_size * (field point), the field's cells one unit wide.
        model_ = glm::mat4(field.cell_size);
        model_[3] = glm::vec4(field.origin, 1.0f);
        // A cell's box with its patch mirrored either way (cell_mirroring.h: p -> 1 - p).
        const Bounds& b = field.patch_box;
        lo_ = glm::vec3(std::min(b.min.x, 1.0f - b.max.x), b.min.y, std::min(b.min.z, 1.0f - b.max.z));
        hi_ = glm::vec3(std::max(b.max.x, 1.0f - b.min.x), b.max.y, std::max(b.max.z, 1.0f - b.min.z));
        out_.bands.resize(bands.size());
    }

    QuadtreeSelection run() {
        if (field_.cells.x == 0 || field_.cells.y == 0 || bands_.empty()) return std::move(out_);
        const uint32_t root = quadtree_root_level(field_.cells);
        visit(root, glm::uvec2(0), *node_at(root, glm::uvec2(0)), (1u << bands_.size()) - 1u);
        return std::move(out_);
    }

private:
    // A node as the traversal tests it: with its ground's height range on a terrain, and the
    // eye's distances to its cells' centres. Worked out once: on a terrain both read its grid.
    struct Tested {
        QuadtreeNode node;
        glm::vec2 distances;
    };

    // The node at (level, index), or none beyond the field.
    std::optional<Tested> node_at(uint32_t level, glm::uvec2 index) const {
        const uint32_t size = 1u << level;
        const glm::uvec2 first = index * size;
        if (first.x >= field_.cells.x || first.y >= field_.cells.y) return std::nullopt;
        QuadtreeNode node{first, glm::min(glm::uvec2(size), field_.cells - first)};
        if (!grid_.empty()) node.heights = macro_height_range(grid_, field_.cells, macro_of(node));
        return Tested{node, node_centre_distances(field_, node, eye_, centre_heights(node))};
    }

    static MacroInstance macro_of(const QuadtreeNode& n) { return MacroInstance(n.first.x, n.first.y, n.span.x, n.span.y); }

    // The range of its cells' first corners' heights, where their centres stand (0 on flat ground).
    glm::vec2 centre_heights(const QuadtreeNode& n) const {
        if (grid_.empty()) return glm::vec2(0.0f);
        return macro_height_range(grid_, field_.cells, MacroInstance(n.first.x, n.first.y, n.span.x - 1, n.span.y - 1));
    }

    void visit(uint32_t level, glm::uvec2 index, const Tested& tested, uint32_t active) {
        const QuadtreeNode& node = tested.node;
        ++out_.nodes_visited;
        // Field units: the heights scaled by the cell's width, as the model scales y.
        const glm::vec2 lift = node.heights / field_.cell_size;
        const glm::vec3 lo(float(node.first.x) + lo_.x, lo_.y + lift.x, float(node.first.y) + lo_.z);
        const glm::vec3 hi(float(node.first.x + node.span.x - 1) + hi_.x, hi_.y + lift.y,
                           float(node.first.y + node.span.y - 1) + hi_.z);
        if (!shader::grass_cell_visible(view_proj_, eye_, model_, lo, hi, 0.0f, 0.0f)) return;
        const glm::vec2 d = tested.distances;
        const float slack = kSlack * std::max(1.0f, d.y);
        const bool reaches_above_eye = field_.origin.y + field_.cell_size * hi.y > eye_.y;
        uint32_t split = 0;
        for (size_t b = 0; b < bands_.size(); ++b) {
            if (!(active & (1u << b))) continue;
            const QuadtreeBand& band = bands_[b];
            if (band.above_eye && !reaches_above_eye) continue;  // discard: no child reaches higher
            const bool unbounded = band.max_distance >= shader::LOD_NO_DISTANCE;
            const float reach = slack + band.root_margin;
            const bool none = d.y < band.min_distance - reach || (!unbounded && d.x > band.max_distance + reach);
            if (none) continue;  // discard
            const bool whole = d.x >= band.min_distance && (unbounded || d.y <= band.max_distance);
            if (level == 0 || (whole && std::max(node.span.x, node.span.y) <= band.max_macro && flat_enough(node, band)))
                out_.bands[b].push_back(node);  // draw
            else
                split |= 1u << b;
        }
        if (split == 0) return;
        // The children that exist, nearest first.
        std::array<std::pair<Tested, glm::uvec2>, 4> children;
        size_t count = 0;
        for (uint32_t c = 0; c < 4; ++c) {
            const glm::uvec2 child = index * 2u + glm::uvec2(c & 1u, c >> 1);
            if (const std::optional<Tested> n = node_at(level - 1, child)) children[count++] = {*n, child};
        }
        for (size_t i = 1; i < count; ++i)  // insertion sort of at most 4
            for (size_t j = i; j > 0 && children[j].first.distances.x < children[j - 1].first.distances.x; --j)
                std::swap(children[j], children[j - 1]);
        for (size_t c = 0; c < count; ++c) visit(level - 1, children[c].second, children[c].first, split);
    }

    bool flat_enough(const QuadtreeNode& node, const QuadtreeBand& band) const {
        if (grid_.empty() || node.cells() == 1 || std::isinf(band.max_unplanarity)) return true;
        return macro_unplanarity(grid_, field_.cells, macro_of(node)) <= band.max_unplanarity;
    }

    const QuadtreeField& field_;
    const std::vector<QuadtreeBand>& bands_;
    glm::vec3 eye_;
    glm::mat4 view_proj_;
    std::span<const float> grid_;
    glm::mat4 model_;
    glm::vec3 lo_, hi_;  // a cell's box, field units relative to its first corner
    QuadtreeSelection out_;
};

}  // namespace

uint32_t quadtree_root_level(glm::uvec2 cells) {
    uint32_t level = 0;
    while ((1u << level) < std::max(cells.x, cells.y)) ++level;
    return level;
}

float root_margin_for(const QuadtreeField& field) {
    const Bounds& b = field.patch_box;
    const float lean = std::max({0.0f, -b.min.x, b.max.x - 1.0f, -b.min.z, b.max.z - 1.0f});
    return field.cell_size * std::sqrt(2.0f) * (0.5f + lean);
}

glm::vec2 node_centre_distances(const QuadtreeField& field, const QuadtreeNode& node, glm::vec3 eye,
                                glm::vec2 centre_heights) {
    const glm::vec2 first = glm::vec2(node.first) + 0.5f, last = glm::vec2(node.first + node.span) - 0.5f;
    const glm::vec3 lo = field.origin + glm::vec3(field.cell_size * first.x, centre_heights.x, field.cell_size * first.y);
    const glm::vec3 hi = field.origin + glm::vec3(field.cell_size * last.x, centre_heights.y, field.cell_size * last.y);
    const glm::vec3 nearest = glm::clamp(eye, lo, hi);
    const glm::vec3 farthest(std::abs(eye.x - lo.x) > std::abs(eye.x - hi.x) ? lo.x : hi.x,
                             std::abs(eye.y - lo.y) > std::abs(eye.y - hi.y) ? lo.y : hi.y,
                             std::abs(eye.z - lo.z) > std::abs(eye.z - hi.z) ? lo.z : hi.z);
    return {glm::length(eye - nearest), glm::length(eye - farthest)};
}

QuadtreeSelection select_cells(const QuadtreeField& field, const std::vector<QuadtreeBand>& bands, glm::vec3 eye,
                               const glm::mat4& view_proj, std::span<const float> grid) {
    if (bands.size() > 31) throw std::logic_error("select_cells: at most 31 bands");  // one bit each, and all set
    if (!grid.empty() && grid.size() != size_t(field.cells.x + 1) * (field.cells.y + 1))
        throw std::logic_error(fmt::format("select_cells: {} grid heights for a field of {} x {} cells", grid.size(),
                                           field.cells.x, field.cells.y));
    return Traversal(field, bands, eye, view_proj, grid).run();
}

}  // namespace canopy::grass
