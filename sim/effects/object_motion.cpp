// SPDX-License-Identifier: Apache-2.0
// object_motion: one named object (or "*" for all) gets an extra constant velocity and/or a
// sinusoidal oscillation p += amplitude sin(2 pi f t), with the exact velocity.
#include "auxiliary/time.hpp"
#include "sim/effects/effects.hpp"

#include <cmath>
#include <numbers>

namespace gazelod::sim::effects {
namespace {

class ObjectMotion final : public Effect {
 public:
  explicit ObjectMotion(EffectInit& in) {
    const std::string name = in.params.required_string("object");
    all_ = name == "*";
    if (!all_) index_ = object_index(in.scenario, in.params, "object", name);
    velocity_m_s_ = in.params.vec3("velocity_m_s", glm::dvec3(0.0), -1e4, 1e4);
    amplitude_m_ = in.params.vec3("amplitude_m", glm::dvec3(0.0), -1e4, 1e4);
    w_ = 2.0 * std::numbers::pi * in.params.number("frequency_hz", 0.0, 0.0, 1000.0);
  }
  unsigned stages() const override { return kStageObjects; }
  void apply_object(std::size_t index, std::int64_t t_ns, ObjectState& o) const override {
    if (!all_ && index != index_) return;
    const double t = aux::seconds_from_ns(t_ns);
    o.position_m += velocity_m_s_ * t + amplitude_m_ * std::sin(w_ * t);
    o.velocity_m_s += velocity_m_s_ + amplitude_m_ * (w_ * std::cos(w_ * t));
  }

 private:
  bool all_ = false;
  std::size_t index_ = 0;
  glm::dvec3 velocity_m_s_{0.0}, amplitude_m_{0.0};
  double w_ = 0.0;
};

}  // namespace

std::unique_ptr<Effect> make_object_motion(EffectInit& init) {
  return std::make_unique<ObjectMotion>(init);
}

}  // namespace gazelod::sim::effects
