#include "gpu/pass_timer.hpp"

#include <algorithm>

namespace canopy {

PassTimer::PassTimer(const GpuContext& gpu, std::vector<std::string> pass_names)
    : gpu_(gpu), names_(std::move(pass_names)) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = uint32_t(2 * names_.size());
    VK_CHECK(vkCreateQueryPool(gpu.device(), &info, nullptr, &pool_));
}

PassTimer::~PassTimer() { vkDestroyQueryPool(gpu_.device(), pool_, nullptr); }

void PassTimer::reset(VkCommandBuffer commands) {
    vkCmdResetQueryPool(commands, pool_, 0, uint32_t(2 * names_.size()));
}

void PassTimer::begin(VkCommandBuffer commands, size_t pass) {
    vkCmdWriteTimestamp2(commands, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, pool_, uint32_t(2 * pass));
}

void PassTimer::end(VkCommandBuffer commands, size_t pass) {
    vkCmdWriteTimestamp2(commands, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, pool_, uint32_t(2 * pass + 1));
}

std::vector<double> PassTimer::read_milliseconds() const {
    std::vector<uint64_t> stamps(2 * names_.size());
    VK_CHECK(vkGetQueryPoolResults(gpu_.device(), pool_, 0, uint32_t(stamps.size()), stamps.size() * sizeof(uint64_t),
                                   stamps.data(), sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const uint64_t mask = gpu_.timestamp_valid_bits() >= 64 ? ~0ull : ((1ull << gpu_.timestamp_valid_bits()) - 1);
    const double to_ms = gpu_.timestamp_period_ns() * 1e-6;
    auto elapsed = [&](uint64_t a, uint64_t b) { return double((b - a) & mask) * to_ms; };
    std::vector<double> ms;
    for (size_t i = 0; i < names_.size(); ++i) ms.push_back(elapsed(stamps[2 * i], stamps[2 * i + 1]));
    ms.push_back(elapsed(stamps.front(), stamps.back()));
    return ms;
}

}  // namespace canopy
