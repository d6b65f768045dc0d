// SPDX-License-Identifier: Apache-2.0
// The one interface every simulated effect implements (one effect per file in sim/effects/).
// An effect reads and validates its parameters when it is made, then takes part in the stages
// it names: head motion, true gaze, tracker timing, tracker samples, object motion. The
// simulator keeps one list per stage, so an effect that a scenario does not list costs nothing.
#pragma once

#include "auxiliary/random.hpp"
#include "gaze/gaze_sample.hpp"
#include "sim/json_fields.hpp"
#include "sim/simulator.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

namespace gazelod::sim {

enum EffectStage : unsigned {
  kStageHead = 1u << 0,           // head yaw / pitch / position
  kStageGaze = 1u << 1,           // the true eye direction in head space
  kStageTrackerTiming = 1u << 2,  // when tracker samples are taken and delivered
  kStageTrackerSample = 1u << 3,  // what a tracker sample reports (noise, validity, offset)
  kStageObjects = 1u << 4,        // object positions
};

// Head motion as the head effects build it (angles in the auxiliary/yaw_pitch.hpp convention).
struct HeadMotion {
  double yaw_rad = 0.0, pitch_rad = 0.0;
  double yaw_rate_rad_s = 0.0, pitch_rate_rad_s = 0.0;
  glm::dvec3 position_m{0.0};
  glm::dvec3 velocity_m_s{0.0};
  // A recorded head pose (head_track) that the yaw / pitch above are applied on top of:
  // orientation = track * Ry(yaw) Rx(pitch).
  bool has_track = false;
  glm::dquat track{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 track_angular_velocity_rad_s{0.0};  // world frame
};

// Tracker timing: a sample taken at s is delivered at s + latency_ns; samples are taken every
// period_ns from time 0 (0: continuously, i.e. at whatever time is asked for).
struct TrackerTiming {
  std::int64_t latency_ns = 0;
  std::int64_t period_ns = 0;
};

// What a gaze effect may look at besides time: the head and the objects, fully simulated.
class EffectContext {
 public:
  virtual ~EffectContext() = default;
  virtual HeadState head_at(std::int64_t t_ns) const = 0;
  virtual ObjectState object_at(std::size_t index, std::int64_t t_ns) const = 0;
};

class Effect {
 public:
  virtual ~Effect() = default;
  virtual unsigned stages() const = 0;
  virtual void apply_head(std::int64_t /*t_ns*/, HeadMotion& /*head*/) const {}
  // `dir` is the eye direction in head space so far (unit); effects later in the list win.
  virtual void apply_gaze(std::int64_t /*t_ns*/, const EffectContext& /*ctx*/, glm::dvec3& /*dir*/) const {}
  virtual void apply_timing(TrackerTiming& /*timing*/) const {}
  // `sample.t_ns` is when the sample was taken.
  virtual void apply_sample(gaze::GazeSample& /*sample*/) const {}
  virtual void apply_object(std::size_t /*index*/, std::int64_t /*t_ns*/, ObjectState& /*object*/) const {}
  // Ground truth (Simulator::eye_truth_at), never seen by a tracker: every effect is asked in
  // list order, whatever its stages; an effect that moves the eye sets what it owns at t.
  virtual void apply_truth(std::int64_t /*t_ns*/, const EffectContext& /*ctx*/, EyeTruth& /*truth*/) const {}
};

// What an effect is made from: the scenario (names, duration), its parameters (the effect's
// JSON object; "type" is already read) and its own random stream (seed, effect index).
struct EffectInit {
  const Scenario& scenario;
  JsonFields& params;
  aux::CounterRng rng;
  const std::string& source;  // the scenario file (relative paths in parameters start there)
};

// Makes the effect named spec.type; throws ScenarioError naming spec.json_path for unknown
// names and bad parameters.
std::unique_ptr<Effect> make_effect(const EffectSpec& spec, const Scenario& scenario, std::size_t index,
                                    const std::string& source);
std::span<const std::string_view> effect_names();

// Optional start_s / end_s window shared by several effects; end_s absent: forever.
struct TimeWindow {
  std::int64_t start_ns = 0;
  std::int64_t end_ns = INT64_MAX;
  bool contains(std::int64_t t_ns) const { return t_ns >= start_ns && t_ns < end_ns; }
};
TimeWindow read_window(JsonFields& params);

}  // namespace gazelod::sim
