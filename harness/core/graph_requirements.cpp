#include "core/graph_requirements.hpp"

#include <fmt/format.h>

namespace canopy {

std::vector<std::string> graph_requirements(const FrameGraph& graph) {
    std::vector<std::string> needs;
    if (graph.needs.area_light) needs.emplace_back("an area light (rect or sphere)");
    else if (graph.needs.light_view_resolution) needs.emplace_back("a shadow-casting light (any type)");
    bool storage_writes = false, indirect = false;
    std::vector<std::string> compare;
    for (const PassDecl& p : graph.passes)
        for (const ResourceUse& u : p.uses) {
            if (u.use == Use::sampled && u.sampler == SamplerKind::compare_linear) {
                const ImageDecl* image = graph.image(u.resource);
                const std::string format = !image ? "?" : image->format == VK_FORMAT_D16_UNORM ? "d16" : "d32f";
                const std::string need = fmt::format("depth-compare sampling of {} on the device", format);
                if (std::find(compare.begin(), compare.end(), need) == compare.end()) compare.push_back(need);
            }
            storage_writes = storage_writes || (u.use == Use::storage_write && graph.image(u.resource));
            indirect = indirect || u.use == Use::indirect;
        }
    needs.insert(needs.end(), compare.begin(), compare.end());
    if (storage_writes) needs.emplace_back("compute filter passes (shaderStorageImageWriteWithoutFormat)");
    if (indirect) needs.emplace_back("indirect draws with a GPU-written count (drawIndirectCount)");
    // A scene holding a population of a kind the graph does not render is refused (check_supported).
    if (graph.needs.populations.empty()) needs.emplace_back("a scene without populations");
    for (const std::string& kind : graph.needs.populations) needs.push_back(fmt::format("renders '{}' populations", kind));
    if (graph.needs.populations_on_terrain) needs.emplace_back("stands populations on a terrain");
    return needs;
}

}  // namespace canopy
