// SPDX-License-Identifier: Apache-2.0
// gazelod eval family --set / --list-settings: the switch-policy and conditioner settings a
// tuning sweep may change, each with its range (family.hpp).
#include "apps/gazelod/eval/family.hpp"

#include "apps/gazelod/eval/work.hpp"
#include "auxiliary/time.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

namespace gazelod::cli {
namespace {

// A tunable: its name and where it lives; times in ns are set in ms.
struct Setting {
  const char* name;
  double lo, hi;
  std::function<double&(FamilySettings&)> real;            // a double field, or
  std::function<std::int64_t&(FamilySettings&)> ms_as_ns;  // an ns field set in ms, or
  std::function<bool&(FamilySettings&)> flag;              // a bool (0 or 1)
};

const std::vector<Setting>& settings_table() {
  using S = FamilySettings;
  static const std::vector<Setting> table{
      {"switch.coarsen_hold_s", 0, 10, [](S& s) -> double& { return s.switching.coarsen_hold_s; }, {}, {}},
      {"switch.max_deferral_s", 0, 10, [](S& s) -> double& { return s.switching.max_deferral_s; }, {}, {}},
      {"switch.suppressed_hold_s", 0, 10, [](S& s) -> double& { return s.switching.suppressed_hold_s; }, {}, {}},
      {"switch.prefer_suppression", 0, 1, {}, {}, [](S& s) -> bool& { return s.switching.prefer_suppression; }},
      {"switch.release_regret_s", 0, 10, [](S& s) -> double& { return s.switching.release_regret_s; }, {}, {}},
      {"switch.release_by_motion", 0, 1, {}, {}, [](S& s) -> bool& { return s.switching.release_by_motion; }},
      {"switch.motion_trusts_eye_velocity",
       0,
       1,
       {},
       {},
       [](S& s) -> bool& { return s.switching.motion_trusts_eye_velocity; }},
      {"switch.motion_eye_may_hold_world",
       0,
       1,
       {},
       {},
       [](S& s) -> bool& { return s.switching.motion_eye_may_hold_world; }},
      {"conditioner.saccade_threshold_deg_s",
       10,
       1000,
       [](S& s) -> double& { return s.conditioning.saccade_threshold_deg_s; },
       {},
       {}},
      {"conditioner.dispersion_threshold_deg",
       0.01,
       20,
       [](S& s) -> double& { return s.conditioning.dispersion_threshold_deg; },
       {},
       {}},
      {"conditioner.pursuit_significance",
       0,
       100,
       [](S& s) -> double& { return s.conditioning.pursuit_significance; },
       {},
       {}},
      {"conditioner.saccade_significance",
       0,
       100,
       [](S& s) -> double& { return s.conditioning.saccade_significance; },
       {},
       {}},
      {"conditioner.carried_evidence", 0, 1e6, [](S& s) -> double& { return s.conditioning.carried_evidence; }, {}, {}},
      {"conditioner.carried_prior_fixations",
       0,
       100,
       [](S& s) -> double& { return s.conditioning.carried_prior_fixations; },
       {},
       {}},
      {"conditioner.carried_prior_exit",
       0,
       1e6,
       [](S& s) -> double& { return s.conditioning.carried_prior_exit; },
       {},
       {}},
      {"conditioner.carried_shift_deg_s",
       0,
       1000,
       [](S& s) -> double& { return s.conditioning.carried_shift_deg_s; },
       {},
       {}},
      {"conditioner.fixation_step_chi2",
       0,
       1e6,
       [](S& s) -> double& { return s.conditioning.fixation_step_chi2; },
       {},
       {}},
      {"conditioner.saccade_cone_ahead", 0, 1, {}, {}, [](S& s) -> bool& { return s.conditioning.saccade_cone_ahead; }},
      {"conditioner.saccade_path_margin",
       0,
       10,
       [](S& s) -> double& { return s.conditioning.saccade_path_margin; },
       {},
       {}},
      {"conditioner.saccade_ahead_of_travelled",
       0,
       10,
       [](S& s) -> double& { return s.conditioning.saccade_ahead_of_travelled; },
       {},
       {}},
      {"conditioner.saccade_follow_newest",
       0,
       1,
       {},
       {},
       [](S& s) -> bool& { return s.conditioning.saccade_follow_newest; }},
      {"conditioner.age_growth_deg_s",
       0,
       1000,
       [](S& s) -> double& { return s.conditioning.age_growth_deg_s; },
       {},
       {}},
      {"conditioner.velocity_error_fraction",
       0,
       10,
       [](S& s) -> double& { return s.conditioning.velocity_error_fraction; },
       {},
       {}},
      {"conditioner.velocity_window_ms",
       1,
       1000,
       {},
       [](S& s) -> std::int64_t& { return s.conditioning.velocity_window_ns; },
       {}},
      {"conditioner.dispersion_window_ms",
       1,
       5000,
       {},
       [](S& s) -> std::int64_t& { return s.conditioning.dispersion_window_ns; },
       {}},
      {"conditioner.fixation_smoothing_tau_ms",
       1,
       10000,
       {},
       [](S& s) -> std::int64_t& { return s.conditioning.fixation_smoothing_tau_ns; },
       {}},
      {"conditioner.prediction_horizon_max_ms",
       0,
       1000,
       {},
       [](S& s) -> std::int64_t& { return s.conditioning.prediction_horizon_max_ns; },
       {}},
      {"conditioner.post_saccade_suppression_ms",
       0,
       1000,
       {},
       [](S& s) -> std::int64_t& { return s.conditioning.post_saccade_suppression_ns; },
       {}},
      {"conditioner.post_saccade_from_landing",
       0,
       1,
       {},
       {},
       [](S& s) -> bool& { return s.conditioning.post_saccade_from_landing; }},
      {"conditioner.saccade_ends_at_landing",
       0,
       1,
       {},
       {},
       [](S& s) -> bool& { return s.conditioning.saccade_ends_at_landing; }},
  };
  return table;
}

double current(const Setting& t, FamilySettings& s) {
  if (t.real) return t.real(s);
  if (t.ms_as_ns) return aux::ms_from_ns(t.ms_as_ns(s));
  return t.flag(s) ? 1.0 : 0.0;
}

std::string number(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

}  // namespace

void apply_setting(const std::string& assignment, FamilySettings& settings) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos) throw UsageError("--set: expected NAME=VALUE, got '" + assignment + "'");
  const std::string name = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  const auto& table = settings_table();
  const auto it = std::find_if(table.begin(), table.end(), [&](const Setting& s) { return name == s.name; });
  if (it == table.end())
    throw UsageError("--set: unknown setting '" + name + "' (gazelod eval family --list-settings)");
  double v = 0.0;
  std::size_t used = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v))
    throw UsageError("--set " + name + ": '" + text + "' is not a number");
  if (v < it->lo || v > it->hi)
    throw UsageError("--set " + name + ": must be in [" + number(it->lo) + ", " + number(it->hi) + "], got " + text);
  if (it->real)
    it->real(settings) = v;
  else if (it->ms_as_ns)
    it->ms_as_ns(settings) = aux::ns_from_ms(v);
  else if (v != 0.0 && v != 1.0)
    throw UsageError("--set " + name + ": must be 0 or 1, got " + text);
  else
    it->flag(settings) = v == 1.0;
  settings.changed.push_back(assignment);
}

std::string settings_list(const FamilySettings& settings) {
  FamilySettings copy = settings;
  std::ostringstream out;
  for (const Setting& s : settings_table())
    out << s.name << "=" << current(s, copy) << "  (range " << s.lo << " to " << s.hi << ")\n";
  return out.str();
}

}  // namespace gazelod::cli
