// SPDX-License-Identifier: Apache-2.0
// head_turn: a turn at a constant rate (up to 300 deg/s, fast head turns in VR) about yaw or
// pitch, from start_s for duration_s; the angle reached is then held.
#include "auxiliary/angles.hpp"
#include "auxiliary/time.hpp"
#include "sim/effects/effects.hpp"

#include <algorithm>

namespace gazelod::sim::effects {
namespace {

class HeadTurn final : public Effect {
 public:
  explicit HeadTurn(EffectInit& in) {
    rate_rad_s_ = in.params.required_number("rate_deg_s", -300.0, 300.0) * aux::kRadPerDeg;
    const std::string axis = in.params.string("axis", "yaw");
    if (axis == "yaw")
      pitch_ = false;
    else if (axis == "pitch")
      pitch_ = true;
    else
      in.params.fail("axis", "expected \"yaw\" or \"pitch\", got \"" + axis + "\"");
    start_ns_ = aux::ns_from_seconds(in.params.number("start_s", 0.0, 0.0, 1e6));
    duration_ns_ = aux::ns_from_seconds(in.params.required_number("duration_s", 0.0, 1e6));
  }
  unsigned stages() const override { return kStageHead; }
  void apply_head(std::int64_t t_ns, HeadMotion& h) const override {
    if (t_ns <= start_ns_) return;
    const std::int64_t into_ns = std::min(t_ns - start_ns_, duration_ns_);
    const double angle = rate_rad_s_ * aux::seconds_from_ns(into_ns);
    const double rate = t_ns - start_ns_ < duration_ns_ ? rate_rad_s_ : 0.0;
    if (pitch_) {
      h.pitch_rad += angle;
      h.pitch_rate_rad_s += rate;
    } else {
      h.yaw_rad += angle;
      h.yaw_rate_rad_s += rate;
    }
  }

 private:
  double rate_rad_s_ = 0.0;
  bool pitch_ = false;
  std::int64_t start_ns_ = 0, duration_ns_ = 0;
};

}  // namespace

std::unique_ptr<Effect> make_head_turn(EffectInit& init) {
  return std::make_unique<HeadTurn>(init);
}

}  // namespace gazelod::sim::effects
