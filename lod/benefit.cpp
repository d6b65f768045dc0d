#include "lod/benefit.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::lod {

namespace {
double finite_or(double v, double fallback) { return std::isfinite(v) ? v : fallback; }
}  // namespace

double fs_accuracy(double samples, double pixels, double interpolation_m, double base_error) {
  samples = finite_or(samples, 0.0);
  if (samples <= 0.0) return 0.0;
  if (std::isfinite(pixels) && pixels >= 1.0) samples = std::min(samples, pixels);
  samples = std::max(samples, 1.0);
  const double m = std::clamp(finite_or(interpolation_m, 1.0), 0.0, 8.0);
  const double e = std::clamp(finite_or(base_error, 0.5), 0.0, 1.0);
  return std::clamp(1.0 - e / std::pow(samples, m), 0.0, 1.0);
}

double visible_loss_share(double acuity_limit_cpd, double removed_detail_cpd) {
  if (!(acuity_limit_cpd > 0.0) || !std::isfinite(acuity_limit_cpd)) return 0.0;
  const double removed = std::max(finite_or(removed_detail_cpd, 0.0), 0.0);
  return std::clamp(1.0 - removed / acuity_limit_cpd, 0.0, 1.0);
}

double hysteresis_factor(double level_change, double per_level) {
  const double change = std::fabs(finite_or(level_change, 0.0));
  const double k = std::max(finite_or(per_level, 0.0), 0.0);
  return std::clamp(1.0 - k * change, 0.0, 1.0);
}

double benefit(const BenefitInputs& in) {
  const double size = std::max(finite_or(in.size_px, 0.0), 0.0);
  const double importance = std::clamp(finite_or(in.importance, 0.0), 0.0, 1.0);
  const double a_full = fs_accuracy(in.full_samples, size, in.interpolation_m, in.base_error);
  const double a_level = fs_accuracy(in.samples, size, in.interpolation_m, in.base_error);
  const double loss = std::max(a_full - a_level, 0.0);
  const double perceived =
      in.samples > 0.0 ? a_full - loss * visible_loss_share(in.acuity_limit_cpd, in.removed_detail_cpd)
                       : 0.0;  // drawing nothing is always visible
  return size * perceived * importance * hysteresis_factor(in.level_change, in.hysteresis_per_level);
}

}  // namespace gazelod::lod
