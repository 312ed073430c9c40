// grass.image: Lemme's far representation (§4.2, §5.3): the patch seen from above, baked at load
// into its colour, density threshold and normal, shown on one horizontal quad per cell a little
// above the ground, cut by the cell's density and lit per pixel. The declarations live in
// image_graph.cpp, which grass.lod shares.
#include "core/registry.hpp"

#include "grass_image_params.h"
#include "image_graph.hpp"
#include "../common/grass_family.hpp"
#include "../common/grass_passes.hpp"
#include "../common/mip_passes.hpp"
#include "../common/grass_population.hpp"

#include "shaders/grass/grass_image_frag.h"
#include "shaders/grass/grass_image_vert.h"

#include <fmt/format.h>

namespace canopy {
namespace {

using grass::cleared;
using grass::kFarDepth;

class GrassImage final : public Technique {
public:
    std::string name() const override { return "grass.image"; }
    std::string summary() const override {
        return "grass as one horizontal slice per cell or macro-cell: the patch's top view baked at load, lit per pixel";
    }
    std::string paper() const override { return "Lemme 2012 §4.2 and §5.3; Boulanger 2008 §4.2 (the far slice)"; }
    std::vector<ParamSpec> params() const override { return shader::GrassImageParams::specs(); }
    ErrorColumns error_columns() const override { return grass::kGrassErrorColumns; }
    std::vector<std::string> pareto_errors() const override { return grass::pareto_errors(); }

    std::optional<ParamConflict> conflict(const ParamSet& params) const override {
        return grass::slice_filtering_conflict(params);
    }

    FrameGraph graph(const ParamSet& params) const override {
        grass::ImageSettings settings{.resolution = uint32_t(params.integer("resolution")),
                                      .slice_height = float(params.real("slice_height")),
                                      .macro_cells = uint32_t(params.integer("macro_cells"))};
        settings.macro_terrain.max_unplanarity = float(params.real("macro_unplanarity"));
        settings.filtering = grass::slice_filtering(params);
        FrameGraph g;
        g.needs.populations = {grass::kGrassPopulationKind};
        // A quad per cell (grass_image_vertex.glsl) or per macro-cell (grass_image_macro_vertex.glsl)
        // follows a terrain.
        g.needs.populations_on_terrain = true;
        g.shader_params.set_block(shader::GrassImageParams::from(params));
        if (settings.macro_cells > 0)
            g.report["macro_cells"] = fmt::format("{} x {}, split above unplanarity {} on a terrain", settings.macro_cells,
                                                  settings.macro_cells, params.real("macro_unplanarity"));
        grass::declare_image_bake(g, settings);
        RasterState per_cell;
        per_cell.vertex_spirv = grass_image_vert;
        per_cell.fragment_spirv = grass_image_frag;
        g.passes.push_back(grass::image_frame_pass(
            settings, per_cell, true,
            {cleared(graph_names::kColor, Use::color_attachment, grass::kUncoveredClear),
             cleared(graph_names::kDepth, Use::depth_attachment, kFarDepth)}));
        if (settings.macro_cells == 0)  // said, as grass.lod says its unused settings
            g.passes.back().settings +=
                fmt::format("; macro_unplanarity {} unused: macro_cells = 0", params.real("macro_unplanarity"));
        return g;
    }
};

RegisterTechnique<GrassImage> registered;

}  // namespace
}  // namespace canopy
