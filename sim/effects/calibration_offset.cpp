// SPDX-License-Identifier: Apache-2.0
// calibration_offset: a constant yaw / pitch error of the tracker plus a slow linear drift
// (headset slipping on the face), added to every sample at its sample time.
#include "auxiliary/angles.hpp"
#include "auxiliary/time.hpp"
#include "auxiliary/yaw_pitch.hpp"
#include "sim/effects/effects.hpp"

namespace gazelod::sim::effects {
namespace {

class CalibrationOffset final : public Effect {
 public:
  explicit CalibrationOffset(EffectInit& in) {
    yaw_rad_ = in.params.number("yaw_deg", 0.0, -30.0, 30.0) * aux::kRadPerDeg;
    pitch_rad_ = in.params.number("pitch_deg", 0.0, -30.0, 30.0) * aux::kRadPerDeg;
    drift_yaw_rad_s_ = in.params.number("drift_yaw_deg_per_min", 0.0, -60.0, 60.0) * aux::kRadPerDeg / 60.0;
    drift_pitch_rad_s_ = in.params.number("drift_pitch_deg_per_min", 0.0, -60.0, 60.0) * aux::kRadPerDeg / 60.0;
  }
  unsigned stages() const override { return kStageTrackerSample; }
  void apply_sample(gaze::GazeSample& s) const override {
    const double t_s = aux::seconds_from_ns(s.t_ns);
    aux::YawPitch yp = aux::yaw_pitch_of(s.direction);
    yp.yaw_rad += yaw_rad_ + drift_yaw_rad_s_ * t_s;
    yp.pitch_rad += pitch_rad_ + drift_pitch_rad_s_ * t_s;
    s.direction = aux::direction_from(yp);
  }

 private:
  double yaw_rad_ = 0.0, pitch_rad_ = 0.0, drift_yaw_rad_s_ = 0.0, drift_pitch_rad_s_ = 0.0;
};

}  // namespace

std::unique_ptr<Effect> make_calibration_offset(EffectInit& init) {
  return std::make_unique<CalibrationOffset>(init);
}

}  // namespace gazelod::sim::effects
