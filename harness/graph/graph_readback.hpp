// Reading a frame graph's resources back to the CPU, for tests, images and debugging: not timed,
// one submission each, the image left in the layout it had.
#pragma once

#include "core/image.hpp"
#include "graph/graph_executor.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace canopy {

// One mip and layer of image `name` as RGBA floats (R32F, RG32F, RGBA32F, R16F, RGBA16F and D32F
// images; missing channels read 0, alpha 1). Throws std::logic_error for other formats.
Image read_graph_image(const GpuContext& gpu, GraphExecutor& executor, const std::string& name, uint32_t mip = 0,
                       uint32_t layer = 0);
// The bytes of buffer `name`.
std::vector<std::byte> read_graph_buffer(const GpuContext& gpu, const GraphExecutor& executor, const std::string& name);

}  // namespace canopy
