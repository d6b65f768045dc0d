// Rigid poses in double precision (glm) and their conversion to and from XrPosef; the gaze
// orientation of a direction (yaw then pitch, so the pose's +X stays level: XR_EXT_eye_gaze
// poses are +Y up, -Z forward).
#pragma once

#include "sim/runtime/xr_headers.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace gazelod::xrrt {

struct Pose {
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 position{0.0};
};

inline Pose compose(const Pose& a, const Pose& b) {  // b expressed in a's frame
  return {glm::normalize(a.orientation * b.orientation), a.position + a.orientation * b.position};
}
inline Pose inverse(const Pose& a) {
  const glm::dquat inv = glm::conjugate(a.orientation);
  return {inv, -(inv * a.position)};
}
inline Pose from_xr(const XrPosef& p) {
  return {glm::normalize(glm::dquat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z)),
          glm::dvec3(p.position.x, p.position.y, p.position.z)};
}
inline XrPosef to_xr(const Pose& p) {
  XrPosef out{};
  out.orientation = {float(p.orientation.x), float(p.orientation.y), float(p.orientation.z), float(p.orientation.w)};
  out.position = {float(p.position.x), float(p.position.y), float(p.position.z)};
  return out;
}
inline XrVector3f to_xr(const glm::dvec3& v) { return {float(v.x), float(v.y), float(v.z)}; }

// True when an XrPosef's orientation is a unit quaternion (within the spec's tolerance).
inline bool is_unit_orientation(const XrPosef& p) {
  const double n = double(p.orientation.x) * p.orientation.x + double(p.orientation.y) * p.orientation.y +
                   double(p.orientation.z) * p.orientation.z + double(p.orientation.w) * p.orientation.w;
  return std::isfinite(n) && std::abs(n - 1.0) < 1e-2;
}

// Orientation whose -Z axis points along `dir` (head space), with no roll.
inline glm::dquat gaze_orientation(const glm::dvec3& dir) {
  const double yaw = std::atan2(-dir.x, -dir.z);
  const double pitch = std::atan2(dir.y, std::hypot(dir.x, dir.z));
  return glm::normalize(glm::angleAxis(yaw, glm::dvec3(0, 1, 0)) * glm::angleAxis(pitch, glm::dvec3(1, 0, 0)));
}

}  // namespace gazelod::xrrt
