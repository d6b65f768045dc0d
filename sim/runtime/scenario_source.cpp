// SPDX-License-Identifier: Apache-2.0
// Loads the runtime's scenario from the environment (see scenario_source.hpp).
#include "sim/runtime/scenario_source.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace gazelod::xrrt {
namespace {

const char* env(const char* name) {
  const char* v = std::getenv(name);
  return (v != nullptr && *v != '\0') ? v : nullptr;
}

}  // namespace

bool env_flag(const char* name, bool fallback) {
  const char* v = env(name);
  if (v == nullptr) return fallback;
  if (std::strcmp(v, "1") == 0) return true;
  if (std::strcmp(v, "0") == 0) return false;
  throw std::runtime_error(std::string(name) + "=\"" + v + "\": expected 0 or 1");
}

sim::Scenario load_runtime_scenario() {
  // Read when first logged; checked here so that a bad value fails instance creation as every
  // other variable does.
  (void)env_flag("GAZELOD_SIM_LOG", false);
  (void)env_flag("GAZELOD_SIM_EYE_GAZE_EXTENSION", true);
  sim::Scenario scenario;
  if (const char* file = env("GAZELOD_SIM_SCENARIO")) {
    scenario = sim::load_scenario_file(file);
  } else {
    scenario = sim::load_scenario_json(sim::default_scenario_json(), "<embedded default scenario>");
  }
  if (const char* d = env("GAZELOD_SIM_DURATION_S")) {
    char* end = nullptr;
    const double seconds = std::strtod(d, &end);
    constexpr double kMax = sim::kMaxScenarioDurationS + sim::kRunSlackS;
    if (end == d || *end != '\0' || !std::isfinite(seconds) || seconds <= 0.0 || seconds > kMax)
      throw std::runtime_error(std::string("GAZELOD_SIM_DURATION_S=\"") + d +
                               "\": expected a number of seconds in (0, 1e6 + 1]");
    scenario.duration_s = seconds;
  }
  scenario.runtime.paced = env_flag("GAZELOD_SIM_PACED", scenario.runtime.paced);
  return scenario;
}

RuntimeFaults load_runtime_faults() {
  RuntimeFaults faults;
  if (const char* n = env("GAZELOD_SIM_LOSE_SESSION_AT_FRAME")) {
    char* end = nullptr;
    const unsigned long long frame = std::strtoull(n, &end, 10);
    if (end == n || *end != '\0' || *n == '-' || frame == 0 || frame > 1'000'000'000ull)
      throw std::runtime_error(std::string("GAZELOD_SIM_LOSE_SESSION_AT_FRAME=\"") + n +
                               "\": expected a frame number in [1, 1e9]");
    faults.lose_session_at_frame = frame;
  }
  faults.lose_session_silently = env_flag("GAZELOD_SIM_LOSE_SESSION_SILENTLY", false);
  return faults;
}

}  // namespace gazelod::xrrt
