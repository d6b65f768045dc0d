// SPDX-License-Identifier: Apache-2.0
// validate_plugin_config (plugin/plugin_config.hpp): the plugin's configuration is checked once,
// when the plugin is created, so that no frame has to refuse it (docs/error-policy.md).
#include "plugin/plugin_config.hpp"

#include <cmath>
#include <sstream>
#include <string>
#include <utility>

namespace gazelod {
namespace {

std::string refusal(const char* name, const char* rule, double value) {
  std::ostringstream m;
  m << name << " must be " << rule << ", got " << value;
  return m.str();
}

}  // namespace

std::string validate_plugin_config(const PluginConfig& c) {
  if (!(std::isfinite(c.gaze_silence_timeout_s) && c.gaze_silence_timeout_s > 0.0))
    return refusal("gaze_silence_timeout_s", "finite and > 0", c.gaze_silence_timeout_s);
  if (!(std::isfinite(c.max_pushed_sample_age_s) && c.max_pushed_sample_age_s > 0.0))
    return refusal("max_pushed_sample_age_s", "finite and > 0", c.max_pushed_sample_age_s);
  // Each source's error replaces conditioning.accuracy_deg (LodCore), so the conditioning is
  // checked without it and the errors against its cap, each under its own name.
  gaze::ConditionerConfig cc = c.conditioning;
  cc.accuracy_deg = 0.0;
  if (std::string e = gaze::validate_conditioner_config(cc); !e.empty()) return "conditioning." + e;
  for (const auto& [name, error_deg] :
       {std::pair<const char*, double>{"openxr_gaze_error_deg", c.openxr_gaze_error_deg},
        {"external_gaze_error_deg", c.external_gaze_error_deg}}) {
    cc.accuracy_deg = error_deg;
    if (!validate_conditioner_config(cc).empty()) {
      std::ostringstream rule;
      rule << "finite, >= 0 and <= conditioning.max_uncertainty_deg (" << c.conditioning.max_uncertainty_deg << ")";
      return refusal(name, rule.str().c_str(), error_deg);
    }
  }
  if (!(std::isfinite(c.head_fixed_cone_deg) && c.head_fixed_cone_deg >= 0.0 && c.head_fixed_cone_deg <= 180.0))
    return refusal("head_fixed_cone_deg", "in [0, 180]", c.head_fixed_cone_deg);
  if (std::string e = lod::validate_switch_config(c.switching); !e.empty()) return "switching." + e;
  if (!(std::isfinite(c.budget_ms) && c.budget_ms >= 0.0))
    return refusal("budget_ms", "0 (no budget) or a positive finite number of ms", c.budget_ms);
  if (std::string e = budget::validate_frame_budget_options(c.budget); !e.empty()) return "budget." + e;
  return {};
}

}  // namespace gazelod
