// SPDX-License-Identifier: Apache-2.0
// The effect makers, one per file in this folder; effect_registry.cpp maps names to them.
#pragma once

#include "gaze/trace_open.hpp"
#include "sim/effect.hpp"

#include <string>
#include <vector>

namespace gazelod::sim::effects {

std::unique_ptr<Effect> make_head_sweep(EffectInit& init);
std::unique_ptr<Effect> make_head_turn(EffectInit& init);
std::unique_ptr<Effect> make_head_track(EffectInit& init);
std::unique_ptr<Effect> make_gaze_track(EffectInit& init);
std::unique_ptr<Effect> make_saccades(EffectInit& init);
std::unique_ptr<Effect> make_vor(EffectInit& init);
std::unique_ptr<Effect> make_smooth_pursuit(EffectInit& init);
std::unique_ptr<Effect> make_tracker_noise(EffectInit& init);
std::unique_ptr<Effect> make_tracker_latency(EffectInit& init);
std::unique_ptr<Effect> make_tracker_rate(EffectInit& init);
std::unique_ptr<Effect> make_dropouts(EffectInit& init);
std::unique_ptr<Effect> make_blinks(EffectInit& init);
std::unique_ptr<Effect> make_calibration_offset(EffectInit& init);
std::unique_ptr<Effect> make_object_motion(EffectInit& init);

// Index of the scenario object called `name`; fails at params' key when there is none.
std::size_t object_index(const Scenario& scenario, JsonFields& params, const std::string& key, const std::string& name);

// The trace a replay effect reads (head_track, gaze_track): its "file" parameter, resolved
// against the scenario file's folder when it is relative and there, else as given, and its
// "format" (default gazelod). Fails at the parameter on an unknown format.
struct TraceParam {
  std::string name;  // as the scenario wrote it, for messages
  std::string path;  // where to open it
  gaze::TraceFormat format = gaze::TraceFormat::gazelod;
};
TraceParam trace_param(EffectInit& init);
// Where a replay effect's "file" is opened (trace_param's rule), also for the scenario loader's
// memory estimate, which must count the file the effect will read.
std::string trace_file_path(const std::string& file, const std::string& scenario_source);

// Fresh copies of the gaze-stage effects listed before the one being made (same specs, same
// random streams, so the same values at any time), for an effect that must know the incoming
// eye direction at other times than the one asked for (vor).
std::vector<std::unique_ptr<Effect>> make_gaze_effects_before(const EffectInit& init);

}  // namespace gazelod::sim::effects
