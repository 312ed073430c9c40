// The grass GPU cull (grass.geometry's culling = "gpu", grass.lod's bands): a cell's copy of the
// patch is drawn when its box (the prototype's bounds through the copy's model matrix) may reach
// the view frustum and lies, in part, within the distances of what draws it: what engines do
// before drawing instances, on the GPU, writing the draw's instance count (no readback). GLSL and
// C++.
#ifndef CANOPY_GRASS_CULLING_H
#define CANOPY_GRASS_CULLING_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

// What one cull pass reads besides the frame (std140).
struct GrassCull {
    vec4 box_min;    // xyz: the prototype's bounds, patch space
    vec4 box_max;    // xyz
    uvec4 draw;      // x: index count, y: first index, z: vertex offset (as uint), w: copies;
                     // for geometry drawn over each copy, (vertex count, 0, 0, copies): the first
                     // four words are then a VkDrawIndirectCommand
    vec4 distances;  // x: least distance of the box's farthest point, y: greatest of its nearest (0: any)
};

// Whether the box [lo, hi] placed by `model` may be seen through `view_proj` (world -> clip,
// depth 0 to 1): false only when all 8 corners lie outside one clip plane (conservative: a box
// across a frustum corner is kept), or when `max_distance` > 0 and the world box's nearest point
// to `eye` is farther than it, or when its farthest point is nearer than `min_distance`.
CANOPY_FN bool grass_cell_visible(mat4 view_proj, vec3 eye, mat4 model, vec3 lo, vec3 hi, float min_distance,
                                  float max_distance) {
    vec3 world_lo = vec3(1e30f), world_hi = vec3(-1e30f);
    int outside_left = 0, outside_right = 0, outside_bottom = 0, outside_top = 0, outside_near = 0, outside_far = 0;
    for (int c = 0; c < 8; ++c) {
        vec3 corner = vec3((c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y, (c & 4) != 0 ? hi.z : lo.z);
        vec4 world = model * vec4(corner, 1.0f);
        world_lo = min(world_lo, vec3(world));
        world_hi = max(world_hi, vec3(world));
        vec4 clip = view_proj * world;
        outside_left += clip.x < -clip.w ? 1 : 0;
        outside_right += clip.x > clip.w ? 1 : 0;
        outside_bottom += clip.y < -clip.w ? 1 : 0;
        outside_top += clip.y > clip.w ? 1 : 0;
        outside_near += clip.z < 0.0f ? 1 : 0;
        outside_far += clip.z > clip.w ? 1 : 0;
    }
    if (outside_left == 8 || outside_right == 8 || outside_bottom == 8 || outside_top == 8 || outside_near == 8 ||
        outside_far == 8)
        return false;
    vec3 farthest = max(abs(eye - world_lo), abs(eye - world_hi));
    if (min_distance > 0.0f && dot(farthest, farthest) < min_distance * min_distance) return false;
    if (max_distance <= 0.0f) return true;
    vec3 nearest = clamp(eye, world_lo, world_hi);
    vec3 to_eye = eye - nearest;
    return dot(to_eye, to_eye) <= max_distance * max_distance;
}

CANOPY_END_NAMESPACE

#endif
