#include "gpu/pipeline.hpp"

namespace canopy {

VkShaderModule create_shader_module(VkDevice device, std::span<const uint32_t> spirv) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    VkShaderModule module;
    VK_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
    return module;
}

VkPipeline create_compute_pipeline(VkDevice device, std::span<const uint32_t> spirv, VkPipelineLayout layout) {
    VkShaderModule module = create_shader_module(device, spirv);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_COMPUTE_BIT, module,
                  "main", nullptr};
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkResult result = vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
    vkDestroyShaderModule(device, module, nullptr);
    vk_check(result, "vkCreateComputePipelines");
    return pipeline;
}

ComputePipeline::ComputePipeline(const GpuContext& gpu, std::span<const uint32_t> spirv, VkPipelineLayout layout)
    : gpu_(gpu), pipeline_(create_compute_pipeline(gpu.device(), spirv, layout)) {}

ComputePipeline::~ComputePipeline() { vkDestroyPipeline(gpu_.device(), pipeline_, nullptr); }

}  // namespace canopy
