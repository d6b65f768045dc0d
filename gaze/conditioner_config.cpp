// SPDX-License-Identifier: Apache-2.0
// validate_conditioner_config (gaze/conditioner_config.hpp): which ConditionerConfig the
// conditioner accepts. A bad setting is refused with its name and value; the conditioner never
// substitutes a default for it (docs/error-policy.md).
#include "gaze/conditioner_config.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <sstream>

namespace gazelod::gaze {
namespace {

template <typename T>
std::string refusal(const char* name, const char* rule, T value) {
  std::ostringstream m;
  m << name << " must be " << rule << ", got " << value;
  return m.str();
}

// The rules, by how the conditioner uses a setting: a window, a threshold, the gap and the lead
// divide or must let some sample through (> 0); a time constant of 0 means no smoothing, a
// horizon of 0 no prediction, a significance of 0 no test (>= 0).
std::string at_least_zero(const char* name, double v) {
  return std::isfinite(v) && v >= 0.0 ? std::string() : refusal(name, "finite and >= 0", v);
}
std::string above_zero(const char* name, double v) {
  return std::isfinite(v) && v > 0.0 ? std::string() : refusal(name, "finite and > 0", v);
}
std::string at_least_zero_ns(const char* name, std::int64_t v) {
  return v >= 0 ? std::string() : refusal(name, ">= 0", v);
}
std::string above_zero_ns(const char* name, std::int64_t v) {
  return v > 0 ? std::string() : refusal(name, "> 0", v);
}

}  // namespace

std::string validate_conditioner_config(const ConditionerConfig& c) {
  std::string uncertainty_range;
  // The uncertainty is clamped to [accuracy_deg, max_uncertainty_deg]: an empty range has no answer.
  if (c.max_uncertainty_deg < c.accuracy_deg) {
    std::ostringstream m;
    m << "max_uncertainty_deg must be >= accuracy_deg (" << c.accuracy_deg << "), got " << c.max_uncertainty_deg;
    uncertainty_range = m.str();
  }
  // In declaration order, so the first bad field is the one reported.
  const std::string problems[] = {
      at_least_zero("accuracy_deg", c.accuracy_deg),
      at_least_zero("precision_deg", c.precision_deg),
      above_zero("saccade_threshold_deg_s", c.saccade_threshold_deg_s),
      at_least_zero("saccade_significance", c.saccade_significance),
      above_zero_ns("velocity_window_ns", c.velocity_window_ns),
      above_zero_ns("dispersion_window_ns", c.dispersion_window_ns),
      above_zero("dispersion_threshold_deg", c.dispersion_threshold_deg),
      at_least_zero("pursuit_significance", c.pursuit_significance),
      // A share of the thresholds (hysteresis): above 1, leaving pursuit would be harder than
      // entering it.
      c.pursuit_exit_fraction >= 0.0 && c.pursuit_exit_fraction <= 1.0
          ? std::string()
          : refusal("pursuit_exit_fraction", "in [0, 1]", c.pursuit_exit_fraction),
      at_least_zero("carried_evidence", c.carried_evidence),
      at_least_zero("carried_shift_deg_s", c.carried_shift_deg_s),
      at_least_zero("carried_prior_fixations", c.carried_prior_fixations),
      at_least_zero("carried_prior_exit", c.carried_prior_exit),
      above_zero_ns("max_gap_ns", c.max_gap_ns),
      at_least_zero_ns("fixation_smoothing_tau_ns", c.fixation_smoothing_tau_ns),
      at_least_zero("fixation_step_chi2", c.fixation_step_chi2),
      at_least_zero_ns("pursuit_velocity_tau_ns", c.pursuit_velocity_tau_ns),
      at_least_zero_ns("prediction_horizon_max_ns", c.prediction_horizon_max_ns),
      at_least_zero_ns("post_saccade_suppression_ns", c.post_saccade_suppression_ns),
      at_least_zero_ns("max_saccade_ns", c.max_saccade_ns),
      at_least_zero_ns("loss_hold_max_ns", c.loss_hold_max_ns),
      at_least_zero("age_growth_deg_s", c.age_growth_deg_s),
      at_least_zero("velocity_error_fraction", c.velocity_error_fraction),
      at_least_zero("saccade_path_margin", c.saccade_path_margin),
      at_least_zero("saccade_ahead_of_travelled", c.saccade_ahead_of_travelled),
      above_zero("max_uncertainty_deg", c.max_uncertainty_deg),
      uncertainty_range,
      above_zero_ns("max_sample_lead_ns", c.max_sample_lead_ns),
  };
  for (const std::string& p : problems)
    if (!p.empty()) return p;
  return {};
}

}  // namespace gazelod::gaze
