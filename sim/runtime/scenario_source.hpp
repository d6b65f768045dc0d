// Where the runtime's scenario comes from: GAZELOD_SIM_SCENARIO (a JSON file) or the embedded
// default, with GAZELOD_SIM_DURATION_S overriding the duration and GAZELOD_SIM_PACED (0 or 1)
// the pacing. Errors name the variable or the scenario's JSON path.
#pragma once

#include "sim/simulator.hpp"

namespace gazelod::xrrt {

// Throws sim::ScenarioError (or std::runtime_error for a bad environment variable).
sim::Scenario load_runtime_scenario();

}  // namespace gazelod::xrrt
