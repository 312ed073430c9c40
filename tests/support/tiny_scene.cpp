#include "support/tiny_scene.hpp"

#include "config/scene_config.hpp"

#include <string>

namespace canopy::test {

Scene tiny_scene() { return load_scene(std::string(CANOPY_TEST_DATA) + "/scenes/tiny.toml"); }

Scene tiny_scene_under_rect_light(float side, glm::vec3 position) {
    Scene scene = tiny_scene();
    Light& light = scene.lights.front();
    light.type = LightType::rect;
    light.position = position;
    light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    light.rect_size = glm::vec2(side);
    light.intensity = 30.0f;
    return scene;
}

}  // namespace canopy::test
