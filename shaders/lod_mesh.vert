// SPDX-License-Identifier: Apache-2.0
// gazelod renderer: one unit-sphere mesh per LOD level, placed and scaled per draw
// (push constants), in the eye's Vulkan clip space. Built a second time with
// -DPER_CLUSTER_TINT (lod_mesh_tinted.*.h) for cuts a compute pass wrote: each draw's tint
// comes per instance from a buffer, indexed by the command's firstInstance (the cluster's id).
#version 450

layout(location = 0) in vec3 in_position;  // unit sphere: also the normal

layout(push_constant) uniform Draw {
  mat4 view_proj;        // world -> clip
  vec4 center_radius;    // xyz: centre (m), w: radius (m)
  vec4 colour;           // rgb: LOD tint in the target's colour space
  vec4 eye_position;     // xyz: eye (m), for the headlight shading
} draw;

layout(location = 0) out vec3 out_normal;
layout(location = 1) out vec3 out_world;
#ifdef PER_CLUSTER_TINT
layout(location = 1) in vec3 in_tint;  // per instance: the draw's cluster
layout(location = 2) flat out vec3 out_tint;
#endif

void main() {
  vec3 world = draw.center_radius.xyz + draw.center_radius.w * in_position;
  out_normal = in_position;
  out_world = world;
  gl_Position = draw.view_proj * vec4(world, 1.0);
#ifdef PER_CLUSTER_TINT
  out_tint = in_tint;
#endif
}
