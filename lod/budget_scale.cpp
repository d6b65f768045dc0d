#include "lod/budget_scale.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::lod {

double BudgetScale::update(double frame_time, double budget) {
  if (!std::isfinite(frame_time) || !std::isfinite(budget) || frame_time <= 0.0 || budget <= 0.0)
    return s_;
  const double s_min = std::clamp(params_.s_min, 1e-6, 1.0);
  if (frame_time > budget) {
    // Proportional cut (time scales roughly with detail), but never more than max_cut at once.
    s_ *= std::max(budget / frame_time, std::clamp(params_.max_cut, 0.0, 1.0));
  } else if (frame_time < params_.slack_fraction * budget) {
    s_ += std::clamp(params_.raise_rate, 0.0, 1.0) * (1.0 - s_);
  }
  s_ = std::clamp(s_, s_min, 1.0);
  return s_;
}

}  // namespace gazelod::lod
