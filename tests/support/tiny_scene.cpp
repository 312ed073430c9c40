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

Scene tiny_grass_scene() {
    return parse_scene(R"([scene]
name = "tiny-grass"
[camera]
position = [0, 1.2, 2.0]
target = [0, 0, 0]
[[light]]
type = "directional"
direction = [-0.3, -1, -0.2]
casts_shadows = false
[[object]]
name = "ground"
shape = "plane"
size = [4, 4]
[[population]]
name = "grass"
kind = "grass"
albedo = [0.2, 0.6, 0.1]
params = { cells_x = 2, cells_z = 2, blades = 60, density = 0.7 }
)",
                       "tiny-grass.toml");
}

}  // namespace canopy::test
