// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/frame_record.hpp"

#include "apps/gazelod/eval/lod_map_frame.hpp"
#include "apps/gazelod/run/in_view.hpp"
#include "auxiliary/angles.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace gazelod::cli {

std::uint64_t chain_triangles(const std::vector<std::vector<lod::LodLevel>>& chains,
                              std::span<const std::uint8_t> lods) {
  std::uint64_t n = 0;
  for (std::size_t i = 0; i < chains.size() && i < lods.size(); ++i)
    n += chains[i][std::min<std::size_t>(lods[i], chains[i].size() - 1)].triangles;
  return n;
}

FrameRecord record_frame(const FrameRecordInput& in) {
  const auto& chains = *in.chains;
  const FrameDecisions& d = *in.decisions;
  const FrameDiagnostics& diag = *in.diagnostics;
  FrameRecord r;
  r.predicted_ms = diag.predicted_ms;
  r.triangles_drawn = chain_triangles(chains, d.lod);
  r.triangles_perceptual = chain_triangles(chains, diag.lod_perceptual);
  r.triangles_full = in.triangles_full;
  r.triangles_size_only = chain_triangles(chains, diag.lod_size_only);
  r.triangles_size_eccentricity = chain_triangles(chains, diag.lod_size_eccentricity);
  r.triangles_size_velocity = chain_triangles(chains, diag.lod_size_velocity);
  for (std::uint8_t l : d.lod) ++r.lod_histogram[l];
  r.objects = static_cast<std::int64_t>(chains.size());
  r.lod_sum_drawn = lod_sum(d.lod);
  r.lod_sum_size_only = lod_sum(diag.lod_size_only);
  r.lod_sum_size_eccentricity = lod_sum(diag.lod_size_eccentricity);
  r.lod_sum_size_velocity = lod_sum(diag.lod_size_velocity);
  // The thesis's policy is an evaluation aid (eval, compare): a fresh selection per frame that
  // plain runs do not pay for.
  LodMapFrame lod_map;
  if (in.lod_map) {
    lod_map = lod_map_frame(chains, in.objects, in.radii, diag, in.head.linear_velocity_m_s);
    r.triangles_lod_map = lod_map.triangles;
    r.lod_sum_lod_map = lod_map.lod_sum;
  }
  const InViewFrame view = in_view_frame(chains, in.objects, in.radii, d, diag, lod_map.levels, in.head.position_m,
                                         in.head.orientation, in.fov);
  r.objects_in_view = view.objects;
  r.in_view_triangles = view.triangles;
  r.in_view_lod_sum = view.lod_sum;
  r.gaze_source = to_string(d.gaze_source);
  r.gaze_valid = d.gaze_valid;
  r.head_speed_dps = glm::length(diag.head_angular_velocity_rad_s) * aux::kDegPerRad;
  r.eye_motion = diag.gaze_carried ? "carried" : gaze::to_string(diag.eye_motion);
  r.plugin_suppressed = diag.gaze_suppressed;
  r.gaze_error_deg = diag.gaze_error_deg;
  return r;
}

}  // namespace gazelod::cli
