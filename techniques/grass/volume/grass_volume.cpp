// grass.volume: Lemme's volume-based representation (§4.2.1, §5.2). At load, the patch is cut by
// pairs of clipping planes into n sections along x and n along z, and each section is baked by an
// orthographic camera along its axis into one layer of a texture array (colour, threshold,
// normal). Every frame, each cell draws its carrier cuboid, and each of its pixels casts a ray
// through the slices (shaders/volume_walk.h), stopping at the first blade the cell's density
// keeps. The declarations live in volume_graph.cpp, which grass.lod shares.
#include "core/registry.hpp"

#include "grass_volume_params.h"
#include "volume_graph.hpp"
#include "../common/grass_family.hpp"
#include "../common/grass_passes.hpp"
#include "../common/mip_passes.hpp"
#include "../common/grass_population.hpp"

#include "shaders/grass/grass_volume_frag.h"
#include "shaders/grass/grass_volume_vert.h"

#include <fmt/format.h>

namespace canopy {
namespace {

using grass::cleared;
using grass::kFarDepth;

class GrassVolume final : public Technique {
public:
    std::string name() const override { return "grass.volume"; }
    std::string summary() const override {
        return "grass as a ray-cast volume: n vertical slices per direction baked at load, walked per pixel in a cuboid per cell or macro-cell";
    }
    std::string paper() const override { return "Lemme 2012 §4.2.1 and §5.2 (eq 5.2-5.21), after Habel et al. 2007"; }
    std::vector<ParamSpec> params() const override { return shader::GrassVolumeParams::specs(); }
    ErrorColumns error_columns() const override { return grass::kGrassErrorColumns; }
    std::vector<std::string> pareto_errors() const override { return grass::pareto_errors(); }

    std::optional<ParamConflict> conflict(const ParamSet& params) const override {
        return grass::slice_filtering_conflict(params);
    }

    FrameGraph graph(const ParamSet& params) const override {
        const auto block = shader::GrassVolumeParams::from(params);
        grass::VolumeSettings settings{.slices = uint32_t(block.slices),
                                       .resolution = uint32_t(params.integer("resolution")),
                                       .height_resolution = uint32_t(params.integer("height_resolution")),
                                       .macro_cells = uint32_t(params.integer("macro_cells"))};
        settings.filtering = grass::slice_filtering(params);
        FrameGraph g;
        g.needs.populations = {grass::kGrassPopulationKind};
        g.shader_params.set_block(block);
        g.report["slices"] = fmt::format("{} per direction", settings.slices);
        // One cuboid a cell (grass_volume_vertex.glsl) or a macro-cell (grass_volume_macro_vertex.glsl)
        // follows a terrain.
        g.needs.populations_on_terrain = true;
        if (settings.macro_cells > 0)
            g.report["macro_cells"] = fmt::format("{} x {}", settings.macro_cells, settings.macro_cells);
        grass::declare_volume_bake(g, settings);
        RasterState per_cell;
        per_cell.vertex_spirv = grass_volume_vert;
        per_cell.fragment_spirv = grass_volume_frag;
        g.passes.push_back(grass::volume_frame_pass(
            settings, per_cell, true,
            {cleared(graph_names::kColor, Use::color_attachment, grass::kUncoveredClear),
             cleared(graph_names::kDepth, Use::depth_attachment, kFarDepth)}));
        return g;
    }
};

RegisterTechnique<GrassVolume> registered;

}  // namespace
}  // namespace canopy
