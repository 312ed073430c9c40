// grass.slices: Boulanger's volume of axis-aligned BTF slices (2008, §4.2.3, App. A). At load, the
// patch and its 8 neighbours are cut by pairs of clipping planes into n sections along x and n
// along z; each section is baked from both sides by an orthographic camera along its axis, and the
// patch once from above for the horizontal slice, each bake storing the blades' albedo, density
// threshold and colour under five light directions. Every frame, each cell draws its 2n vertical
// quads and one horizontal quad; a fragment shows the side its eye sees, cut by the cell's
// density, lit by the light's spherical barycentric weights over the baked directions. The
// declarations live in slices_graph.cpp.
#include "core/registry.hpp"

#include "grass_slices_params.h"
#include "slices_graph.hpp"
#include "../common/grass_family.hpp"
#include "../common/grass_passes.hpp"
#include "../common/mip_passes.hpp"
#include "../common/grass_population.hpp"

#include "shaders/grass/grass_slices_frag.h"
#include "shaders/grass/grass_slices_vert.h"

#include <fmt/format.h>

namespace canopy {
namespace {

using grass::cleared;
using grass::kFarDepth;

class GrassSlices final : public Technique {
public:
    std::string name() const override { return "grass.slices"; }
    std::string summary() const override {
        return "grass as axis-aligned BTF slices: n vertical slices per direction and one horizontal, baked at load under 5 light directions";
    }
    std::string paper() const override { return "Boulanger 2008 §4.2.3, eq 4.2 and App. A (spherical barycentric interpolation)"; }
    std::vector<ParamSpec> params() const override { return shader::GrassSlicesParams::specs(); }
    ErrorColumns error_columns() const override { return grass::kGrassErrorColumns; }
    std::vector<std::string> pareto_errors() const override { return grass::pareto_errors(); }

    std::optional<ParamConflict> conflict(const ParamSet& params) const override {
        return grass::slice_filtering_conflict(params);
    }

    FrameGraph graph(const ParamSet& params) const override {
        const auto block = shader::GrassSlicesParams::from(params);
        const grass::SlicesSettings settings{.slices = uint32_t(block.slices),
                                             .resolution = uint32_t(params.integer("resolution")),
                                             .height_resolution = uint32_t(params.integer("height_resolution")),
                                             .slice_height = block.slice_height,
                                             .neighbours = params.boolean("neighbours"),
                                             .shadow_resolution = uint32_t(params.integer("shadow_resolution")),
                                             .filtering = grass::slice_filtering(params)};
        FrameGraph g;
        g.needs.populations = {grass::kGrassPopulationKind};
        g.needs.populations_on_terrain = true;  // the quads follow it (grass_slices_vertex.glsl)
        g.shader_params.set_block(block);
        g.report["slices"] = fmt::format("{} per direction and 1 horizontal", settings.slices);
        grass::declare_slices_bake(g, settings);
        RasterState per_cell;
        per_cell.vertex_spirv = grass_slices_vert;
        per_cell.fragment_spirv = grass_slices_frag;
        g.passes.push_back(grass::slices_frame_pass(
            settings, per_cell, true,
            {cleared(graph_names::kColor, Use::color_attachment, grass::kUncoveredClear),
             cleared(graph_names::kDepth, Use::depth_attachment, kFarDepth)}));
        return g;
    }
};

RegisterTechnique<GrassSlices> registered;

}  // namespace
}  // namespace canopy
