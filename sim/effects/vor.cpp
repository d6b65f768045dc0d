// SPDX-License-Identifier: Apache-2.0
// vor: the vestibulo-ocular reflex. While the eye fixates, it counter-rotates the head's rotation
// since the fixation began, so the gaze stays on a world point while the head moves:
//   eye(t) = scale(H(t)^-1 H(a), gain) * in(t)
// with H the head orientation (world from head), `in` the eye-in-head direction that the gaze
// effects listed before this one give (saccades), a the fixation's start and scale() the
// rotation's angle times the gain. The gain of the human VOR is close to 1 (~0.95-1.0) for
// natural, active head rotations in the light (Leigh & Zee 2015, The Neurology of Eye Movements,
// ch. 2; Tomlinson, Saunders & Schwarz 1980: unity even in darkness for active high-frequency
// rotation). Only rotation is compensated: no translational VOR, no vergence, no latency
// (~8.6 ms, Collewijn & Smeets 2000).
//
// Fixation boundaries come from the incoming direction itself. This effect makes its own copies
// of the gaze effects before it (same specs, same random streams, hence the same values) and so
// can evaluate `in` at any time. Time from start_s is cut into 1 ms steps; a step over which
// `in` moves faster than 1 deg/s starts a movement (the saccades effect's fixations are exactly
// still), which lasts while it keeps moving. At its start the eye makes a main-sequence saccade
// (gaze/main_sequence.hpp) from where it is to where `in` lands relative to the head, so
// saccades land where the effects before put them and, starting from a counter-rotated eye,
// keep main-sequence durations and speeds; the counter-rotation restarts when the eye lands.
// When the counter-rotated eye would leave the oculomotor range (range_deg from straight
// ahead, or the incoming eccentricity when that is larger), a quick phase (a main-sequence
// saccade, as in vestibular nystagmus) takes it back to `in` and the counter-rotation restarts
// there. At end_s a last saccade hands the eye back to `in`. The gaze is continuous throughout.
//
// The schedule (holds, saccades, quick phases) is worked out step by step in time order, as far
// as the latest time asked for, like the saccades effect's: any order of queries gives the same
// values bit for bit.
#include "auxiliary/angles.hpp"
#include "auxiliary/time.hpp"
#include "gaze/main_sequence.hpp"
#include "sim/effects/effects.hpp"

#include <algorithm>
#include <climits>
#include <deque>
#include <vector>

namespace gazelod::sim::effects {
namespace {

constexpr std::int64_t kStepNs = aux::ns_from_ms(1.0);              // detection and range checks: 1 ms
constexpr double kMovingRadPerStep = 1.0 * aux::kRadPerDeg * 1e-3;  // 1 deg/s over one step
constexpr std::int64_t kMaxMoveSteps = 250;                         // a longer movement is followed in 250 ms pieces
constexpr double kRangeSlackRad = 1e-9;                             // rounding, not physiology
const glm::dvec3 kForward{0.0, 0.0, -1.0};

// q with its angle times s, about the same axis (the short way round).
glm::dquat scale_rotation(glm::dquat q, double s) {
  if (s == 1.0) return q;
  if (q.w < 0.0) q = -q;
  const glm::dvec3 v(q.x, q.y, q.z);
  const double sv = glm::length(v);
  if (sv == 0.0 || s == 0.0) return {1.0, 0.0, 0.0, 0.0};
  return glm::angleAxis(s * 2.0 * std::atan2(sv, q.w), v / sv);
}

double eccentricity_rad(const glm::dvec3& d) {
  return aux::angle_between_rad(d, kForward);
}

// One piece of the eye's path; it lasts until the next one starts.
struct Segment {
  bool saccade = false;
  std::int64_t start_ns = 0;
  // A saccade: from -> to along the main sequence, landing at end_ns.
  std::int64_t end_ns = 0;
  glm::dvec3 from{0.0, 0.0, -1.0}, to{0.0, 0.0, -1.0};
  double ratio = 0.5;  // mean / peak velocity
  // A hold: eye = scale(H(t)^-1 anchor_head, gain) * (t < land_until_ns ? land : in(t)).
  glm::dquat anchor_head{1.0, 0.0, 0.0, 0.0};
  std::int64_t land_until_ns = 0;
  glm::dvec3 land{0.0, 0.0, -1.0};
};

glm::dvec3 saccade_dir(const Segment& s, std::int64_t t_ns) {
  const double tau = static_cast<double>(t_ns - s.start_ns) / static_cast<double>(s.end_ns - s.start_ns);
  return glm::normalize(aux::slerp_direction(s.from, s.to, gaze::main_sequence::progress(tau, s.ratio)));
}

class Vor final : public Effect {
 public:
  explicit Vor(EffectInit& in) {
    gain_ = in.params.number("gain", 1.0, 0.0, 2.0);
    range_rad_ = in.params.number("range_deg", 45.0, 1.0, 90.0) * aux::kRadPerDeg;
    window_ = read_window(in.params);
    before_ = make_gaze_effects_before(in);
  }
  unsigned stages() const override { return kStageGaze; }

  void apply_gaze(std::int64_t t_ns, const EffectContext& ctx, glm::dvec3& dir) const override {
    if (t_ns < window_.start_ns) return;
    if (t_ns < window_.end_ns) {
      extend_to(t_ns, ctx);
      dir = eye_at(segments_[segment_index(t_ns, ctx)], t_ns, ctx, &dir);
      return;
    }
    const Segment& e = end_saccade(ctx);
    if (t_ns < e.end_ns) dir = saccade_dir(e, t_ns);
  }

  void apply_truth(std::int64_t t_ns, const EffectContext& ctx, EyeTruth& truth) const override {
    truth_at(t_ns, ctx, truth);
  }

 private:
  std::int64_t step_time(std::int64_t k) const { return window_.start_ns + k * kStepNs; }
  std::int64_t step_of(std::int64_t t_ns) const { return (t_ns - window_.start_ns) / kStepNs; }

  glm::dvec3 incoming(std::int64_t t_ns, const EffectContext& ctx) const {
    glm::dvec3 d = kForward;
    for (const std::unique_ptr<Effect>& e : before_) e->apply_gaze(t_ns, ctx, d);
    return d;
  }
  bool moves(const glm::dvec3& a, const glm::dvec3& b) const {
    return aux::angle_between_rad(a, b) > kMovingRadPerStep;
  }

  glm::dquat counter(const glm::dquat& anchor_head, std::int64_t t_ns, const EffectContext& ctx) const {
    return scale_rotation(glm::conjugate(ctx.head_at(t_ns).orientation) * anchor_head, gain_);
  }
  // What a hold counter-rotates: where the last saccade landed, then the incoming direction.
  glm::dvec3 source(const Segment& h, std::int64_t t_ns, const EffectContext& ctx, const glm::dvec3* in) const {
    if (t_ns < h.land_until_ns) return h.land;
    return in != nullptr ? *in : incoming(t_ns, ctx);
  }
  glm::dvec3 eye_at(const Segment& s, std::int64_t t_ns, const EffectContext& ctx, const glm::dvec3* in) const {
    if (s.saccade) return saccade_dir(s, t_ns);
    return glm::normalize(counter(s.anchor_head, t_ns, ctx) * source(s, t_ns, ctx, in));
  }
  bool out_of_range(const Segment& h, std::int64_t t_ns, const EffectContext& ctx, const glm::dvec3* in) const {
    const glm::dvec3 g = source(h, t_ns, ctx, in);
    const double limit = std::max(range_rad_, eccentricity_rad(g)) + kRangeSlackRad;
    return eccentricity_rad(counter(h.anchor_head, t_ns, ctx) * g) > limit;
  }

  // Only the newest kKeptSegments stay (memory bounded for any session length); a query older
  // than those works the schedule out again from the start: the same segments whatever the
  // order of queries, only slower (the frame loop asks at most a tracker latency back).
  static constexpr std::size_t kKeptSegments = 1024;

  // The segment that holds t (t in the window), after working the schedule out through t.
  std::size_t segment_index(std::int64_t t_ns, const EffectContext& ctx) const {
    if (first_index_ > 0 && t_ns < segments_.front().start_ns) {
      segments_.clear();
      first_index_ = 0;
      next_step_ = move_first_ = 0;
      prev_moving_ = false;
    }
    extend_to(t_ns, ctx);
    const auto it = std::upper_bound(segments_.begin(), segments_.end(), t_ns,
                                     [](std::int64_t t, const Segment& s) { return t < s.start_ns; });
    return static_cast<std::size_t>(std::prev(it) - segments_.begin());
  }
  void trim() const {
    while (segments_.size() > kKeptSegments) {
      segments_.pop_front();
      ++first_index_;
    }
  }

  // A main-sequence saccade from `from` at t to where the hold after it starts (land until
  // land_until, then the incoming direction), and that hold.
  void push_saccade(std::int64_t t_ns, const glm::dvec3& from, std::int64_t land_until_ns, const glm::dvec3& land,
                    const EffectContext& ctx) const {
    const double amp_deg = aux::angle_between_rad(from, land) * aux::kDegPerRad;
    Segment s;
    s.saccade = true;
    s.start_ns = t_ns;
    s.end_ns = t_ns + aux::ns_from_seconds(gaze::main_sequence::duration_s(amp_deg));
    s.from = from;
    s.ratio = gaze::main_sequence::velocity_ratio(amp_deg);
    Segment h;
    h.start_ns = s.end_ns;
    h.anchor_head = ctx.head_at(s.end_ns).orientation;
    h.land_until_ns = land_until_ns;
    h.land = land;
    s.to = source(h, s.end_ns, ctx, nullptr);  // the hold starts exactly there
    segments_.push_back(s);
    segments_.push_back(h);
    trim();
  }

  // Works the schedule out through step k + 1 for the step k that holds t: later steps only
  // add what starts after t.
  void extend_to(std::int64_t t_ns, const EffectContext& ctx) const {
    if (segments_.empty()) {
      Segment h;
      h.start_ns = h.land_until_ns = window_.start_ns;
      h.anchor_head = ctx.head_at(window_.start_ns).orientation;
      segments_.push_back(h);
      in_next_ = incoming(window_.start_ns, ctx);
    }
    const std::int64_t last = step_of(t_ns) + 1;
    for (; next_step_ <= last; ++next_step_) {
      const std::int64_t k = next_step_, tau = step_time(k);
      const glm::dvec3 in = in_next_;
      in_next_ = incoming(step_time(k + 1), ctx);
      // The range over (tau - 1 step, tau]: a quick phase where the eye would leave it.
      const Segment& h = segments_.back();
      if (k > 0 && !h.saccade && tau > h.start_ns && out_of_range(h, tau, ctx, &in)) {
        const Segment hold = h;
        std::int64_t lo = std::max(hold.start_ns, step_time(k - 1)), hi = tau;  // lo: in range
        while (hi - lo > 1) {
          const std::int64_t mid = lo + (hi - lo) / 2;
          (out_of_range(hold, mid, ctx, nullptr) ? hi : lo) = mid;
        }
        push_saccade(lo, eye_at(hold, lo, ctx, nullptr), hold.land_until_ns, source(hold, lo, ctx, nullptr), ctx);
      }
      // A movement of the incoming direction starting at tau: a saccade to where it lands.
      const bool mv = moves(in, in_next_);
      if (mv && (!prev_moving_ || (k - move_first_) % kMaxMoveSteps == 0)) {
        if (!prev_moving_) move_first_ = k;
        std::int64_t ke = k + 1;
        for (glm::dvec3 a = in_next_; ke < k + kMaxMoveSteps; ++ke) {
          const glm::dvec3 b = incoming(step_time(ke + 1), ctx);
          if (!moves(a, b)) break;
          a = b;
        }
        const std::int64_t me = step_time(ke);
        while (segments_.back().start_ns > tau) segments_.pop_back();  // a hold not yet begun
        const glm::dvec3 from = eye_at(segments_.back(), tau, ctx, &in);
        push_saccade(tau, from, me, incoming(me, ctx), ctx);
      }
      prev_moving_ = mv;
    }
  }

  // The saccade that hands the eye back to the incoming direction at end_s.
  const Segment& end_saccade(const EffectContext& ctx) const {
    if (!end_known_) {
      const std::int64_t t = window_.end_ns;
      const glm::dvec3 from = eye_at(segments_[segment_index(t, ctx)], t, ctx, nullptr);
      const double amp_deg = aux::angle_between_rad(from, incoming(t, ctx)) * aux::kDegPerRad;
      end_.saccade = true;
      end_.start_ns = t;
      end_.end_ns = amp_deg > 1e-7 ? t + aux::ns_from_seconds(gaze::main_sequence::duration_s(amp_deg)) : t;
      end_.from = from;
      end_.to = incoming(end_.end_ns, ctx);
      end_.ratio = gaze::main_sequence::velocity_ratio(amp_deg);
      end_known_ = true;
    }
    return end_;
  }

  // In the window this effect owns the eye: in a saccade (or quick phase) or not, and the
  // latest one ended where the hold after it began.
  void truth_at(std::int64_t t_ns, const EffectContext& ctx, EyeTruth& truth) const {
    if (t_ns < window_.start_ns) return;
    if (t_ns >= window_.end_ns) {
      const Segment& e = end_saccade(ctx);
      if (t_ns < e.end_ns)
        truth.in_saccade = true;
      else if (e.end_ns > e.start_ns)
        truth.last_saccade_end_ns = std::max(truth.last_saccade_end_ns, e.end_ns);
      return;
    }
    std::size_t i = segment_index(t_ns, ctx);
    truth.in_saccade = segments_[i].saccade;
    while (segments_[i].saccade && i > 0) --i;  // the latest hold: it began when the saccade before it landed
    if (first_index_ + i != 0)
      truth.last_saccade_end_ns = segments_[i].start_ns;
    else
      truth.last_saccade_end_ns = std::min(truth.last_saccade_end_ns, window_.start_ns);
  }

  double gain_ = 1.0, range_rad_ = 0.0;
  TimeWindow window_;
  std::vector<std::unique_ptr<Effect>> before_;  // copies of the gaze effects listed before
  // Lazily extended schedule (the Simulator is not thread-safe; the runtime holds one lock).
  mutable std::deque<Segment> segments_;
  mutable std::uint64_t first_index_ = 0;  // schedule index of segments_.front()
  mutable std::int64_t next_step_ = 0, move_first_ = 0;
  mutable bool prev_moving_ = false;
  mutable glm::dvec3 in_next_{0.0, 0.0, -1.0};
  mutable Segment end_;
  mutable bool end_known_ = false;
};

}  // namespace

std::unique_ptr<Effect> make_vor(EffectInit& init) {
  return std::make_unique<Vor>(init);
}

}  // namespace gazelod::sim::effects
