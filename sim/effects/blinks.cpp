// SPDX-License-Identifier: Apache-2.0
// blinks: the eye closes for duration_ms about rate_per_min times a minute (people blink
// ~15-20 times a minute, 100-300 ms each). Time is cut into periods of 60 / rate s; one blink
// starts at a random offset in each (seed, effect, period index). Samples in a blink are invalid.
#include "auxiliary/time.hpp"
#include "sim/effects/effects.hpp"

namespace gazelod::sim::effects {
namespace {

class Blinks final : public Effect {
 public:
  explicit Blinks(EffectInit& in) : rng_(in.rng) {
    const double rate_per_min = in.params.number("rate_per_min", 15.0, 0.1, 120.0);
    blink_ns_ = aux::ns_from_seconds(aux::seconds_from_ms(in.params.number("duration_ms", 150.0, 1.0, 1000.0)));
    period_ns_ = aux::ns_from_seconds(60.0 / rate_per_min);
    if (blink_ns_ >= period_ns_) in.params.fail("duration_ms", "must be shorter than 60 s / rate_per_min");
  }
  unsigned stages() const override { return kStageTrackerSample; }
  void apply_sample(gaze::GazeSample& s) const override {
    if (closed(s.t_ns)) {
      s.valid = false;
      s.confidence = 0.0f;
    }
  }
  void apply_truth(std::int64_t t_ns, const EffectContext&, EyeTruth& truth) const override {
    if (closed(t_ns)) truth.in_blink = true;
  }

 private:
  bool closed(std::int64_t t_ns) const {
    if (t_ns < 0) return false;
    const std::int64_t k = t_ns / period_ns_;
    const double slack_ns = static_cast<double>(period_ns_ - blink_ns_);
    const std::int64_t start =
        k * period_ns_ + static_cast<std::int64_t>(rng_.uniform(static_cast<std::uint64_t>(k)) * slack_ns);
    return t_ns >= start && t_ns < start + blink_ns_;
  }
  aux::CounterRng rng_;
  std::int64_t blink_ns_ = 0, period_ns_ = 1;
};

}  // namespace

std::unique_ptr<Effect> make_blinks(EffectInit& init) {
  return std::make_unique<Blinks>(init);
}

}  // namespace gazelod::sim::effects
