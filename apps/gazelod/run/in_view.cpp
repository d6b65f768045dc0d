// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/in_view.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::cli {

std::uint64_t lod_sum(std::span<const std::uint8_t> lods) {
  std::uint64_t n = 0;
  for (std::uint8_t l : lods) n += l;
  return n;
}

bool sphere_in_view(const glm::dvec3& center_m, double radius_m, const glm::dvec3& eye_m, const glm::dquat& head,
                    const lod::FovRad& fov) {
  const glm::dvec3 p = glm::inverse(head) * (center_m - eye_m);  // head space
  const double dist = glm::length(p);
  const double r = std::max(0.0, radius_m);
  if (!std::isfinite(dist)) return false;
  if (dist <= r) return true;
  const double margin = std::atan2(r, std::sqrt(dist * dist - r * r));  // the sphere's angular radius
  const double h = std::atan2(p.x, -p.z), v = std::atan2(p.y, -p.z);
  return h >= fov.angle_left_rad - margin && h <= fov.angle_right_rad + margin && v >= fov.angle_down_rad - margin &&
         v <= fov.angle_up_rad + margin;
}

InViewFrame in_view_frame(const std::vector<std::vector<lod::LodLevel>>& chains,
                          std::span<const sim::ObjectState> objects, std::span<const double> radii,
                          const FrameDecisions& decisions, const FrameDiagnostics& d,
                          std::span<const std::uint8_t> lod_map_levels, const glm::dvec3& eye_m, const glm::dquat& head,
                          const lod::FovRad& fov) {
  InViewFrame f;
  const std::size_t n = std::min({chains.size(), objects.size(), radii.size()});
  const auto level_of = [](std::span<const std::uint8_t> lods, std::size_t i) -> std::uint8_t {
    return i < lods.size() ? lods[i] : 0;  // a set the plugin did not compute counts as level 0
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!sphere_in_view(objects[i].position_m, radii[i], eye_m, head, fov)) continue;
    ++f.objects;
    const std::array<std::uint8_t, kEvalSets> level{0,
                                                    level_of(d.lod_size_only, i),
                                                    level_of(d.lod_size_eccentricity, i),
                                                    level_of(d.lod_size_velocity, i),
                                                    level_of(decisions.lod, i),
                                                    level_of(lod_map_levels, i)};
    for (std::size_t s = 0; s < kEvalSets; ++s) {
      f.triangles[s] += chains[i][std::min<std::size_t>(level[s], chains[i].size() - 1)].triangles;
      f.lod_sum[s] += level[s];
    }
  }
  return f;
}

}  // namespace gazelod::cli
