// SPDX-License-Identifier: Apache-2.0
// validate_conditioner_config (gaze/gaze_conditioner.hpp): a bad setting is refused with a
// message naming the field and its value, by the function and by GazeConditioner's
// constructor; nothing is replaced by a default, and valid settings are kept as given.
#include "gaze/gaze_conditioner.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace gazelod::gaze {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

struct BadSetting {
  std::string field;  // the name the message must start with
  std::string value;  // how the bad value is printed in it
  std::function<void(ConditionerConfig&)> set;
};

// One bad value per rule: every setting the conditioner once replaced by its default (or
// clamped) is in this list.
std::vector<BadSetting> bad_settings() {
  using C = ConditionerConfig;
  return {
      {"accuracy_deg", "-1", [](C& c) { c.accuracy_deg = -1.0; }},
      {"precision_deg", "nan", [](C& c) { c.precision_deg = kNaN; }},
      {"saccade_threshold_deg_s", "0", [](C& c) { c.saccade_threshold_deg_s = 0.0; }},
      {"saccade_significance", "-0.5", [](C& c) { c.saccade_significance = -0.5; }},
      {"velocity_window_ns", "0", [](C& c) { c.velocity_window_ns = 0; }},
      {"dispersion_window_ns", "-5", [](C& c) { c.dispersion_window_ns = -5; }},
      {"dispersion_threshold_deg", "inf", [](C& c) { c.dispersion_threshold_deg = kInf; }},
      {"pursuit_significance", "-1", [](C& c) { c.pursuit_significance = -1.0; }},
      {"pursuit_exit_fraction", "1.5", [](C& c) { c.pursuit_exit_fraction = 1.5; }},  // was clamped to 1
      {"pursuit_exit_fraction", "nan", [](C& c) { c.pursuit_exit_fraction = kNaN; }},
      {"carried_evidence", "-2", [](C& c) { c.carried_evidence = -2.0; }},
      {"carried_prior_fixations", "-1", [](C& c) { c.carried_prior_fixations = -1.0; }},
      {"carried_prior_exit", "nan", [](C& c) { c.carried_prior_exit = kNaN; }},
      {"max_gap_ns", "0", [](C& c) { c.max_gap_ns = 0; }},
      {"fixation_smoothing_tau_ns", "-1", [](C& c) { c.fixation_smoothing_tau_ns = -1; }},
      {"fixation_step_chi2", "-1", [](C& c) { c.fixation_step_chi2 = -1.0; }},
      {"fixation_step_chi2", "nan", [](C& c) { c.fixation_step_chi2 = kNaN; }},
      {"pursuit_velocity_tau_ns", "-1", [](C& c) { c.pursuit_velocity_tau_ns = -1; }},
      {"prediction_horizon_max_ns", "-1", [](C& c) { c.prediction_horizon_max_ns = -1; }},
      {"post_saccade_suppression_ns", "-1", [](C& c) { c.post_saccade_suppression_ns = -1; }},
      {"max_saccade_ns", "-1", [](C& c) { c.max_saccade_ns = -1; }},
      {"loss_hold_max_ns", "-1", [](C& c) { c.loss_hold_max_ns = -1; }},
      {"age_growth_deg_s", "-inf", [](C& c) { c.age_growth_deg_s = -kInf; }},
      {"velocity_error_fraction", "-0.25", [](C& c) { c.velocity_error_fraction = -0.25; }},
      {"saccade_path_margin", "-0.5", [](C& c) { c.saccade_path_margin = -0.5; }},
      {"saccade_ahead_of_travelled", "-1", [](C& c) { c.saccade_ahead_of_travelled = -1.0; }},
      {"max_uncertainty_deg", "0", [](C& c) { c.max_uncertainty_deg = 0.0; }},
      // Below the accuracy: the uncertainty's clamp range would be empty (was raised to it).
      {"max_uncertainty_deg", "1", [](C& c) { c.max_uncertainty_deg = 1.0; }},
      {"max_sample_lead_ns", "0", [](C& c) { c.max_sample_lead_ns = 0; }},
  };
}

TEST(ConditionerConfig, DefaultsAreValid) {
  EXPECT_EQ(validate_conditioner_config(ConditionerConfig{}), "");
  EXPECT_NO_THROW(GazeConditioner{});
}

TEST(ConditionerConfig, EachBadSettingIsRefusedWithItsNameAndValue) {
  for (const BadSetting& b : bad_settings()) {
    ConditionerConfig c;
    b.set(c);
    const std::string why = validate_conditioner_config(c);
    EXPECT_EQ(why.rfind(b.field + " must be", 0), 0u) << b.field << ": " << why;
    EXPECT_NE(why.find("got " + b.value), std::string::npos) << b.field << ": " << why;
  }
}

TEST(ConditionerConfig, TheConstructorRefusesWhatValidationRefuses) {
  for (const BadSetting& b : bad_settings()) {
    ConditionerConfig c;
    b.set(c);
    try {
      GazeConditioner g(c);
      ADD_FAILURE() << b.field << ": accepted (a default would have replaced it silently)";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(validate_conditioner_config(c)), std::string::npos) << what;
      EXPECT_NE(what.find(b.field), std::string::npos) << what;
    }
  }
}

TEST(ConditionerConfig, TheFirstBadFieldIsReported) {
  ConditionerConfig c;
  c.max_gap_ns = 0;
  c.precision_deg = -1.0;
  EXPECT_EQ(validate_conditioner_config(c).rfind("precision_deg", 0), 0u) << validate_conditioner_config(c);
}

TEST(ConditionerConfig, ValidEdgeValuesAreKeptAsGiven) {
  // The limits of each rule are accepted and reach the conditioner unchanged.
  ConditionerConfig c{.accuracy_deg = 0.0,
                      .precision_deg = 0.0,
                      .pursuit_exit_fraction = 1.0,
                      .fixation_smoothing_tau_ns = 0,
                      .prediction_horizon_max_ns = 0,
                      .max_uncertainty_deg = 0.5,
                      .max_sample_lead_ns = 1};
  ASSERT_EQ(validate_conditioner_config(c), "");
  const GazeConditioner g(c);
  EXPECT_EQ(g.config().pursuit_exit_fraction, 1.0);
  EXPECT_EQ(g.config().max_uncertainty_deg, 0.5);
  EXPECT_EQ(g.config().fixation_smoothing_tau_ns, 0);
  EXPECT_EQ(g.config().max_sample_lead_ns, 1);
  c.max_uncertainty_deg = c.accuracy_deg = 3.0;  // an empty-width range is still a range
  EXPECT_EQ(validate_conditioner_config(c), "");
}

}  // namespace
}  // namespace gazelod::gaze
