// SPDX-License-Identifier: Apache-2.0
#include "layer/decision.hpp"

namespace gazelod::layer {

bool needs_source(const DecisionInputs& in) {
  return in.application_enables_extension && (!in.runtime_has_extension || in.override_runtime);
}

Decision decide(const DecisionInputs& in) {
  Decision d;
  if (!in.application_enables_extension) {
    d.why = "the application does not enable XR_EXT_eye_gaze_interaction: passing everything through";
    return d;
  }
  if (in.runtime_has_extension && !in.override_runtime) {
    d.why = "the runtime offers XR_EXT_eye_gaze_interaction: passing it through";
    return d;
  }
  d.mode = LayerMode::emulate;
  const std::string what = in.runtime_has_extension ? "overriding the runtime's XR_EXT_eye_gaze_interaction"
                                                    : "emulating XR_EXT_eye_gaze_interaction";
  const std::string& error = !in.config_error.empty() ? in.config_error : in.source_error;
  if (!error.empty()) {
    d.why = "gaze unavailable (" + error + "): " + what +
            " without gaze (supportsEyeGazeInteraction false), everything else passed through";
    return d;
  }
  d.gaze_available = true;
  d.why = what + " with gaze from " + in.source;
  return d;
}

}  // namespace gazelod::layer
