// SPDX-License-Identifier: Apache-2.0
// tracker_latency: a sample taken at s reaches the application at s + latency_ms, so at time t
// the newest sample is one taken at or before t - latency.
#include "auxiliary/time.hpp"
#include "sim/effects/effects.hpp"

namespace gazelod::sim::effects {
namespace {

class TrackerLatency final : public Effect {
 public:
  explicit TrackerLatency(EffectInit& in) {
    latency_ns_ = aux::ns_from_seconds(aux::seconds_from_ms(in.params.required_number("latency_ms", 0.0, 1000.0)));
  }
  unsigned stages() const override { return kStageTrackerTiming; }
  void apply_timing(TrackerTiming& t) const override { t.latency_ns += latency_ns_; }

 private:
  std::int64_t latency_ns_ = 0;
};

}  // namespace

std::unique_ptr<Effect> make_tracker_latency(EffectInit& init) {
  return std::make_unique<TrackerLatency>(init);
}

}  // namespace gazelod::sim::effects
