// Per-object LOD selection over structure-of-arrays data (see select.hpp). The loop avoids
// libm: angles by fast::atan2_nonneg, G's log by fast::log10_normal (only for v > 0.825), and
// levels are compared as w_k * q > A (a multiply per level, no log or division per level).
#include "lod/select.hpp"

#include "lod/acuity.hpp"
#include "lod/fast_math.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace gazelod::lod {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

bool finite3(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// G and M as in acuity.cpp, inlined for the loop (tests check they agree).
inline double g_fast(double vel_dps, double vel_zero_dps) {
  if (!(vel_dps > kVelocitySeamDps)) return kAcuityMaxCpd;
  if (vel_dps >= vel_zero_dps) return 0.0;
  return std::clamp(kGIntercept - kGSlope * fast::log10_normal(vel_dps), 0.0, kAcuityMaxCpd);
}
inline double m_inline(double ecc_deg) {
  if (!(ecc_deg > kEccentricitySeamDeg)) return 1.0;
  const double q = kMSlope * ecc_deg + 1.0;
  return std::min(1.0, kMNumerator / (q * q));
}

}  // namespace

const char* to_string(Criterion c) {
  switch (c) {
    case Criterion::none: return "none";
    case Criterion::size: return "size";
    case Criterion::eccentricity: return "eccentricity";
    case Criterion::velocity: return "velocity";
    case Criterion::combined: return "combined";
    case Criterion::invalid_input: return "invalid_input";
  }
  return "unknown";
}

std::string validate_viewer(const Viewer& v) {
  std::ostringstream m;
  if (!finite3(v.eye_position_m)) m << "eye_position_m is not finite";
  else if (!finite3(v.eye_velocity_m_s)) m << "eye_velocity_m_s is not finite";
  else if (!finite3(v.gaze_direction) || !(glm::length(v.gaze_direction) > 0.0))
    m << "gaze_direction must be finite and non-zero";
  else if (!finite3(v.head_angular_velocity_rad_s)) m << "head_angular_velocity_rad_s is not finite";
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
  f.tracker_error_rad = v.tracker_error_deg / kDegPerRad;
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
  if (o.center_x_m.size() != n || o.center_y_m.size() != n || o.center_z_m.size() != n ||
      o.lod_first.size() != n || o.lod_count.size() != n || o.detail_kind.size() != n ||
      (moving && (o.vel_x_m_s.size() != n || o.vel_y_m_s.size() != n || o.vel_z_m_s.size() != n)) ||
      (!moving && (!o.vel_y_m_s.empty() || !o.vel_z_m_s.empty())))
    return "objects: arrays differ in length";
  if (out.lod.size() < n || out.limited_by.size() < n || out.lod_size_only.size() < n ||
      out.lod_eccentricity_only.size() < n || out.lod_velocity_only.size() < n)
    return "decisions: an output array is shorter than the object count";
  const bool diag_e = out.ecc_deg.size() >= n, diag_v = out.vel_dps.size() >= n,
             diag_a = out.angular_radius_deg.size() >= n;

  const FrameConstants f = prepare_frame(viewer);
  const double vel_zero = velocity_zero_dps();
  const double a0 = f.acuity_static_cpd;
  const double s = f.scale, xi = f.xi_cpd;
  const std::size_t n_weights = o.level_weight.size();
  const double* w_all = o.level_weight.data();

  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 c{o.center_x_m[i] - f.eye.x, o.center_y_m[i] - f.eye.y,
                       o.center_z_m[i] - f.eye.z};
    const double r = o.radius_m[i];
    const glm::dvec3 vo = moving ? glm::dvec3{o.vel_x_m_s[i], o.vel_y_m_s[i], o.vel_z_m_s[i]}
                                 : glm::dvec3{0.0};
    const std::size_t first = o.lod_first[i], count = o.lod_count[i];
    const double d2 = glm::dot(c, c);
    if (!std::isfinite(d2) || !std::isfinite(r) || r < 0.0 || !finite3(vo) || count == 0 ||
        first + count > n_weights) {
      out.lod[i] = out.lod_size_only[i] = out.lod_eccentricity_only[i] = out.lod_velocity_only[i] = 0;
      out.limited_by[i] = static_cast<std::uint8_t>(Criterion::invalid_input);
      if (diag_e) out.ecc_deg[i] = 0.0f;
      if (diag_v) out.vel_dps[i] = 0.0f;
      if (diag_a) out.angular_radius_deg[i] = 0.0f;
      continue;
    }
    const double d = std::sqrt(d2);
    const bool inside = !(d > r);
    const double alpha =
        inside ? std::numbers::pi / 2 : fast::atan2_nonneg(r, std::sqrt((d - r) * (d + r)));
    const glm::dvec3 cr = glm::cross(f.gaze_unit, c);
    const double phi = fast::atan2_nonneg(std::sqrt(glm::dot(cr, cr)), glm::dot(f.gaze_unit, c));
    const double ecc_deg = inside ? 0.0 : std::max(0.0, phi - alpha - f.tracker_error_rad) * kDegPerRad;

    double vel_dps = 0.0;
    if (d2 > 0.0) {
      const glm::dvec3 w = glm::cross(c, vo - f.eye_vel) / d2 - f.gaze_omega;
      const glm::dvec3 t = glm::cross(w, c);
      vel_dps = std::sqrt(glm::dot(t, t)) / d * kDegPerRad;
      if (!(vel_dps >= 0.0)) vel_dps = 0.0;  // overflow to NaN: keep detail
    }
    const double g = f.use_velocity ? g_fast(vel_dps, vel_zero) : kAcuityMaxCpd;
    const double m = f.use_eccentricity ? m_inline(ecc_deg) : 1.0;

    // Frequency per unit weight: f_k = w_k * q.
    const double alpha_deg = alpha * kDegPerRad;
    const double q = o.detail_kind[i] == DetailKind::removed_cycles_per_diameter
                         ? 0.5 / alpha_deg
                         : d * (std::numbers::pi / 360.0);
    const double* w = w_all + first;
    const double w1 = count > 1 ? w[1] : 0.0;
    // Size switched off: no smaller than where level 1 sits at the static limit. The factor
    // keeps w1 * cap <= a0 despite rounding, so size-off never drops level 1 on its own.
    const double q_off = w1 > 0.0 ? std::min(q, a0 / w1 * (1.0 - 1e-15)) : q;
    const double q_comb = f.use_size ? q : q_off;
    const double a_e = s * std::min(kAcuityMaxCpd * m, xi);
    const double a_v = s * std::min(g, xi);
    const double a_c = s * std::min(g * m, xi);

    unsigned ls = 0, le = 0, lv = 0, lc = 0;
    for (std::size_t k = 1; k < count; ++k) {
      ls += w[k] * q > a0;
      le += w[k] * q_off > a_e;
      lv += w[k] * q_off > a_v;
      lc += w[k] * q_comb > a_c;
    }
    if (!f.use_size) ls = 0;
    if (!f.use_eccentricity) le = 0;
    if (!f.use_velocity) lv = 0;
    Criterion why = Criterion::combined;
    if (lc == 0) why = Criterion::none;
    else if (f.use_size && lc == ls) why = Criterion::size;
    else if (f.use_eccentricity && lc == le) why = Criterion::eccentricity;
    else if (f.use_velocity && lc == lv) why = Criterion::velocity;

    out.lod[i] = static_cast<std::uint8_t>(lc);
    out.lod_size_only[i] = static_cast<std::uint8_t>(ls);
    out.lod_eccentricity_only[i] = static_cast<std::uint8_t>(le);
    out.lod_velocity_only[i] = static_cast<std::uint8_t>(lv);
    out.limited_by[i] = static_cast<std::uint8_t>(why);
    if (diag_e) out.ecc_deg[i] = static_cast<float>(ecc_deg);
    if (diag_v) out.vel_dps[i] = static_cast<float>(std::min(vel_dps, 3.0e38));
    if (diag_a) out.angular_radius_deg[i] = static_cast<float>(alpha_deg);
  }
  return {};
}

}  // namespace gazelod::lod
