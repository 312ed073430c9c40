// grass.lod: a field drawn near as blades, in the middle as the ray-cast volume (Lemme) or the BTF
// slices (Boulanger) and far as the image slice (Boulanger 2008 §4.2.5, Lemme 2012 §5.4), the
// three meeting by density thresholds:
// at a cell's distance, lod_cuts (shaders/lod_selection.h) splits its blades' thresholds into
// three bands, and each representation draws only the blades of its band, so a transition moves
// blades one by one and none is drawn twice or dropped. One pass per band, so each band's share
// of the frame is timed apart; the middle and far bakes are those of grass.volume or grass.slices
// and grass.image (volume_graph.hpp, slices_graph.hpp, image_graph.hpp), and the shaders are compiled from the same
// bodies with the band switched on (shaders/grass_lod_band.glsl).
#include "core/registry.hpp"
#include "graph/pass_context.hpp"
#include "render/frame_uniforms.hpp"

#include "grass_lod_params.h"
#include "../common/grass_cull.hpp"
#include "../common/grass_family.hpp"
#include "../common/grass_passes.hpp"
#include "../common/grass_population.hpp"
#include "../common/quadtree_passes.hpp"
#include "../image/image_graph.hpp"
#include "../shaders/lod_selection.h"
#include "../slices/slices_graph.hpp"
#include "../volume/volume_graph.hpp"

#include "shaders/grass/grass_lod_blades_frag.h"
#include "shaders/grass/grass_lod_blades_vert.h"
#include "shaders/grass/grass_lod_image_frag.h"
#include "shaders/grass/grass_lod_image_macro_frag.h"
#include "shaders/grass/grass_lod_image_macro_terrain_frag.h"
#include "shaders/grass/grass_lod_image_macro_terrain_vert.h"
#include "shaders/grass/grass_lod_image_macro_vert.h"
#include "shaders/grass/grass_lod_image_vert.h"
#include "shaders/grass/grass_lod_slices_frag.h"
#include "shaders/grass/grass_lod_slices_vert.h"
#include "shaders/grass/grass_lod_volume_frag.h"
#include "shaders/grass/grass_lod_volume_per_sample_frag.h"
#include "shaders/grass/grass_lod_volume_macro_frag.h"
#include "shaders/grass/grass_lod_volume_macro_per_sample_frag.h"
#include "shaders/grass/grass_lod_volume_macro_terrain_frag.h"
#include "shaders/grass/grass_lod_volume_macro_terrain_per_sample_frag.h"
#include "shaders/grass/grass_lod_volume_macro_terrain_vert.h"
#include "shaders/grass/grass_lod_volume_macro_vert.h"
#include "shaders/grass/grass_lod_volume_vert.h"

#include <fmt/format.h>

#include <algorithm>

namespace canopy {
namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;  // as the camera target

using grass::cleared;
using grass::kFarDepth;
using grass::use;

// The three passes' attachments: the first clears, the others load; with MSAA they render into
// multisampled targets kept between the passes, and the last resolves into the camera's colour.
std::vector<ResourceUse> band_attachments(uint32_t samples, bool first, bool last) {
    const std::array<float, 4> background = grass::kUncoveredClear;
    const std::string color = samples > 1 ? "msaa_color" : graph_names::kColor;
    const std::string depth = samples > 1 ? "msaa_depth" : graph_names::kDepth;
    std::vector<ResourceUse> uses;
    if (first) {
        uses.push_back(cleared(color, Use::color_attachment, background));
        uses.push_back(cleared(depth, Use::depth_attachment, kFarDepth));
    } else {
        uses.push_back(use(color, Use::color_attachment));
        uses.push_back(use(depth, Use::depth_attachment));
    }
    if (samples > 1 && last) uses.push_back(use(graph_names::kColor, Use::resolve_target));
    return uses;
}

const std::vector<ParamSpec>& params_specs() {
    static const std::vector<ParamSpec> specs = shader::GrassLodParams::specs();
    return specs;
}

class GrassLod final : public Technique {
public:
    std::string name() const override { return "grass.lod"; }
    std::string summary() const override {
        return "grass in three distance bands: blades near, the ray-cast volume or BTF slices in the middle, the image slice far, meeting blade by blade by density thresholds";
    }
    std::string paper() const override {
        return "Boulanger 2008 §4.2.5 (eq 4.3-4.6, Algorithm 1); Lemme 2012 §5.4 (eq 5.22-5.26)";
    }
    std::vector<ParamSpec> params() const override { return params_specs(); }
    ErrorColumns error_columns() const override { return grass::kGrassErrorColumns; }
    std::vector<std::string> pareto_errors() const override { return grass::pareto_errors(); }

    std::optional<ParamConflict> conflict(const ParamSet& params) const override {
        if (auto c = grass::blade_samples_conflict(params)) return c;
        if (params.choice("culling") == "quadtree" && params.choice("middle") == "slices")
            return ParamConflict{{"culling", "middle"},
                                 "the quadtree draws the middle band as macro-cells, which the BTF slices do not have",
                                 "culling = \"gpu\" with middle = \"slices\", or middle = \"volume\" with the quadtree"};
        if (params.integer("middle_shadow_resolution") > 0 && params.choice("middle") != "slices")
            return ParamConflict{{"middle_shadow_resolution", "middle"},
                                 "only the BTF slices bake the blades' shadows; the volume's bake is unshadowed",
                                 "middle = \"slices\" with middle_shadow_resolution, or middle_shadow_resolution = 0"};
        if (params.boolean("middle_per_sample") && (params.integer("samples") != 4 || params.choice("middle") != "volume"))
            return ParamConflict{{"middle_per_sample", "samples", "middle"},
                                 "the middle band is ray-cast per sample only for the volume under 4x MSAA",
                                 "middle_per_sample = true with samples = 4 and middle = \"volume\", or middle_per_sample = false"};
        const double d[4] = {params.real("geometry_full"), params.real("geometry_none"), params.real("image_start"),
                             params.real("image_full")};
        if (!(d[0] <= d[1] && d[1] <= d[2] && d[2] <= d[3]))
            return ParamConflict{{"geometry_full", "geometry_none", "image_start", "image_full"},
                                 fmt::format("the bands' distances {}, {}, {}, {} are out of order", d[0], d[1], d[2], d[3]),
                                 "geometry_full <= geometry_none <= image_start <= image_full"};
        return std::nullopt;
    }

    FrameGraph graph(const ParamSet& params) const override {
        const auto block = shader::GrassLodParams::from(params);
        const uint32_t samples = uint32_t(params.integer("samples"));
        const bool to_coverage = block.coverage == shader::GRASS_COVERAGE_ALPHA_TO_COVERAGE;
        const bool gpu_culled = params.choice("culling") == "gpu";
        const bool quadtree = params.choice("culling") == "quadtree";
        // The quadtree's bands (Lemme §6.1-6.2): the blades' copies, the volume's and image's macro-cells.
        const auto band_distances = [&](int representation) {
            return shader::lod_band_distances(representation, block.geometry_full, block.geometry_none, block.image_start,
                                              block.image_full);
        };
        const grass::QuadtreeBandDecl near_band{.name = "near",
                                                .min_distance = band_distances(shader::GRASS_LOD_GEOMETRY).x,
                                                .max_distance = band_distances(shader::GRASS_LOD_GEOMETRY).y};
        const grass::QuadtreeBandDecl middle_band{.name = "middle",
                                                  .min_distance = band_distances(shader::GRASS_LOD_VOLUME).x,
                                                  .max_distance = band_distances(shader::GRASS_LOD_VOLUME).y,
                                                  .vertex_count = grass::kVolumeCellVertices,
                                                  .max_macro = uint32_t(params.integer("middle_macro_max")),
                                                  .height_ranges = true};
        const grass::QuadtreeBandDecl far_band{.name = "far",
                                               .min_distance = band_distances(shader::GRASS_LOD_IMAGE).x,
                                               .max_distance = band_distances(shader::GRASS_LOD_IMAGE).y,
                                               .vertex_count = grass::kImageCellVertices,
                                               .max_macro = uint32_t(params.integer("far_macro_max")),
                                               .max_unplanarity = float(params.real("macro_unplanarity"))};
        const grass::VolumeSettings volume{.slices = uint32_t(block.slices),
                                           .resolution = uint32_t(params.integer("resolution")),
                                           .height_resolution = uint32_t(params.integer("height_resolution")),
                                           .prefix = "volume_",
                                           .culled_by = gpu_culled ? std::optional<std::string>("middle_") : std::nullopt,
                                           .selected_by = quadtree ? std::optional(middle_band) : std::nullopt};
        const bool btf = params.choice("middle") == "slices";
        const grass::SlicesSettings slices{.slices = uint32_t(block.slices),
                                           .resolution = uint32_t(params.integer("resolution")),
                                           .height_resolution = uint32_t(params.integer("height_resolution")),
                                           .shadow_resolution = uint32_t(params.integer("middle_shadow_resolution")),
                                           .prefix = "middle_",
                                           .culled_by = gpu_culled ? std::optional<std::string>("middle_") : std::nullopt};
        const grass::ImageSettings image{.resolution = uint32_t(params.integer("image_resolution")),
                                         .slice_height = float(params.real("slice_height")),
                                         .prefix = "image_",
                                         .culled_by = gpu_culled ? std::optional<std::string>("far_") : std::nullopt,
                                         .selected_by = quadtree ? std::optional(far_band) : std::nullopt};
        FrameGraph g;
        g.needs.populations = {grass::kGrassPopulationKind};
        // Each band's per-cell representation follows a terrain as it does alone, and so do the
        // quadtree's macro-cells (their _terrain shaders, chosen when the frame is recorded).
        g.needs.populations_on_terrain = true;
        g.shader_params.set_block(block);
        const bool per_sample = params.boolean("middle_per_sample");
        // The shadowed bake is the slices' alone; given with the volume (a config refuses that, conflict()) it is said unused.
        const std::string middle_shadows =
            slices.shadow_resolution == 0 ? ""
            : btf ? fmt::format(", shadows baked from {}x{} light views", slices.shadow_resolution, slices.shadow_resolution)
                  : fmt::format(" (middle_shadow_resolution {} unused: middle = \"slices\" only)", slices.shadow_resolution);
        g.report["bands"] = fmt::format("blades to {}-{}, {} ({} slices{}{}) to {}-{}, image beyond", block.geometry_full,
                                        block.geometry_none, btf ? "BTF slices" : "volume", volume.slices,
                                        per_sample ? ", ray-cast per sample" : "", middle_shadows, block.image_start,
                                        block.image_full);
        g.report["coverage"] = to_coverage ? "alpha-to-coverage" : "alpha-test";
        g.report["samples"] = std::to_string(samples);
        const bool culled = gpu_culled;
        g.report["culling"] = culled     ? "gpu, each band's copies within its distances"
                              : quadtree ? fmt::format("quadtree, macro-cells up to {} (middle) and {} (far) cells a side, "
                                                       "at most {} near cells",
                                                       middle_band.max_macro, far_band.max_macro,
                                                       params.integer("near_capacity"))
                                         : "none";
        if (!quadtree) {
            // The quadtree's settings, when given without it: said, so a sweep over them shows why nothing moves.
            std::string unused;
            for (const char* name : {"middle_macro_max", "far_macro_max", "near_capacity", "macro_unplanarity"}) {
                const ParamSpec& spec = *std::find_if(params_specs().begin(), params_specs().end(),
                                                      [&](const ParamSpec& p) { return p.name == name; });
                const ParamValue& value = std::find_if(params.values().begin(), params.values().end(),
                                                       [&](const auto& v) { return v.first == name; })->second;
                if (value != spec.default_value)
                    unused += fmt::format("{}{} {}", unused.empty() ? "" : ", ", name, to_string(value));
            }
            if (!unused.empty()) g.report["culling"] += " (" + unused + " unused: culling = \"quadtree\" only)";
        }
        if (quadtree)
            grass::declare_quadtree(g, {near_band, middle_band, far_band}, uint32_t(params.integer("near_capacity")),
                                    "near_capacity");
        if (culled) {
            // One cull per band, to the distances outside which its share of a cell is nothing.
            const auto band = [&](int representation, std::string prefix, uint32_t vertices, uint32_t on_terrain = 0) {
                const shader::vec2 d = shader::lod_band_distances(representation, block.geometry_full, block.geometry_none,
                                                                  block.image_start, block.image_full);
                return grass::CullBand{.prefix = std::move(prefix), .min_distance = d.x,
                                       .max_distance = d.y >= shader::LOD_NO_DISTANCE ? 0.0f : d.y,
                                       .vertex_count = vertices, .vertex_count_on_terrain = on_terrain};
            };
            grass::declare_grass_cull(
                g, {band(shader::GRASS_LOD_GEOMETRY, "", 0),
                    btf ? band(shader::GRASS_LOD_VOLUME, "middle_", grass::slices_cell_vertices(slices),
                               grass::slices_cell_vertices_on_terrain(slices))
                        : band(shader::GRASS_LOD_VOLUME, "middle_", grass::kVolumeCellVertices),
                    band(shader::GRASS_LOD_IMAGE, "far_", grass::kImageCellVertices)});
        }
        if (samples > 1) {
            g.images.push_back({.name = "msaa_color", .format = kColorFormat, .extent = ImageExtent::screen(),
                                .samples = samples});
            g.images.push_back({.name = "msaa_depth", .format = VK_FORMAT_D32_SFLOAT, .extent = ImageExtent::screen(),
                                .samples = samples});
        }
        if (btf) grass::declare_slices_bake(g, slices);
        else grass::declare_volume_bake(g, volume);
        grass::declare_image_bake(g, image);

        // Near: the ground and the blades of the geometry's band.
        PassDecl blades{.name = "blades", .kind = PassKind::raster};
        blades.push_constant_bytes = sizeof(DrawConstants);
        blades.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0)};
        for (ResourceUse& u : band_attachments(samples, true, false)) blades.uses.push_back(std::move(u));
        RasterState field;
        field.vertex_spirv = grass_lod_blades_vert;
        field.fragment_spirv = grass_lod_blades_frag;
        field.vertices = VertexLayout::population();
        field.alpha_to_coverage = to_coverage && samples > 1;
        blades.settings = fmt::format("samples={} coverage={} culling={}", samples, g.report["coverage"], g.report["culling"]);
        if (culled) grass::use_cull_survivors(blades);
        if (quadtree) grass::use_quadtree_band(blades, near_band);
        blades.record = [ground = grass::ground_state(), field, culled, quadtree, near_band](PassContext& pc) {
            grass::record_ground(pc, ground);
            pc.bind(pc.raster_pipeline(field));
            if (culled)
                grass::draw_populations_culled(pc);
            else if (quadtree)
                grass::draw_quadtree_band(pc, near_band);
            else
                for (const GeneratedPopulation& population : pc.populations()) pc.draw_population(population.name);
        };
        g.passes.push_back(std::move(blades));

        // Middle: the volume's or the slices' band, then far: the image's.
        RasterState middle;
        middle.vertex_spirv = btf        ? std::span<const uint32_t>(grass_lod_slices_vert)
                              : quadtree ? std::span<const uint32_t>(grass_lod_volume_macro_vert)
                                         : std::span<const uint32_t>(grass_lod_volume_vert);
        middle.fragment_spirv = btf ? std::span<const uint32_t>(grass_lod_slices_frag)
                                : quadtree ? (per_sample ? std::span<const uint32_t>(grass_lod_volume_macro_per_sample_frag)
                                                         : std::span<const uint32_t>(grass_lod_volume_macro_frag))
                                           : (per_sample ? std::span<const uint32_t>(grass_lod_volume_per_sample_frag)
                                                         : std::span<const uint32_t>(grass_lod_volume_frag));
        middle.sample_shading = per_sample;
        RasterState middle_on_terrain = middle;  // the quadtree's macro-cells on a terrain
        middle_on_terrain.vertex_spirv = grass_lod_volume_macro_terrain_vert;
        middle_on_terrain.fragment_spirv = per_sample ? std::span<const uint32_t>(grass_lod_volume_macro_terrain_per_sample_frag)
                                                      : std::span<const uint32_t>(grass_lod_volume_macro_terrain_frag);
        g.passes.push_back(btf ? grass::slices_frame_pass(slices, middle, false, band_attachments(samples, false, false))
                               : grass::volume_frame_pass(volume, middle, false, band_attachments(samples, false, false),
                                                          middle_on_terrain));
        if (per_sample) g.passes.back().settings += "; ray-cast once per covered sample";
        if (!btf && !middle_shadows.empty()) g.passes.back().settings += ";" + middle_shadows;  // said, as unused culling settings are
        RasterState quads;
        quads.vertex_spirv = quadtree ? std::span<const uint32_t>(grass_lod_image_macro_vert)
                                      : std::span<const uint32_t>(grass_lod_image_vert);
        quads.fragment_spirv = quadtree ? std::span<const uint32_t>(grass_lod_image_macro_frag)
                                        : std::span<const uint32_t>(grass_lod_image_frag);
        RasterState quads_on_terrain = quads;
        quads_on_terrain.vertex_spirv = grass_lod_image_macro_terrain_vert;
        quads_on_terrain.fragment_spirv = grass_lod_image_macro_terrain_frag;
        g.passes.push_back(grass::image_frame_pass(image, quads, false, band_attachments(samples, false, true), quads_on_terrain));
        if (samples > 1) g.passes.push_back(grass::clear_camera_depth_pass());
        return g;
    }
};

RegisterTechnique<GrassLod> registered;

}  // namespace
}  // namespace canopy
