// SPDX-License-Identifier: Apache-2.0
// Fuzzes the scenario loader. Invariants: a loaded scenario has a positive finite duration and
// frame rate, and what scenario_to_json writes loads back.
#include "fuzz/fuzz_entry.hpp"

#include "sim/scene_json.hpp"
#include "sim/simulator.hpp"

#include <cmath>
#include <string>

namespace gazelod::fuzz {

int scenario(const std::uint8_t* data, std::size_t size) {
  sim::Scenario s;
  try {
    s = sim::load_scenario_json(as_text(data, size), "fuzz.json");
  } catch (const sim::ScenarioError&) {
    return 0;  // the documented rejection (names the JSON path)
  }
  check(std::isfinite(s.duration_s) && s.duration_s > 0.0, "duration_s not finite and > 0");
  check(std::isfinite(s.frame_rate_hz) && s.frame_rate_hz > 0.0, "frame_rate_hz not finite and > 0");
  // Round trip: the writer's output must be accepted by the reader.
  const std::string again = sim::scenario_to_json(s);
  // Generated objects written out explicitly can pass the text-size limit the reader checks
  // first: not a round-trip failure.
  if (again.size() > sim::kMaxScenarioBytes) return 0;
  try {
    const sim::Scenario back = sim::load_scenario_json(again, "fuzz-roundtrip.json");
    check(back.objects.size() == s.objects.size(), "round trip changed the object count");
    check(back.effects.size() == s.effects.size(), "round trip changed the effect count");
  } catch (const sim::ScenarioError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    check(false, "scenario_to_json wrote a scenario load_scenario_json rejects");
  }
  return 0;
}

}  // namespace gazelod::fuzz

GAZELOD_FUZZ_TARGET(scenario)
