// SPDX-License-Identifier: Apache-2.0
#include "render/camera.hpp"

#include "render/render_error.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <numbers>

namespace gazelod::render {

glm::dmat4 view_matrix(const Pose& pose) {
  const glm::dmat4 eye_to_world =
      glm::translate(glm::dmat4(1.0), pose.position_m) * glm::mat4_cast(glm::normalize(pose.orientation));
  return glm::inverse(eye_to_world);
}

glm::dmat4 projection_matrix(const Fov& fov, double near_m, double far_m) {
  const double limit = std::numbers::pi / 2.0;
  auto inside = [limit](double a) { return std::isfinite(a) && std::abs(a) < limit; };
  if (!inside(fov.angle_left) || !inside(fov.angle_right) || !inside(fov.angle_up) || !inside(fov.angle_down) ||
      fov.angle_left >= fov.angle_right || fov.angle_down >= fov.angle_up)
    throw RenderError("projection: degenerate field of view (left " + std::to_string(fov.angle_left) + ", right " +
                      std::to_string(fov.angle_right) + ", up " + std::to_string(fov.angle_up) + ", down " +
                      std::to_string(fov.angle_down) + " rad)");
  if (!(near_m > 0.0) || !(far_m > near_m) || !std::isfinite(far_m))
    throw RenderError("projection: need 0 < near < far (near " + std::to_string(near_m) + " m, far " +
                      std::to_string(far_m) + " m)");
  const double tan_left = std::tan(fov.angle_left);
  const double tan_right = std::tan(fov.angle_right);
  const double tan_up = std::tan(fov.angle_up);
  const double tan_down = std::tan(fov.angle_down);
  const double width = tan_right - tan_left;
  // Vulkan's clip space has y pointing down, so the height runs from up to down.
  const double height = tan_down - tan_up;

  glm::dmat4 m(0.0);  // glm: m[column][row]
  m[0][0] = 2.0 / width;
  m[2][0] = (tan_right + tan_left) / width;
  m[1][1] = 2.0 / height;
  m[2][1] = (tan_up + tan_down) / height;
  // Depth 0 at the near plane, 1 at the far plane.
  m[2][2] = -far_m / (far_m - near_m);
  m[3][2] = -(far_m * near_m) / (far_m - near_m);
  m[2][3] = -1.0;
  return m;
}

bool project_to_pixel(const EyeView& view, const glm::dvec3& point_world_m, int width, int height, glm::dvec2& pixel) {
  const glm::dvec4 clip =
      projection_matrix(view.fov, view.near_m, view.far_m) * view_matrix(view.pose) * glm::dvec4(point_world_m, 1.0);
  if (!(clip.w > 0.0)) return false;
  const double x_ndc = clip.x / clip.w;
  const double y_ndc = clip.y / clip.w;
  pixel = {(x_ndc + 1.0) * 0.5 * width, (y_ndc + 1.0) * 0.5 * height};
  return true;
}

ViewCuller::ViewCuller(const EyeView& view)
    : world_to_eye_(view_matrix(view.pose)), near_m_(view.near_m), far_m_(view.far_m) {
  const double l = std::tan(view.fov.angle_left), r = std::tan(view.fov.angle_right);
  const double u = std::tan(view.fov.angle_up), d = std::tan(view.fov.angle_down);
  // Inside the left plane: x >= l * depth, i.e. x - l * depth >= 0; and so on.
  left_ = glm::dvec2(1.0, -l) / std::sqrt(1.0 + l * l);
  right_ = glm::dvec2(-1.0, r) / std::sqrt(1.0 + r * r);
  up_ = glm::dvec2(-1.0, u) / std::sqrt(1.0 + u * u);
  down_ = glm::dvec2(1.0, -d) / std::sqrt(1.0 + d * d);
}

bool ViewCuller::visible(const glm::dvec3& center_world_m, double radius_m) const {
  const glm::dvec3 c = glm::dvec3(world_to_eye_ * glm::dvec4(center_world_m, 1.0));
  const double depth = -c.z;  // the eye looks down -z
  if (depth < near_m_ - radius_m || depth > far_m_ + radius_m) return false;
  return glm::dot(left_, glm::dvec2(c.x, depth)) >= -radius_m &&
         glm::dot(right_, glm::dvec2(c.x, depth)) >= -radius_m && glm::dot(up_, glm::dvec2(c.y, depth)) >= -radius_m &&
         glm::dot(down_, glm::dvec2(c.y, depth)) >= -radius_m;
}

}  // namespace gazelod::render
