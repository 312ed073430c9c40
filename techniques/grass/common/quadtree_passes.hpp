// grass.lod's culling = "quadtree" as frame-graph pieces: Lemme's quadtree (quadtree_selection.hpp)
// traversed by a CPU pass every frame, which writes, per band, what its raster pass draws and how
// many (an indirect record, so the pass records without a readback): the near band the kept cells'
// copies (PopulationInstance records, the blades drawn over them as the population's prototype),
// the other bands their macro-cells (first cell, span: the macro shaders' per-instance vec4 over
// the field's GrassCell records, macro_cells.hpp). The population's copies stay on the CPU
// (GraphNeeds::population_copies_on_gpu = false): on the GPU the field costs its GrassCell records
// and the bands' macro lists, O(cells), and the near band's copies, O(its capacity).
#pragma once

#include "graph/frame_graph.hpp"
#include "graph/pass_context.hpp"
#include "graph/raster_state.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace canopy::grass {

struct QuadtreeBandDecl {
    std::string name;          // the band in counts and names: "near", "middle", "far"
    float min_distance = 0.0f;  // lod_band_distances
    float max_distance = 0.0f;
    // 0: the band draws the population's copies of single cells (the blades); else macro-cells of
    // at most `max_macro` cells a side, `vertex_count` vertices each (a cuboid, a quad).
    uint32_t vertex_count = 0;
    uint32_t max_macro = 1;
    // On a terrain (the first grass population's): split a macro-cell whose ground departs from
    // its corners' bilinear patch by more than this (world units; the image's quads follow their
    // corners alone); infinite: never.
    float max_unplanarity = std::numeric_limits<float>::infinity();
    // On a terrain: write each macro-cell's height range beside its record (the volume's cuboids span it).
    bool height_ranges = false;
    // Only the nodes whose box reaches above the eye (QuadtreeBand::above_eye: Lemme's hilltops).
    bool above_eye = false;
    // Its shaders take each blade's band at the blade's root (grass.lod's transition_distance =
    // "blade"): a node is kept while any root may lie within the band (QuadtreeBand::root_margin).
    bool by_blade_root = false;
};

// Names of a band's buffers: "<name>_quadtree_list" (copies or macro-cells),
// "<name>_quadtree_draw" (its indirect record) and, on a terrain with `height_ranges`,
// "<name>_quadtree_ranges" (a vec2 per macro-cell of the list).
std::string quadtree_list(const std::string& band);
std::string quadtree_draw(const std::string& band);
std::string quadtree_ranges(const std::string& band);

// How many entries a band's list holds: a frame whose selection keeps more fails, naming the
// parameter to raise. Sized by these, not by the field, the lists cost O(1) memory whatever the
// field's size: what a frame draws depends on the view.
struct QuadtreeCapacity {
    uint32_t copies = 8192;  // cells a copies band (the blades) may keep
    std::string copies_parameter;
    uint32_t macros = 16384;  // macro-cells (single cells included) a macro band may keep
    std::string macros_parameter;
};

// The field's records (macro_names::kCells, kField; on a terrain kHeights, which the traversal
// reads too) and their load-phase upload, the bands' host-visible lists and records, and the
// frame's CPU pass `quadtree`. Counts per frame: <band>_cells (cells drawn), <band>_draws
// (instances: cells or macro-cells), quadtree_nodes (nodes tested).
void declare_quadtree(FrameGraph& g, const std::vector<QuadtreeBandDecl>& bands, const QuadtreeCapacity& capacity);

// The uses a pass drawing a band's list adds: a copies band's list (vertex) and record
// (indirect); a macro band's also the field's records (uniform at binding 3, storage at 4), its
// grid heights (storage at 5) and, with `height_ranges`, its ranges (storage at 6).
void use_quadtree_band(PassDecl& pass, const QuadtreeBandDecl& band);

// Draws a copies band with the bound pipeline (the first grass population's prototype over the
// kept copies), or a macro band: `vertex_buffer` (binding 0) once per macro-cell (binding 1).
void draw_quadtree_band(PassContext& pc, const QuadtreeBandDecl& band, const std::string& vertex_buffer = "");
// Whether the band's CPU selection kept nothing this frame (its draw record holds no instance):
// then draw_quadtree_band records no draw.
bool quadtree_band_empty(const PassContext& pc, const QuadtreeBandDecl& band);

// Makes `frame` a macro band's frame pass (grass.volume's and grass.image's under a quadtree):
// the band's uses (use_quadtree_band), and a record that draws the scene's objects with `ground`
// when given, then the band's cells and macro-cells with the per-cell shaders `over` on
// macro-cell vertices (macro_layout), or `over_on_terrain` when the first grass population stands
// on a terrain. `vertex_buffer` is the representation's own (binding 0). The caller says what
// the pass draws in `frame.settings`.
void declare_macro_band_pass(PassDecl& frame, const QuadtreeBandDecl& band, const std::optional<RasterState>& ground,
                             RasterState over, RasterState over_on_terrain, const std::string& vertex_buffer);

}  // namespace canopy::grass
