#include "support/test_gpu.hpp"

#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "scene/geometry.hpp"

#include <cstdlib>
#include <stdexcept>

namespace canopy::test {

std::string device_selector() {
    const char* device = std::getenv("CANOPY_TEST_DEVICE");
    return device ? device : "";
}

GpuContext& gpu() {
    static GpuContext context(device_selector());
    return context;
}

FrameGraph technique_graph(const std::string& technique, const std::map<std::string, ParamValue>& params) {
    const Technique* t = TechniqueRegistry::instance().find(technique);
    if (!t) throw std::invalid_argument("no technique " + technique);
    return t->graph(ParamSet::resolve(t->params(), params, {}, SourceLocation{}, technique));
}

Image render_technique(const Scene& scene, const std::string& technique,
                       const std::map<std::string, ParamValue>& params, int width, int height) {
    return render_technique(gpu(), scene, technique, params, width, height);
}

Image render_technique(GpuContext& context, const Scene& scene, const std::string& technique,
                       const std::map<std::string, ParamValue>& params, int width, int height) {
    FrameRenderer renderer(context, scene, build_scene_meshes(scene), uint32_t(width), uint32_t(height),
                           technique_graph(technique, params));
    renderer.render();
    return renderer.read_color();
}

}  // namespace canopy::test
