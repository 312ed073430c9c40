#include "graph/frame_graph.hpp"

#include "gpu/format_names.hpp"

#include <fmt/format.h>

#include <set>

namespace canopy {

const char* to_string(PassKind kind) {
    switch (kind) {
        case PassKind::raster: return "raster";
        case PassKind::compute: return "compute";
        case PassKind::copy: return "copy";
        case PassKind::cpu: return "cpu";
    }
    return "?";
}

const char* to_string(Phase phase) { return phase == Phase::load ? "load" : "frame"; }

namespace {

const char* use_name(Use use) {
    switch (use) {
        case Use::sampled: return "sampled";
        case Use::storage_read: return "storage-read";
        case Use::storage_write: return "storage-write";
        case Use::color_attachment: return "color-attachment";
        case Use::depth_attachment: return "depth-attachment";
        case Use::resolve_target: return "resolve-target";
        case Use::uniform: return "uniform";
        case Use::vertex: return "vertex";
        case Use::index: return "index";
        case Use::indirect: return "indirect";
        case Use::transfer_read: return "transfer-read";
        case Use::transfer_write: return "transfer-write";
    }
    return "?";
}

const char* sampler_name(SamplerKind kind) {
    switch (kind) {
        case SamplerKind::nearest: return "nearest";
        case SamplerKind::linear: return "linear";
        case SamplerKind::linear_mipmap: return "linear-mipmap";
        case SamplerKind::anisotropic: return "anisotropic";
        case SamplerKind::compare_linear: return "compare-linear";
    }
    return "?";
}

bool is_image_use(Use use) {
    return use == Use::sampled || use == Use::color_attachment || use == Use::depth_attachment ||
           use == Use::resolve_target;
}
bool is_buffer_use(Use use) {
    return use == Use::uniform || use == Use::vertex || use == Use::index || use == Use::indirect;
}
bool is_attachment(Use use) {
    return use == Use::color_attachment || use == Use::depth_attachment || use == Use::resolve_target;
}
bool is_descriptor(Use use) {
    return use == Use::sampled || use == Use::storage_read || use == Use::storage_write || use == Use::uniform;
}

}  // namespace

const ImageDecl* FrameGraph::image(const std::string& name) const {
    for (const ImageDecl& i : images)
        if (i.name == name) return &i;
    return nullptr;
}

const BufferDecl* FrameGraph::buffer(const std::string& name) const {
    for (const BufferDecl& b : buffers)
        if (b.name == name) return &b;
    return nullptr;
}

std::string validate(const FrameGraph& graph) {
    std::set<std::string> names{graph_names::kFrameUniforms, graph_names::kColor, graph_names::kDepth};
    for (const ImageDecl& i : graph.images) {
        if (!names.insert(i.name).second) return fmt::format("resource '{}' is declared twice (or is a harness name)", i.name);
        if (i.format == VK_FORMAT_UNDEFINED) return fmt::format("image '{}' has no format", i.name);
        if (i.extent.rule == ImageExtent::Rule::absolute && (i.extent.width == 0 || i.extent.height == 0))
            return fmt::format("image '{}' has an empty extent", i.name);
        if (i.extent.rule == ImageExtent::Rule::screen && i.extent.divisor == 0)
            return fmt::format("image '{}' divides the screen by 0", i.name);
        if (i.layers == 0 || i.mips == 0) return fmt::format("image '{}' has no layers or no mips", i.name);
        if (i.samples != 1 && i.samples != 2 && i.samples != 4 && i.samples != 8)
            return fmt::format("image '{}' has {} samples (1, 2, 4 or 8)", i.name, i.samples);
    }
    for (const BufferDecl& b : graph.buffers) {
        if (!names.insert(b.name).second) return fmt::format("resource '{}' is declared twice (or is a harness name)", b.name);
        if (b.bytes == 0 && b.bytes_per_copy == 0) return fmt::format("buffer '{}' is empty", b.name);
    }
    const auto is_image = [&](const std::string& n) {
        return graph.image(n) || n == graph_names::kColor || n == graph_names::kDepth;
    };
    const auto is_buffer = [&](const std::string& n) { return graph.buffer(n) || n == graph_names::kFrameUniforms; };

    // Written so far: persistent resources and harness inputs count as written (they hold
    // something from the start: zeros, the load phase, or the previous frame).
    std::set<std::string> written{graph_names::kFrameUniforms};
    for (const ImageDecl& i : graph.images)
        if (i.persistent) written.insert(i.name);
    for (const BufferDecl& b : graph.buffers)
        if (b.persistent || b.host_visible) written.insert(b.name);
    std::set<std::string> pass_names;
    for (int phase = 0; phase < 2; ++phase) {
        for (const PassDecl& p : graph.passes) {
            if (int(p.phase) != phase) continue;
            if (!pass_names.insert(p.name).second) return fmt::format("pass '{}' is declared twice", p.name);
            if (p.kind == PassKind::cpu ? !p.run : !p.record)
                return fmt::format("pass '{}' has no {} callback", p.name, p.kind == PassKind::cpu ? "run" : "record");
            std::set<int> bindings;
            bool has_target = false;
            for (const ResourceUse& u : p.uses) {
                if (!is_image(u.resource) && !is_buffer(u.resource))
                    return fmt::format("pass '{}' uses '{}', which the graph does not declare", p.name, u.resource);
                if (is_image_use(u.use) && !is_image(u.resource))
                    return fmt::format("pass '{}' uses buffer '{}' as {}", p.name, u.resource, use_name(u.use));
                if (is_buffer_use(u.use) && !is_buffer(u.resource))
                    return fmt::format("pass '{}' uses image '{}' as {}", p.name, u.resource, use_name(u.use));
                if (is_attachment(u.use)) {
                    if (p.kind != PassKind::raster)
                        return fmt::format("{} pass '{}' has attachment '{}'", to_string(p.kind), p.name, u.resource);
                    has_target = true;
                }
                if (is_descriptor(u.use)) {
                    if (u.binding < 0)
                        return fmt::format("pass '{}' uses '{}' as {} without a binding", p.name, u.resource, use_name(u.use));
                    if (!bindings.insert(u.binding).second)
                        return fmt::format("pass '{}' binds two resources at binding {}", p.name, u.binding);
                }
                if (p.kind == PassKind::cpu && !(is_buffer(u.resource) && (u.use == Use::transfer_write || u.use == Use::storage_read)))
                    return fmt::format("CPU pass '{}' may only write (transfer-write) or read (storage-read) buffers, not '{}'",
                                       p.name, u.resource);
                if (p.kind == PassKind::cpu && u.use == Use::transfer_write) {
                    const BufferDecl* b = graph.buffer(u.resource);
                    if (!b || !b->host_visible)
                        return fmt::format("CPU pass '{}' writes buffer '{}', which is not host_visible", p.name, u.resource);
                }
                // A read, or an attachment that loads (no clear) what an earlier pass left.
                const bool loads = (u.use == Use::color_attachment || u.use == Use::depth_attachment) && !u.clear;
                if ((!u.writes() || loads) && !written.count(u.resource) && p.kind != PassKind::cpu)
                    return fmt::format("pass '{}' reads '{}' before any pass writes it", p.name, u.resource);
            }
            if (p.kind == PassKind::raster && !has_target)
                return fmt::format("raster pass '{}' has no attachment", p.name);
            for (const ResourceUse& u : p.uses)
                if (u.writes()) written.insert(u.resource);
        }
    }
    return {};
}

std::string describe(const FrameGraph& graph) {
    std::string out;
    for (const ImageDecl& i : graph.images) {
        const std::string size = i.extent.rule == ImageExtent::Rule::screen
                                     ? fmt::format("screen/{}", i.extent.divisor)
                                     : fmt::format("{}x{}", i.extent.width, i.extent.height);
        out += fmt::format("image {} format={} size={} layers={} mips={} samples={}{}{}\n", i.name, format_name(i.format), size,
                           i.layers, i.mips, i.samples, i.persistent ? " persistent" : "",
                           i.arrayed ? " arrayed" : "");
    }
    for (const BufferDecl& b : graph.buffers)
        out += fmt::format("buffer {} bytes={}{} usage={}{}{}{}\n", b.name, b.bytes,
                           b.bytes_per_copy ? fmt::format("+{}/copy", b.bytes_per_copy) : "", b.usage,
                           b.persistent ? " persistent" : "", b.host_visible ? " host-visible" : "",
                           b.only_on_terrain ? " terrain-only" : "");
    for (const PassDecl& p : graph.passes) {
        out += fmt::format("pass {} {} {} push={} [{}]\n", to_string(p.phase), to_string(p.kind), p.name,
                           p.push_constant_bytes, p.settings);
        for (const ResourceUse& u : p.uses) {
            out += fmt::format("  {} {}", use_name(u.use), u.resource);
            if (u.binding >= 0) out += fmt::format(" binding={}", u.binding);
            if (u.use == Use::sampled) out += fmt::format(" sampler={}", sampler_name(u.sampler));
            if (u.range.mip != 0 || u.range.mip_count != ~0u || u.range.layer != 0 || u.range.layer_count != ~0u)
                out += fmt::format(" mips={}+{} layers={}+{}", u.range.mip, int(u.range.mip_count), u.range.layer,
                                   int(u.range.layer_count));
            if (u.clear) out += fmt::format(" clear=({},{},{},{})", (*u.clear)[0], (*u.clear)[1], (*u.clear)[2], (*u.clear)[3]);
            if (u.use == Use::depth_attachment) out += u.store ? " store" : " discard";
            out += "\n";
        }
    }
    const GraphNeeds& n = graph.needs;
    if (n.light_view_resolution) out += fmt::format("needs light-view {}\n", *n.light_view_resolution);
    if (n.area_light) out += "needs area-light\n";
    for (const std::string& kind : n.populations) out += fmt::format("renders population {}\n", kind);
    if (!n.populations.empty() && !n.population_copies_on_gpu) out += "keeps population copies on the CPU\n";
    if (n.populations_on_terrain) out += "stands populations on a terrain\n";
    return out;
}

}  // namespace canopy
