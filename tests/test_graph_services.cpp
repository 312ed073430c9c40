// The frame graph's services (graph/frame_graph.hpp, graph/pass_context.hpp) that no shipped
// technique uses yet, exercised by one test-only graph (not in the technique registry) and checked
// against values the CPU computes (issue 9):
//   - a load-phase bake into a persistent, 2-layer, 3-mip image: a raster pass per layer writes
//     mip 0, a compute pass per mip averages the one above (Subresource ranges), every mip and
//     layer read back;
//   - an instanced draw of technique-owned geometry (a vertex and a per-instance buffer through a
//     VertexLayout) with alpha-to-coverage at 4x MSAA (colour and depth), resolved into a
//     single-sample image: alpha 1 covers a quad's pixels fully, 0.5 about half, 0 not at all;
//   - a compute cull that appends survivors' indices, VkDrawIndexedIndirectCommands and a draw
//     count, drawn by draw_indexed_indirect_count with no readback in between;
//   - a CPU pass that uploads a per-frame rectangle into a host-visible buffer a later pass draws;
//   - a persistent buffer a compute pass increments every frame;
//   - a camera path: a world-space triangle lands where the CPU's projection puts it, every frame;
//   - timing: every declared pass has a finite, non-negative time every frame, and the GPU passes'
//     sum agrees with the fence-to-fence wall clock over frames with a few milliseconds of known
//     compute work (the ballast shader of tests/test_compute_timing.cpp, which checks one lone
//     compute submission; here it is a frame of several passes);
//   - and all of it without one validation message, synchronisation validation included.
#include "gpu/context.hpp"
#include "graph/frame_graph.hpp"
#include "graph/pass_context.hpp"
#include "render/frame_renderer.hpp"
#include "run/statistics.hpp"
#include "scene/camera.hpp"
#include "scene/geometry.hpp"
#include "support/test_gpu.hpp"
#include "support/tiny_scene.hpp"

#include "shaders/tests/services_bake_frag.h"
#include "shaders/tests/services_counter_comp.h"
#include "shaders/tests/services_cull_comp.h"
#include "shaders/tests/services_downsample_comp.h"
#include "shaders/tests/services_fullscreen_vert.h"
#include "shaders/tests/services_marker_frag.h"
#include "shaders/tests/services_marker_vert.h"
#include "shaders/tests/services_rect_frag.h"
#include "shaders/tests/services_rect_vert.h"
#include "shaders/tests/services_survivor_frag.h"
#include "shaders/tests/services_survivor_vert.h"
#include "shaders/harness/test_ballast_comp.h"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <set>
#include <string>
#include <vector>

using namespace canopy;

namespace {

constexpr uint32_t kWidth = 96, kHeight = 64;  // the camera target; every screen image is this size

// The baked image: kBakeLayers layers of kBakeMips mips, mip 0 kBakeSize texels square.
constexpr uint32_t kBakeSize = 16, kBakeLayers = 2, kBakeMips = 3;

// A screen-space rectangle instance: pixels [x0, x1) x [y0, y1), and an RGBA colour.
struct RectInstance {
    std::array<float, 4> rect{};
    std::array<float, 4> color{};
};
static_assert(sizeof(RectInstance) == 32);

// The alpha-to-coverage quads, disjoint, with integer pixel edges: every sample of a pixel lies
// inside the pixel, so a pixel is wholly inside a quad or wholly outside it.
const std::array<RectInstance, 4> kCoverageQuads{{
    {{4, 20, 20, 36}, {1, 0, 0, 1.0f}},
    {{28, 20, 44, 36}, {0, 1, 0, 0.5f}},
    {{52, 20, 68, 36}, {0, 0, 1, 0.0f}},
    {{76, 20, 92, 36}, {1, 1, 0, 0.75f}},
}};

// The quads the compute pass culls: a grid of kCullQuads, each with a value; those at or above
// kCullThreshold survive.
constexpr uint32_t kCullQuads = 16;
constexpr float kCullThreshold = 0.5f;
float cull_value(uint32_t quad) { return float((quad * 5u) % 16u) / 16.0f; }
std::array<float, 4> cull_rect(uint32_t quad) {
    const float x0 = 4.0f + 11.0f * float(quad % 8), y0 = 8.0f + 24.0f * float(quad / 8);
    return {x0, y0, x0 + 8.0f, y0 + 16.0f};
}
std::set<uint32_t> cpu_survivors() {
    std::set<uint32_t> survivors;
    for (uint32_t q = 0; q < kCullQuads; ++q)
        if (cull_value(q) >= kCullThreshold) survivors.insert(q);
    return survivors;
}

// The CPU pass's rectangle for frame `index`: it moves right 5 pixels a frame along the top.
RectInstance cpu_rect(uint32_t index) {
    const float x0 = 2.0f + 5.0f * float(index);
    return {{x0, 2.0f, x0 + 8.0f, 8.0f}, {1, 0, 1, 1}};
}
constexpr float kCpuBandBottom = 10.0f;  // the CPU rectangle's band: rows above this

// The world-space triangle the camera pass draws through frame.view_proj.
const std::array<glm::vec3, 3> kMarker{glm::vec3(-0.8f, 0.2f, 0.6f), glm::vec3(0.9f, 0.1f, 0.2f),
                                       glm::vec3(0.1f, 1.0f, -0.6f)};
constexpr std::array<float, 3> kMarkerColor{0.25f, 0.5f, 1.0f};  // services_marker.frag

// Known GPU work every frame (harness/shaders/test_ballast.comp): a few milliseconds on lavapipe.
constexpr uint32_t kBusyInvocations = 320 * 180, kBusyIterations = 250;  // about 5 ms on lavapipe, 2 cores: well above the 2 ms the timing test needs

// The texel the bake writes at (x, y) of mip 0 of `layer` (services_bake.frag): small integers,
// so the mips' averages are exact in float.
std::array<float, 4> bake_texel(uint32_t x, uint32_t y, uint32_t layer) {
    return {float(x) + 100.0f * float(layer), float(y), float((x * y) % 7u), 1.0f + float(layer)};
}

// Mip `mip` of `layer` as the CPU computes it: 2x2 means of the mip above, as services_downsample.comp sums.
std::vector<std::array<float, 4>> expected_bake(uint32_t mip, uint32_t layer) {
    uint32_t size = kBakeSize;
    std::vector<std::array<float, 4>> texels(size_t(size) * size);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) texels[y * size + x] = bake_texel(x, y, layer);
    for (uint32_t m = 1; m <= mip; ++m) {
        const uint32_t half = size / 2;
        std::vector<std::array<float, 4>> next(size_t(half) * half);
        for (uint32_t y = 0; y < half; ++y)
            for (uint32_t x = 0; x < half; ++x)
                for (size_t c = 0; c < 4; ++c) {
                    const auto at = [&](uint32_t dx, uint32_t dy) { return texels[(2 * y + dy) * size + 2 * x + dx][c]; };
                    next[y * half + x][c] = 0.25f * (((at(0, 0) + at(1, 0)) + at(0, 1)) + at(1, 1));
                }
        texels = std::move(next);
        size = half;
    }
    return texels;
}

// The cameras of the path: from around the marker, each looking somewhere near it, so that it
// moves across the image from frame to frame.
std::vector<Camera> camera_path() {
    const Camera base = test::tiny_scene().camera;
    const std::array<std::pair<glm::vec3, glm::vec3>, 5> positions_and_targets{{
        {glm::vec3(0, 5, 5), glm::vec3(0.0f, 0.4f, 0.0f)},
        {glm::vec3(3.5f, 3.5f, 3.5f), glm::vec3(0.8f, 0.3f, 0.0f)},
        {glm::vec3(-4, 3, 2.5f), glm::vec3(0.0f, 0.8f, 0.6f)},
        {glm::vec3(1, 2.5f, 5.5f), glm::vec3(-0.9f, 0.1f, 0.0f)},
        {glm::vec3(-2, 5, -3), glm::vec3(0.3f, 0.9f, 0.0f)},
    }};
    std::vector<Camera> path;
    for (const auto& [position, target] : positions_and_targets) {
        Camera c = base;
        c.position = position;
        c.target = target;
        path.push_back(c);
    }
    return path;
}

template <typename T>
std::vector<T> as_vector(const std::vector<std::byte>& bytes) {
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
}

// --- The test technique's frame graph ---------------------------------------------------------

ResourceUse use(const std::string& resource, Use how, int binding = -1) {
    return ResourceUse{.resource = resource, .use = how, .binding = binding};
}
ResourceUse attachment(const std::string& image, Use how, std::array<float, 4> clear, Subresource range = {}) {
    return ResourceUse{.resource = image, .use = how, .range = range, .clear = clear};
}

// Instanced screen-space rectangles: unit-square corners per vertex, RectInstance per instance.
RasterState rect_state(bool depth_test, bool alpha_to_coverage) {
    RasterState s;
    s.vertex_spirv = services_rect_vert;
    s.fragment_spirv = services_rect_frag;
    s.vertices.bindings = {{8, false}, {uint32_t(sizeof(RectInstance)), true}};
    s.vertices.attributes = {{0, 0, VK_FORMAT_R32G32_SFLOAT, 0},
                             {1, 1, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(offsetof(RectInstance, rect))},
                             {2, 1, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(offsetof(RectInstance, color))}};
    s.depth_test = s.depth_write = depth_test;
    s.alpha_to_coverage = alpha_to_coverage;
    return s;
}

// The geometry and values the load phase uploads, each buffer's bytes.
struct Uploads {
    std::vector<std::array<float, 2>> quad_corners{{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    std::vector<float> cull_values;
    std::vector<std::array<float, 4>> cull_vertices;  // xy pixels, z the quad's tag (index + 1)
    std::vector<glm::vec3> marker = std::vector<glm::vec3>(kMarker.begin(), kMarker.end());
    Uploads() {
        for (uint32_t q = 0; q < kCullQuads; ++q) {
            cull_values.push_back(cull_value(q));
            const auto [x0, y0, x1, y1] = cull_rect(q);
            const float tag = float(q + 1);
            for (const auto& corner : {std::array<float, 4>{x0, y0, tag, 0}, {x1, y0, tag, 0}, {x1, y1, tag, 0},
                                       {x0, y1, tag, 0}})
                cull_vertices.push_back(corner);
        }
    }
    uint64_t total_bytes() const {
        return quad_corners.size() * sizeof(quad_corners[0]) + sizeof(kCoverageQuads) +
               cull_values.size() * sizeof(float) + cull_vertices.size() * sizeof(cull_vertices[0]) +
               marker.size() * sizeof(glm::vec3);
    }
};

FrameGraph services_graph() {
    FrameGraph g;
    const VkFormat rgba32f = VK_FORMAT_R32G32B32A32_SFLOAT;
    g.images = {
        {.name = "bake", .format = rgba32f, .extent = ImageExtent::square(kBakeSize), .layers = kBakeLayers,
         .mips = kBakeMips, .persistent = true},
        {.name = "msaa_color", .format = rgba32f, .extent = ImageExtent::screen(), .samples = 4},
        {.name = "msaa_depth", .format = VK_FORMAT_D32_SFLOAT, .extent = ImageExtent::screen(), .samples = 4},
        {.name = "resolved", .format = rgba32f, .extent = ImageExtent::screen()},
        {.name = "survivors", .format = rgba32f, .extent = ImageExtent::screen()},
    };
    const Uploads sizes;
    const auto bytes_of = [](const auto& v) { return uint64_t(v.size() * sizeof(v[0])); };
    g.buffers = {
        {.name = "quad_corners", .bytes = bytes_of(sizes.quad_corners), .usage = kVertexBuffer, .persistent = true},
        {.name = "coverage_quads", .bytes = sizeof(kCoverageQuads), .usage = kVertexBuffer, .persistent = true},
        {.name = "cull_values", .bytes = bytes_of(sizes.cull_values), .usage = kStorageBuffer, .persistent = true},
        {.name = "cull_vertices", .bytes = bytes_of(sizes.cull_vertices), .usage = kVertexBuffer, .persistent = true},
        {.name = "marker", .bytes = bytes_of(sizes.marker), .usage = kVertexBuffer, .persistent = true},
        {.name = "cull_indices", .bytes = 6 * 4 * kCullQuads, .usage = kIndexBuffer | kStorageBuffer},
        {.name = "cull_arguments", .bytes = sizeof(VkDrawIndexedIndirectCommand) * kCullQuads,
         .usage = kIndirectBuffer | kStorageBuffer},
        {.name = "cull_count", .bytes = 4, .usage = kIndirectBuffer | kStorageBuffer},
        {.name = "cpu_rect", .bytes = sizeof(RectInstance), .usage = kVertexBuffer, .host_visible = true},
        {.name = "cpu_rect_draw", .bytes = sizeof(VkDrawIndirectCommand), .usage = kIndirectBuffer, .host_visible = true},
        {.name = "frame_counter", .bytes = 8, .usage = kStorageBuffer, .persistent = true},
        {.name = "busy_sink", .bytes = 4 * kBusyInvocations, .usage = kStorageBuffer},
    };

    // Load phase: the geometry through staging, then the bake.
    g.passes.push_back(PassDecl{
        .name = "upload_geometry",
        .kind = PassKind::copy,
        .phase = Phase::load,
        .uses = {use("quad_corners", Use::transfer_write), use("coverage_quads", Use::transfer_write),
                 use("cull_values", Use::transfer_write), use("cull_vertices", Use::transfer_write),
                 use("marker", Use::transfer_write)},
        .record =
            [](PassContext& pc) {
                const Uploads u;
                pc.upload("quad_corners", u.quad_corners.data(), u.quad_corners.size() * sizeof(u.quad_corners[0]));
                pc.upload("coverage_quads", kCoverageQuads.data(), sizeof(kCoverageQuads));
                pc.upload("cull_values", u.cull_values.data(), u.cull_values.size() * sizeof(float));
                pc.upload("cull_vertices", u.cull_vertices.data(), u.cull_vertices.size() * sizeof(u.cull_vertices[0]));
                pc.upload("marker", u.marker.data(), u.marker.size() * sizeof(glm::vec3));
            },
    });
    for (uint32_t layer = 0; layer < kBakeLayers; ++layer) {
        RasterState bake;
        bake.vertex_spirv = services_fullscreen_vert;
        bake.fragment_spirv = services_bake_frag;
        bake.vertices = {};
        g.passes.push_back(PassDecl{
            .name = "bake_layer" + std::to_string(layer),
            .kind = PassKind::raster,
            .phase = Phase::load,
            .uses = {attachment("bake", Use::color_attachment, {0, 0, 0, 0}, {0, 1, layer, 1})},
            .push_constant_bytes = 4,
            .record =
                [bake, layer](PassContext& pc) {
                    pc.bind(pc.raster_pipeline(bake));
                    pc.push_constants(&layer, sizeof(layer));
                    pc.draw({}, 3, 1);
                },
        });
    }
    for (uint32_t mip = 1; mip < kBakeMips; ++mip) {
        ResourceUse source = use("bake", Use::storage_read, 0), target = use("bake", Use::storage_write, 1);
        source.range = {mip - 1, 1, 0, kBakeLayers};
        target.range = {mip, 1, 0, kBakeLayers};
        g.passes.push_back(PassDecl{
            .name = "bake_mip" + std::to_string(mip),
            .kind = PassKind::compute,
            .phase = Phase::load,
            .uses = {source, target},
            .record =
                [mip](PassContext& pc) {
                    const uint32_t size = kBakeSize >> mip;
                    pc.dispatch(pc.compute_pipeline(services_downsample_comp), (size + 7) / 8, (size + 7) / 8, kBakeLayers);
                },
        });
    }

    // Frame phase.
    g.passes.push_back(PassDecl{
        .name = "place_cpu_rect",
        .kind = PassKind::cpu,
        .uses = {use("cpu_rect", Use::transfer_write), use("cpu_rect_draw", Use::transfer_write)},
        .run =
            [](CpuPassContext& cc) {
                const RectInstance rect = cpu_rect(cc.frame().frame_index);
                cc.upload("cpu_rect", &rect, sizeof(rect));
                // Its draw's counts, chosen here and read by the GPU (draw_indirect): 6 corners, once.
                const VkDrawIndirectCommand draw{6, 1, 0, 0};
                cc.upload("cpu_rect_draw", &draw, sizeof(draw));
                cc.count("rect_left", rect.rect[0]);
                cc.count("rect_left", 0.5);  // a name counted twice adds up
                // Where the marker's first corner lands through the frame's view_proj, in pixels.
                const glm::vec4 clip = cc.view_proj() * glm::vec4(kMarker[0], 1.0f);
                cc.count("marker_x", (clip.x / clip.w * 0.5 + 0.5) * double(kWidth));
            },
    });
    g.passes.push_back(PassDecl{
        .name = "count_frames",
        .kind = PassKind::compute,
        .uses = {use("frame_counter", Use::storage_write, 0)},
        .push_constant_bytes = 4,
        .record =
            [](PassContext& pc) {
                const uint32_t index = pc.frame().frame_index;
                pc.push_constants(&index, sizeof(index));
                pc.dispatch(pc.compute_pipeline(services_counter_comp), 1, 1, 1);
            },
    });
    g.passes.push_back(PassDecl{
        .name = "cull_quads",
        .kind = PassKind::compute,
        .uses = {use("cull_values", Use::storage_read, 0), use("cull_indices", Use::storage_write, 1),
                 use("cull_arguments", Use::storage_write, 2), use("cull_count", Use::storage_write, 3)},
        .push_constant_bytes = 8,
        .record =
            [](PassContext& pc) {
                pc.fill("cull_count", 0);  // the atomic append starts at 0 every frame
                const struct {
                    uint32_t quad_count;
                    float threshold;
                } cull{kCullQuads, kCullThreshold};
                pc.push_constants(&cull, sizeof(cull));
                pc.dispatch(pc.compute_pipeline(services_cull_comp), (kCullQuads + 63) / 64, 1, 1);
            },
    });
    RasterState survivor;
    survivor.vertex_spirv = services_survivor_vert;
    survivor.fragment_spirv = services_survivor_frag;
    survivor.vertices.bindings = {{16, false}};
    survivor.vertices.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}};
    g.passes.push_back(PassDecl{
        .name = "draw_survivors",
        .kind = PassKind::raster,
        .uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use("cull_vertices", Use::vertex),
                 use("cull_indices", Use::index), use("cull_arguments", Use::indirect), use("cull_count", Use::indirect),
                 attachment("survivors", Use::color_attachment, {0, 0, 0, 0})},
        .record =
            [survivor](PassContext& pc) {
                pc.bind(pc.raster_pipeline(survivor));
                const std::array<std::string, 1> vertices{"cull_vertices"};
                pc.draw_indexed_indirect_count(vertices, "cull_indices", "cull_arguments", "cull_count", kCullQuads);
            },
    });
    ResourceUse msaa_depth = attachment("msaa_depth", Use::depth_attachment, {1, 0, 0, 0});
    msaa_depth.store = false;
    g.passes.push_back(PassDecl{
        .name = "alpha_to_coverage",
        .kind = PassKind::raster,
        .uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use("quad_corners", Use::vertex),
                 use("coverage_quads", Use::vertex), attachment("msaa_color", Use::color_attachment, {0, 0, 0, 0}),
                 msaa_depth, use("resolved", Use::resolve_target)},
        .record =
            [state = rect_state(true, true)](PassContext& pc) {
                pc.bind(pc.raster_pipeline(state));
                const std::array<std::string, 2> vertices{"quad_corners", "coverage_quads"};
                pc.draw(vertices, 6, uint32_t(kCoverageQuads.size()));
            },
    });
    RasterState marker;
    marker.vertex_spirv = services_marker_vert;
    marker.fragment_spirv = services_marker_frag;
    marker.vertices.bindings = {{uint32_t(sizeof(glm::vec3)), false}};
    marker.vertices.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}};
    g.passes.push_back(PassDecl{
        .name = "camera_view",
        .kind = PassKind::raster,
        .uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use("marker", Use::vertex),
                 use("quad_corners", Use::vertex), use("cpu_rect", Use::vertex), use("cpu_rect_draw", Use::indirect),
                 attachment(graph_names::kColor, Use::color_attachment, {0, 0, 0, 0}),
                 attachment(graph_names::kDepth, Use::depth_attachment, {1, 0, 0, 0})},
        .record =
            [marker, rect = rect_state(false, false)](PassContext& pc) {
                pc.bind(pc.raster_pipeline(marker));
                const std::array<std::string, 1> marker_vertices{"marker"};
                pc.draw(marker_vertices, 3, 1);
                pc.bind(pc.raster_pipeline(rect));
                const std::array<std::string, 2> rect_vertices{"quad_corners", "cpu_rect"};
                pc.draw_indirect(rect_vertices, "cpu_rect_draw");
            },
    });
    g.passes.push_back(PassDecl{
        .name = "busy_work",
        .kind = PassKind::compute,
        .uses = {use("busy_sink", Use::storage_write, 0)},
        .push_constant_bytes = 8,
        .record =
            [](PassContext& pc) {
                const std::array<uint32_t, 2> work{kBusyIterations, kBusyInvocations};
                pc.push_constants(work.data(), sizeof(work));
                pc.dispatch(pc.compute_pipeline(test_ballast_comp), (kBusyInvocations + 63) / 64, 1, 1);
            },
    });
    return g;
}

// --- Running it along the camera path ---------------------------------------------------------

struct FrameResult {
    uint32_t index = 0;
    Camera camera;
    FrameTiming timing;
    Image color, resolved, survivors;
    std::vector<uint32_t> counter;  // frames seen, sum of their indices
};

struct PathRun {
    FrameTiming load;
    std::vector<std::string> load_pass_names, load_cpu_pass_names, pass_names, cpu_pass_names;
    std::vector<FrameResult> frames;
    std::vector<Image> bake;  // mip-major: bake[mip * kBakeLayers + layer]
    std::vector<uint32_t> cull_indices, cull_count;
    std::vector<VkDrawIndexedIndirectCommand> cull_arguments;
};

PathRun run_camera_path(const GpuContext& gpu) {
    const Scene scene = test::tiny_scene();
    FrameRenderer renderer(gpu, scene, build_scene_meshes(scene), kWidth, kHeight, services_graph());
    PathRun run;
    run.load = renderer.load_timing();
    run.load_pass_names = renderer.load_pass_names();
    run.load_cpu_pass_names = renderer.load_cpu_pass_names();
    run.pass_names = renderer.pass_names();
    run.cpu_pass_names = renderer.cpu_pass_names();
    const std::vector<Camera> path = camera_path();
    for (uint32_t i = 0; i < path.size(); ++i) {
        FrameResult f;
        f.index = i;
        f.camera = path[i];
        f.timing = renderer.render(FrameState{i, path[i]});
        f.color = renderer.read_color();
        f.resolved = renderer.read_image("resolved");
        f.survivors = renderer.read_image("survivors");
        f.counter = as_vector<uint32_t>(renderer.read_buffer("frame_counter"));
        run.frames.push_back(std::move(f));
    }
    // Read after every frame: the bake is persistent, so the load phase's result is still there.
    for (uint32_t mip = 0; mip < kBakeMips; ++mip)
        for (uint32_t layer = 0; layer < kBakeLayers; ++layer) run.bake.push_back(renderer.read_image("bake", mip, layer));
    run.cull_indices = as_vector<uint32_t>(renderer.read_buffer("cull_indices"));
    run.cull_count = as_vector<uint32_t>(renderer.read_buffer("cull_count"));
    run.cull_arguments = as_vector<VkDrawIndexedIndirectCommand>(renderer.read_buffer("cull_arguments"));
    return run;
}

bool inside(const std::array<float, 4>& rect, int x, int y) {
    const float px = float(x) + 0.5f, py = float(y) + 0.5f;
    return px >= rect[0] && px < rect[2] && py >= rect[1] && py < rect[3];
}

bool is_color(const float* pixel, const std::array<float, 3>& rgb) {
    return pixel[0] == rgb[0] && pixel[1] == rgb[1] && pixel[2] == rgb[2];
}

// The smallest signed distance, in pixels, from `p` to the edges of triangle `t` (positive inside).
float inside_distance(const std::array<glm::vec2, 3>& t, glm::vec2 p) {
    const auto cross = [](glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; };
    const float orientation = cross(t[1] - t[0], t[2] - t[0]) > 0 ? 1.0f : -1.0f;
    float distance = INFINITY;
    for (int e = 0; e < 3; ++e) {
        const glm::vec2 a = t[size_t(e)], b = t[size_t((e + 1) % 3)];
        distance = std::min(distance, orientation * cross(b - a, p - a) / glm::length(b - a));
    }
    return distance;
}

// Sets an environment variable for its lifetime, then restores what was there.
class ScopedEnvironment {
public:
    ScopedEnvironment(const char* name, const char* value) : name_(name) {
        const char* previous = std::getenv(name);
        if (previous) previous_ = previous;
        had_previous_ = previous != nullptr;
        setenv(name, value, 1);
    }
    ~ScopedEnvironment() { had_previous_ ? setenv(name_, previous_.c_str(), 1) : unsetenv(name_); }
    ScopedEnvironment(const ScopedEnvironment&) = delete;
    ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

private:
    const char* name_;
    std::string previous_;
    bool had_previous_ = false;
};

bool all_finite_non_negative(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v) && v >= 0.0; });
}

}  // namespace

TEST_CASE("graph services: the load phase bakes every mip and layer of a persistent layered image") {
    const PathRun run = run_camera_path(test::gpu());
    REQUIRE(run.bake.size() == size_t(kBakeMips) * kBakeLayers);
    for (uint32_t mip = 0; mip < kBakeMips; ++mip)
        for (uint32_t layer = 0; layer < kBakeLayers; ++layer) {
            CAPTURE(mip);
            CAPTURE(layer);
            const Image& image = run.bake[mip * kBakeLayers + layer];
            const int size = int(kBakeSize >> mip);
            REQUIRE(image.width == size);
            REQUIRE(image.height == size);
            const std::vector<std::array<float, 4>> expected = expected_bake(mip, layer);
            int wrong = 0;
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x)
                    for (size_t c = 0; c < 4; ++c)
                        if (std::abs(image.at(x, y)[c] - expected[size_t(y * size + x)][c]) > 1e-5f) ++wrong;
            CHECK(wrong == 0);
            CHECK(image.at(size - 1, size - 1)[3] == 1.0f + float(layer));  // the layer's own bake, not the other's
        }
}

TEST_CASE("graph services: instanced alpha-to-coverage at 4x MSAA resolves to each quad's coverage") {
    const PathRun run = run_camera_path(test::gpu());
    const Image& resolved = run.frames.back().resolved;
    REQUIRE(resolved.width == int(kWidth));
    REQUIRE(resolved.height == int(kHeight));
    // Per quad: the coverage fraction of each pixel inside it (its colour's non-zero channels).
    std::array<std::vector<float>, kCoverageQuads.size()> coverage;
    int outside_drawn = 0, off_colour = 0;
    for (int y = 0; y < resolved.height; ++y)
        for (int x = 0; x < resolved.width; ++x) {
            const float* p = resolved.at(x, y);
            size_t quad = kCoverageQuads.size();
            for (size_t q = 0; q < kCoverageQuads.size(); ++q)
                if (inside(kCoverageQuads[q].rect, x, y)) quad = q;
            if (quad == kCoverageQuads.size()) {
                if (p[0] != 0.0f || p[1] != 0.0f || p[2] != 0.0f || p[3] != 0.0f) ++outside_drawn;
                continue;
            }
            const std::array<float, 4>& rgba = kCoverageQuads[quad].color;
            float fraction = 0;
            int lit = 0;
            for (size_t c = 0; c < 3; ++c) {
                if (rgba[c] == 0.0f) {
                    if (p[c] != 0.0f) ++off_colour;
                } else {
                    fraction += p[c] / rgba[c];
                    ++lit;
                }
            }
            coverage[quad].push_back(fraction / float(lit));
        }
    CHECK(outside_drawn == 0);
    CHECK(off_colour == 0);
    const auto fractions_in = [&](size_t quad, float low, float high) {
        return std::all_of(coverage[quad].begin(), coverage[quad].end(),
                           [&](float f) { return f >= low - 1e-6f && f <= high + 1e-6f; });
    };
    const auto mean = [&](size_t quad) {
        return std::accumulate(coverage[quad].begin(), coverage[quad].end(), 0.0f) / float(coverage[quad].size());
    };
    for (size_t q = 0; q < coverage.size(); ++q) REQUIRE(coverage[q].size() == 16 * 16);
    CAPTURE(mean(1));
    CAPTURE(mean(3));
    CHECK(fractions_in(0, 1.0f, 1.0f));  // alpha 1: every sample
    CHECK(fractions_in(2, 0.0f, 0.0f));  // alpha 0: no sample
    // Alpha 0.5: about half the samples, never none or all (an opaque draw would cover every one).
    CHECK(fractions_in(1, 0.25f, 0.75f));
    CHECK(std::abs(mean(1) - 0.5f) <= 0.125f);
    // Alpha 0.75: more than alpha 0.5's and fewer than all, within the 4-sample quantisation.
    CHECK(fractions_in(3, 0.5f, 1.0f));
    CHECK(mean(3) > mean(1));
    CHECK(mean(3) < 1.0f);
}

TEST_CASE("graph services: a compute cull feeds draw_indexed_indirect_count") {
    const PathRun run = run_camera_path(test::gpu());
    const std::set<uint32_t> expected = cpu_survivors();
    REQUIRE(!expected.empty());
    REQUIRE(expected.size() < kCullQuads);  // the rule culls some
    REQUIRE(run.cull_count.size() == 1);
    const uint32_t count = run.cull_count[0];
    CHECK(count == expected.size());
    REQUIRE(count <= kCullQuads);
    // The atomic append's order is not deterministic: compare sets, draw by draw.
    std::set<uint32_t> drawn;
    int malformed = 0;
    for (uint32_t k = 0; k < count; ++k) {
        const VkDrawIndexedIndirectCommand& a = run.cull_arguments[k];
        if (a.indexCount != 6 || a.instanceCount != 1 || a.firstIndex != 6 * k || a.vertexOffset != 0 || a.firstInstance != 0)
            ++malformed;
        const uint32_t* i = &run.cull_indices[6 * k];
        const uint32_t v = i[0];
        if (v % 4 != 0 || i[1] != v + 1 || i[2] != v + 2 || i[3] != v || i[4] != v + 2 || i[5] != v + 3) ++malformed;
        if (!drawn.insert(v / 4).second) ++malformed;  // each survivor once
    }
    CHECK(malformed == 0);
    CHECK(drawn == expected);
    // The pixels: each quad's tag where it survived, nothing where it was culled or no quad is.
    for (const FrameResult& f : run.frames) {
        CAPTURE(f.index);
        int wrong = 0;
        for (int y = 0; y < f.survivors.height; ++y)
            for (int x = 0; x < f.survivors.width; ++x) {
                float tag = 0.0f;
                for (uint32_t q = 0; q < kCullQuads; ++q)
                    if (inside(cull_rect(q), x, y) && expected.count(q)) tag = float(q + 1);
                if (f.survivors.at(x, y)[0] != tag) ++wrong;
            }
        CHECK(wrong == 0);
    }
}

TEST_CASE("graph services: a CPU pass's per-frame upload, a persistent counter and a camera path") {
    const PathRun run = run_camera_path(test::gpu());
    REQUIRE(run.frames.size() >= 4);
    std::vector<glm::vec2> centroids;
    for (const FrameResult& f : run.frames) {
        CAPTURE(f.index);
        // The CPU pass uploaded this frame's rectangle and its draw, and only them.
        CHECK(f.timing.uploaded_bytes == sizeof(RectInstance) + sizeof(VkDrawIndirectCommand));
        const RectInstance rect = cpu_rect(f.index);
        // Its counts: this frame's, named as counted, and its view_proj the frame's.
        REQUIRE(f.timing.counters.size() == 2);
        CHECK(f.timing.counters[0].first == "rect_left");
        CHECK(f.timing.counters[0].second == double(rect.rect[0]) + 0.5);
        CHECK(f.timing.counters[1].first == "marker_x");
        CHECK(f.timing.counters[1].second ==
              doctest::Approx(project_to_pixel(f.camera, int(kWidth), int(kHeight), kMarker[0]).x).epsilon(1e-5));
        int rect_wrong = 0;
        for (int y = 0; y < int(kCpuBandBottom); ++y)
            for (int x = 0; x < f.color.width; ++x)
                if (is_color(f.color.at(x, y), {1, 0, 1}) != inside(rect.rect, x, y)) ++rect_wrong;
        CHECK(rect_wrong == 0);

        // The persistent counter carried every earlier frame's increments.
        REQUIRE(f.counter.size() == 2);
        CHECK(f.counter[0] == f.index + 1);
        CHECK(f.counter[1] == f.index * (f.index + 1) / 2);

        // The marker lies where this frame's camera projects it.
        std::array<glm::vec2, 3> projected;
        for (size_t v = 0; v < 3; ++v) projected[v] = project_to_pixel(f.camera, int(kWidth), int(kHeight), kMarker[v]);
        for (const glm::vec2 p : projected) {
            REQUIRE(p.x > 0.0f);
            REQUIRE(p.x < float(kWidth));
            REQUIRE(p.y > kCpuBandBottom);  // below the CPU rectangle's band, which is drawn over it
            REQUIRE(p.y < float(kHeight));
        }
        int covered = 0, marker_wrong = 0;
        glm::vec2 sum(0.0f);
        for (int y = int(kCpuBandBottom); y < f.color.height; ++y)
            for (int x = 0; x < f.color.width; ++x) {
                const float d = inside_distance(projected, glm::vec2(float(x) + 0.5f, float(y) + 0.5f));
                const bool drawn = is_color(f.color.at(x, y), kMarkerColor);
                if (drawn) {
                    ++covered;
                    sum += glm::vec2(float(x) + 0.5f, float(y) + 0.5f);
                }
                if ((d > 0.05f && !drawn) || (d < -0.05f && drawn)) ++marker_wrong;
            }
        CHECK(marker_wrong == 0);
        REQUIRE(covered > 30);  // big enough to say where it is
        centroids.push_back(sum / float(covered));
    }
    // The path moves the marker across the image (the cameras differ, and so do the images).
    for (size_t i = 1; i < centroids.size(); ++i) CHECK(glm::length(centroids[i] - centroids[i - 1]) > 2.0f);
}

TEST_CASE("graph services: every pass is timed, and the GPU passes' times add up to the frame's wall time") {
    const PathRun run = run_camera_path(test::gpu());
    const std::vector<std::string> load_passes{"upload_geometry", "bake_layer0", "bake_layer1", "bake_mip1", "bake_mip2"};
    const std::vector<std::string> gpu_passes{"count_frames", "cull_quads", "draw_survivors", "alpha_to_coverage",
                                              "camera_view", "busy_work"};
    CHECK(run.load_pass_names == load_passes);
    CHECK(run.load_cpu_pass_names.empty());
    CHECK(run.pass_names == gpu_passes);
    CHECK(run.cpu_pass_names == std::vector<std::string>{"place_cpu_rect"});
    CHECK(run.load.pass_gpu_ms.size() == load_passes.size());
    CHECK(all_finite_non_negative(run.load.pass_gpu_ms));
    CHECK(run.load.pass_cpu_ms.empty());
    CHECK(run.load.uploaded_bytes == Uploads().total_bytes());

    std::vector<double> pass_sums, walls, busy;
    for (const FrameResult& f : run.frames) {
        CAPTURE(f.index);
        const FrameTiming& t = f.timing;
        REQUIRE(t.pass_gpu_ms.size() == gpu_passes.size());
        REQUIRE(t.pass_cpu_ms.size() == 1);
        CHECK(all_finite_non_negative(t.pass_gpu_ms));
        CHECK(all_finite_non_negative(t.pass_cpu_ms));
        CHECK(std::isfinite(t.wall_ms));
        const double sum = std::accumulate(t.pass_gpu_ms.begin(), t.pass_gpu_ms.end(), 0.0);
        CAPTURE(sum);
        CAPTURE(t.gpu_ms);
        CAPTURE(t.wall_ms);
        // The passes run one after another inside the first-start-to-last-end span, inside the fence wait.
        CHECK(sum <= t.gpu_ms + 1e-3);
        CHECK(t.gpu_ms <= t.wall_ms);
        pass_sums.push_back(sum);
        walls.push_back(t.wall_ms);
        busy.push_back(t.pass_gpu_ms.back());
    }
    // Medians, as tests/test_compute_timing.cpp takes: other processes share this machine's cores.
    const double sum_ms = summarize(pass_sums).median, wall_ms = summarize(walls).median;
    CAPTURE(sum_ms);
    CAPTURE(wall_ms);
    CHECK(summarize(busy).median > 2.0);  // known work long enough that a short reading cannot hide
    CHECK(wall_ms - sum_ms <= std::max(0.1 * wall_ms, 0.5));
}

TEST_CASE("graph services: the whole graph renders without a single validation message") {
    // Synchronisation validation too: the barriers the executor derives from the declared uses
    // (and the one after a transfer inside a compute pass) must leave no hazard. The layer reads
    // VK_LAYER_ENABLES when the instance is created.
    std::shared_ptr<const ValidationLog> log;
    {
        GpuContext context = [] {
            const ScopedEnvironment sync("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT");
            return GpuContext(test::device_selector(), GpuContext::Validation::on);
        }();
        log = context.validation_log();
        REQUIRE(log != nullptr);
        const PathRun run = run_camera_path(context);
        CHECK(run.frames.size() == camera_path().size());
        std::string messages;
        for (const std::string& m : log->messages()) messages += "\n  " + m;
        CHECK_MESSAGE(log->count() == 0, "validation messages:" << messages);
    }
    // Objects left alive are reported as the device and the instance are destroyed.
    std::string messages;
    for (const std::string& m : log->messages()) messages += "\n  " + m;
    CHECK_MESSAGE(log->count() == 0, "validation messages:" << messages);
}
