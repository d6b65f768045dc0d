// SPDX-License-Identifier: Apache-2.0
// Camera for one eye: view matrix from an XrPosef-like pose and an asymmetric projection from
// four XrFovf angles, in Vulkan clip space (y down, depth 0..1). Follows the OpenXR SDK's
// xr_linear.h XrMatrix4x4f_CreateProjectionFov for GRAPHICS_VULKAN.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace gazelod::render {

struct Pose {
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // w, x, y, z (glm order); eye space -> world
  glm::dvec3 position_m{0.0};
};

// OpenXR convention: radians, left and down negative for a symmetric view.
struct Fov {
  double angle_left = -0.7;
  double angle_right = 0.7;
  double angle_up = 0.7;
  double angle_down = -0.7;
};

struct EyeView {
  Pose pose;
  Fov fov;
  double near_m = 0.05;
  double far_m = 1000.0;
};

// World -> eye space (the inverse of the pose; the eye looks down -z, +y up).
glm::dmat4 view_matrix(const Pose& pose);

// Eye space -> Vulkan clip space. Throws RenderError when the FOV is degenerate (left >= right,
// down >= up, any angle outside (-90, 90) degrees) or not 0 < near < far.
glm::dmat4 projection_matrix(const Fov& fov, double near_m, double far_m);

// Where a world point lands on a width x height image, in pixels from the top-left corner
// (pixel centres at +0.5). Returns false for points behind the eye.
bool project_to_pixel(const EyeView& view, const glm::dvec3& point_world_m, int width, int height, glm::dvec2& pixel);

// Conservative sphere-against-view-frustum test (the four FOV planes, near and far), so
// objects entirely outside an eye's view are not submitted. May keep a sphere near a
// frustum corner that is just outside; never drops one that is partly inside.
class ViewCuller {
 public:
  explicit ViewCuller(const EyeView& view);
  bool visible(const glm::dvec3& center_world_m, double radius_m) const;

 private:
  glm::dmat4 world_to_eye_;
  double near_m_, far_m_;
  // Side planes through the eye as (a, b) with a * x_or_y + b * depth >= 0 inside, unit length.
  glm::dvec2 left_, right_, up_, down_;
};

}  // namespace gazelod::render
