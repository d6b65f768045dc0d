// Reddy's global acuity scale (1998, the reactive frame-rate control): one factor s in (0, 1]
// multiplies every acuity limit, so all objects coarsen together. Lowered on an overrun,
// raised back toward 1 when there is slack. The simple alternative to the knapsack solvers.
#pragma once

namespace gazelod::lod {

struct BudgetScaleParams {
  double s_min = 0.05;           // never below this (s stays in (0, 1])
  double slack_fraction = 0.85;  // a frame under this share of the budget counts as slack
  double raise_rate = 0.1;       // on slack: s += raise_rate * (1 - s)
  double max_cut = 0.5;          // on overrun: s *= max(budget / measured, max_cut)
};

class BudgetScale {
 public:
  explicit BudgetScale(const BudgetScaleParams& params = {}) : params_(params) {}
  double scale() const { return s_; }
  // Feeds one measured frame time against the budget (same units); returns the new s.
  // Non-finite or non-positive inputs leave s unchanged.
  double update(double frame_time, double budget);
  // Scaled acuity limit: s * limit_cpd.
  double apply(double acuity_limit_cpd) const { return s_ * acuity_limit_cpd; }

 private:
  BudgetScaleParams params_;
  double s_ = 1.0;
};

}  // namespace gazelod::lod
