// SPDX-License-Identifier: Apache-2.0
// dropouts: the tracker loses the eye now and then. Time is cut into bursts of burst_ms; each
// burst is lost with probability `fraction`, drawn from (seed, effect, burst index).
#include "auxiliary/time.hpp"
#include "sim/effects/effects.hpp"

#include <algorithm>

namespace gazelod::sim::effects {
namespace {

class Dropouts final : public Effect {
 public:
  explicit Dropouts(EffectInit& in) : rng_(in.rng) {
    fraction_ = in.params.required_number("fraction", 0.0, 1.0);
    burst_ns_ = std::max<std::int64_t>(
        1, aux::ns_from_seconds(aux::seconds_from_ms(in.params.number("burst_ms", 20.0, 0.001, 1e5))));
  }
  unsigned stages() const override { return kStageTrackerSample; }
  void apply_sample(gaze::GazeSample& s) const override {
    const std::int64_t burst = s.t_ns >= 0 ? s.t_ns / burst_ns_ : -1 - (-1 - s.t_ns) / burst_ns_;
    if (rng_.uniform(static_cast<std::uint64_t>(burst)) < fraction_) {
      s.valid = false;
      s.confidence = 0.0f;
    }
  }

 private:
  aux::CounterRng rng_;
  double fraction_ = 0.0;
  std::int64_t burst_ns_ = 1;
};

}  // namespace

std::unique_ptr<Effect> make_dropouts(EffectInit& init) {
  return std::make_unique<Dropouts>(init);
}

}  // namespace gazelod::sim::effects
