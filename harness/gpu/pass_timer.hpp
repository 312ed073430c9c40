// Per-pass GPU time from Vulkan timestamp queries: a TOP_OF_PIPE stamp before each pass and a
// BOTTOM_OF_PIPE stamp after it (on lavapipe the latter includes rasterisation work).
#pragma once

#include "gpu/context.hpp"

#include <string>
#include <vector>

namespace canopy {

class PassTimer {
public:
    PassTimer(const GpuContext& gpu, std::vector<std::string> pass_names);
    ~PassTimer();
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

    void reset(VkCommandBuffer commands);               // record before the first pass
    void begin(VkCommandBuffer commands, size_t pass);  // record before pass `pass`
    void end(VkCommandBuffer commands, size_t pass);    // record after it
    // After the submission completed: milliseconds per pass, in pass order, then the whole
    // frame (first begin to last end) as the last element.
    std::vector<double> read_milliseconds() const;
    const std::vector<std::string>& pass_names() const { return names_; }

private:
    const GpuContext& gpu_;
    std::vector<std::string> names_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
};

}  // namespace canopy
