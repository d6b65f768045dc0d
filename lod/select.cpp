// SPDX-License-Identifier: Apache-2.0
// Per-object LOD selection over structure-of-arrays data (see select.hpp), in blocks of
// detail::kSelectBlock objects (lod/select_kernel.hpp): phase 1 computes E, v, alpha and the
// acuity terms of every object, the chains' weights are gathered into rows, phase 2 counts
// the levels each criterion allows and writes the decisions; both phases are vectorised
// (AVX2 / AVX-512 where the CPU has them). This file validates, drives the blocks and handles
// the rare objects the vector path leaves out. bench/lod/bench_select.cpp measures it.
#include "auxiliary/angles.hpp"
#include "lod/select.hpp"

#include "lod/acuity.hpp"
#include "lod/select_kernel.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace gazelod::lod {
namespace {

bool finite3(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

detail::KernelFrame kernel_frame(const FrameConstants& f) {
  detail::KernelFrame kf{};
  for (int k = 0; k < 3; ++k) {
    kf.eye_m[k] = f.eye[k];
    kf.eye_vel_m_s[k] = f.eye_vel[k];
    kf.gaze_unit[k] = f.gaze_unit[k];
    kf.gaze_omega_rad_s[k] = f.gaze_omega[k];
  }
  kf.tracker_error_rad = f.tracker_error_rad;
  kf.xi_cpd = f.xi_cpd;
  kf.scale = f.scale;
  kf.acuity_static_cpd = f.acuity_static_cpd;
  kf.use_size = f.use_size;
  kf.use_eccentricity = f.use_eccentricity;
  kf.use_velocity = f.use_velocity;
  return kf;
}

void write_diagnostics(const detail::KernelBlock& b, std::size_t m, std::size_t base, const Decisions& out) {
  const std::size_t n = base + m;
  if (out.ecc_deg.size() >= n)
    for (std::size_t j = 0; j < m; ++j) out.ecc_deg[base + j] = static_cast<float>(b.ecc_deg[j]);
  if (out.vel_dps.size() >= n)
    for (std::size_t j = 0; j < m; ++j)
      out.vel_dps[base + j] = static_cast<float>(std::min(std::sqrt(b.vel2_dps2[j]), 3.0e38));
  if (out.angular_radius_deg.size() >= n)
    for (std::size_t j = 0; j < m; ++j) out.angular_radius_deg[base + j] = static_cast<float>(b.alpha_deg[j]);
}

// The same counts as select_kernel_levels, scalar, for a chain longer than the rows hold,
// against the thresholds phase 1 computed (its rows hold the chain's first levels).
void decide_long_chain(const detail::KernelFrame& f, const detail::KernelBlock& b, std::size_t j,
                       std::span<const float> w, const Decisions& out, std::size_t i) {
  if (b.invalid[j] > 0.5) return;  // invalid geometry: phase 2 has marked it
  const float ts = static_cast<float>(b.t_size[j]), te = static_cast<float>(b.t_ecc[j]),
              tv = static_cast<float>(b.t_vel[j]), tc = static_cast<float>(b.t_comb[j]);
  unsigned ls = 0, le = 0, lv = 0, lc = 0;
  for (std::size_t k = 1; k < w.size(); ++k) {
    const float w2 = w[k] * w[k];
    ls += w2 > ts;
    le += w2 > te;
    lv += w2 > tv;
    lc += w2 > tc;
  }
  ls = f.use_size ? ls : 0;
  le = f.use_eccentricity ? le : 0;
  lv = f.use_velocity ? lv : 0;
  const auto why = static_cast<Criterion>(limiting_criterion(lc, ls, le, lv));
  out.lod[i] = static_cast<std::uint8_t>(lc);
  out.lod_size_only[i] = static_cast<std::uint8_t>(ls);
  out.lod_eccentricity_only[i] = static_cast<std::uint8_t>(le);
  out.lod_velocity_only[i] = static_cast<std::uint8_t>(lv);
  out.limited_by[i] = static_cast<std::uint8_t>(why);
}

}  // namespace

const char* to_string(Criterion c) {
  switch (c) {
    case Criterion::none:
      return "none";
    case Criterion::size:
      return "size";
    case Criterion::eccentricity:
      return "eccentricity";
    case Criterion::velocity:
      return "velocity";
    case Criterion::combined:
      return "combined";
    case Criterion::invalid_input:
      return "invalid_input";
  }
  return "unknown";
}

std::string validate_viewer(const Viewer& v) {
  std::ostringstream m;
  if (!finite3(v.eye_position_m))
    m << "eye_position_m is not finite";
  else if (!finite3(v.eye_velocity_m_s))
    m << "eye_velocity_m_s is not finite";
  else if (!finite3(v.gaze_direction) || !(glm::length(v.gaze_direction) > 0.0))
    m << "gaze_direction must be finite and non-zero";
  else if (!finite3(v.head_angular_velocity_rad_s))
    m << "head_angular_velocity_rad_s is not finite";
  else if (!finite3(v.gaze_angular_velocity_in_head_rad_s))
    m << "gaze_angular_velocity_in_head_rad_s is not finite";
  else if (!std::isfinite(v.xi_cpd) || !(v.xi_cpd > 0.0))
    m << "xi_cpd must be finite and > 0, got " << v.xi_cpd;
  else if (!(v.tracker_error_deg >= 0.0 && v.tracker_error_deg < 90.0))
    m << "tracker_error_deg must be in [0, 90), got " << v.tracker_error_deg;
  else if (!(v.scale > 0.0 && v.scale <= 1.0))
    m << "scale must be in (0, 1], got " << v.scale;
  return m.str();
}

FrameConstants prepare_frame(const Viewer& v) {
  FrameConstants f;
  f.eye = v.eye_position_m;
  f.eye_vel = v.eye_velocity_m_s;
  f.gaze_unit = glm::normalize(v.gaze_direction);
  f.gaze_omega = v.head_angular_velocity_rad_s + v.gaze_angular_velocity_in_head_rad_s;
  f.xi_cpd = v.xi_cpd;
  f.scale = v.scale;
  f.tracker_error_rad = v.tracker_error_deg / aux::kDegPerRad;
  f.acuity_static_cpd = v.scale * std::min(kAcuityMaxCpd, v.xi_cpd);
  f.use_size = v.use_size;
  f.use_eccentricity = v.use_eccentricity;
  f.use_velocity = v.use_velocity;
  return f;
}

std::string select_lods(const Viewer& viewer, const ObjectSet& o, const Decisions& out) {
  if (std::string e = validate_viewer(viewer); !e.empty()) return "viewer: " + e;
  const std::size_t n = o.size();
  const bool moving = !o.vel_x_m_s.empty();
  if (o.center_x_m.size() != n || o.center_y_m.size() != n || o.center_z_m.size() != n || o.lod_first.size() != n ||
      o.lod_count.size() != n || o.detail_kind.size() != n ||
      (moving && (o.vel_x_m_s.size() != n || o.vel_y_m_s.size() != n || o.vel_z_m_s.size() != n)) ||
      (!moving && (!o.vel_y_m_s.empty() || !o.vel_z_m_s.empty())))
    return "objects: arrays differ in length";
  if (out.lod.size() < n || out.limited_by.size() < n || out.lod_size_only.size() < n ||
      out.lod_eccentricity_only.size() < n || out.lod_velocity_only.size() < n)
    return "decisions: an output array is shorter than the object count";
  const bool diag_e = out.ecc_deg.size() >= n, diag_v = out.vel_dps.size() >= n,
             diag_a = out.angular_radius_deg.size() >= n;

  const FrameConstants f = prepare_frame(viewer);
  detail::KernelFrame kf = kernel_frame(f);
  kf.diagnostics = diag_e || diag_v || diag_a;
  const detail::KernelInput in{o.center_x_m.data(),
                               o.center_y_m.data(),
                               o.center_z_m.data(),
                               o.radius_m.data(),
                               moving ? o.vel_x_m_s.data() : nullptr,
                               moving ? o.vel_y_m_s.data() : nullptr,
                               moving ? o.vel_z_m_s.data() : nullptr};
  const std::size_t n_weights = o.level_weight.size();
  const float* w_all = o.level_weight.data();
  const detail::ChainInput chains{o.lod_first.data(), o.lod_count.data(), o.detail_kind.data(), w_all, n_weights};
  detail::KernelBlock blk;  // about 13 KiB, reused per block
  std::uint32_t first_b[detail::kSelectBlock];
  std::uint16_t count_b[detail::kSelectBlock];  // levels in the fast path (1 = none coarser)
  std::uint16_t bad[detail::kSelectBlock], slow[detail::kSelectBlock];

  for (std::size_t base = 0; base < n; base += detail::kSelectBlock) {
    const std::size_t m = std::min(detail::kSelectBlock, n - base);
    if (base + m < n) {
      const std::size_t nb = base + m, mb = std::min(detail::kSelectBlock, n - nb);
      const std::size_t f0 = o.lod_first[nb], f1 = o.lod_first[nb + mb - 1] + o.lod_count[nb + mb - 1];
      if (f0 < f1 && f1 <= n_weights)
        for (std::size_t off = f0; off < f1; off += 16) __builtin_prefetch(w_all + off);
      // and its chain indices, which select_kernel_rows_regular reads first.
      for (std::size_t off = 0; off < mb; off += 16) __builtin_prefetch(o.lod_first.data() + nb + off);
      for (std::size_t off = 0; off < mb; off += 64) {
        __builtin_prefetch(o.lod_count.data() + nb + off);
        __builtin_prefetch(o.detail_kind.data() + nb + off);
      }
    }

    // Kinds and the chains' weights as rows: in bulk for back-to-back chains of one length,
    // else object by object. Chains out of range run with one level (no coarser level) and
    // are overwritten below; chains too long for the rows fill them with their first levels
    // (row 0 feeds the size-off floor) and are recounted below.
    std::size_t n_bad = 0, n_slow = 0;
    std::size_t rows = detail::select_kernel_rows_regular(chains, base, m, blk);
    const bool regular = rows > 0;
    rows = regular ? rows : 1;
    for (std::size_t j = 0; j < m && !regular; ++j) {
      const std::size_t i = base + j;
      const std::size_t first = o.lod_first[i], count = o.lod_count[i];
      const bool ok = count > 0 && first + count <= n_weights;  // bad geometry: phase 2
      const bool fits = count <= detail::kRowLevels + 1;
      if (!ok) [[unlikely]]
        bad[n_bad++] = static_cast<std::uint16_t>(j);
      else if (!fits) [[unlikely]]
        slow[n_slow++] = static_cast<std::uint16_t>(j);
      first_b[j] = static_cast<std::uint32_t>(first);
      count_b[j] = static_cast<std::uint16_t>(!ok ? 1 : fits ? count : detail::kRowLevels + 1);
      rows = std::max<std::size_t>(rows, count_b[j] - 1u);
      blk.kind_error[j] = o.detail_kind[i] != DetailKind::removed_cycles_per_diameter ? 1.0 : 0.0;
    }
    for (std::size_t k = 0; k < rows && !regular; ++k) {  // row k: w_{k+1}^2
      for (std::size_t j = 0; j < m; ++j) {
        const float w = k + 1 < count_b[j] ? w_all[first_b[j] + k + 1] : 0.0f;
        blk.weight[k][j] = w * w;
        if (k == 0) blk.w1_sq[j] = detail::size_off_w1_sq(w);
      }
    }
    detail::select_kernel_geometry(kf, in, base, m, blk);
    detail::select_kernel_levels(kf, m, rows, blk,
                                 {out.lod.data() + base, out.limited_by.data() + base, out.lod_size_only.data() + base,
                                  out.lod_eccentricity_only.data() + base, out.lod_velocity_only.data() + base});
    if (diag_e || diag_v || diag_a) write_diagnostics(blk, m, base, out);
    for (std::size_t t = 0; t < n_slow; ++t) {
      const std::size_t j = slow[t], i = base + j;
      decide_long_chain(kf, blk, j, {w_all + o.lod_first[i], o.lod_count[i]}, out, i);
    }
    for (std::size_t t = 0; t < n_bad; ++t) {
      const std::size_t i = base + bad[t];
      out.lod[i] = out.lod_size_only[i] = out.lod_eccentricity_only[i] = out.lod_velocity_only[i] = 0;
      out.limited_by[i] = static_cast<std::uint8_t>(Criterion::invalid_input);
      if (diag_e) out.ecc_deg[i] = 0.0f;
      if (diag_v) out.vel_dps[i] = 0.0f;
      if (diag_a) out.angular_radius_deg[i] = 0.0f;
    }
  }
  return {};
}

}  // namespace gazelod::lod
