#include "render/gpu_scene.hpp"

#include "scene/population_kind.hpp"

#include <fmt/format.h>

#include <array>
#include <stdexcept>

namespace canopy {

GpuScene::GpuScene(const GpuContext& gpu, MemoryLedger& ledger, const Scene& scene,
                   const std::vector<TriangleMesh>& meshes, const std::vector<std::string>& population_kinds,
                   bool copies_on_gpu)
    : populations_(generate_populations(scene, meshes, population_kinds)) {
    std::vector<Vertex> all_vertices;
    std::vector<uint32_t> all_indices;
    std::vector<PopulationVertexData> all_vertex_data;  // only when there are populations
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        const TriangleMesh& mesh = meshes[i];
        const uint32_t first_index = uint32_t(all_indices.size());
        const int32_t vertex_offset = int32_t(all_vertices.size());
        all_vertices.insert(all_vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
        all_indices.insert(all_indices.end(), mesh.indices.begin(), mesh.indices.end());
        for (const Transform& instance : object.instances) {
            SceneDraw draw;
            draw.first_index = first_index;
            draw.index_count = uint32_t(mesh.indices.size());
            draw.vertex_offset = vertex_offset;
            draw.casts_shadows = object.casts_shadows;
            draw.constants.model = instance.matrix();
            glm::mat3 normal = glm::transpose(glm::inverse(glm::mat3(draw.constants.model)));
            for (int c = 0; c < 3; ++c) draw.constants.normal_matrix[c] = glm::vec4(normal[c], 0.0f);
            draw.constants.albedo = glm::vec4(object.material.albedo, 0.0f);  // w: transmission (none)
            draws_.push_back(draw);
            triangles_ += mesh.triangle_count();
        }
    }
    for (const GeneratedPopulation& population : populations_) {
        PopulationDraw draw;
        draw.draw.first_index = uint32_t(all_indices.size());
        draw.draw.index_count = uint32_t(population.prototype.indices.size());
        draw.draw.vertex_offset = int32_t(all_vertices.size());
        draw.draw.casts_shadows = population.casts_shadows;
        // The copies' matrices come per instance: the pushed model and normal matrix are identities.
        draw.draw.constants.model = glm::mat4(1.0f);
        for (int c = 0; c < 3; ++c) draw.draw.constants.normal_matrix[c] = glm::vec4(glm::mat3(1.0f)[c], 0.0f);
        draw.draw.constants.albedo = glm::vec4(population.material.albedo, population.transmission);
        draw.instance_count = uint32_t(population.instances.size());
        triangles_ += population.prototype.triangle_count() * population.instances.size();
        // Per-vertex family data parallel to the shared vertex buffer: zeros for the objects'
        // vertices and for populations that have none.
        all_vertex_data.resize(all_vertices.size());
        if (population.vertex_data.size() == population.prototype.vertices.size())
            all_vertex_data.insert(all_vertex_data.end(), population.vertex_data.begin(), population.vertex_data.end());
        all_vertices.insert(all_vertices.end(), population.prototype.vertices.begin(), population.prototype.vertices.end());
        all_vertex_data.resize(all_vertices.size());
        all_indices.insert(all_indices.end(), population.prototype.indices.begin(), population.prototype.indices.end());
        if (copies_on_gpu && draw.draw.index_count > 0 && draw.instance_count > 0)
            draw.instances = upload_buffer(gpu, ledger, "scene", population.instances.data(),
                                           population.instances.size() * sizeof(PopulationInstance),
                                           VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        population_draws_.push_back(std::move(draw));
    }
    // A scene without triangles (no objects) draws nothing: Vulkan has no empty buffers.
    if (all_indices.empty()) {
        draws_.clear();
        population_draws_.clear();
        populations_.clear();
        return;
    }
    vertices_ = upload_buffer(gpu, ledger, "scene", all_vertices.data(), all_vertices.size() * sizeof(Vertex),
                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    indices_ = upload_buffer(gpu, ledger, "scene", all_indices.data(), all_indices.size() * sizeof(uint32_t),
                             VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    if (!population_draws_.empty())
        vertex_data_ = upload_buffer(gpu, ledger, "scene", all_vertex_data.data(),
                                     all_vertex_data.size() * sizeof(PopulationVertexData),
                                     VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
}

void GpuScene::draw(VkCommandBuffer commands, VkPipelineLayout layout, bool casters_only) const {
    if (draws_.empty()) return;
    VkBuffer vertex_buffer = vertices_.handle();
    VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(commands, 0, 1, &vertex_buffer, &offset);
    vkCmdBindIndexBuffer(commands, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
    for (const SceneDraw& d : draws_) {
        if (casters_only && !d.casts_shadows) continue;
        vkCmdPushConstants(commands, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(DrawConstants), &d.constants);
        vkCmdDrawIndexed(commands, d.index_count, 1, d.first_index, d.vertex_offset, 0);
    }
}

void GpuScene::draw_population(VkCommandBuffer commands, VkPipelineLayout layout, const std::string& name,
                               uint32_t max_copies) const {
    const PopulationDraw& d = population_draw_with_copies(name);
    draw_instances(commands, layout, d, std::min(d.instance_count, max_copies));
}

void GpuScene::draw_prototype(VkCommandBuffer commands, VkPipelineLayout layout, const std::string& name,
                              uint32_t instances) const {
    const PopulationDraw& d = population_draw(name);
    draw_instances(commands, layout, d, d.instance_count == 0 ? 0 : instances);
}

void GpuScene::draw_instances(VkCommandBuffer commands, VkPipelineLayout layout, const PopulationDraw& d,
                              uint32_t copies) const {
    if (d.draw.index_count == 0 || copies == 0) return;
    // Without copies on the GPU (draw_prototype only), the vertices stand in at the copies' binding.
    const VkBuffer instances = d.instances.handle() ? d.instances.handle() : vertices_.handle();
    const std::array<VkBuffer, 3> buffers{vertices_.handle(), instances, vertex_data_.handle()};
    const std::array<VkDeviceSize, 3> offsets{0, 0, 0};
    vkCmdBindVertexBuffers(commands, 0, 3, buffers.data(), offsets.data());
    vkCmdBindIndexBuffer(commands, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdPushConstants(commands, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(DrawConstants), &d.draw.constants);
    vkCmdDrawIndexed(commands, d.draw.index_count, copies, d.draw.first_index, d.draw.vertex_offset, 0);
}

VkDrawIndexedIndirectCommand GpuScene::draw_arguments(const std::string& name) const {
    const PopulationDraw& d = population_draw(name);
    if (d.draw.index_count == 0 || d.instance_count == 0) return VkDrawIndexedIndirectCommand{};
    return VkDrawIndexedIndirectCommand{d.draw.index_count, d.instance_count, d.draw.first_index, d.draw.vertex_offset, 0};
}

void GpuScene::draw_population_indirect(VkCommandBuffer commands, VkPipelineLayout layout, const std::string& name,
                                        VkBuffer copies, VkBuffer arguments) const {
    const PopulationDraw& d = population_draw(name);
    if (d.draw.index_count == 0 || d.instance_count == 0) return;
    const std::array<VkBuffer, 3> buffers{vertices_.handle(), copies, vertex_data_.handle()};
    const std::array<VkDeviceSize, 3> offsets{0, 0, 0};
    vkCmdBindVertexBuffers(commands, 0, 3, buffers.data(), offsets.data());
    vkCmdBindIndexBuffer(commands, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdPushConstants(commands, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(DrawConstants), &d.draw.constants);
    vkCmdDrawIndexedIndirect(commands, arguments, 0, 1, sizeof(VkDrawIndexedIndirectCommand));
}

void GpuScene::draw_over_population(VkCommandBuffer commands, VkPipelineLayout layout, const std::string& name,
                                    std::span<const VkBuffer> vertex_buffers, uint32_t vertex_count) const {
    const PopulationDraw& d = population_draw_with_copies(name);
    if (d.instance_count == 0 || vertex_count == 0 || !d.instances.handle()) return;  // nothing uploaded: an empty prototype
    std::vector<VkBuffer> buffers(vertex_buffers.begin(), vertex_buffers.end());
    buffers.push_back(d.instances.handle());
    const std::vector<VkDeviceSize> offsets(buffers.size(), 0);
    vkCmdBindVertexBuffers(commands, 0, uint32_t(buffers.size()), buffers.data(), offsets.data());
    vkCmdPushConstants(commands, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(DrawConstants), &d.draw.constants);
    vkCmdDraw(commands, vertex_count, d.instance_count, 0, 0);
}

void GpuScene::draw_over_population_indirect(VkCommandBuffer commands, VkPipelineLayout layout,
                                             const std::string& name, std::span<const VkBuffer> vertex_buffers,
                                             VkBuffer copies, VkBuffer arguments) const {
    const PopulationDraw& d = population_draw(name);
    if (d.instance_count == 0) return;
    std::vector<VkBuffer> buffers(vertex_buffers.begin(), vertex_buffers.end());
    buffers.push_back(copies);
    const std::vector<VkDeviceSize> offsets(buffers.size(), 0);
    vkCmdBindVertexBuffers(commands, 0, uint32_t(buffers.size()), buffers.data(), offsets.data());
    vkCmdPushConstants(commands, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(DrawConstants), &d.draw.constants);
    vkCmdDrawIndirect(commands, arguments, 0, 1, sizeof(VkDrawIndirectCommand));
}

const GpuScene::PopulationDraw& GpuScene::population_draw_with_copies(const std::string& name) const {
    const PopulationDraw& d = population_draw(name);
    if (d.instance_count > 0 && d.draw.index_count > 0 && !d.instances.handle())
        throw std::logic_error(fmt::format("population '{}': its copies are not on the GPU (the technique declares "
                                           "needs.population_copies_on_gpu = false); draw them from a buffer of its own "
                                           "(draw_population_indirect, draw_over_population_indirect)",
                                           name));
    return d;
}

const GpuScene::PopulationDraw& GpuScene::population_draw(const std::string& name) const {
    for (size_t i = 0; i < populations_.size(); ++i)
        if (populations_[i].name == name) return population_draws_[i];
    std::string names;
    for (const GeneratedPopulation& p : populations_) names += (names.empty() ? "'" : ", '") + p.name + "'";
    throw std::logic_error(fmt::format("draw_population: the scene has no population '{}' of the kinds the technique "
                                       "renders ({})",
                                       name, names.empty() ? "it has none" : names));
}

}  // namespace canopy
