// SPDX-License-Identifier: Apache-2.0
// What the layer does with an instance, decided once at xrCreateInstance (and printed by
// `gazelod layer check`, from the same function):
//  - the application did not enable XR_EXT_eye_gaze_interaction: pass through;
//  - the runtime offers it and the configuration does not say "override": pass through;
//  - otherwise emulate it: strip it from what goes down, answer its queries, and serve gaze
//    from the configured source, or (a misconfiguration, logged once) serve none.
#pragma once

#include <string>

namespace gazelod::layer {

enum class LayerMode { pass_through, emulate };

struct Decision {
  LayerMode mode = LayerMode::pass_through;
  bool gaze_available = false;  // emulating with a usable source
  std::string why;              // one line
};

struct DecisionInputs {
  bool application_enables_extension = true;
  bool runtime_has_extension = false;
  bool override_runtime = false;
  std::string config_error;  // "" = the configuration is fine
  std::string source_error;  // "" = the source opened (only asked when emulating)
  std::string source;        // what it is, when it opened
};

// Whether the source must be opened: only when the layer emulates.
bool needs_source(const DecisionInputs& in);
Decision decide(const DecisionInputs& in);

}  // namespace gazelod::layer
