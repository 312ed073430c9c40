// The volume's vertex stage (grass.volume, and grass.lod's middle band): each cell's carrier
// cuboid (Lemme eq 5.2, the patch's bounding volume), placed and mirrored with the cell
// (PassContext::draw_over_population). Only the faces a ray leaves the cuboid by are kept: the
// test is made in patch space, where a mirrored cell's faces keep their outward normals (the
// rasteriser's winding flips with the mirror), and it keeps the faces around an eye inside the
// cuboid, which Lemme's front faces would lose. The fragment shader finds the entry along the ray
// (volume_entry). Included after the technique's parameter block.
#include "frame_uniforms.glsl"
#include "volume_walk.h"
#include "grass_terrain.h"

layout(set = 0, binding = 3, std140) uniform BoxBlock { VolumeBox box; };

layout(location = 0) in vec4 corner;                     // q space: a corner of the unit cube
layout(location = 1) in vec4 face_plane;                 // outward normal xyz; w: dot(normal, q) on the face
layout(location = 2) in mat4 instance_model;             // locations 2-5
layout(location = 6) in vec4 instance_normal_matrix[3];  // locations 6-8
layout(location = 9) in vec4 corner_densities;           // patch order (grass_density.h)

layout(location = 0) out vec3 exit_q;
layout(location = 1) flat out vec3 eye_q;
layout(location = 2) flat out vec4 densities;
layout(location = 3) flat out mat4 model;              // locations 3-6
layout(location = 7) flat out vec3 normal_matrix[3];  // locations 7-9
layout(location = 11) flat out vec3 lifts;            // grass_terrain.h: the cell's other corners over its first
layout(location = 12) flat out vec2 stretch;          // the cuboid's bottom and top moved by, patch units

void main() {
    // On a terrain (Lemme eq 6.14) the cuboid reaches from the cell's lowest ground to the patch's
    // height over its highest: the model stands it on the first corner, the lifts give the others.
    lifts = vec3(instance_normal_matrix[0].w, instance_normal_matrix[1].w, instance_normal_matrix[2].w);
    stretch = vec2(min(0.0, min(lifts.x, min(lifts.y, lifts.z))), max(0.0, max(lifts.x, max(lifts.y, lifts.z)))) /
              instance_model[1][1];
    vec3 origin = box.origin.xyz + vec3(0.0, stretch.x, 0.0);
    vec3 extent = box.extent.xyz + vec3(0.0, stretch.y - stretch.x, 0.0);
    vec3 p = origin + corner.xyz * extent;
    vec3 eye = (inverse(instance_model) * vec4(frame.camera_position.xyz, 1.0)).xyz;
    exit_q = corner.xyz;
    eye_q = (eye - origin) / extent;
    densities = corner_densities;
    model = instance_model;
    for (int c = 0; c < 3; ++c) normal_matrix[c] = instance_normal_matrix[c].xyz;
    // A face the eye sees from outside is where rays enter: outside the clip volume, so culled.
    // The test reads only what the face's three vertices share, so they agree.
    bool entry_face = dot(face_plane.xyz, eye_q) > face_plane.w;
    gl_Position = entry_face ? vec4(2.0, 2.0, 2.0, 1.0) : frame.view_proj * (instance_model * vec4(p, 1.0));
}
