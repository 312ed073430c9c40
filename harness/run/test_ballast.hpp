// TEST-ONLY: a known amount of extra GPU work added to one technique's frames, so a test can make
// a real, measured slowdown and check that `canopy compare` flags it (tests/cli/measurement.sh).
// It reads an environment variable that nothing else uses; unset, nothing changes:
//   CANOPY_TEST_BALLAST=<technique>=<iterations>   after every frame of that technique's cases,
//       a compute pass runs <iterations> rounds of a xorshift per pixel; its time (its own
//       pass "test_ballast", timestamps like every pass) is added to the frame's GPU time.
// Images are not touched: the pass writes only its own buffer.
#pragma once

#include "gpu/context.hpp"
#include "gpu/pass_timer.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/resources.hpp"

#include <memory>
#include <optional>
#include <string>

namespace canopy {

struct BallastSpec {
    std::string technique;
    uint32_t iterations = 0;
};

// The spec in CANOPY_TEST_BALLAST, or nullopt when it is unset or empty. Throws
// std::invalid_argument on a malformed value.
std::optional<BallastSpec> ballast_from_environment();

class Ballast {
public:
    Ballast(const GpuContext& gpu, uint32_t width, uint32_t height, uint32_t iterations);
    ~Ballast();
    Ballast(const Ballast&) = delete;
    Ballast& operator=(const Ballast&) = delete;

    double run_ms();  // one pass, waited for: its GPU time in milliseconds

private:
    const GpuContext& gpu_;
    uint32_t count_, iterations_;
    MemoryLedger ledger_;  // not the technique's memory
    Buffer sink_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    std::unique_ptr<ComputePipeline> pipeline_;
    std::unique_ptr<PassTimer> timer_;
    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace canopy
