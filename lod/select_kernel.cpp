// SPDX-License-Identifier: Apache-2.0
// Phase 1 of the selection (see select_kernel.hpp): straight-line, branch-free arithmetic per
// object so that GCC vectorises the loop (check with -fopt-info-vec). Conventions:
//   - every "if" is a ternary (a blend), every helper is inlined (fast_math.hpp);
//   - invalid objects are not skipped: their NaNs flow through and are replaced at the
//     end by +inf thresholds (no level) and the invalid flag;
//   - '&' and '|' instead of '&&' and '||', 0/1 factors instead of bool blends on
//     loop-invariant flags, no byte-wide data (each of these stops GCC 12 vectorising);
//   - few divisions and square roots (per object: 5 divisions, 3 roots, on a unit of their
//     own): one reciprocal 1 / d^2 is reused, d and v stay squared, the eccentricity
//     phi - alpha is a single atan2 of the rotated (cos, sin) pair, and the levels compare
//     squares against A^2 p^2 instead of dividing.
#include "auxiliary/angles.hpp"
#include "lod/select_kernel.hpp"

#include "lod/acuity.hpp"
#include "lod/fast_math.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gazelod::lod::detail {
namespace {

constexpr double kMaxFinite = std::numeric_limits<double>::max();
constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

// The loop, twice: with the diagnostics (E, v^2, alpha) stored, and without (fewer blends
// and stores, for callers that ask only for decisions).
template <bool kDiagnostics, bool kUseSize>
[[gnu::always_inline]] inline void geometry_loop(const KernelFrame& f, const KernelInput& in, std::size_t begin,
                                                 std::size_t count, KernelBlock& out) {
  const double* __restrict cx = in.center_x_m + begin;
  const double* __restrict cy = in.center_y_m + begin;
  const double* __restrict cz = in.center_z_m + begin;
  const double* __restrict rad = in.radius_m + begin;
  // Static objects read a block of zeros: the loads stay unconditional (a conditional load
  // or a blend on a loop-invariant flag blocks if-conversion, and with it vectorisation).
  static constexpr double kZeros[kSelectBlock] = {};
  const bool moving = in.vel_x_m_s != nullptr;
  const double* __restrict vx = moving ? in.vel_x_m_s + begin : kZeros;
  const double* __restrict vy = moving ? in.vel_y_m_s + begin : kZeros;
  const double* __restrict vz = moving ? in.vel_z_m_s + begin : kZeros;

  const double ex = f.eye_m[0], ey = f.eye_m[1], ez = f.eye_m[2];
  const double evx = f.eye_vel_m_s[0], evy = f.eye_vel_m_s[1], evz = f.eye_vel_m_s[2];
  const double gx = f.gaze_unit[0], gy = f.gaze_unit[1], gz = f.gaze_unit[2];
  const double ox = f.gaze_omega_rad_s[0], oy = f.gaze_omega_rad_s[1], oz = f.gaze_omega_rad_s[2];
  const double err = f.tracker_error_rad;
  // Switches as 0/1 factors, not bool blends: a loop-invariant bool mixed with the
  // double-width masks is a mask conversion GCC 12 does not vectorise.
  const double on_e = f.use_eccentricity ? 1.0 : 0.0, on_v = f.use_velocity ? 1.0 : 0.0;
  const double a0 = f.acuity_static_cpd, s = f.scale, xi = f.xi_cpd, a0_2 = a0 * a0;
  // Size switched off: p^2 >= w_1^2 floor2_per_w2 (kSizeOffMargin, select_kernel.hpp).
  const double floor_per_w = kSizeOffMargin / a0;  // a0 > 0 for a valid Viewer
  const double floor2_per_w2 = floor_per_w * floor_per_w;

  GAZELOD_IVDEP  // no overlap (select_kernel.hpp)
      for (std::size_t i = 0; i < count; ++i) {
    const double c_x = cx[i] - ex, c_y = cy[i] - ey, c_z = cz[i] - ez;
    const double r = rad[i];
    const double ovx = vx[i], ovy = vy[i], ovz = vz[i];
    const double d2 = c_x * c_x + c_y * c_y + c_z * c_z;
    // '&' and '|', never '&&' / '||': a short circuit is a branch (or a bool phi GCC 12
    // cannot vectorise).
    // x * 0 is NaN exactly when x is not finite, so one comparison checks all three velocity
    // components (and the radius) at once.
    const bool ok = (d2 <= kMaxFinite) & (r >= 0.0) & (r * 0.0 + ovx * 0.0 + ovy * 0.0 + ovz * 0.0 == 0.0);
    const double r2 = r * r;
    const bool inside = !(d2 > r2);

    // Angular radius alpha = atan2(r, h), h = sqrt(d^2 - r^2) (by an FMA, as exact as
    // (d-r)(d+r)), by the half-angle form with the length d: 2 atan(r / (d + h)), a ratio in
    // [0, 1] (fast_math.hpp).
    const double h = std::sqrt(inside ? 0.0 : d2 - r2);
    const double d = std::sqrt(d2);
    const double alpha = inside ? std::numbers::pi / 2 : 2.0 * fast::atan_unit_ratio(r, d + h);

    // Gaze-to-centre angle phi: sin phi = |g x c| / d, cos phi = g.c / d. With sin alpha =
    // r / d and cos alpha = h / d, phi - alpha = atan2(sp h - cp r, cp h + sp r) (all times
    // d^2, so the pair's length is d^2): one atan2, still exact for tiny angles. Negative
    // sine: the gaze ray passes through the sphere (E = 0); sine 0 with a negative cosine is
    // a point straight behind the eye (pi).
    const double kx = gy * c_z - gz * c_y, ky = gz * c_x - gx * c_z, kz = gx * c_y - gy * c_x;
    const double sp = std::sqrt(kx * kx + ky * ky + kz * kz);
    const double cp = gx * c_x + gy * c_y + gz * c_z;
    const double sin_e = sp * h - cp * r, cos_e = cp * h + sp * r;
    const double ecc_rad = sin_e >= 0.0 ? fast::atan2_with_norm(sin_e, cos_e, d2) - err : 0.0;
    const double ecc_deg = (!inside & (ecc_rad > 0.0)) ? ecc_rad * aux::kDegPerRad : 0.0;

    // Retinal velocity: w = c x (v_obj - v_eye) / d^2 - w_gaze, speed^2 = |w x c|^2 / d^2
    // (squared: G needs only its log, and the comparisons work on v^2; no sqrt).
    const double inv_d2 = 1.0 / d2;
    const double rx = ovx - evx, ry = ovy - evy, rz = ovz - evz;
    const double wx = (c_y * rz - c_z * ry) * inv_d2 - ox;
    const double wy = (c_z * rx - c_x * rz) * inv_d2 - oy;
    const double wz = (c_x * ry - c_y * rx) * inv_d2 - oz;
    const double tx = wy * c_z - wz * c_y, ty = wz * c_x - wx * c_z, tz = wx * c_y - wy * c_x;
    const double vel2_raw = (tx * tx + ty * ty + tz * tz) * inv_d2 * (aux::kDegPerRad * aux::kDegPerRad);
    // d = 0 or overflow gives NaN: 0 keeps detail (as the scalar criteria do at r = 0).
    const double vel2 = vel2_raw >= 0.0 ? vel2_raw : 0.0;
    // The level's detail seen from the sphere's nearest point (lod/lod_chain.hpp): its size per
    // unit weight (r for removed cycles per diameter, 1 m for a geometric error) over the
    // nearest point's distance, squared.
    const double d_near_raw = d - r;
    const double d_near = d_near_raw > kNearestPointFloorM ? d_near_raw : kNearestPointFloorM;
    const double size_per_weight = out.kind_error[i] > 0.5 ? 1.0 : r;
    out.ecc_deg[i] = ecc_deg;
    out.vel2_dps2[i] = vel2;
    out.alpha_deg[i] = alpha * aux::kDegPerRad;
    out.near_ratio_sq[i] = (size_per_weight * size_per_weight) / (d_near * d_near);
    out.invalid[i] = ok ? 0.0 : 1.0;
  }

  // Second loop: the acuity terms and thresholds (split so that neither loop runs out of
  // vector registers).
  GAZELOD_IVDEP
  for (std::size_t i = 0; i < count; ++i) {
    const double ecc_deg = out.ecc_deg[i], vel2 = out.vel2_dps2[i], alpha_deg = out.alpha_deg[i];
    const double near_ratio_sq = out.near_ratio_sq[i];
    const bool ok = out.invalid[i] < 0.5;

    // G(v) on v^2 clamped into the log branch's range (log10 v = log10(v^2) / 2) and into
    // [0, 60] (0 from v0 = velocity_zero_dps() on, where the log branch crosses 0), then the
    // flat piece below the seam by a blend. Switched off: v = 0 (Reddy 1998 section 6), G = 60.
    constexpr double kSeam2 = kVelocitySeamDps * kVelocitySeamDps, kCap2 = 200.0 * 200.0;
    const double vel2_on = vel2 * on_v;  // NaN for inf * 0: the blend below gives 60
    const double v2_log = std::min(std::max(vel2, kSeam2), kCap2);
    const double g_log = kGIntercept - (0.5 * kGSlope) * fast::log10_normal(v2_log);
    const double g_clamped = std::min(std::max(g_log, 0.0), kAcuityMaxCpd);
    const double g = vel2_on > kSeam2 ? g_clamped : kAcuityMaxCpd;

    // M(E) = min(1, 7.49 / (0.3 E + 1)^2) beyond the seam (acuity.hpp).
    const double ecc_on = ecc_deg * on_e;  // switched off: E = 0, so M = 1
    const double mq = kMSlope * ecc_on + 1.0;
    const double m_branch = kMNumerator / (mq * mq);
    const double m_min = m_branch < 1.0 ? m_branch : 1.0;
    const double m = ecc_on > kEccentricitySeamDeg ? m_min : 1.0;

    // The threshold factor p^2 (select_kernel.hpp); +inf for an invalid object, so that no
    // level passes. Inside the sphere d_near is the floor: p^2 about 1e17 r^2, no level.
    constexpr double kErrFactor = 360.0 / std::numbers::pi;
    const double p2 = ok ? (kErrFactor * kErrFactor) * near_ratio_sq : kInf;
    // Size switched off: p no smaller than where level 1 sits at the static limit a0.
    const double p2_floor = out.w1_sq[i] * floor2_per_w2;
    const double p2_off = p2 > p2_floor ? p2 : p2_floor;
    const double gm = g * m, em = kAcuityMaxCpd * m;
    const double av = s * (g < xi ? g : xi);
    const double ae = s * (em < xi ? em : xi);
    const double ac = s * (gm < xi ? gm : xi);
    // +inf stays +inf, and A = 0 with p = +inf gives NaN: no level either way.
    out.t_size[i] = a0_2 * p2;
    out.t_ecc[i] = ae * ae * p2_off;
    out.t_vel[i] = av * av * p2_off;
    out.t_comb[i] = ac * ac * (kUseSize ? p2 : p2_off);
    if constexpr (kDiagnostics) {
      out.ecc_deg[i] = ok ? ecc_deg : 0.0;
      out.vel2_dps2[i] = ok ? vel2 : 0.0;
      out.alpha_deg[i] = ok ? alpha_deg : 0.0;
    }
  }
}

// The clones: baseline x86-64 (SSE2) for any CPU, x86-64-v3 (AVX2, FMA) and x86-64-v4
// (AVX-512) where present. Dispatch happens once, at load time, through an ifunc (glibc).
// -DGAZELOD_NO_CLONES builds the baseline only (to test it on a machine with AVX).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GAZELOD_NO_CLONES)
__attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif
void select_kernel_geometry(const KernelFrame& f, const KernelInput& in, std::size_t begin,
                            std::size_t count, KernelBlock& out) {
  if (f.diagnostics) {
    if (f.use_size)
      geometry_loop<true, true>(f, in, begin, count, out);
    else
      geometry_loop<true, false>(f, in, begin, count, out);
  } else {
    if (f.use_size)
      geometry_loop<false, true>(f, in, begin, count, out);
    else
      geometry_loop<false, false>(f, in, begin, count, out);
  }
}

}  // namespace gazelod::lod::detail
