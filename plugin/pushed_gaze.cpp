// SPDX-License-Identifier: Apache-2.0
// Pushed gaze samples and the frames' head orientations (plugin/pushed_gaze.hpp).
#include "plugin/pushed_gaze.hpp"

#include "auxiliary/time.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace gazelod::plugin {
namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::optional<glm::dquat> unit(const glm::dquat& q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  if (!std::isfinite(n) || n < 1e-6) return std::nullopt;
  if (std::abs(n - 1.0) <= 1e-9) return q;  // unit already (a recorded pose): kept bit for bit
  return glm::dquat(q.w / n, q.x / n, q.y / n, q.z / n);
}

}  // namespace

void HeadHistory::push(std::int64_t t_ns, const glm::dquat& q) {
  // Frames arrive in time order; a repeated time replaces the newest entry.
  if (count_ > 0) {
    const std::size_t newest = (next_ + kFrames - 1) % kFrames;
    if (t_ns <= t_ns_[newest]) {
      if (t_ns == t_ns_[newest]) q_[newest] = q;
      return;
    }
  }
  t_ns_[next_] = t_ns;
  q_[next_] = q;
  next_ = (next_ + 1) % kFrames;
  if (count_ < kFrames) ++count_;
}

std::optional<glm::dquat> HeadHistory::at(std::int64_t t_ns) const {
  if (count_ == 0) return std::nullopt;
  const std::size_t oldest = (next_ + kFrames - count_) % kFrames;
  if (t_ns <= t_ns_[oldest]) return q_[oldest];
  for (std::size_t k = 1; k < count_; ++k) {
    const std::size_t b = (oldest + k) % kFrames, a = (oldest + k - 1) % kFrames;
    if (t_ns <= t_ns_[b]) {
      const double s = static_cast<double>(t_ns - t_ns_[a]) / static_cast<double>(t_ns_[b] - t_ns_[a]);
      return glm::slerp(q_[a], q_[b], s);  // glm takes the short way for q and -q
    }
  }
  return q_[(next_ + kFrames - 1) % kFrames];
}

PushResult PushedGazeSource::push(const PushedSample& in, std::string& why) {
  PushedSample s = in;
  if (s.sample.valid) {
    const double len = glm::length(s.sample.direction);
    if (!finite(s.sample.direction) || !std::isfinite(len) || len < 1e-9) {
      why =
          "gazelod: gaze sample direction must be finite and non-zero (push the sample with GZL_GAZE_SAMPLE_VALID "
          "cleared for a blink or lost tracking)";
      return PushResult::invalid;
    }
    if (std::abs(len - 1.0) > 1e-9) s.sample.direction /= len;  // a unit one is kept bit for bit
  }
  if (!finite(s.sample.origin_m) || glm::length(s.sample.origin_m) > 1.0) {
    why =
        "gazelod: gaze sample origin_m must be finite and within 1 m of the head's origin (it is the eye, in head "
        "space)";
    return PushResult::invalid;
  }
  if (s.has_head_orientation) {
    const auto q = unit(s.head_orientation);
    if (!q) {
      why =
          "gazelod: gaze sample head_orientation must be a finite, non-zero quaternion (or clear "
          "GZL_GAZE_SAMPLE_HEAD_ORIENTATION)";
      return PushResult::invalid;
    }
    s.head_orientation = *q;
  }
  if (have_last_t_ && s.sample.t_ns < last_t_ns_) {
    why = "gazelod: gaze sample at " + std::to_string(s.sample.t_ns) + " ns is older than the previous one (" +
          std::to_string(last_t_ns_) + " ns); push samples in time order, on the frame loop's clock";
    return PushResult::out_of_order;
  }
  if (have_frame_ && s.sample.t_ns > frame_t_ns_ + lead_ns_) {
    why = "gazelod: gaze sample at " + std::to_string(s.sample.t_ns) + " ns is more than " +
          std::to_string(aux::whole_ms_from_ns(lead_ns_)) + " ms after the last frame's display time (" +
          std::to_string(frame_t_ns_) + " ns); stamp samples on the frame loop's clock (XrTime in OpenXR mode)";
    return PushResult::in_future;
  }
  ring_[next_] = s;
  next_ = (next_ + 1) % kSamples;
  if (count_ < kSamples) ++count_;
  have_last_t_ = true;
  last_t_ns_ = s.sample.t_ns;
  return PushResult::ok;
}

std::optional<gaze::GazeSample> PushedGazeSource::sample_at(std::int64_t t_ns) {
  last_head_.reset();
  for (std::size_t k = 0; k < count_; ++k) {
    const PushedSample& p = ring_[(next_ + kSamples - 1 - k) % kSamples];
    if (p.sample.t_ns > t_ns) continue;
    if (t_ns - p.sample.t_ns > max_age_ns_) break;
    const std::optional<glm::dquat> head =
        p.has_head_orientation ? std::optional<glm::dquat>(p.head_orientation) : heads_.at(p.sample.t_ns);
    if (!p.sample.valid) {
      // A blink: handed on as invalid, so the plugin holds its estimate through it as it does
      // for the runtime's gaze (gaze_arbiter.hpp, blink_bridge_ns).
      status_ = "the application pushed an invalid sample (blink or lost tracking)";
      return p.sample;
    }
    gaze::GazeSample s = p.sample;
    if (p.in_world) {
      if (!head) {
        status_ = "a sample in the base space, but no head pose yet to bring it into the head";
        return std::nullopt;
      }
      s.direction = glm::conjugate(*head) * s.direction;
    }
    last_head_ = head;
    status_ = "ok";
    return s;
  }
  status_ = count_ == 0 ? none_status_ : stale_status_;  // copies into status_'s own room: no allocation
  return std::nullopt;
}

void PushedGazeSource::frame_time(std::int64_t t_ns) {
  const bool first = !have_frame_;
  frame_t_ns_ = t_ns;
  have_frame_ = true;
  if (!first) return;
  std::size_t dropped = 0;
  while (count_ > 0) {
    const std::size_t newest = (next_ + kSamples - 1) % kSamples;
    if (ring_[newest].sample.t_ns <= t_ns + lead_ns_) break;
    next_ = newest;
    --count_;
    ++dropped;
  }
  if (dropped == 0) return;
  have_last_t_ = count_ > 0;
  if (have_last_t_) last_t_ns_ = ring_[(next_ + kSamples - 1) % kSamples].sample.t_ns;
  none_status_ = std::to_string(dropped) + " sample(s) pushed before the first frame were stamped more than " +
                 std::to_string(aux::whole_ms_from_ns(lead_ns_)) +
                 " ms after its display time (another clock?) and were dropped; stamp samples on the frame loop's "
                 "clock";
}

}  // namespace gazelod::plugin
