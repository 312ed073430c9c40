// Lemme's quadtree over a field's cells (§6.1-6.2), traversed on the CPU every frame: which cells
// each of grass.lod's distance bands draws, single cells or macro-cells, within the view frustum.
//
// The tree is implicit: a node of level l is the square of 2^l x 2^l cells whose first cell is a
// multiple of 2^l (cut at the field's far edges), so the field's cells alone define it, it costs no
// memory per cell (Lemme's nodes hold about 164 bytes each, L676), and its nodes are always square,
// which is what Lemme builds bottom-up for (Fig 6.2). One traversal serves every band at once; a
// band that has decided a node (drawn or discarded) no longer tests its children (Lemme's flags,
// Fig 6.3). Per band and node, Lemme's lod tests:
//   discard: no cell centre of the node lies within the band's distances (lod_band_distances);
//   draw:    every cell centre of the node does, and the node is at most the band's largest
//            macro-cell (a level-0 node, one cell, is drawn when its centre is in range, within
//            the slack);
//   split:   otherwise.
// So macro-cells grow with the distance from the band's edges, as in Lemme's Fig 6.5. A node whose
// box lies outside the view frustum is dropped for every band (canopy tests the box against the
// frustum, as the GPU cull does, where Lemme tests a bounding sphere against a sphere and a cone).
// Children are visited nearest first, so each band's list runs roughly front to back.
//
// On a terrain (the field's grid heights given), a node's box spans the lowest to the highest grid
// height under it, its cells' centres are lifted to their first corners' ground (where a copy's
// model puts them, and where the shaders measure a cell's distance), and a band may require its
// macro-cells to be flat enough: a node whose unplanarity (macro_unplanarity) exceeds the band's
// is split, Lemme's lod test for a terrain (L906-908). A band may also keep only the nodes whose
// box reaches above the eye (Lemme's hilltops, §6.4.6).
//
// Pure CPU: tests check it against a brute-force pass over every cell.
#pragma once

#include "scene/geometry.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace canopy::grass {

// The field as the quadtree sees it.
struct QuadtreeField {
    glm::uvec2 cells{0, 0};
    glm::vec3 origin{0.0f};  // the corner of cell (0, 0), world
    float cell_size = 1.0f;
    // The prototype's bounds, patch units: a node's box is the union of its cells' boxes, each
    // cell's patch mirrored either way (so blades leaning out of a cell count where they lean).
    Bounds patch_box{glm::vec3(0.0f), glm::vec3(1.0f)};
};

struct QuadtreeBand {
    // The cell-centre distances within which the band may draw something (lod_band_distances);
    // max_distance >= LOD_NO_DISTANCE: no upper limit.
    float min_distance = 0.0f;
    float max_distance = 0.0f;
    uint32_t max_macro = 1;  // the widest node (cells a side) drawn as one macro-cell; 1: single cells
    // On a terrain: the most a macro-cell's ground may depart from the bilinear patch of its
    // corners (world units); a node beyond it is split. Infinite: never split for it.
    float max_unplanarity = std::numeric_limits<float>::infinity();
    // Lemme's hilltop test (§6.4.6, L917-920): the band draws only nodes whose box (its cells'
    // blades over their ground) reaches above the eye, where the grass may stand against the sky;
    // a node whose box tops out at or below the eye is discarded with all its children.
    bool above_eye = false;
    // The farthest a blade's root may lie from its cell's centre (world units; 0 when the band is
    // taken at the cell's centre): with transition_distance = "blade" each blade's band follows
    // its root's distance, so a node is discarded only when every root lies outside the band
    // (root_margin_for).
    float root_margin = 0.0f;
};

// The root_margin of a field whose prototype has `patch_box`: a cell's own blades root inside it,
// a tiled bake's neighbours' blades as far beyond its edges as blades lean out of a cell.
float root_margin_for(const QuadtreeField& field);

// A drawn node: its first cell and its span in cells (x, z), as the macro shaders read it.
struct QuadtreeNode {
    glm::uvec2 first{0, 0};
    glm::uvec2 span{1, 1};
    glm::vec2 heights{0.0f, 0.0f};  // on a terrain: the lowest and highest grid height under it (macro_height_range)
    uint32_t cells() const { return span.x * span.y; }
};

struct QuadtreeSelection {
    std::vector<std::vector<QuadtreeNode>> bands;  // per band, in traversal order
    uint64_t nodes_visited = 0;                    // nodes tested (Lemme's traversal cost)
};

// The tree's root level: the least l with 2^l >= both of the field's sides.
uint32_t quadtree_root_level(glm::uvec2 cells);

// The eye's least and greatest distance to the centres of the node's cells (patch point
// (0.5, 0, 0.5) of each, on the field's plane; on a terrain lifted to their first corners'
// ground, whose heights `centre_heights` bound): a bound on what lod_cuts sees in its cells.
glm::vec2 node_centre_distances(const QuadtreeField& field, const QuadtreeNode& node, glm::vec3 eye,
                                glm::vec2 centre_heights = glm::vec2(0.0f));

// The traversal for one frame: `eye` and `view_proj` (world -> clip, frame.view_proj). `grid`: on
// a terrain, the field's grid heights above its origin (macro_cells.hpp's grid_heights,
// (cells.x + 1)(cells.y + 1) of them); empty on flat ground.
QuadtreeSelection select_cells(const QuadtreeField& field, const std::vector<QuadtreeBand>& bands, glm::vec3 eye,
                               const glm::mat4& view_proj, std::span<const float> grid = {});

}  // namespace canopy::grass
