#include "config/camera_path_config.hpp"

#include "scene/scene_limits.hpp"

#include <fmt/format.h>

#include <cmath>

namespace canopy {

namespace {

constexpr long long kMaxPathFrames = 10000;
constexpr const char* kPoseExample =
    "[[camera_path.pose]]\n    position = [0, 2, 6]\n    target = [0, 0, 0]";

void require_in_scene(const TomlReader& reader, std::string_view key, const glm::vec3& value) {
    const double bound = limits::kMaxCoordinate;
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(value[i]) <= float(bound)))
            throw reader.error(key, fmt::format("{} = [{}, {}, {}] lies outside the scene's coordinate range [-{}, {}]",
                                                reader.describe_key(key), value.x, value.y, value.z, bound, bound),
                               "keep every coordinate within 1e6 scene units (configs/README.md, \"Limits\")");
}

CameraPose read_pose(TomlReader& reader, const std::vector<Scene>& scenes) {
    if (!reader.has("position") || !reader.has("target"))
        throw ConfigError(reader.file(), reader.line(), fmt::format("{} needs both 'position' and 'target'", reader.context()),
                          fmt::format("a pose looks like this:\n    {}", kPoseExample));
    CameraPose pose;
    pose.position = reader.get_vec3("position", pose.position, Broadcast::forbidden);
    require_in_scene(reader, "position", pose.position);
    pose.target = reader.get_vec3("target", pose.target, Broadcast::forbidden);
    require_in_scene(reader, "target", pose.target);
    pose.fov_y_degrees = float(reader.get_float("fov", 0.0));
    reader.finish();
    if (reader.has("fov") && !(pose.fov_y_degrees > 0.0f && pose.fov_y_degrees < 179.0f))
        throw reader.error("fov", fmt::format("'fov' of {} must lie in (0, 179) degrees, got {}", reader.context(),
                                              pose.fov_y_degrees),
                           "leave fov out to keep the scene camera's, or give e.g. fov = 45");
    const glm::vec3 view = pose.target - pose.position;
    if (glm::length(view) < 1e-6f)
        throw reader.error("target", fmt::format("{}: 'target' equals 'position'", reader.context()),
                           "the camera looks from position towards target; move one of them");
    for (const Scene& scene : scenes)
        if (std::abs(glm::dot(glm::normalize(view), glm::normalize(scene.camera.up))) > 0.9999f)
            throw reader.error("target",
                               fmt::format("{} looks along the 'up' of scene '{}''s camera", reader.context(), scene.name),
                               "tilt the pose's target a little, or change the scene camera's up");
    return pose;
}

}  // namespace

CameraPath read_camera_path(TomlReader& section, const std::vector<Scene>& scenes) {
    CameraPath path;
    const long long frames = section.get_int("frames", 0);
    path.popping = section.get_bool("popping", false);
    std::vector<TomlReader> poses = section.get_tables("pose", "[[camera_path.pose]]");
    section.finish();
    if (!section.has("frames"))
        throw ConfigError(section.file(), section.line(), "[camera_path] needs 'frames', the frames of one traversal",
                          "e.g. frames = 16: every timing sample renders the 16 frames of the path");
    if (frames < 2 || frames > kMaxPathFrames)
        throw section.error("frames", fmt::format("'frames' in [camera_path] must lie in [2, {}], got {}", kMaxPathFrames,
                                                  frames),
                            "frames is the number of frames of one traversal, e.g. frames = 16");
    if (poses.size() < 2)
        throw ConfigError(section.file(), section.line(),
                          fmt::format("[camera_path] has {} pose(s); a path needs at least two", poses.size()),
                          fmt::format("add [[camera_path.pose]] tables in the order the camera visits them:\n    {}",
                                      kPoseExample));
    if (poses.size() > size_t(frames))
        throw section.error("frames", fmt::format("[camera_path] has {} poses but only {} frames", poses.size(), frames),
                            "every pose is reached at a frame of its own: give at least as many frames as poses");
    path.frames = int(frames);
    for (TomlReader& pose : poses) path.poses.push_back(read_pose(pose, scenes));
    return path;
}

}  // namespace canopy
