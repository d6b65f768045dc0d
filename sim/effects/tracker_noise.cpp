// SPDX-License-Identifier: Apache-2.0
// tracker_noise: Gaussian angular noise on each tracker sample, std_deg per axis (yaw and
// pitch independent), drawn from (seed, effect, sample time) so a sample is always the same.
#include "auxiliary/angles.hpp"
#include "auxiliary/yaw_pitch.hpp"
#include "sim/effects/effects.hpp"

namespace gazelod::sim::effects {
namespace {

class TrackerNoise final : public Effect {
 public:
  explicit TrackerNoise(EffectInit& in) : rng_(in.rng) {
    std_rad_ = in.params.required_number("std_deg", 0.0, 30.0) * aux::kRadPerDeg;
  }
  unsigned stages() const override { return kStageTrackerSample; }
  void apply_sample(gaze::GazeSample& s) const override {
    double a = 0.0, b = 0.0;
    rng_.normal2(static_cast<std::uint64_t>(s.t_ns), a, b);
    aux::YawPitch yp = aux::yaw_pitch_of(s.direction);
    yp.yaw_rad += std_rad_ * a;
    yp.pitch_rad += std_rad_ * b;
    s.direction = aux::direction_from(yp);
  }

 private:
  aux::CounterRng rng_;
  double std_rad_ = 0.0;
};

}  // namespace

std::unique_ptr<Effect> make_tracker_noise(EffectInit& init) {
  return std::make_unique<TrackerNoise>(init);
}

}  // namespace gazelod::sim::effects
