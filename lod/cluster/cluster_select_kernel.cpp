// SPDX-License-Identifier: Apache-2.0
// The per-cluster kernel (see cluster_select_kernel.hpp): straight-line float arithmetic per
// record so that GCC vectorises the loop, in the conventions of lod/select_kernel.cpp (every
// "if" a ternary, '&' and '|' on same-width masks, 0/1 factors for loop-invariant switches,
// invalid records computed and blended away at the end).
//
// Error bounds behind the slacks (eps = 2^-24): c - eye is formed against the eye as a float
// pair, so each component of r is within 2 eps of exact, |r|^2 within 7 eps and d within
// 5 eps: kDistanceLow (2^-20 = 16 eps) and the "inside" test on |r|^2 lowered by 2^-19 (32
// eps, covering r^2 and the subtraction's rounding) keep the nearest point and the tangent
// length h below exact, so alpha is above it and E below. The rotated pair (sin, cos) of
// phi - alpha has length |r| sqrt(|r|^2 - 32 eps ...) and is normalised by |r|^2 (1 - 2^-20):
// a mismatch of a few eps, at most pi times that in angle; with the atan's 3e-8 (doubled by
// the half angle) and rounding the angle is within about 1e-6 rad: kEccentricitySlackRad is
// 4e-6. The retinal velocity's terms are each within ~25 eps (1.5e-6) of |V|/d + |w|:
// kVelocitySlack is 1e-5 of that sum. log10 within 5e-7 moves G by 1.4e-5: kGSlackCpd 1e-4.
// The threshold products round a few eps apiece (and the constants 7.49, 0.3 by one):
// kThresholdMargin is 2^-16. tests/lod/cluster_select_test.cpp checks the kernel against the
// exact rule in double, never coarser, on random and adversarial records.
#include "lod/cluster/cluster_select_kernel.hpp"

#include "lod/acuity.hpp"
#include "auxiliary/angles.hpp"
#include "lod/cluster/cluster_select_math.hpp"
#include "lod/criterion.hpp"
#include "lod/select_kernel.hpp"  // GAZELOD_IVDEP

#include <algorithm>
#include <cmath>
#include <limits>

namespace gazelod::lod::detail {
namespace {

constexpr float kDegPerRadF = static_cast<float>(aux::kDegPerRad);
constexpr float kD2Low = 1.0f - 0x1p-19f;    // |r|^2 lowered for "inside" and h
constexpr float kNormLow = 1.0f - 0x1p-20f;  // the rotated pair's length over |r|^2
constexpr float kSeamF = static_cast<float>(kVelocitySeamDps);
constexpr float kCapF = 200.0f;  // v clamped here before the log (G is 0 from 119.3 on)
constexpr float kGInterceptF = static_cast<float>(kGIntercept) + kGSlackCpd;
constexpr float kGSlopeF = static_cast<float>(kGSlope);
constexpr float kMaxCpdF = static_cast<float>(kAcuityMaxCpd);
constexpr float kEccSeamF = static_cast<float>(kEccentricitySeamDeg);
constexpr float kMSlopeF = static_cast<float>(kMSlope);
constexpr float kMNumeratorF = static_cast<float>(kMNumerator);

// What the loops share, so that each computes it bit for bit alike (the screen's decisions
// must equal the full evaluation's): the eye-relative centre, validity, and the nearest-point
// distance rounded down (at the floor, or inside, the record is "near").
struct Geometry {
  float rx, ry, rz, d2, d, dn;
  bool ok, near;
};
[[gnu::always_inline]] inline Geometry geometry(const ClusterFrame& f, float cx, float cy, float cz, float rho,
                                                float e) {
  Geometry g;
  g.rx = (cx - f.eye_hi_m[0]) - f.eye_lo_m[0];
  g.ry = (cy - f.eye_hi_m[1]) - f.eye_lo_m[1];
  g.rz = (cz - f.eye_hi_m[2]) - f.eye_lo_m[2];
  // x * 0 is NaN exactly when x is not finite: one comparison checks the centre and radius.
  g.ok = ((cx + cy + cz + rho) * 0.0f == 0.0f) & (rho >= 0.0f) & (e >= 0.0f);
  g.d2 = g.rx * g.rx + g.ry * g.ry + g.rz * g.rz;
  g.d = std::sqrt(g.d2);
  const float dn_raw = g.d * kDistanceLow - rho;
  g.near = !(dn_raw > kNearFloorM);
  g.dn = g.near ? kNearFloorM : dn_raw;
  return g;
}

// Size alone lets the error go (a0 e K < d, a0 = +inf with size off): then so does the
// combined rule (A <= a0), which therefore includes this very comparison.
// The error factor is the mesh's (ClusterMeshFrame::error_factor: the frame's, divided by the
// mesh's detail scale), so that a budget's coarser step scales every error of the mesh alike.
[[gnu::always_inline]] inline bool by_size(const ClusterFrame& f, float error_factor, float e, float dn) {
  return f.static_limit_cpd * (e * error_factor) < dn;
}

// The screen (RecordScreen::trivial or by_size, cluster_select_kernel.hpp): every record whose
// decisions need no eccentricity or velocity is decided here; the rest are flagged for the full
// evaluation below. Trivial ones (invalid, error 0 or +inf) get every output as the full path
// gives it. Where size decides (kBySize), the eccentricity-alone and velocity-alone outputs are
// set only for an error of 0 (invisible under any criterion): the limiting criterion is size
// there whatever they would be, so they are not computed.
template <bool kAll, bool kBySize>
[[gnu::always_inline]] inline void screen_loop(const ClusterFrame& f, const ClusterMeshFrame& m, const RecordInput& in,
                                               std::size_t begin, std::size_t count, RecordBlock& out) {
  const float* __restrict cx = in.center_x_m + begin;
  const float* __restrict cy = in.center_y_m + begin;
  const float* __restrict cz = in.center_z_m + begin;
  const float* __restrict rad = in.radius_m + begin;
  const float* __restrict err = in.error_m + begin;
  constexpr float kInfF = std::numeric_limits<float>::infinity();
  const float k_err = m.error_factor;
  GAZELOD_IVDEP  // no overlap (select_kernel.hpp)
      for (std::size_t i = 0; i < count; ++i) {
    const float e = err[i];
    const Geometry g = geometry(f, cx[i], cy[i], cz[i], rad[i], e);
    const bool zero = e == 0.0f, never = e == kInfF, size_ok = kBySize && by_size(f, k_err, e, g.dn);
    const bool decided = !g.ok | zero | never | size_ok;
    const bool invisible = g.ok & (zero | size_ok);
    out.combined[i] = invisible ? 1.0f : 0.0f;
    out.invalid[i] = g.ok ? 0.0f : 1.0f;
    out.pending[i] = decided ? 0 : 1;
    if constexpr (kAll) {
      const float zf = (g.ok & zero) ? 1.0f : 0.0f;
      out.size[i] = invisible ? 1.0f : 0.0f;
      out.eccentricity[i] = zf;  // as the full path: an error of 0 goes under any criterion
      out.velocity[i] = zf;
      out.positive[i] = e > 0.0f ? 1.0f : 0.0f;
    }
  }
}

// The full evaluation, first loop: eccentricity and retinal velocity (split from the acuity
// and thresholds so that neither loop runs out of registers). Input [begin, begin + count),
// output [at, at + count).
[[gnu::always_inline]] inline void geometry_loop(const ClusterFrame& f, const ClusterMeshFrame& m,
                                                 const RecordInput& in, std::size_t begin, std::size_t at,
                                                 std::size_t count, RecordBlock& out) {
  const float* __restrict cx = in.center_x_m + begin;
  const float* __restrict cy = in.center_y_m + begin;
  const float* __restrict cz = in.center_z_m + begin;
  const float* __restrict rad = in.radius_m + begin;
  const float* __restrict err = in.error_m + begin;
  float* __restrict near_m = out.near_m + at;
  float* __restrict ecc_out = out.ecc_deg + at;
  float* __restrict vel_out = out.vel_dps + at;
  float* __restrict invalid = out.invalid + at;
  const float gx = f.gaze_unit[0], gy = f.gaze_unit[1], gz = f.gaze_unit[2];
  const float ox = f.gaze_omega_rad_s[0], oy = f.gaze_omega_rad_s[1], oz = f.gaze_omega_rad_s[2];
  const float w_norm = f.gaze_omega_norm_rad_s;
  const float vx = m.rel_vel_m_s[0], vy = m.rel_vel_m_s[1], vz = m.rel_vel_m_s[2];
  const float v_norm = m.rel_speed_m_s;
  const float ecc_off = f.ecc_offset_rad;
  // The velocity slack's coefficients (cluster_select_kernel.hpp): v - kVelocitySlack (|V|/dn +
  // |w|) - (1 + kVelocitySlack) rho (2 |V| / dn + |w|) / dn.
  const float lip_v = 2.0f * (1.0f + kVelocitySlack) * v_norm;
  const float lip_w = (1.0f + kVelocitySlack) * w_norm;
  const float slack_v = kVelocitySlack * v_norm, slack_w = kVelocitySlack * w_norm;

  GAZELOD_IVDEP
  for (std::size_t i = 0; i < count; ++i) {
    const float rho = rad[i];
    const Geometry g = geometry(f, cx[i], cy[i], cz[i], rho, err[i]);
    const float rx = g.rx, ry = g.ry, rz = g.rz, d2 = g.d2, d = g.d, dn = g.dn;

    // Eccentricity of the nearest point, as select_kernel.cpp: phi - alpha by one atan2 of the
    // rotated pair (sp h - cp rho, cp h + sp rho), h the tangent length rounded down.
    const float d2_low = d2 * kD2Low, rho2 = rho * rho;
    const bool inside = !(d2_low > rho2);
    const float h = std::sqrt(inside ? 0.0f : d2_low - rho2);
    const float kx = gy * rz - gz * ry, ky = gz * rx - gx * rz, kz = gx * ry - gy * rx;
    const float sp = std::sqrt(kx * kx + ky * ky + kz * kz);
    const float cp = gx * rx + gy * ry + gz * rz;
    const float sin_e = sp * h - cp * rho, cos_e = cp * h + sp * rho;
    const float ecc_rad = fastf::atan2_with_norm(sin_e, cos_e, d2 * kNormLow) - ecc_off;
    const bool eccentric = !inside & (sin_e >= 0.0f) & (ecc_rad > 0.0f);

    // Retinal velocity at the centre (select_kernel.cpp's form), lowered to the sphere's
    // slowest point and by the rounding slack. One division for 1/d and 1/dn.
    const float d_safe = d > kNearFloorM ? d : kNearFloorM;
    const float inv_ddn = 1.0f / (d_safe * dn);
    const float inv_d = dn * inv_ddn, inv_dn = d_safe * inv_ddn;
    const float inv_d2 = inv_d * inv_d;
    const float wx = (ry * vz - rz * vy) * inv_d2 - ox;
    const float wy = (rz * vx - rx * vz) * inv_d2 - oy;
    const float wz = (rx * vy - ry * vx) * inv_d2 - oz;
    const float tx = wy * rz - wz * ry, ty = wz * rx - wx * rz, tz = wx * ry - wy * rx;
    const float v_c = std::sqrt(tx * tx + ty * ty + tz * tz) * inv_d;
    // (The slack over dn, not d: a function of dn and rho only, like the bound, so that a
    // containing sphere's is never smaller: the lowering keeps the records' nesting.)
    const float v_slack = (slack_v * inv_dn + slack_w) + rho * inv_dn * (lip_v * inv_dn + lip_w);
    const float v_lo = v_c - v_slack;

    near_m[i] = dn;
    ecc_out[i] = eccentric ? ecc_rad * kDegPerRadF : 0.0f;
    vel_out[i] = (!g.near & (v_lo > 0.0f)) ? v_lo * kDegPerRadF : 0.0f;  // NaN: 0
    invalid[i] = g.ok ? 0.0f : 1.0f;
  }
}

// The full evaluation, second loop: G, M and the decisions.
template <bool kAll>
[[gnu::always_inline]] inline void decision_loop(const ClusterFrame& f, const ClusterMeshFrame& m,
                                                 const RecordInput& in, std::size_t begin, std::size_t at,
                                                 std::size_t count, RecordBlock& out) {
  const float* __restrict err = in.error_m + begin;
  const float on_e = f.on_eccentricity, on_v = f.on_velocity;
  const float s = f.scale, s_xi = f.scale_xi_cpd, k_err = m.error_factor;
  // s 60 rounded as s G is (G <= 60): then each criterion alone letting an error go implies the
  // combined rule does, exactly, as it does exactly.
  const float s_60 = s * kMaxCpdF;
  const float cap = m.cap_m, cap_c = m.cap_combined_m;
  GAZELOD_IVDEP
  for (std::size_t j = at; j < at + count; ++j) {
    const float e = err[j - at];
    const float dn = out.near_m[j], ecc_deg = out.ecc_deg[j], v_deg = out.vel_dps[j];
    const bool ok = out.invalid[j] < 0.5f;

    // G(v), raised by its slack; switched off: v = 0, G = 60.
    const float v_clamped = std::min(std::max(v_deg, kSeamF), kCapF);
    const float g_log = kGInterceptF - kGSlopeF * fastf::log10_normal(v_clamped);
    const float g_clamped = std::min(std::max(g_log, 0.0f), kMaxCpdF);
    const float g = v_deg * on_v > kSeamF ? g_clamped : kMaxCpdF;

    // M(E) enters as a comparison: min(1, 7.49 / q^2) x < dist <=> x < dist or 7.49 x < dist
    // q^2 (beyond the seam), so no division. Switched off: E = 0, M = 1.
    const float ecc_on = ecc_deg * on_e;
    const bool beyond = ecc_on > kEccSeamF;
    const float mq = kMSlopeF * ecc_on + 1.0f;
    const float mq2 = mq * mq;

    // Invisible when A e K < dist (f > A): each min() of A as an "or". e = +inf gives +inf or
    // NaN (0 inf): visible.
    const float b = e * k_err;
    const float x_xi = s_xi * b, x_g = (s * g) * b;
    const float dist_c = dn < cap_c ? dn : cap_c;
    const bool size_ok = by_size(f, k_err, e, dn), zero = e == 0.0f;  // 0 goes even at a 0 cap
    const bool comb =
        size_ok | zero | (x_xi < dist_c) | (x_g < dist_c) | (beyond & (kMNumeratorF * x_g < dist_c * mq2));
    out.combined[j] = (ok & comb) ? 1.0f : 0.0f;
    if constexpr (kAll) {
      // Each criterion alone (the others off; size off: the mesh's cap), a switched-off one
      // only an error of 0.
      const float dist_o = dn < cap ? dn : cap;
      const float x_60 = s_60 * b;  // as x_g with G = 60
      const bool by_ecc = (x_xi < dist_o) | (x_60 < dist_o) | (beyond & (kMNumeratorF * x_60 < dist_o * mq2));
      const bool by_vel = (x_xi < dist_o) | (x_g < dist_o);
      const float zf = zero ? 1.0f : 0.0f;
      const float fe = by_ecc ? on_e : 0.0f, fv = by_vel ? on_v : 0.0f;
      out.size[j] = (ok & (size_ok | zero)) ? 1.0f : 0.0f;
      out.eccentricity[j] = ok ? std::max(fe, zf) : 0.0f;
      out.velocity[j] = ok ? std::max(fv, zf) : 0.0f;
      out.positive[j] = e > 0.0f ? 1.0f : 0.0f;
    }
  }
}

// Inlined into each clone of evaluate_records (an out-of-line helper would be compiled for the
// baseline ISA only). With the screen, the records it leaves pending are gathered into
// contiguous arrays, fully evaluated there and scattered back: the same arithmetic on the same
// values, so the decisions do not depend on where a record sits. Where most are pending, the
// whole block is evaluated in place instead (cheaper than gathering).
template <bool kAll>
[[gnu::always_inline]] inline void evaluate(const ClusterFrame& f, const ClusterMeshFrame& m, const RecordInput& in,
                                            std::size_t begin, std::size_t count, RecordScreen how,
                                            const float* implied, RecordBlock& out) {
  const bool screen = how != RecordScreen::none;
  if (how == RecordScreen::by_size) screen_loop<kAll, true>(f, m, in, begin, count, out);
  if (how == RecordScreen::trivial) screen_loop<kAll, false>(f, m, in, begin, count, out);
  // A record implied invisible is left out of the full evaluation (and set below, after it).
  const bool imply = screen && implied != nullptr;
  if (imply) {
    GAZELOD_IVDEP
    for (std::size_t j = 0; j < count; ++j) out.pending[j] = implied[j] > 0.5f ? 0 : out.pending[j];
  }
  std::uint16_t list[kClusterBlock];
  std::size_t n = 0;
  // Compaction, 8 flags at a time: an octet with none pending (the common case) is skipped
  // with one test, the others by a branch-free append.
  for (std::size_t j = count; j < (count + 7) / 8 * 8; ++j) out.pending[j] = 0;
  for (std::size_t j = 0; screen && j < count; j += 8) {
    std::int32_t any = 0;
    for (std::size_t k = 0; k < 8; ++k) any |= out.pending[j + k];
    if (any == 0) continue;
    for (std::size_t k = j; k < j + 8; ++k) {
      list[n] = static_cast<std::uint16_t>(k);
      n += static_cast<std::size_t>(out.pending[k]);
    }
  }
  if (!screen || 2 * n > count) {
    geometry_loop(f, m, in, begin, 0, count, out);
    decision_loop<kAll>(f, m, in, begin, 0, count, out);
  } else if (n > 0) {
    float cx[kClusterBlock], cy[kClusterBlock], cz[kClusterBlock], r[kClusterBlock], e[kClusterBlock];
    for (std::size_t t = 0; t < n; ++t) {
      const std::size_t i = begin + list[t];
      cx[t] = in.center_x_m[i], cy[t] = in.center_y_m[i], cz[t] = in.center_z_m[i];
      r[t] = in.radius_m[i], e[t] = in.error_m[i];
    }
    const RecordInput packed{cx, cy, cz, r, e};
    RecordBlock tmp;
    geometry_loop(f, m, packed, 0, 0, n, tmp);
    decision_loop<kAll>(f, m, packed, 0, 0, n, tmp);
    for (std::size_t t = 0; t < n; ++t) {
      const std::size_t j = list[t];
      out.combined[j] = tmp.combined[t], out.invalid[j] = tmp.invalid[t];
      if constexpr (kAll) {
        out.size[j] = tmp.size[t], out.eccentricity[j] = tmp.eccentricity[t];
        out.velocity[j] = tmp.velocity[t], out.positive[j] = tmp.positive[t];
      }
    }
  }
  if (imply) {  // whichever path ran: a valid record implied invisible is invisible
    GAZELOD_IVDEP
    for (std::size_t j = 0; j < count; ++j)
      out.combined[j] = ((implied[j] > 0.5f) & (out.invalid[j] < 0.5f)) ? 1.0f : out.combined[j];
  }
}

}  // namespace

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GAZELOD_NO_CLONES)
__attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif
void evaluate_records(const ClusterFrame& frame, const ClusterMeshFrame& mesh,
                      const RecordInput& in, std::size_t begin, std::size_t count,
                      bool all_criteria, RecordScreen screen, const float* implied_invisible,
                      RecordBlock& out) {
  if (all_criteria)
    evaluate<true>(frame, mesh, in, begin, count, screen, implied_invisible, out);
  else
    evaluate<false>(frame, mesh, in, begin, count, screen, implied_invisible, out);
}

}  // namespace gazelod::lod::detail
