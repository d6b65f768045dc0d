// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/eval/lod_map_frame.hpp"

#include "lod/object_set.hpp"
#include "lod/select.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::cli {

LodMapFrame lod_map_frame(const std::vector<std::vector<lod::LodLevel>>& chains,
                          std::span<const sim::ObjectState> objects, std::span<const double> radii,
                          const FrameDiagnostics& d, const glm::dvec3& eye_velocity_m_s,
                          const lod::LodMapParams& params) {
  LodMapFrame result;
  const std::size_t n = std::min({chains.size(), objects.size(), radii.size()});
  if (n == 0) return result;
  // An evaluation aid, not the per-frame path: a fresh store each frame keeps it stateless.
  lod::ObjectStore store;
  std::vector<std::uint8_t> counts(n);
  for (std::size_t i = 0; i < n; ++i) {
    store.add(objects[i].position_m, radii[i], objects[i].velocity_m_s, chains[i]);
    counts[i] = static_cast<std::uint8_t>(std::min<std::size_t>(chains[i].size(), 255));
  }
  lod::Viewer viewer;
  viewer.eye_position_m = d.eye_position_world;
  viewer.eye_velocity_m_s = eye_velocity_m_s;
  viewer.gaze_direction = d.gaze_direction_world;
  viewer.head_angular_velocity_rad_s = d.head_angular_velocity_rad_s;
  viewer.xi_cpd = d.xi_cpd > 0.0 ? d.xi_cpd : 60.0;
  std::vector<std::uint8_t> lod(n), limited(n), s(n), e(n), v(n);
  std::vector<float> ecc(n), vel(n), radius(n);
  const lod::Decisions out{lod, limited, s, e, v, ecc, vel, radius};
  std::vector<std::uint8_t> chosen(n, 0);
  if (lod::select_lods(viewer, store.view(), out).empty()) {
    std::vector<lod::LodMapInput> in(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (limited[i] == static_cast<std::uint8_t>(lod::Criterion::invalid_input)) {
        in[i].angular_radius_deg = 90.0;  // keep detail for what cannot be measured
        continue;
      }
      in[i].angular_radius_deg = radius[i];
      in[i].eccentricity_deg = ecc[i];
      in[i].speed_deg_s = vel[i];
    }
    if (!lod::lod_map_select(in, counts, params, chosen).empty()) std::fill(chosen.begin(), chosen.end(), 0);
  }
  result.levels = chosen;
  for (std::size_t i = 0; i < n; ++i) {
    result.triangles += chains[i][std::min<std::size_t>(chosen[i], chains[i].size() - 1)].triangles;
    result.lod_sum += chosen[i];
  }
  return result;
}

}  // namespace gazelod::cli
