// SPDX-License-Identifier: Apache-2.0
// head_sweep: the head swings in yaw and pitch as sinusoids (a visual search / look-around).
//   yaw(t) = A_yaw sin(2 pi (t - start) / T_yaw), likewise pitch; rates are the exact derivatives.
#include "auxiliary/angles.hpp"
#include "auxiliary/time.hpp"
#include "sim/effects/effects.hpp"

#include <cstdio>
#include <numbers>
#include <tuple>

namespace gazelod::sim::effects {
namespace {

constexpr double kMaxSweepRateDegS = 300.0;

class HeadSweep final : public Effect {
 public:
  explicit HeadSweep(EffectInit& in) {
    yaw_amp_rad_ = in.params.number("yaw_amplitude_deg", 0.0, 0.0, 180.0) * aux::kRadPerDeg;
    pitch_amp_rad_ = in.params.number("pitch_amplitude_deg", 0.0, 0.0, 90.0) * aux::kRadPerDeg;
    const double yaw_period_s = in.params.number("yaw_period_s", 4.0, 0.05, 1e5);
    const double pitch_period_s = in.params.number("pitch_period_s", yaw_period_s, 0.05, 1e5);
    yaw_w_ = 2.0 * std::numbers::pi / yaw_period_s;
    pitch_w_ = 2.0 * std::numbers::pi / pitch_period_s;
    // The peak rate, amplitude x 2 pi / period, within head_turn's 300 deg/s (fast head turns in
    // VR): 180 deg over 0.05 s swung the head at 23 000 deg/s without a word.
    for (const auto& [amp_rad, w, key] :
         {std::tuple{yaw_amp_rad_, yaw_w_, "yaw_period_s"}, std::tuple{pitch_amp_rad_, pitch_w_, "pitch_period_s"}}) {
      const double peak_deg_s = amp_rad * w / aux::kRadPerDeg;
      if (peak_deg_s > kMaxSweepRateDegS * (1.0 + 1e-12)) {
        char b[160];
        std::snprintf(b, sizeof b, "gives a peak head rate of %.0f deg/s (amplitude x 2 pi / period), more than %.0f",
                      peak_deg_s, kMaxSweepRateDegS);
        in.params.fail(key, b);
      }
    }
    window_ = read_window(in.params);
  }
  unsigned stages() const override { return kStageHead; }
  void apply_head(std::int64_t t_ns, HeadMotion& h) const override {
    if (!window_.contains(t_ns)) return;
    const double t = aux::seconds_from_ns(t_ns - window_.start_ns);
    h.yaw_rad += yaw_amp_rad_ * std::sin(yaw_w_ * t);
    h.yaw_rate_rad_s += yaw_amp_rad_ * yaw_w_ * std::cos(yaw_w_ * t);
    h.pitch_rad += pitch_amp_rad_ * std::sin(pitch_w_ * t);
    h.pitch_rate_rad_s += pitch_amp_rad_ * pitch_w_ * std::cos(pitch_w_ * t);
  }

 private:
  double yaw_amp_rad_ = 0.0, pitch_amp_rad_ = 0.0, yaw_w_ = 0.0, pitch_w_ = 0.0;
  TimeWindow window_;
};

}  // namespace

std::unique_ptr<Effect> make_head_sweep(EffectInit& init) {
  return std::make_unique<HeadSweep>(init);
}

}  // namespace gazelod::sim::effects
