// SPDX-License-Identifier: Apache-2.0
// gazelod renderer: flat LOD tint with headlight shading, so the point facing the eye has
// exactly the tint and the silhouette darkens to the ambient share.
#version 450

layout(push_constant) uniform Draw {
  mat4 view_proj;
  vec4 center_radius;
  vec4 colour;
  vec4 eye_position;
} draw;

layout(location = 0) in vec3 in_normal;
layout(location = 1) in vec3 in_world;
layout(location = 0) out vec4 out_colour;
#ifdef PER_CLUSTER_TINT
layout(location = 2) flat in vec3 in_tint;  // lod_mesh.vert's, per cluster
#define TINT in_tint
#else
#define TINT draw.colour.rgb
#endif

const float kAmbient = 0.35;

void main() {
  vec3 n = normalize(in_normal);
  vec3 to_eye = normalize(draw.eye_position.xyz - in_world);
  float light = kAmbient + (1.0 - kAmbient) * max(dot(n, to_eye), 0.0);
  out_colour = vec4(TINT * light, 1.0);
}
