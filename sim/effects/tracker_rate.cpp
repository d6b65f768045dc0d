// SPDX-License-Identifier: Apache-2.0
// tracker_rate: the tracker samples at rate_hz (samples at k / rate from time 0); between
// samples the application sees the newest one. Default: the display preset's eye-tracking rate.
#include "auxiliary/time.hpp"
#include "sim/effects/effects.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::sim::effects {
namespace {

class TrackerRate final : public Effect {
 public:
  explicit TrackerRate(EffectInit& in) {
    const double preset_hz = in.scenario.display.eye_tracking_hz;
    if (!in.params.has("rate_hz") && !(preset_hz > 0.0))
      in.params.fail("rate_hz", "missing (the display has no eye-tracking rate to default to)");
    const double rate_hz = in.params.number("rate_hz", preset_hz, 1.0, 10000.0);
    period_ns_ = std::max<std::int64_t>(1, aux::period_ns_from_hz(rate_hz));
  }
  unsigned stages() const override { return kStageTrackerTiming; }
  void apply_timing(TrackerTiming& t) const override { t.period_ns = period_ns_; }

 private:
  std::int64_t period_ns_ = 1;
};

}  // namespace

std::unique_ptr<Effect> make_tracker_rate(EffectInit& init) {
  return std::make_unique<TrackerRate>(init);
}

}  // namespace gazelod::sim::effects
