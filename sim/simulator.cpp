// SPDX-License-Identifier: Apache-2.0
// The simulator: builds the listed effects once, sorts them into per-stage lists and evaluates
// every query as a pure function of time (no state carried between queries).
#include "sim/simulator.hpp"

#include "auxiliary/time.hpp"
#include "auxiliary/yaw_pitch.hpp"
#include "sim/effect.hpp"

#include <cmath>

namespace gazelod::sim {

struct Simulator::Impl final : EffectContext {
  Scenario scenario;
  std::vector<std::unique_ptr<Effect>> owned;
  std::vector<const Effect*> head, gaze, sample, objects;
  TrackerTiming timing;
  std::vector<ObjectState> objects_buf;

  explicit Impl(Scenario s) : scenario(std::move(s)) {
    // The file, where there is one: a relative trace file is found beside it (a scenario's
    // "name" is a label, and named ones looked for their traces in the working folder).
    const std::string source = !scenario.file.empty() ? scenario.file
                               : scenario.name.empty() ? "<scenario>"
                                                       : scenario.name;
    for (std::size_t i = 0; i < scenario.effects.size(); ++i) {
      owned.push_back(make_effect(scenario.effects[i], scenario, i, source));
      const Effect* e = owned.back().get();
      const unsigned st = e->stages();
      if (st & kStageHead) head.push_back(e);
      if (st & kStageGaze) gaze.push_back(e);
      if (st & kStageTrackerTiming) e->apply_timing(timing);
      if (st & kStageTrackerSample) sample.push_back(e);
      if (st & kStageObjects) objects.push_back(e);
    }
    objects_buf.resize(scenario.objects.size());
  }

  HeadState head_at(std::int64_t t_ns) const override {
    const double t_s = aux::seconds_from_ns(t_ns);
    HeadMotion m;
    m.position_m = scenario.head_path.start_m + scenario.head_path.velocity_m_s * t_s;
    m.velocity_m_s = scenario.head_path.velocity_m_s;
    HeadState h;
    h.t_ns = t_ns;
    if (head.empty()) {  // no head effect listed: a still head on its path, no trigonometry
      h.position_m = m.position_m;
      h.linear_velocity_m_s = m.velocity_m_s;
      return h;
    }
    for (const Effect* e : head) e->apply_head(t_ns, m);
    h.orientation = aux::rotation_from({m.yaw_rad, m.pitch_rad});
    // R = Ry(yaw) Rx(pitch): omega = yaw' Y + Ry(yaw) (pitch' X), in the world frame.
    const glm::dvec3 pitch_axis(std::cos(m.yaw_rad), 0.0, -std::sin(m.yaw_rad));
    h.angular_velocity_rad_s = m.yaw_rate_rad_s * glm::dvec3(0, 1, 0) + m.pitch_rate_rad_s * pitch_axis;
    if (m.has_track) {  // Q(t) R(t): omega = omega_Q + Q omega_R
      h.orientation = m.track * h.orientation;
      h.angular_velocity_rad_s = m.track_angular_velocity_rad_s + m.track * h.angular_velocity_rad_s;
    }
    h.position_m = m.position_m;
    h.linear_velocity_m_s = m.velocity_m_s;
    return h;
  }

  ObjectState object_at(std::size_t i, std::int64_t t_ns) const override {
    const SceneObject& so = scenario.objects[i];
    ObjectState o{so.position_m + so.velocity_m_s * aux::seconds_from_ns(t_ns), so.velocity_m_s};
    for (const Effect* e : objects) e->apply_object(i, t_ns, o);
    return o;
  }

  gaze::GazeSample true_gaze_at(std::int64_t t_ns) const {
    gaze::GazeSample g;
    g.t_ns = t_ns;
    for (const Effect* e : gaze) e->apply_gaze(t_ns, *this, g.direction);
    g.valid = true;
    g.confidence = 1.0f;
    return g;
  }

  EyeTruth eye_truth_at(std::int64_t t_ns) const {
    EyeTruth truth;
    for (const auto& e : owned) e->apply_truth(t_ns, *this, truth);
    return truth;
  }

  gaze::GazeSample tracker_at(std::int64_t t_ns) const {
    std::int64_t s = t_ns - timing.latency_ns;
    if (timing.period_ns > 0) {  // newest sample k * period <= s (floor division)
      const std::int64_t p = timing.period_ns;
      const std::int64_t k = s >= 0 ? s / p : -((-s + p - 1) / p);
      s = k * p;
    }
    if (s < 0) return gaze::GazeSample{};  // nothing delivered yet: invalid
    gaze::GazeSample g = true_gaze_at(s);
    for (const Effect* e : sample) e->apply_sample(g);
    return g;
  }
};

Simulator::Simulator(Scenario scenario) : impl_(std::make_unique<Impl>(std::move(scenario))) {}
Simulator::~Simulator() = default;
Simulator::Simulator(Simulator&&) noexcept = default;
Simulator& Simulator::operator=(Simulator&&) noexcept = default;

const Scenario& Simulator::scenario() const {
  return impl_->scenario;
}
HeadState Simulator::head_at(std::int64_t t_ns) {
  return impl_->head_at(t_ns);
}
gaze::GazeSample Simulator::tracker_at(std::int64_t t_ns) {
  return impl_->tracker_at(t_ns);
}
gaze::GazeSample Simulator::true_gaze_at(std::int64_t t_ns) {
  return impl_->true_gaze_at(t_ns);
}

std::span<const ObjectState> Simulator::objects_at(std::int64_t t_ns) {
  for (std::size_t i = 0; i < impl_->objects_buf.size(); ++i) impl_->objects_buf[i] = impl_->object_at(i, t_ns);
  return impl_->objects_buf;
}

EyeTruth Simulator::eye_truth_at(std::int64_t t_ns) {
  return impl_->eye_truth_at(t_ns);
}

std::int64_t Simulator::duration_ns() const {
  return aux::ns_from_seconds(impl_->scenario.duration_s);
}
std::int64_t Simulator::first_tracker_sample_ns() const {
  return impl_->timing.latency_ns;
}

}  // namespace gazelod::sim
