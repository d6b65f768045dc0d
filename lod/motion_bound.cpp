// SPDX-License-Identifier: Apache-2.0
// The size-and-motion level of the switch policy's candidates (see motion_bound.hpp): gather,
// select with eccentricity off, scatter.
#include "lod/motion_bound.hpp"

#include <glm/vec3.hpp>

#include <algorithm>

namespace gazelod::lod {

std::string motion_bound_levels(const Viewer& viewer, const ObjectSet& o, std::span<const std::uint8_t> perceptual,
                                std::span<const std::uint8_t> drawn, MotionBoundScratch& s, std::span<std::uint8_t> out,
                                EyeHypotheses also) {
  const std::size_t n = o.size();
  if (perceptual.size() != n || drawn.size() != n || out.size() != n)
    return "motion_bound_levels: perceptual, drawn and out must have one entry per object";
  if (std::string e = validate_viewer(viewer); !e.empty()) return "motion_bound_levels: viewer: " + e;
  const bool moving = !o.vel_x_m_s.empty();
  if (o.center_x_m.size() != n || o.center_y_m.size() != n || o.center_z_m.size() != n || o.lod_first.size() != n ||
      o.lod_count.size() != n || o.detail_kind.size() != n ||
      (moving && (o.vel_y_m_s.size() != n || o.vel_z_m_s.size() != n || o.vel_x_m_s.size() != n)))
    return "motion_bound_levels: objects: arrays differ in length";

  s.index.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (perceptual[i] > drawn[i]) s.index.push_back(static_cast<std::uint32_t>(i));
  std::fill(out.begin(), out.end(), std::uint8_t{0});
  const std::size_t m = s.index.size();
  if (m == 0) return {};

  auto gather = [&](std::span<const double> from, std::vector<double>& to) {
    to.resize(m);
    for (std::size_t j = 0; j < m; ++j) to[j] = from[s.index[j]];
  };
  gather(o.center_x_m, s.cx_m), gather(o.center_y_m, s.cy_m), gather(o.center_z_m, s.cz_m);
  gather(o.radius_m, s.radius_m);
  if (moving) gather(o.vel_x_m_s, s.vx_m_s), gather(o.vel_y_m_s, s.vy_m_s), gather(o.vel_z_m_s, s.vz_m_s);
  s.kind.resize(m), s.first.resize(m), s.count.resize(m);
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t i = s.index[j];
    s.kind[j] = o.detail_kind[i], s.first[j] = o.lod_first[i], s.count[j] = o.lod_count[i];
  }
  for (auto* v : {&s.lod, &s.limited, &s.size_only, &s.ecc_only, &s.vel_only}) v->resize(m);

  ObjectSet sub;
  sub.center_x_m = s.cx_m, sub.center_y_m = s.cy_m, sub.center_z_m = s.cz_m, sub.radius_m = s.radius_m;
  if (moving) sub.vel_x_m_s = s.vx_m_s, sub.vel_y_m_s = s.vy_m_s, sub.vel_z_m_s = s.vz_m_s;
  sub.detail_kind = s.kind, sub.lod_first = s.first, sub.lod_count = s.count;
  sub.level_weight = o.level_weight;  // the chains' weights stay where they are

  // Eccentricity off: the gaze direction and the tracker's error are not read (motion_bound.hpp).
  Viewer sv = viewer;
  sv.use_eccentricity = false;
  if (std::string e = select_lods(sv, sub, {s.lod, s.limited, s.size_only, s.ecc_only, s.vel_only, {}, {}, {}});
      !e.empty())
    return "motion_bound_levels: " + e;
  for (std::size_t j = 0; j < m; ++j) out[s.index[j]] = s.lod[j];
  const glm::dvec3 estimate = viewer.gaze_angular_velocity_in_head_rad_s;
  auto also_with = [&](const glm::dvec3& eye_in_head_rad_s) {
    if (eye_in_head_rad_s == estimate) return;  // the same viewer: the same levels
    sv.gaze_angular_velocity_in_head_rad_s = eye_in_head_rad_s;
    // Cannot be refused: the same objects, and a viewer that differs only by a finite vector.
    (void)select_lods(sv, sub, {s.lod, s.limited, s.size_only, s.ecc_only, s.vel_only, {}, {}, {}});
    for (std::size_t j = 0; j < m; ++j) out[s.index[j]] = std::min(out[s.index[j]], s.lod[j]);
  };
  if (also.at_rest_in_head) also_with(glm::dvec3(0.0));
  if (also.at_rest_in_world) also_with(-viewer.head_angular_velocity_rad_s);
  return {};
}

}  // namespace gazelod::lod
