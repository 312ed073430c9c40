#include "support/lod_field.hpp"

#include "config/scene_config.hpp"

namespace canopy::grass::test {

Scene lod_field_scene(const std::string& more) {
    return parse_scene(R"([scene]
name = "lod-field"
ambient = 0.2
[camera]
position = [1.5, 0.6, 4.6]
target = [1.5, 0.0, 1.0]
fov = 50
near = 0.05
far = 40
[[light]]
type = "directional"
direction = [-0.3, -1, -0.2]
casts_shadows = false
[[object]]
name = "ground"
shape = "plane"
size = [6, 6]
albedo = [0.35, 0.25, 0.15]
[[population]]
name = "grass"
kind = "grass"
albedo = [0.1, 0.8, 0.1]
params = { cells_x = 3, cells_z = 3, centre_x = 1.5, centre_z = 1.5, blades = 60, subdivisions = 3, width_min = 0.06, width_max = 0.1 }
)" + more,
                       "lod-field.toml");
}

}  // namespace canopy::grass::test
