#include "gaze/gaze_predictor.hpp"

#include "gaze/angles.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::gaze {

void GazePredictor::push(const GazeSample& sample) {
  if (!sample.valid || (!recent_.empty() && sample.t_ns <= recent_.back().t_ns) ||
      (!recent_.empty() && sample.t_ns - recent_.back().t_ns > options_.max_gap_ns)) {
    recent_.clear();
  }
  if (!sample.valid) return;
  GazeSample s = sample;
  s.direction = glm::normalize(s.direction);
  recent_.push_back(s);
  while (recent_.size() > std::max<std::size_t>(options_.window, 2)) recent_.pop_front();
}

std::optional<glm::dvec3> GazePredictor::velocity_axis_rad_s() const {
  if (recent_.size() < 2) return std::nullopt;
  const GazeSample& c = recent_.back();
  glm::dvec3 e1, e2;
  tangent_basis(c.direction, e1, e2);
  double st = 0, sx = 0, sy = 0, stt = 0, stx = 0, sty = 0;
  const double n = static_cast<double>(recent_.size());
  for (const GazeSample& g : recent_) {
    const double t = static_cast<double>(g.t_ns - c.t_ns) * 1e-9;
    const glm::dvec2 a = angular_offset_rad(g.direction, c.direction, e1, e2);
    st += t; sx += a.x; sy += a.y; stt += t * t; stx += t * a.x; sty += t * a.y;
  }
  const double denom = n * stt - st * st;
  if (!(denom > 1e-18)) return std::nullopt;
  const double vx = (n * stx - st * sx) / denom, vy = (n * sty - st * sy) / denom;
  // The tangent-plane velocity (rad/s along e1, e2) as a 3D tangent vector at c.
  return e1 * vx + e2 * vy;
}

double GazePredictor::speed_deg_s() const {
  const auto v = velocity_axis_rad_s();
  return v ? glm::length(*v) * kDegPerRad : 0.0;
}

std::optional<Prediction> GazePredictor::predict(std::int64_t display_t_ns) const {
  if (recent_.empty()) return std::nullopt;
  const GazeSample& newest = recent_.back();
  Prediction p;
  p.horizon_ns = std::max<std::int64_t>(0, display_t_ns - newest.t_ns);
  p.clamped = p.horizon_ns > options_.max_horizon_ns;
  const double h_s = static_cast<double>(p.horizon_ns) * 1e-9;
  const double h_used_s = static_cast<double>(std::min(p.horizon_ns, options_.max_horizon_ns)) * 1e-9;
  const auto v = velocity_axis_rad_s();
  const double speed_deg_s = v ? glm::length(*v) * kDegPerRad : 0.0;
  p.in_saccade = speed_deg_s > options_.saccade_threshold_deg_s;
  p.sample = newest;
  p.sample.t_ns = display_t_ns;
  if (v && !p.in_saccade && speed_deg_s > 0.0) {
    // Rotate along the great circle in the direction of the tangent velocity.
    const double angle = glm::length(*v) * h_used_s;
    const glm::dvec3 u = *v / glm::length(*v);
    p.sample.direction = newest.direction * std::cos(angle) + u * std::sin(angle);
  }
  double unc = options_.accuracy_deg +
               (options_.drift_deg_s + options_.velocity_error_fraction * speed_deg_s) * h_s;
  if (p.in_saccade) unc += speed_deg_s * h_s;
  p.uncertainty_deg = std::clamp(unc, 0.0, options_.max_uncertainty_deg);
  return p;
}

}  // namespace gazelod::gaze
