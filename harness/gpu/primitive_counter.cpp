#include "gpu/primitive_counter.hpp"

#include "gpu/vk_check.hpp"

#include <array>

namespace canopy {

namespace {
// Results come back in bit order: input assembly primitives before clipping primitives.
constexpr VkQueryPipelineStatisticFlags kCounted =
    VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_PRIMITIVES_BIT | VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT;
}  // namespace

PrimitiveCounter::PrimitiveCounter(const GpuContext& gpu) : gpu_(gpu) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    info.queryCount = 1;
    info.pipelineStatistics = kCounted;
    VK_CHECK(vkCreateQueryPool(gpu.device(), &info, nullptr, &pool_));
}

PrimitiveCounter::~PrimitiveCounter() { vkDestroyQueryPool(gpu_.device(), pool_, nullptr); }

void PrimitiveCounter::begin(VkCommandBuffer commands) {
    vkCmdResetQueryPool(commands, pool_, 0, 1);
    vkCmdBeginQuery(commands, pool_, 0, 0);
}

void PrimitiveCounter::end(VkCommandBuffer commands) { vkCmdEndQuery(commands, pool_, 0); }

PrimitiveCounts PrimitiveCounter::read() const {
    std::array<uint64_t, 2> values{};
    VK_CHECK(vkGetQueryPoolResults(gpu_.device(), pool_, 0, 1, sizeof(values), values.data(), sizeof(values),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    return PrimitiveCounts{values[0], values[1]};
}

}  // namespace canopy
