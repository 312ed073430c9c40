#include "quadtree_passes.hpp"

#include "grass_passes.hpp"
#include "grass_population.hpp"
#include "macro_cells.hpp"
#include "macro_passes.hpp"
#include "patch_bake.hpp"
#include "quadtree_selection.hpp"

#include "core/error.hpp"
#include "scene/population.hpp"

#include <fmt/format.h>

#include <array>
#include <cstddef>
#include <cstring>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace canopy::grass {

namespace {

bool draws_copies(const QuadtreeBandDecl& band) { return band.vertex_count == 0; }

// The field as the traversal reads it every frame, worked out once at load (the prototype's
// bounds run over every vertex of the patch: 60,000 on the football field).
constexpr const char* kQuadtreeField = "quadtree_field";
static_assert(std::is_trivially_copyable_v<QuadtreeField>);

}  // namespace

std::string quadtree_list(const std::string& band) { return band + "_quadtree_list"; }
std::string quadtree_draw(const std::string& band) { return band + "_quadtree_draw"; }
std::string quadtree_ranges(const std::string& band) { return band + "_quadtree_ranges"; }

void declare_quadtree(FrameGraph& g, const std::vector<QuadtreeBandDecl>& bands, const QuadtreeCapacity& capacity) {
    g.needs.population_copies_on_gpu = false;
    g.buffers.push_back({.name = macro_names::kCells, .bytes_per_copy = sizeof(shader::GrassCell),
                         .usage = kStorageBuffer, .persistent = true});
    g.buffers.push_back({.name = macro_names::kField, .bytes = sizeof(shader::GrassMacroField),
                         .usage = kUniformBuffer, .persistent = true});
    g.buffers.push_back({.name = kQuadtreeField, .bytes = sizeof(QuadtreeField), .usage = kStorageBuffer,
                         .persistent = true, .host_visible = true});
    // The grid heights, read by the traversal on the CPU and by the macro shaders.
    g.buffers.push_back(grid_heights_buffer(true));
    for (const QuadtreeBandDecl& band : bands) {
        if (draws_copies(band))
            g.buffers.push_back({.name = quadtree_list(band.name), .bytes = uint64_t(capacity.copies) * sizeof(PopulationInstance),
                                 .usage = kVertexBuffer, .host_visible = true});
        else
            g.buffers.push_back({.name = quadtree_list(band.name), .bytes = uint64_t(capacity.macros) * sizeof(MacroInstance),
                                 .usage = kVertexBuffer, .host_visible = true});
        if (!draws_copies(band) && band.height_ranges)
            g.buffers.push_back({.name = quadtree_ranges(band.name), .bytes = uint64_t(capacity.macros) * sizeof(glm::vec2),
                                 .usage = kStorageBuffer, .host_visible = true, .only_on_terrain = true});
        g.buffers.push_back({.name = quadtree_draw(band.name),
                             .bytes = draws_copies(band) ? sizeof(VkDrawIndexedIndirectCommand) : sizeof(VkDrawIndirectCommand),
                             .usage = kIndirectBuffer, .host_visible = true});
    }

    // Load: the field's cells as the macro shaders read them, and its placement.
    PassDecl setup{.name = "quadtree_setup", .kind = PassKind::copy, .phase = Phase::load};
    setup.uses = {use(macro_names::kCells, Use::transfer_write), use(macro_names::kField, Use::transfer_write),
                  use(kQuadtreeField, Use::transfer_write), use(macro_names::kHeights, Use::transfer_write)};
    setup.settings = "the first grass population's cells";
    setup.record = [](PassContext& pc) {
        const GeneratedPopulation* grass = first_grass(pc.populations());
        if (!grass || grass->instances.empty()) {
            const QuadtreeField nothing;  // no cells: nothing to traverse
            pc.upload(kQuadtreeField, &nothing, sizeof(nothing));
            return;
        }
        const GrassField field = grass_field_placement(grass->params);
        const Bounds bounds = prototype_bounds(grass);  // over every vertex of the patch: once
        const QuadtreeField traversed{field.cells, field.origin, field.cell_size, bounds};
        pc.upload(kQuadtreeField, &traversed, sizeof(traversed));
        const std::vector<shader::GrassCell> cells = grass_cells(field, grass->instances);
        const shader::GrassMacroField placement = macro_field(field, 0, cell_frame(bounds).max.y, grass->transmission);
        pc.upload(macro_names::kCells, cells.data(), cells.size() * sizeof(shader::GrassCell));
        pc.upload(macro_names::kField, &placement, sizeof(placement));
        if (macros_on_terrain(pc.populations())) upload_grid_heights(pc, field, *grass);
    };
    g.passes.push_back(std::move(setup));

    // Every frame: the traversal, and each band's list and record.
    PassDecl select{.name = "quadtree", .kind = PassKind::cpu};
    select.uses.push_back(use(kQuadtreeField, Use::storage_read, 0));  // read on the CPU (no descriptor)
    select.uses.push_back(use(macro_names::kHeights, Use::storage_read, 1));
    std::string settings;
    for (const QuadtreeBandDecl& band : bands) {
        select.uses.push_back(use(quadtree_list(band.name), Use::transfer_write));
        select.uses.push_back(use(quadtree_draw(band.name), Use::transfer_write));
        if (!draws_copies(band) && band.height_ranges)
            select.uses.push_back(use(quadtree_ranges(band.name), Use::transfer_write));
        settings += fmt::format("{}{} {}-{} {}{}{}{}{}", settings.empty() ? "" : "; ", band.name, band.min_distance,
                                band.max_distance, draws_copies(band) ? "copies" : fmt::format("macro<={}", band.max_macro),
                                std::isinf(band.max_unplanarity)
                                    ? ""
                                    : fmt::format(" unplanarity<={} on a terrain", band.max_unplanarity),
                                band.height_ranges ? " height ranges on a terrain" : "",
                                band.above_eye ? " above the eye only" : "",
                                band.by_blade_root ? " by blade roots" : "");
    }
    select.settings = fmt::format("{}; capacity {} copies, {} macro-cells", settings, capacity.copies, capacity.macros);
    select.run = [bands, capacity](CpuPassContext& cc) {
        const GeneratedPopulation* grass = first_grass(cc.populations());
        size_t grass_populations = 0;
        for (const GeneratedPopulation& p : cc.populations()) grass_populations += p.kind == kGrassPopulationKind;
        if (grass_populations > 1)
            throw GpuError(fmt::format("the quadtree draws one grass population, and the scene has {}: use culling = "
                                       "\"gpu\", or one population",
                                       grass_populations));
        QuadtreeSelection selection;
        QuadtreeField field;
        std::memcpy(&field, cc.read(kQuadtreeField).data(), sizeof(field));
        const bool on_terrain = macros_on_terrain(cc.populations());
        if (grass && !grass->instances.empty()) {
            std::vector<QuadtreeBand> tests;
            for (const QuadtreeBandDecl& band : bands)
                tests.push_back({band.min_distance, band.max_distance, draws_copies(band) ? 1u : band.max_macro,
                                 band.max_unplanarity, band.above_eye,
                                 band.by_blade_root ? root_margin_for(field) : 0.0f});
            std::span<const float> grid;
            if (on_terrain) {
                const std::span<const std::byte> bytes = cc.read(macro_names::kHeights);
                const size_t vertices = size_t(field.cells.x + 1) * size_t(field.cells.y + 1);
                if (bytes.size() < vertices * sizeof(float))
                    throw std::logic_error(fmt::format("the quadtree's grid heights hold {} bytes for {} grid vertices",
                                                       bytes.size(), vertices));
                grid = {reinterpret_cast<const float*>(bytes.data()), vertices};
            }
            selection = select_cells(field, tests, cc.frame().camera.position, cc.view_proj(), grid);
        } else {
            selection.bands.resize(bands.size());
        }
        cc.count("quadtree_nodes", double(selection.nodes_visited));
        for (size_t b = 0; b < bands.size(); ++b) {
            const QuadtreeBandDecl& band = bands[b];
            const std::vector<QuadtreeNode>& nodes = selection.bands[b];
            size_t cells = 0;
            for (const QuadtreeNode& n : nodes) cells += n.cells();
            cc.count(band.name + "_cells", double(cells));
            cc.count(band.name + "_draws", double(nodes.size()));
            if (draws_copies(band)) {
                if (nodes.size() > capacity.copies)
                    throw GpuError(fmt::format("the {} band keeps {} cells this frame, more than {} = {}: raise {} (each "
                                               "costs {} bytes) or move the band's far end nearer",
                                               band.name, nodes.size(), capacity.copies_parameter, capacity.copies,
                                               capacity.copies_parameter, sizeof(PopulationInstance)));
                std::vector<PopulationInstance> copies;
                copies.reserve(nodes.size());
                for (const QuadtreeNode& n : nodes)
                    copies.push_back(grass->instances[size_t(n.first.y) * field.cells.x + n.first.x]);
                VkDrawIndexedIndirectCommand draw{};
                if (grass) {
                    draw = cc.population_draw_arguments(grass->name);
                    draw.instanceCount = uint32_t(copies.size());
                }
                if (!copies.empty()) cc.upload(quadtree_list(band.name), copies.data(), copies.size() * sizeof(PopulationInstance));
                cc.upload(quadtree_draw(band.name), &draw, sizeof(draw));
            } else {
                if (nodes.size() > capacity.macros)
                    throw GpuError(fmt::format("the {} band keeps {} macro-cells this frame, more than {} = {}: raise {} "
                                               "(each costs {} bytes{})",
                                               band.name, nodes.size(), capacity.macros_parameter, capacity.macros,
                                               capacity.macros_parameter, sizeof(MacroInstance),
                                               band.height_ranges ? fmt::format(", {} on a terrain",
                                                                                sizeof(MacroInstance) + sizeof(glm::vec2))
                                                                  : std::string()));
                std::vector<MacroInstance> macros;
                macros.reserve(nodes.size());
                for (const QuadtreeNode& n : nodes) macros.emplace_back(n.first.x, n.first.y, n.span.x, n.span.y);
                const VkDrawIndirectCommand draw{band.vertex_count, uint32_t(macros.size()), 0, 0};
                if (!macros.empty())
                    cc.upload(quadtree_list(band.name), macros.data(), macros.size() * sizeof(MacroInstance));
                if (on_terrain && band.height_ranges && !nodes.empty()) {
                    std::vector<glm::vec2> ranges;
                    ranges.reserve(nodes.size());
                    for (const QuadtreeNode& n : nodes) ranges.push_back(n.heights);
                    cc.upload(quadtree_ranges(band.name), ranges.data(), ranges.size() * sizeof(glm::vec2));
                }
                cc.upload(quadtree_draw(band.name), &draw, sizeof(draw));
            }
        }
    };
    g.passes.push_back(std::move(select));
}

void use_quadtree_band(PassDecl& pass, const QuadtreeBandDecl& band) {
    if (!draws_copies(band)) {
        pass.uses.push_back(use(macro_names::kField, Use::uniform, 3));
        pass.uses.push_back(use(macro_names::kCells, Use::storage_read, 4));
        pass.uses.push_back(use(macro_names::kHeights, Use::storage_read, 5));
        if (band.height_ranges) pass.uses.push_back(use(quadtree_ranges(band.name), Use::storage_read, 6));
    }
    pass.uses.push_back(use(quadtree_list(band.name), Use::vertex));
    pass.uses.push_back(use(quadtree_draw(band.name), Use::indirect));
}

bool quadtree_band_empty(const PassContext& pc, const QuadtreeBandDecl& band) {
    // The record the band's CPU selection wrote this frame (select_quadtree above): its instances.
    const std::span<const std::byte> record = pc.read(quadtree_draw(band.name));
    uint32_t instances = 0;
    if (draws_copies(band)) {
        if (record.size() < sizeof(VkDrawIndexedIndirectCommand)) return false;
        std::memcpy(&instances, record.data() + offsetof(VkDrawIndexedIndirectCommand, instanceCount), sizeof instances);
    } else {
        if (record.size() < sizeof(VkDrawIndirectCommand)) return false;
        std::memcpy(&instances, record.data() + offsetof(VkDrawIndirectCommand, instanceCount), sizeof instances);
    }
    return instances == 0;
}

void draw_quadtree_band(PassContext& pc, const QuadtreeBandDecl& band, const std::string& vertex_buffer) {
    // A band that keeps nothing this frame records no draw: on lavapipe an indirect draw of no
    // instances still costs milliseconds (issue 37).
    if (quadtree_band_empty(pc, band)) return;
    if (draws_copies(band)) {
        if (const GeneratedPopulation* grass = first_grass(pc.populations()))
            pc.draw_population_indirect(grass->name, quadtree_list(band.name), quadtree_draw(band.name));
        return;
    }
    const std::array<std::string, 2> buffers{vertex_buffer, quadtree_list(band.name)};
    pc.draw_indirect(buffers, quadtree_draw(band.name));
}

void declare_macro_band_pass(PassDecl& frame, const QuadtreeBandDecl& band, const std::optional<RasterState>& ground,
                             RasterState over, RasterState over_on_terrain, const std::string& vertex_buffer) {
    use_quadtree_band(frame, band);
    over.vertices = macro_layout();
    over_on_terrain.vertices = macro_layout();
    frame.record = [ground, over, over_on_terrain, band, vertex_buffer](PassContext& pc) {
        if (ground) record_ground(pc, *ground);
        if (quadtree_band_empty(pc, band)) return;
        pc.bind(pc.raster_pipeline(macros_on_terrain(pc.populations()) ? over_on_terrain : over));
        draw_quadtree_band(pc, band, vertex_buffer);
    };
}

}  // namespace canopy::grass
