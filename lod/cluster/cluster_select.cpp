// SPDX-License-Identifier: Apache-2.0
// Per-cluster selection (see cluster_select.hpp): validation, the frame and mesh constants
// (rounded towards keeping detail), and the block loop over each mesh's clusters; the
// arithmetic is in cluster_select_kernel.cpp.
#include "lod/cluster/cluster_select.hpp"

#include "lod/acuity.hpp"
#include "auxiliary/angles.hpp"
#include "lod/cluster/cluster_select_kernel.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

namespace gazelod::lod {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kErrorFactor = 360.0 / std::numbers::pi;  // f = d / (K e): K, deg per rad x 2

float round_up(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}
float round_down(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

bool finite3(float x, float y, float z) {
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

}  // namespace

std::string check_detail_scales(std::span<const double> detail_scale, std::size_t meshes) {
  if (detail_scale.empty()) return {};
  if (detail_scale.size() != meshes)
    return "mesh_detail_scale has " + std::to_string(detail_scale.size()) + " entries, the set " +
           std::to_string(meshes) + " meshes";
  for (std::size_t k = 0; k < meshes; ++k)
    if (!(detail_scale[k] >= 1.0 && detail_scale[k] <= detail::kMaxClusterDetailScale))
      return "mesh " + std::to_string(k) + ": detail scale must be in [1, 1e6], got " + std::to_string(detail_scale[k]);
  return {};
}

namespace {

// "" or the lengths' problem (select_clusters checks this per frame, validate_clusters too).
[[nodiscard]] std::string check_lengths(const ClusterSet& c) {
  const std::size_t n = c.size(), m = c.mesh_count();
  for (std::span<const float> s :
       {c.self_center_x_m, c.self_center_y_m, c.self_center_z_m, c.self_radius_m, c.parent_center_x_m,
        c.parent_center_y_m, c.parent_center_z_m, c.parent_radius_m, c.parent_error_m})
    if (s.size() != n) return "cluster arrays differ in length (self_error_m has " + std::to_string(n) + ")";
  const bool moving = !c.mesh_vel_x_m_s.empty() || !c.mesh_vel_y_m_s.empty() || !c.mesh_vel_z_m_s.empty();
  if (c.mesh_first_cluster.size() != m || c.mesh_finest_error_m.size() != m ||
      (moving && (c.mesh_vel_x_m_s.size() != m || c.mesh_vel_y_m_s.size() != m || c.mesh_vel_z_m_s.size() != m)))
    return "mesh arrays differ in length (mesh_cluster_count has " + std::to_string(m) + ")";
  if (std::string e = check_detail_scales(c.mesh_detail_scale, m); !e.empty()) return e;
  // Back to back from 0 over all clusters (O(meshes)): every output byte is written.
  std::size_t next = 0;
  for (std::size_t k = 0; k < m; ++k) {
    if (c.mesh_first_cluster[k] != next)
      return "mesh " + std::to_string(k) + ": mesh_first_cluster is " + std::to_string(c.mesh_first_cluster[k]) +
             ", expected " + std::to_string(next) + " (meshes lie back to back)";
    next += c.mesh_cluster_count[k];
  }
  if (next != n) return "meshes cover " + std::to_string(next) + " clusters, the arrays hold " + std::to_string(n);
  if (!c.has_records()) return {};
  // The distinct records: their arrays, one range per mesh (none empty where the mesh has
  // clusters), back to back over all of them.
  const std::size_t r = c.record_count();
  for (std::span<const float> s : {c.record_center_x_m, c.record_center_y_m, c.record_center_z_m, c.record_radius_m})
    if (s.size() != r) return "record arrays differ in length (record_error_m has " + std::to_string(r) + ")";
  if (c.self_record.size() != n || c.parent_record.size() != n)
    return "self_record and parent_record must have one entry per cluster (" + std::to_string(n) + ")";
  if (c.mesh_first_record.size() != m || c.mesh_record_count.size() != m)
    return "mesh record arrays differ in length (mesh_cluster_count has " + std::to_string(m) + ")";
  next = 0;
  for (std::size_t k = 0; k < m; ++k) {
    if (c.mesh_first_record[k] != next || (c.mesh_record_count[k] == 0 && c.mesh_cluster_count[k] > 0) ||
        c.mesh_record_count[k] > std::uint32_t{std::numeric_limits<std::int32_t>::max()})
      return "mesh " + std::to_string(k) + ": its record range [" + std::to_string(c.mesh_first_record[k]) + ", +" +
             std::to_string(c.mesh_record_count[k]) + ") must start at " + std::to_string(next) +
             " and hold a record where the mesh has clusters (at most 2^31 - 1)";
    next += c.mesh_record_count[k];
  }
  if (next != r) return "meshes cover " + std::to_string(next) + " records, the arrays hold " + std::to_string(r);
  return {};
}

// "" or the first cluster whose record indices leave its mesh's range or name a record that
// differs from its own fields (bit for bit: equal inputs are what makes the decisions equal).
[[nodiscard]] std::string record_index_problem(const ClusterSet& c) {
  const auto same = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (std::size_t k = 0; k < c.mesh_count(); ++k) {
    const std::size_t lo = c.mesh_first_record[k], hi = lo + c.mesh_record_count[k];
    const std::size_t first = c.mesh_first_cluster[k], end = first + c.mesh_cluster_count[k];
    for (std::size_t i = first; i < end; ++i)
      for (int which = 0; which < 2; ++which) {
        const std::uint32_t at = which == 0 ? c.self_record[i] : c.parent_record[i];
        const char* name = which == 0 ? "self_record" : "parent_record";
        if (at < lo || at >= hi)
          return "cluster " + std::to_string(i) + ": " + name + " " + std::to_string(at) +
                 " is outside its mesh's records [" + std::to_string(lo) + ", " + std::to_string(hi) + ")";
        const bool equal = which == 0 ? same(c.record_center_x_m[at], c.self_center_x_m[i]) &&
                                            same(c.record_center_y_m[at], c.self_center_y_m[i]) &&
                                            same(c.record_center_z_m[at], c.self_center_z_m[i]) &&
                                            same(c.record_radius_m[at], c.self_radius_m[i]) &&
                                            same(c.record_error_m[at], c.self_error_m[i])
                                      : same(c.record_center_x_m[at], c.parent_center_x_m[i]) &&
                                            same(c.record_center_y_m[at], c.parent_center_y_m[i]) &&
                                            same(c.record_center_z_m[at], c.parent_center_z_m[i]) &&
                                            same(c.record_radius_m[at], c.parent_radius_m[i]) &&
                                            same(c.record_error_m[at], c.parent_error_m[i]);
        if (!equal)
          return "cluster " + std::to_string(i) + ": " + name + " " + std::to_string(at) +
                 " differs from the cluster's own " + (which == 0 ? "self" : "parent") + " record";
      }
  }
  return {};
}

}  // namespace

namespace detail {

ClusterFrame make_cluster_frame(const Viewer& v) {
  ClusterFrame f{};
  const glm::dvec3 g = glm::normalize(v.gaze_direction);
  const glm::dvec3 w = v.head_angular_velocity_rad_s + v.gaze_angular_velocity_in_head_rad_s;
  for (int k = 0; k < 3; ++k) {
    f.eye_hi_m[k] = static_cast<float>(v.eye_position_m[k]);
    f.eye_lo_m[k] = static_cast<float>(v.eye_position_m[k] - static_cast<double>(f.eye_hi_m[k]));
    f.gaze_unit[k] = static_cast<float>(g[k]);
    f.gaze_omega_rad_s[k] = static_cast<float>(w[k]);
  }
  f.gaze_omega_norm_rad_s = round_up(glm::length(w) * (1.0 + 1e-6));
  f.ecc_offset_rad = round_up(v.tracker_error_deg * aux::kRadPerDeg + kEccentricitySlackRad);
  f.scale = round_up(v.scale);
  f.scale_xi_cpd = round_up(v.scale * v.xi_cpd);
  f.static_limit_cpd =
      v.use_size ? round_up(v.scale * std::min(kAcuityMaxCpd, v.xi_cpd)) : std::numeric_limits<float>::infinity();
  f.error_factor = round_up(kErrorFactor * kThresholdMargin);
  f.on_eccentricity = v.use_eccentricity ? 1.0f : 0.0f;
  f.on_velocity = v.use_velocity ? 1.0f : 0.0f;
  return f;
}

ClusterMeshFrame make_cluster_mesh_frame(const Viewer& v, const ClusterSet& c, std::size_t k, double detail_scale) {
  ClusterMeshFrame mf{};
  const glm::dvec3 vel = c.mesh_vel_x_m_s.empty()
                             ? glm::dvec3{0.0}
                             : glm::dvec3{c.mesh_vel_x_m_s[k], c.mesh_vel_y_m_s[k], c.mesh_vel_z_m_s[k]};
  const glm::dvec3 rel = vel - v.eye_velocity_m_s;
  for (int j = 0; j < 3; ++j) mf.rel_vel_m_s[j] = static_cast<float>(rel[j]);
  mf.rel_speed_m_s = round_up(glm::length(rel) * (1.0 + 1e-6));
  // Size off: no farther than where the finest error sits at the static limit a0 (f = a0).
  const double a0 = v.scale * std::min(kAcuityMaxCpd, v.xi_cpd);
  const double cap = kErrorFactor * a0 * c.mesh_finest_error_m[k];  // +inf stays +inf
  mf.cap_m = round_down(cap);  // may be below the floor: an error of 0 is decided apart
  mf.cap_combined_m = v.use_size ? std::numeric_limits<float>::infinity() : mf.cap_m;
  // Division by exactly 1 is exact: the frame's factor, bit for bit, at the perceptual cut.
  mf.error_factor = round_up(kErrorFactor * kThresholdMargin / detail_scale);
  return mf;
}

}  // namespace detail

namespace {

// The first problem of cluster i's records, or "" (the message is built only on failure).
[[nodiscard]] std::string record_problem(const ClusterSet& c, std::size_t i) {
  const float se = c.self_error_m[i], pe = c.parent_error_m[i];
  const float sr = c.self_radius_m[i], pr = c.parent_radius_m[i];
  std::optional<std::ostringstream> m;  // built on failure only: a stream per cluster is slow
  const auto bad = [&]() -> std::ostream& { return m.emplace() << "cluster " << i << ": "; };
  if (!finite3(c.self_center_x_m[i], c.self_center_y_m[i], c.self_center_z_m[i]))
    bad() << "self centre is not finite";
  else if (!std::isfinite(sr) || !(sr >= 0.0f))
    bad() << "self_radius_m must be finite and >= 0, got " << sr;
  else if (!std::isfinite(se) || !(se >= 0.0f))
    bad() << "self_error_m must be finite and >= 0, got " << se;
  else if (!finite3(c.parent_center_x_m[i], c.parent_center_y_m[i], c.parent_center_z_m[i]))
    bad() << "parent centre is not finite";
  else if (!std::isfinite(pr) || !(pr >= 0.0f))
    bad() << "parent_radius_m must be finite and >= 0, got " << pr;
  else if (!(pe >= 0.0f))  // +inf (kNoParentError) allowed
    bad() << "parent_error_m must be >= 0 or +inf, got " << pe;
  else if (se > pe)
    bad() << "self_error_m " << se << " exceeds parent_error_m " << pe
          << " (errors must not decrease up the hierarchy)";
  else if (std::isfinite(pe)) {
    // Containment, to the float rounding of the coordinates (1e-6 of their magnitude).
    const double px = c.parent_center_x_m[i], py = c.parent_center_y_m[i], pz = c.parent_center_z_m[i];
    const double reach =
        std::hypot(px - c.self_center_x_m[i], py - c.self_center_y_m[i], pz - c.self_center_z_m[i]) + sr;
    const double scale = std::max({std::abs(px), std::abs(py), std::abs(pz), double(pr), double(sr)});
    if (!(reach <= double(pr) + 1e-6 * scale))
      bad() << "parent sphere (radius " << pr << ") does not contain the self sphere (which reaches " << reach
            << " from the parent centre)";
  }
  return m ? m->str() : std::string();
}

}  // namespace

double finest_cluster_error_m(std::span<const float> self_error_m, std::span<const float> parent_error_m) {
  double finest = kInf;
  for (std::span<const float> s : {self_error_m, parent_error_m})
    for (float e : s)
      if (e > 0.0f && e < finest) finest = e;
  return finest;
}

std::string validate_clusters(const ClusterSet& c) {
  if (std::string e = check_lengths(c); !e.empty()) return e;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (std::string e = record_problem(c, i); !e.empty()) return e;
  if (c.has_records())
    if (std::string e = record_index_problem(c); !e.empty()) return e;
  const bool moving = !c.mesh_vel_x_m_s.empty();
  for (std::size_t k = 0; k < c.mesh_count(); ++k) {
    const std::string where = "mesh " + std::to_string(k) + ": ";
    if (moving && !(std::isfinite(c.mesh_vel_x_m_s[k]) && std::isfinite(c.mesh_vel_y_m_s[k]) &&
                    std::isfinite(c.mesh_vel_z_m_s[k])))
      return where + "velocity is not finite";
    const std::size_t first = c.mesh_first_cluster[k], count = c.mesh_cluster_count[k];
    const double finest =
        finest_cluster_error_m(c.self_error_m.subspan(first, count), c.parent_error_m.subspan(first, count));
    const double given = c.mesh_finest_error_m[k];
    if (!(given > 0.0) || (std::isfinite(finest) && !(given <= finest))) {
      std::ostringstream m;
      m << where << "mesh_finest_error_m must be > 0 and <= the mesh's finest positive error " << finest << ", got "
        << given;
      return m.str();
    }
  }
  return {};
}

namespace {

// Where the block of clusters from `base` on writes its outcomes.
detail::ClusterOutput output_at(const ClusterDecisions& out, std::size_t base, bool per_criterion, bool records) {
  return {out.drawn.data() + base,
          out.limited_by.data() + base,
          per_criterion ? out.drawn_size_only.data() + base : nullptr,
          per_criterion ? out.drawn_eccentricity_only.data() + base : nullptr,
          per_criterion ? out.drawn_velocity_only.data() + base : nullptr,
          records ? out.record_invisible.data() + base : nullptr};
}

}  // namespace

std::string select_clusters(const Viewer& viewer, const ClusterSet& c, const ClusterDecisions& out) {
  if (std::string e = validate_viewer(viewer); !e.empty()) return "viewer: " + e;
  if (std::string e = check_lengths(c); !e.empty()) return "clusters: " + e;
  const std::size_t n = c.size();
  if (out.drawn.size() < n || out.limited_by.size() < n)
    return "decisions: drawn or limited_by is shorter than the cluster count";
  const bool per_criterion =
      !out.drawn_size_only.empty() || !out.drawn_eccentricity_only.empty() || !out.drawn_velocity_only.empty();
  if (per_criterion &&
      (out.drawn_size_only.size() < n || out.drawn_eccentricity_only.size() < n || out.drawn_velocity_only.size() < n))
    return "decisions: the per-criterion outputs must all be given, each at least the cluster count";
  const bool records = !out.record_invisible.empty();
  if (records && out.record_invisible.size() < n)
    return "decisions: record_invisible is shorter than the cluster count";
  if (!out.record_flags.empty() && c.has_records() && out.record_flags.size() < c.record_count())
    return "decisions: record_flags has " + std::to_string(out.record_flags.size()) + " words, the set " +
           std::to_string(c.record_count()) + " distinct records";

  const bool by_record = c.has_records() && !out.record_flags.empty();

  const detail::ClusterFrame frame = detail::make_cluster_frame(viewer);
  const detail::RecordInput self_in{c.self_center_x_m.data(), c.self_center_y_m.data(), c.self_center_z_m.data(),
                                    c.self_radius_m.data(), c.self_error_m.data()};
  const detail::RecordInput parent_in{c.parent_center_x_m.data(), c.parent_center_y_m.data(),
                                      c.parent_center_z_m.data(), c.parent_radius_m.data(), c.parent_error_m.data()};
  const detail::RecordInput table_in{c.record_center_x_m.data(), c.record_center_y_m.data(), c.record_center_z_m.data(),
                                     c.record_radius_m.data(), c.record_error_m.data()};
  detail::RecordBlock self_blk, parent_blk;  // 10 KiB each, reused per block
  for (std::size_t k = 0; k < c.mesh_count(); ++k) {
    const double detail_scale = c.mesh_detail_scale.empty() ? 1.0 : c.mesh_detail_scale[k];
    const detail::ClusterMeshFrame mesh = detail::make_cluster_mesh_frame(viewer, c, k, detail_scale);
    const std::size_t end = std::size_t{c.mesh_first_cluster[k]} + c.mesh_cluster_count[k];
    if (by_record && end > c.mesh_first_cluster[k]) {
      // Each distinct record once (with the per-criterion cuts: every criterion's outcome;
      // without: the size screen, as below), then every cluster from its two records' outcomes.
      const std::size_t lo = c.mesh_first_record[k], hi = lo + c.mesh_record_count[k];
      for (std::size_t base = lo; base < hi; base += detail::kClusterBlock) {
        const std::size_t m = std::min(detail::kClusterBlock, hi - base);
        detail::evaluate_records(frame, mesh, table_in, base, m, true,
                                 per_criterion ? detail::RecordScreen::trivial : detail::RecordScreen::by_size, nullptr,
                                 self_blk);
        detail::pack_record_flags(m, self_blk, out.record_flags.data() + base);
      }
      const auto first = static_cast<std::uint32_t>(lo), last = static_cast<std::uint32_t>(hi - 1);
      for (std::size_t base = c.mesh_first_cluster[k]; base < end; base += detail::kClusterBlock) {
        const std::size_t m = std::min(detail::kClusterBlock, end - base);
        detail::combine_record_flags(m, out.record_flags.data(), c.self_record.data() + base,
                                     c.parent_record.data() + base, first, last,
                                     output_at(out, base, per_criterion, records));
      }
      continue;
    }
    for (std::size_t base = c.mesh_first_cluster[k]; base < end; base += detail::kClusterBlock) {
      const std::size_t m = std::min(detail::kClusterBlock, end - base);
      // The size screen only where no per-criterion cut needs every record's E and v (with
      // one, only the trivial records are screened). The parent first: where it is invisible
      // the cluster is not drawn and its self record is invisible too (nesting), so that is not
      // evaluated.
      const detail::RecordScreen screen = per_criterion ? detail::RecordScreen::trivial : detail::RecordScreen::by_size;
      detail::evaluate_records(frame, mesh, parent_in, base, m, per_criterion, screen, nullptr, parent_blk);
      detail::evaluate_records(frame, mesh, self_in, base, m, true, screen,
                               per_criterion ? nullptr : parent_blk.combined, self_blk);
      detail::combine_records(m, self_blk, parent_blk, output_at(out, base, per_criterion, records));
    }
  }
  return {};
}

}  // namespace gazelod::lod
