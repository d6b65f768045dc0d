// SPDX-License-Identifier: Apache-2.0
#include "render/foveal_marker.hpp"
#include "auxiliary/angles.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gazelod::render {

std::size_t foveal_circle(const glm::dvec3& eye_m, const glm::dvec3& gaze_dir, double radius_deg, std::uint32_t mesh,
                          std::span<DrawItem> out, double distance_m, double dot_deg) {
  const double len = glm::length(gaze_dir);
  if (!std::isfinite(len) || len <= 0.0 || !std::isfinite(radius_deg) || out.empty()) return 0;
  const glm::dvec3 g = gaze_dir / len;
  // Any vector not parallel to g gives the circle's plane.
  const glm::dvec3 helper = std::abs(g.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
  const glm::dvec3 u = glm::normalize(glm::cross(g, helper));
  const glm::dvec3 v = glm::cross(g, u);
  const double r = std::clamp(radius_deg, 0.0, 89.0) * aux::kRadPerDeg;
  const auto dot_radius = static_cast<float>(distance_m * std::tan(dot_deg * aux::kRadPerDeg));
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double phi = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(out.size());
    const glm::dvec3 dir = std::cos(r) * g + std::sin(r) * (std::cos(phi) * u + std::sin(phi) * v);
    out[i] = {glm::vec3(eye_m + distance_m * dir), dot_radius, mesh, kMarkerLevel};
  }
  return out.size();
}

}  // namespace gazelod::render
