// grass.lod: a field drawn near as blades, in the middle as the ray-cast volume (Lemme; in up to
// three levels of slices, his football field's 8, 2 and 1) or the BTF slices (Boulanger) and far as
// the image slice (Boulanger 2008 §4.2.5, Lemme 2012 §5.4), the three meeting by density thresholds:
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

const std::vector<ParamSpec>& params_specs();

// "name value, ..." of those of `names` given other than their defaults.
std::string given_values(const ParamSet& params, std::initializer_list<const char*> names) {
    std::string out;
    for (const char* name : names) {
        const ParamSpec& spec = *std::find_if(params_specs().begin(), params_specs().end(),
                                              [&](const ParamSpec& p) { return p.name == name; });
        const ParamValue& value = std::find_if(params.values().begin(), params.values().end(),
                                               [&](const auto& v) { return v.first == name; })->second;
        if (value != spec.default_value) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", name, to_string(value));
    }
    return out;
}

// Each volume level's GrassLodVolumeLevel (its level and slices, binding 7 of its pass), uploaded at load.
std::string volume_level_name(const grass::VolumeSettings& volume) { return volume.prefix + "level"; }
constexpr const char* kHilltopLevel = "hilltop_level";  // the hilltop pass's: the last level's, z = 1

void declare_volume_levels(FrameGraph& g, const std::vector<grass::VolumeSettings>& volumes, bool hilltop) {
    PassDecl setup{.name = "volume_levels_setup", .kind = PassKind::copy, .phase = Phase::load};
    std::vector<std::pair<std::string, shader::GrassLodVolumeLevel>> records;
    for (size_t level = 0; level < volumes.size(); ++level)
        records.push_back({volume_level_name(volumes[level]), {glm::ivec4(int(level + 1), int(volumes[level].slices), 0, 0)}});
    if (hilltop) records.push_back({kHilltopLevel, {glm::ivec4(int(volumes.size()), int(volumes.back().slices), 1, 0)}});
    for (const auto& [name, record] : records) {
        g.buffers.push_back({.name = name, .bytes = sizeof(record), .usage = kUniformBuffer, .persistent = true});
        setup.uses.push_back(use(name, Use::transfer_write));
    }
    setup.settings = fmt::format("{} volume levels{}", volumes.size(), hilltop ? ", the hilltops' pass" : "");
    setup.record = [records](PassContext& pc) {
        for (const auto& [name, record] : records) pc.upload(name, &record, sizeof(record));
    };
    g.passes.push_back(std::move(setup));
}

const std::vector<ParamSpec>& params_specs() {
    static const std::vector<ParamSpec> specs = shader::GrassLodParams::specs();
    return specs;
}

// The window each cut is crossed over (grass_lod_params.h's `transition`): "thesis" is the
// middle band's author's, Boulanger's with his BTF slices, Lemme's with his volume.
int transition_window(const ParamSet& params) {
    const std::string& transition = params.choice("transition");
    if (transition == "binary") return shader::GRASS_LOD_WINDOW_BINARY;
    if (transition == "boulanger") return shader::GRASS_LOD_WINDOW_LINEAR;
    if (transition == "lemme") return shader::GRASS_LOD_WINDOW_SMOOTHSTEP;
    return params.choice("middle") == "slices" ? shader::GRASS_LOD_WINDOW_LINEAR : shader::GRASS_LOD_WINDOW_SMOOTHSTEP;
}

std::string transition_report(const shader::GrassLodParams& block) {
    if (block.transition_window == shader::GRASS_LOD_WINDOW_BINARY || !(block.transition_width > 0.0f))
        return "binary cut";
    return fmt::format("{} over +-{} of the local density, screen door",
                       block.transition_window == shader::GRASS_LOD_WINDOW_LINEAR
                           ? "Boulanger's linear window (Algorithm 1, eq 4.6), omega_max"
                           : "Lemme's smoothstep window (eq 5.26), epsilon",
                       block.transition_width);
}

class GrassLod final : public Technique {
public:
    std::string name() const override { return "grass.lod"; }
    std::string summary() const override {
        return "grass in three distance bands: blades near, the ray-cast volume (in up to three levels of slices) or BTF slices in the middle, the image slice far, meeting blade by blade by density thresholds";
    }
    std::string paper() const override {
        return "Boulanger 2008 §4.2.5 (eq 4.3-4.6, Algorithm 1); Lemme 2012 §5.4 (eq 5.22-5.26)";
    }
    std::vector<ParamSpec> params() const override { return params_specs(); }
    ErrorColumns error_columns() const override { return grass::kGrassErrorColumns; }
    std::vector<std::string> pareto_errors() const override { return grass::pareto_errors(); }

    std::optional<ParamConflict> conflict(const ParamSet& params) const override {
        if (auto c = grass::blade_samples_conflict(params)) return c;
        if (auto c = grass::slice_filtering_conflict(params)) return c;
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
        if (params.boolean("hilltop_volume") && params.choice("culling") != "quadtree")
            return ParamConflict{{"hilltop_volume", "culling"},
                                 "the hilltops are a lod test of the quadtree's traversal (Lemme §6.4.6)",
                                 "culling = \"quadtree\" with hilltop_volume, or hilltop_volume = false"};
        const long long levels = params.integer("volume_levels");
        if (levels > 1 && params.choice("middle") != "volume")
            return ParamConflict{{"volume_levels", "middle"},
                                 "only the volume has levels (Lemme's); the BTF slices are one level",
                                 "middle = \"volume\" with volume_levels, or volume_levels = 1"};
        // The distances in order, with the used levels' ramps between the blades' and the image's.
        std::vector<std::string> names{"geometry_full", "geometry_none"};
        if (levels >= 2) names.insert(names.end(), {"volume_2_start", "volume_2_full"});
        if (levels >= 3) names.insert(names.end(), {"volume_3_start", "volume_3_full"});
        names.insert(names.end(), {"image_start", "image_full"});
        std::string values, order;
        bool ordered = true;
        for (size_t i = 0; i < names.size(); ++i) {
            values += fmt::format("{}{} = {}", i ? ", " : "", names[i], params.real(names[i]));
            order += (i ? " <= " : "") + names[i];
            if (i > 0 && params.real(names[i - 1]) > params.real(names[i])) ordered = false;
        }
        if (!ordered)
            return ParamConflict{names, fmt::format("the bands' distances are out of order: {}", values), order};
        return std::nullopt;
    }

    FrameGraph graph(const ParamSet& params) const override {
        auto block = shader::GrassLodParams::from(params);
        block.transition_window = transition_window(params);
        const uint32_t samples = uint32_t(params.integer("samples"));
        const bool to_coverage = block.coverage == shader::GRASS_COVERAGE_ALPHA_TO_COVERAGE;
        const bool gpu_culled = params.choice("culling") == "gpu";
        const grass::SliceFiltering filtering = grass::slice_filtering(params);
        const bool quadtree = params.choice("culling") == "quadtree";
        // Each band's distances, for the quadtree (Lemme §6.1-6.2: the blades' copies, the volume's and image's
        // macro-cells) and the GPU culls alike.
        const auto band_distances = [&](int representation) {
            return shader::lod_band_distances(representation, block.geometry_full, block.geometry_none, block.image_start,
                                              block.image_full);
        };
        // Each blade's band at its root (transition_distance = "blade"), or at its cell's centre.
        const bool by_blade_root = block.transition_distance == shader::GRASS_LOD_DISTANCE_BLADE;
        const grass::QuadtreeBandDecl near_band{.name = "near",
                                                .min_distance = band_distances(shader::GRASS_LOD_GEOMETRY).x,
                                                .max_distance = band_distances(shader::GRASS_LOD_GEOMETRY).y,
                                                .by_blade_root = by_blade_root};
        // The volume's levels (Lemme's 8, 2 and 1 slices): level 1 keeps the names it has alone.
        const int levels = block.volume_levels;
        const shader::vec4 ramps = shader::lod_volume_ramps(levels, block.volume_2_start, block.volume_2_full,
                                                            block.volume_3_start, block.volume_3_full);
        const auto level_name = [](const char* stem, int level) {
            return level == 1 ? fmt::format("{}", stem) : fmt::format("{}{}", stem, level);
        };
        std::vector<grass::QuadtreeBandDecl> middle_bands;
        for (int level = 1; level <= levels; ++level) {
            const shader::vec2 d = shader::lod_volume_level_distances(level, ramps, block.geometry_full, block.image_full);
            middle_bands.push_back({.name = level_name("middle", level),
                                    .min_distance = d.x,
                                    .max_distance = d.y,
                                    .vertex_count = grass::kVolumeCellVertices,
                                    .max_macro = uint32_t(params.integer("middle_macro_max")),
                                    .height_ranges = true,
                                    .by_blade_root = by_blade_root});
        }
        const grass::QuadtreeBandDecl& middle_band = middle_bands.front();
        const grass::QuadtreeBandDecl far_band{.name = "far",
                                               .min_distance = band_distances(shader::GRASS_LOD_IMAGE).x,
                                               .max_distance = band_distances(shader::GRASS_LOD_IMAGE).y,
                                               .vertex_count = grass::kImageCellVertices,
                                               .max_macro = uint32_t(params.integer("far_macro_max")),
                                               .max_unplanarity = float(params.real("macro_unplanarity")),
                                               .by_blade_root = by_blade_root};
        // Lemme's hilltops (§6.4.6): the far band's cells again, those whose box reaches above the
        // eye, drawn by the volume in its own macro-cells.
        const bool hilltop = quadtree && params.boolean("hilltop_volume");
        const grass::QuadtreeBandDecl hilltop_band{.name = "hilltop",
                                                   .min_distance = far_band.min_distance,
                                                   .max_distance = far_band.max_distance,
                                                   .vertex_count = grass::kVolumeCellVertices,
                                                   .max_macro = middle_band.max_macro,
                                                   .height_ranges = true,
                                                   .above_eye = true,
                                                   .by_blade_root = by_blade_root};
        std::vector<grass::VolumeSettings> volumes;
        const uint32_t level_slices[3] = {uint32_t(block.slices), uint32_t(params.integer("slices_2")),
                                          uint32_t(params.integer("slices_3"))};
        for (int level = 1; level <= levels; ++level)
            volumes.push_back({.slices = level_slices[level - 1],
                               .resolution = uint32_t(params.integer("resolution")),
                               .height_resolution = uint32_t(params.integer("height_resolution")),
                               .prefix = level_name("volume", level) + "_",
                               .culled_by = gpu_culled ? std::optional<std::string>(level_name("middle", level) + "_")
                                                       : std::nullopt,
                               .selected_by = quadtree ? std::optional(middle_bands[size_t(level - 1)]) : std::nullopt,
                               .filtering = filtering});
        const bool btf = params.choice("middle") == "slices";
        const grass::SlicesSettings slices{.slices = uint32_t(block.slices),
                                           .resolution = uint32_t(params.integer("resolution")),
                                           .height_resolution = uint32_t(params.integer("height_resolution")),
                                           .shadow_resolution = uint32_t(params.integer("middle_shadow_resolution")),
                                           .prefix = "middle_",
                                           .culled_by = gpu_culled ? std::optional<std::string>("middle_") : std::nullopt,
                                           .filtering = filtering};
        const grass::ImageSettings image{.resolution = uint32_t(params.integer("image_resolution")),
                                         .slice_height = float(params.real("slice_height")),
                                         .prefix = "image_",
                                         .culled_by = gpu_culled ? std::optional<std::string>("far_") : std::nullopt,
                                         .selected_by = quadtree ? std::optional(far_band) : std::nullopt,
                                         .filtering = filtering};
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
        std::string volume_levels;  // Lemme's levels beyond the first, when used
        if (!btf && levels >= 2)
            volume_levels = fmt::format(", {} slices from {}-{}", volumes[1].slices, block.volume_2_start, block.volume_2_full);
        if (!btf && levels >= 3)
            volume_levels += fmt::format(", {} from {}-{}", volumes[2].slices, block.volume_3_start, block.volume_3_full);
        g.report["bands"] = fmt::format("blades to {}-{}, {} ({} slices{}{}{}) to {}-{}, image beyond", block.geometry_full,
                                        block.geometry_none, btf ? "BTF slices" : "volume", volumes[0].slices,
                                        volume_levels, per_sample ? ", ray-cast per sample" : "", middle_shadows,
                                        block.image_start, block.image_full);
        g.report["transition"] = transition_report(block);
        g.report["coverage"] = to_coverage ? "alpha-to-coverage" : "alpha-test";
        g.report["samples"] = std::to_string(samples);
        const bool culled = gpu_culled;
        g.report["culling"] = culled     ? "gpu, each band's copies within its distances"
                              : quadtree ? fmt::format("quadtree, macro-cells up to {} (middle) and {} (far) cells a side, "
                                                       "at most {} near cells and {} macro-cells a band{}",
                                                       middle_band.max_macro, far_band.max_macro,
                                                       params.integer("near_capacity"), params.integer("macro_capacity"),
                                                       hilltop ? ", the volume again on hilltops" : "")
                                         : "none";
        if (!quadtree) {
            // The quadtree's settings, when given without it: said, so a sweep over them shows why nothing moves.
            const std::string unused =
                given_values(params, {"middle_macro_max", "far_macro_max", "near_capacity", "macro_capacity",
                                      "macro_unplanarity", "hilltop_volume"});
            if (!unused.empty()) g.report["culling"] += " (" + unused + " unused: culling = \"quadtree\" only)";
        }
        if (quadtree) {
            std::vector<grass::QuadtreeBandDecl> bands{near_band};
            bands.insert(bands.end(), middle_bands.begin(), middle_bands.end());
            bands.push_back(far_band);
            if (hilltop) bands.push_back(hilltop_band);
            grass::declare_quadtree(g, bands,
                                    {.copies = uint32_t(params.integer("near_capacity")),
                                     .copies_parameter = "near_capacity",
                                     .macros = uint32_t(params.integer("macro_capacity")),
                                     .macros_parameter = "macro_capacity"});
        }
        if (culled) {
            // One cull per band, to the distances outside which its share of a cell is nothing.
            // The same distances as the quadtree's bands (lod_band_distances, lod_volume_level_distances).
            const auto cull = [](const grass::QuadtreeBandDecl& band, uint32_t vertices, uint32_t on_terrain = 0) {
                return grass::CullBand{.prefix = band.name == "near" ? "" : band.name + "_",
                                       .min_distance = band.min_distance,
                                       .max_distance = band.max_distance >= shader::LOD_NO_DISTANCE ? 0.0f : band.max_distance,
                                       .vertex_count = vertices, .vertex_count_on_terrain = on_terrain};
            };
            std::vector<grass::CullBand> culls{cull(near_band, 0)};
            if (btf)
                culls.push_back(cull(middle_band, grass::slices_cell_vertices(slices),
                                     grass::slices_cell_vertices_on_terrain(slices)));
            else
                for (const grass::QuadtreeBandDecl& level : middle_bands) culls.push_back(cull(level, grass::kVolumeCellVertices));
            culls.push_back(cull(far_band, grass::kImageCellVertices));
            grass::declare_grass_cull(g, culls);
        }
        if (samples > 1) {
            g.images.push_back({.name = "msaa_color", .format = kColorFormat, .extent = ImageExtent::screen(),
                                .samples = samples});
            g.images.push_back({.name = "msaa_depth", .format = VK_FORMAT_D32_SFLOAT, .extent = ImageExtent::screen(),
                                .samples = samples});
        }
        if (btf) grass::declare_slices_bake(g, slices);
        else
            for (const grass::VolumeSettings& volume : volumes) grass::declare_volume_bake(g, volume);
        if (!btf) declare_volume_levels(g, volumes, hilltop);
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
        // The slices' filtered alpha is coverage as the blades' outline is (grass_slice_coverage.glsl).
        middle.alpha_to_coverage = to_coverage && samples > 1;
        RasterState middle_on_terrain = middle;  // the quadtree's macro-cells on a terrain
        middle_on_terrain.vertex_spirv = grass_lod_volume_macro_terrain_vert;
        middle_on_terrain.fragment_spirv = per_sample ? std::span<const uint32_t>(grass_lod_volume_macro_terrain_per_sample_frag)
                                                      : std::span<const uint32_t>(grass_lod_volume_macro_terrain_frag);
        if (btf) {
            g.passes.push_back(grass::slices_frame_pass(slices, middle, false, band_attachments(samples, false, false)));
        } else {
            for (size_t level = 0; level < volumes.size(); ++level) {
                g.passes.push_back(grass::volume_frame_pass(volumes[level], middle, false,
                                                            band_attachments(samples, false, false), middle_on_terrain));
                g.passes.back().uses.push_back(use(volume_level_name(volumes[level]), Use::uniform, 7));
                g.passes.back().settings += fmt::format("; volume level {} of {}", level + 1, volumes.size());
                if (per_sample) g.passes.back().settings += "; ray-cast once per covered sample";
                // said, as unused culling settings are
                if (!middle_shadows.empty()) g.passes.back().settings += ";" + middle_shadows;
            }
        }
        if (btf && per_sample) g.passes.back().settings += "; ray-cast once per covered sample";
        // The levels' settings, when given without their levels: said, as the quadtree's are.
        const std::string unused_2 = levels >= 2 ? "" : given_values(params, {"volume_2_start", "volume_2_full", "slices_2"});
        const std::string unused_3 = levels >= 3 ? "" : given_values(params, {"volume_3_start", "volume_3_full", "slices_3"});
        if (!unused_2.empty()) g.passes.back().settings += fmt::format("; {} unused: volume_levels >= 2 only", unused_2);
        if (!unused_3.empty()) g.passes.back().settings += fmt::format("; {} unused: volume_levels = 3 only", unused_3);
        if (hilltop) {  // after the levels' settings, which go on the middle band's last pass
            // The last level's bake and slices, the hilltop band's macro-cells, the image's blades.
            grass::VolumeSettings top = volumes.back();
            top.selected_by = hilltop_band;
            PassDecl pass = grass::volume_frame_pass(top, middle, false, band_attachments(samples, false, false),
                                                     middle_on_terrain);
            pass.name = "hilltop_volumes";
            pass.uses.push_back(use(kHilltopLevel, Use::uniform, 7));
            pass.settings += fmt::format("; the far band's blades again where a cell reaches above the eye, with volume "
                                         "level {}'s {} slices (Lemme's hilltops)",
                                         volumes.size(), top.slices);
            if (per_sample) pass.settings += "; ray-cast once per covered sample";
            g.passes.push_back(std::move(pass));
        }
        RasterState quads;
        quads.vertex_spirv = quadtree ? std::span<const uint32_t>(grass_lod_image_macro_vert)
                                      : std::span<const uint32_t>(grass_lod_image_vert);
        quads.fragment_spirv = quadtree ? std::span<const uint32_t>(grass_lod_image_macro_frag)
                                        : std::span<const uint32_t>(grass_lod_image_frag);
        quads.alpha_to_coverage = to_coverage && samples > 1;
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
