// SPDX-License-Identifier: Apache-2.0
// Where the runtime's scenario comes from: GAZELOD_SIM_SCENARIO (a JSON file) or the embedded
// default, with GAZELOD_SIM_DURATION_S overriding the duration and GAZELOD_SIM_PACED (0 or 1)
// the pacing. Errors name the variable or the scenario's JSON path.
#pragma once

#include "sim/simulator.hpp"

namespace gazelod::xrrt {

// Throws sim::ScenarioError (or std::runtime_error for a bad environment variable, including
// GAZELOD_SIM_LOG and GAZELOD_SIM_EYE_GAZE_EXTENSION).
sim::Scenario load_runtime_scenario();

// The one parser of the runtime's boolean variables (GAZELOD_SIM_PACED, GAZELOD_SIM_LOG,
// GAZELOD_SIM_LOSE_SESSION_SILENTLY): "1" or "0"; unset or empty gives `fallback`; anything
// else throws std::runtime_error "NAME=\"value\": expected 0 or 1".
bool env_flag(const char* name, bool fallback);

// Injected faults (docs/runtime.md, "Fault injection"), for testing applications' error paths:
// GAZELOD_SIM_LOSE_SESSION_AT_FRAME=N loses the session after the Nth xrEndFrame: it queues
// XR_SESSION_STATE_LOSS_PENDING (unless GAZELOD_SIM_LOSE_SESSION_SILENTLY=1) and every later
// xrWaitFrame / xrBeginFrame / xrEndFrame returns XR_ERROR_SESSION_LOST.
struct RuntimeFaults {
  std::uint64_t lose_session_at_frame = 0;  // 0: never
  bool lose_session_silently = false;
};
// Throws std::runtime_error naming a bad variable.
RuntimeFaults load_runtime_faults();

}  // namespace gazelod::xrrt
