// Scene geometry on the GPU: every object's mesh in one vertex and one index buffer, and a
// draw per object instance.
#pragma once

#include "gpu/resources.hpp"
#include "render/frame_uniforms.hpp"
#include "scene/geometry.hpp"

#include <vector>

namespace canopy {

struct SceneDraw {
    uint32_t first_index = 0;
    uint32_t index_count = 0;
    int32_t vertex_offset = 0;
    bool casts_shadows = true;
    DrawConstants constants;
};

class GpuScene {
public:
    GpuScene(const GpuContext& gpu, MemoryLedger& ledger, const Scene& scene, const std::vector<TriangleMesh>& meshes);

    // Binds the buffers and draws every instance (only shadow casters when `casters_only`).
    void draw(VkCommandBuffer commands, VkPipelineLayout layout, bool casters_only) const;
    size_t triangle_count() const { return triangles_; }  // summed over instances

private:
    Buffer vertices_;
    Buffer indices_;
    std::vector<SceneDraw> draws_;
    size_t triangles_ = 0;
};

}  // namespace canopy
