// SPDX-License-Identifier: Apache-2.0
// saccades: fixations of random duration joined by saccades of random amplitude and direction
// that follow the main sequence (gaze/main_sequence.hpp). The whole schedule is drawn once, from
// (seed, effect, fixation index) in order, so any time can be asked for in any order.
#include "auxiliary/angles.hpp"
#include "auxiliary/time.hpp"
#include "auxiliary/yaw_pitch.hpp"
#include "gaze/main_sequence.hpp"
#include "sim/effects/effects.hpp"

#include <algorithm>
#include <deque>

namespace gazelod::sim::effects {
namespace {

struct Segment {
  std::int64_t fix_start_ns = 0;  // fixation on `from` ...
  std::int64_t sac_start_ns = 0;  // ... then a saccade to `to` ...
  std::int64_t sac_end_ns = 0;    // ... that lands here
  glm::dvec3 from{0, 0, -1}, to{0, 0, -1};
  double ratio = 0.5;  // mean / peak velocity
};

class Saccades final : public Effect {
 public:
  explicit Saccades(EffectInit& in) : rng_(in.rng) {
    fix_min_ms_ = in.params.number("fixation_min_ms", 150.0, 20.0, 1e5);
    fix_max_ms_ = in.params.number("fixation_max_ms", std::max(400.0, fix_min_ms_), fix_min_ms_, 1e5);
    amp_min_deg_ = in.params.number("amplitude_min_deg", 2.0, 0.0, 90.0);
    amp_max_deg_ = in.params.number("amplitude_max_deg", std::max(15.0, amp_min_deg_), amp_min_deg_, 90.0);
    range_rad_ = in.params.number("range_deg", 20.0, 0.0, 60.0) * aux::kRadPerDeg;
    window_ = read_window(in.params);
    next_start_ns_ = window_.start_ns;
    extend_to(std::min(window_.end_ns, window_.start_ns + aux::ns_from_seconds(60.0)));
  }
  unsigned stages() const override { return kStageGaze; }
  void apply_gaze(std::int64_t t_ns, const EffectContext&, glm::dvec3& dir) const override {
    if (!window_.contains(t_ns)) return;
    const Segment& s = segments_[segment_index(t_ns)];
    if (t_ns < s.sac_start_ns)
      dir = s.from;
    else if (t_ns >= s.sac_end_ns)
      dir = s.to;
    else {
      const double tau =
          static_cast<double>(t_ns - s.sac_start_ns) / static_cast<double>(s.sac_end_ns - s.sac_start_ns);
      dir = glm::normalize(aux::slerp_direction(s.from, s.to, gaze::main_sequence::progress(tau, s.ratio)));
    }
  }
  // In the window this effect owns the eye: in a saccade from sac_start to sac_end, and the
  // latest saccade ended where the current fixation began. After the window the eye is left
  // to earlier effects: a jump there, counted as a saccade ending at end_s.
  void apply_truth(std::int64_t t_ns, const EffectContext&, EyeTruth& truth) const override {
    if (t_ns < window_.start_ns) return;
    if (!window_.contains(t_ns)) {
      truth.last_saccade_end_ns = std::max(truth.last_saccade_end_ns, window_.end_ns);
      return;
    }
    const std::size_t i = segment_index(t_ns);
    const Segment& s = segments_[i];
    truth.in_saccade = t_ns >= s.sac_start_ns && t_ns < s.sac_end_ns;
    truth.pursuit_object = -1;
    if (first_index_ + i != 0) truth.last_saccade_end_ns = s.fix_start_ns;
  }

 private:
  // The schedule is drawn in order, fixation by fixation, each from (seed, effect, index), as
  // far as the latest time asked for; only the newest kKeptSegments stay (memory bounded for
  // any session length). A query older than those draws the schedule again from the start:
  // the same segments whatever the order of queries, only slower (the frame loop asks at most
  // a tracker latency back).
  static constexpr std::size_t kKeptSegments = 1024;  // ~5 min of fixations

  // The segment whose fixation starts at or before t (t in the window).
  std::size_t segment_index(std::int64_t t_ns) const {
    if (first_index_ > 0 && t_ns < segments_.front().fix_start_ns) {
      segments_.clear();
      first_index_ = 0;
      cur_ = {};
      next_start_ns_ = window_.start_ns;
    }
    extend_to(t_ns);
    const auto it = std::upper_bound(segments_.begin(), segments_.end(), t_ns,
                                     [](std::int64_t t, const Segment& s) { return t < s.fix_start_ns; });
    return static_cast<std::size_t>(std::prev(it) - segments_.begin());
  }

  void extend_to(std::int64_t t_ns) const {
    while (segments_.empty() || segments_.back().sac_end_ns <= t_ns) {
      const std::uint64_t i = first_index_ + segments_.size();
      Segment s;
      s.fix_start_ns = next_start_ns_;
      s.sac_start_ns =
          s.fix_start_ns + aux::ns_from_seconds(aux::seconds_from_ms(rng_.uniform(4 * i, fix_min_ms_, fix_max_ms_)));
      const double amp_rad = rng_.uniform(4 * i + 1, amp_min_deg_, amp_max_deg_) * aux::kRadPerDeg;
      const double theta = rng_.uniform(4 * i + 2, 0.0, 2.0 * std::numbers::pi);
      aux::YawPitch next{cur_.yaw_rad + amp_rad * std::cos(theta), cur_.pitch_rad + amp_rad * std::sin(theta)};
      if (std::hypot(next.yaw_rad, next.pitch_rad) > range_rad_) {  // turn back towards the centre
        next = {cur_.yaw_rad - amp_rad * std::cos(theta), cur_.pitch_rad - amp_rad * std::sin(theta)};
        const double ecc = std::hypot(next.yaw_rad, next.pitch_rad);
        if (ecc > range_rad_ && ecc > 0.0) next = {next.yaw_rad * range_rad_ / ecc, next.pitch_rad * range_rad_ / ecc};
      }
      s.from = aux::direction_from(cur_);
      s.to = aux::direction_from(next);
      const double amp_deg = aux::angle_between_rad(s.from, s.to) * aux::kDegPerRad;
      s.ratio = gaze::main_sequence::velocity_ratio(amp_deg);
      s.sac_end_ns = s.sac_start_ns + aux::ns_from_seconds(gaze::main_sequence::duration_s(amp_deg));
      segments_.push_back(s);
      if (segments_.size() > kKeptSegments) {
        segments_.pop_front();
        ++first_index_;
      }
      cur_ = next;
      next_start_ns_ = s.sac_end_ns;
    }
  }

  aux::CounterRng rng_;
  double fix_min_ms_ = 0, fix_max_ms_ = 0, amp_min_deg_ = 0, amp_max_deg_ = 0, range_rad_ = 0;
  TimeWindow window_;
  // Lazily extended schedule (the Simulator is not thread-safe; the runtime holds one lock).
  mutable std::deque<Segment> segments_;
  mutable std::uint64_t first_index_ = 0;  // schedule index of segments_.front()
  mutable aux::YawPitch cur_{};
  mutable std::int64_t next_start_ns_ = 0;
};

}  // namespace

std::unique_ptr<Effect> make_saccades(EffectInit& init) {
  return std::make_unique<Saccades>(init);
}

}  // namespace gazelod::sim::effects
