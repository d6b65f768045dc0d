// SPDX-License-Identifier: Apache-2.0
// head_track: the head pose replayed from a recorded trace (gazelod's trace format, or any
// layout gaze/trace_open.hpp reads) with head columns. Trace time `offset_s` (default: its
// first row, with a head pose or not) plays at scenario time `start_s` (default 0); poses are interpolated (slerp /
// lerp) and the angular and linear velocities are those of the segment. Before the first row
// and after the last the pose is held (or, with "loop": true, the track repeats). With
// "relative": true the track moves the scenario's head as the recorded head moved from its
// first pose: that pose's heading (its yaw about +Y) is turned to the scenario's forward and its
// position to the scenario's head position; its pitch and roll stay, since gravity is the same
// in both worlds. Other head effects add on top.
#include "auxiliary/time.hpp"
#include "auxiliary/yaw_pitch.hpp"
#include "gaze/trace_error.hpp"
#include "gaze/trace_open.hpp"
#include "sim/effects/effects.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace gazelod::sim::effects {
namespace {

class HeadTrack final : public Effect {
 public:
  explicit HeadTrack(EffectInit& in) {
    const TraceParam trace = trace_param(in);
    const std::string& file = trace.name;
    loop_ = in.params.boolean("loop", false);
    const bool relative = in.params.boolean("relative", false);
    const bool has_offset = in.params.has("offset_s");
    const double offset_s = in.params.number("offset_s", 0.0, -1e9, 1e9);
    const double start_s = in.params.number("start_s", 0.0, -1e6, 1e6);
    std::optional<std::int64_t> first_row_ns;
    try {
      std::unique_ptr<gaze::RecordStream> stream = gaze::open_trace(trace.path, trace.format);
      if (!stream->has_head()) in.params.fail("file", file + ": the trace has no head columns");
      gaze::TraceRecord r;
      while (stream->next(r)) {
        if (!first_row_ns) first_row_ns = r.gaze.t_ns;  // the trace's first row, with a pose or not
        if (!r.has_head || !r.head.valid) continue;
        if (!t_ns_.empty() && r.head.t_ns <= t_ns_.back()) continue;  // keep times strictly increasing
        t_ns_.push_back(r.head.t_ns);
        q_.push_back(glm::normalize(r.head.orientation));
        p_.push_back(r.head.position_m);
      }
    } catch (const gaze::TraceError& e) {
      in.params.fail("file", e.what());
    }
    if (t_ns_.empty()) in.params.fail("file", file + ": no valid head pose in the trace");
    // The first row, as a gaze replay of the same file counts it (ReplaySource).
    const std::int64_t origin = has_offset ? aux::ns_from_seconds(offset_s) : *first_row_ns;
    const std::int64_t start = aux::ns_from_seconds(start_s);
    for (std::int64_t& t : t_ns_)
      if (__builtin_sub_overflow(t, origin, &t) || __builtin_add_overflow(t, start, &t))
        in.params.fail("file", file + ": trace times beyond +-292 years of offset_s");
    if (relative) make_relative();
  }
  unsigned stages() const override { return kStageHead; }
  // The first pose's heading turned to -Z and its position moved to the origin (the scenario's
  // head path then places it): a yaw-only rotation, atan2 of the forward's horizontal part.
  void make_relative() {
    const glm::dvec3 forward = q_.front() * glm::dvec3(0.0, 0.0, -1.0);
    const double horizontal = std::hypot(forward.x, forward.z);
    // Looking straight up or down the heading is undefined: take the head's up instead.
    const glm::dvec3 ahead = horizontal > 1e-6 ? forward : q_.front() * glm::dvec3(0.0, 1.0, 0.0) * -forward.y;
    const double yaw_rad = aux::yaw_pitch_of(ahead).yaw_rad;  // of the first pose, about +Y
    const glm::dquat undo = glm::angleAxis(-yaw_rad, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dvec3 first = p_.front();
    for (std::size_t i = 0; i < q_.size(); ++i) {
      q_[i] = glm::normalize(undo * q_[i]);
      p_[i] = undo * (p_[i] - first);
    }
  }
  void apply_head(std::int64_t t_ns, HeadMotion& h) const override {
    if (loop_ && t_ns_.size() > 1) {
      const std::int64_t span = t_ns_.back() - t_ns_.front();
      t_ns = t_ns_.front() + ((t_ns - t_ns_.front()) % span + span) % span;
    }
    h.has_track = true;
    const auto it = std::upper_bound(t_ns_.begin(), t_ns_.end(), t_ns);
    if (it == t_ns_.begin() || it == t_ns_.end()) {  // outside the track: hold
      const std::size_t i = it == t_ns_.begin() ? 0 : t_ns_.size() - 1;
      h.track = q_[i];
      h.position_m += p_[i];
      return;
    }
    const std::size_t i = static_cast<std::size_t>(it - t_ns_.begin()) - 1;
    const double dt_s = aux::seconds_from_ns(t_ns_[i + 1] - t_ns_[i]);
    const double f = static_cast<double>(t_ns - t_ns_[i]) / static_cast<double>(t_ns_[i + 1] - t_ns_[i]);
    glm::dquat b = q_[i + 1];
    if (glm::dot(q_[i], b) < 0.0) b = -b;  // the short way
    h.track = glm::normalize(glm::slerp(q_[i], b, f));
    glm::dquat d = b * glm::conjugate(q_[i]);  // world-frame rotation over the segment
    const glm::dvec3 v(d.x, d.y, d.z);
    const double s = glm::length(v);
    if (s > 1e-15) h.track_angular_velocity_rad_s = v / s * (2.0 * std::atan2(s, d.w) / dt_s);
    h.position_m += p_[i] + (p_[i + 1] - p_[i]) * f;
    h.velocity_m_s += (p_[i + 1] - p_[i]) / dt_s;
  }

 private:
  bool loop_ = false;
  std::vector<std::int64_t> t_ns_;
  std::vector<glm::dquat> q_;
  std::vector<glm::dvec3> p_;
};

}  // namespace

std::unique_ptr<Effect> make_head_track(EffectInit& init) {
  return std::make_unique<HeadTrack>(init);
}

}  // namespace gazelod::sim::effects
