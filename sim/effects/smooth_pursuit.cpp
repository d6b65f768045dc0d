// SPDX-License-Identifier: Apache-2.0
// smooth_pursuit: the eye follows a named scene object with a velocity gain (pursuit gain is
// ~0.9 for slow targets and falls for fast ones). The lag that a gain below 1 builds up is
// removed by a catch-up saccade every catch_up_interval_s: within an interval starting at ts,
//   eye(t) = target(ts) + gain * (target(t) - target(ts))   (yaw / pitch in head space).
#include "auxiliary/time.hpp"
#include "auxiliary/yaw_pitch.hpp"
#include "sim/effects/effects.hpp"

#include <algorithm>

namespace gazelod::sim::effects {
namespace {

class SmoothPursuit final : public Effect {
 public:
  explicit SmoothPursuit(EffectInit& in) {
    const std::string name = in.params.required_string("object");
    index_ = object_index(in.scenario, in.params, "object", name);
    gain_ = in.params.number("gain", 0.9, 0.0, 1.5);
    interval_ns_ = aux::ns_from_seconds(in.params.number("catch_up_interval_s", 0.3, 0.01, 1e5));
    window_ = read_window(in.params);
  }
  unsigned stages() const override { return kStageGaze; }
  void apply_gaze(std::int64_t t_ns, const EffectContext& ctx, glm::dvec3& dir) const override {
    if (!window_.contains(t_ns)) return;
    const std::int64_t ts = window_.start_ns + (t_ns - window_.start_ns) / interval_ns_ * interval_ns_;
    const aux::YawPitch a = aux::yaw_pitch_of(target_dir(ctx, ts));
    const aux::YawPitch b = aux::yaw_pitch_of(target_dir(ctx, t_ns));
    double dyaw = b.yaw_rad - a.yaw_rad;
    dyaw = std::remainder(dyaw, 2.0 * std::numbers::pi);  // the short way round
    dir = aux::direction_from({a.yaw_rad + gain_ * dyaw, a.pitch_rad + gain_ * (b.pitch_rad - a.pitch_rad)});
  }
  // In the window the eye pursues the object; the jump onto it at start_s and each catch-up
  // saccade (instantaneous here; none with gain 1) end a saccade. After the window the eye
  // jumps back to what earlier effects say: a saccade ending at end_s.
  void apply_truth(std::int64_t t_ns, const EffectContext&, EyeTruth& truth) const override {
    if (t_ns < window_.start_ns) return;
    if (!window_.contains(t_ns)) {
      truth.last_saccade_end_ns = std::max(truth.last_saccade_end_ns, window_.end_ns);
      return;
    }
    const std::int64_t ts = window_.start_ns + (t_ns - window_.start_ns) / interval_ns_ * interval_ns_;
    truth.pursuit_object = static_cast<int>(index_);
    truth.in_saccade = false;
    truth.last_saccade_end_ns = gain_ != 1.0 ? ts : window_.start_ns;
  }

 private:
  glm::dvec3 target_dir(const EffectContext& ctx, std::int64_t t_ns) const {
    const HeadState h = ctx.head_at(t_ns);
    const glm::dvec3 rel = glm::conjugate(h.orientation) * (ctx.object_at(index_, t_ns).position_m - h.position_m);
    const double len = glm::length(rel);
    return len > 1e-9 ? rel / len : glm::dvec3(0, 0, -1);
  }
  std::size_t index_ = 0;
  double gain_ = 0.9;
  std::int64_t interval_ns_ = 1;
  TimeWindow window_;
};

}  // namespace

std::unique_ptr<Effect> make_smooth_pursuit(EffectInit& init) {
  return std::make_unique<SmoothPursuit>(init);
}

}  // namespace gazelod::sim::effects
