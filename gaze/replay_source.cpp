// SPDX-License-Identifier: Apache-2.0
#include "gaze/replay_source.hpp"

#include "auxiliary/time.hpp"
#include "auxiliary/angles.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace gazelod::gaze {

ReplaySource::ReplaySource(std::vector<TraceRecord> records, ReplayOptions options)
    : records_(std::move(records)), options_(options) {
  for (std::size_t i = 1; i < records_.size(); ++i)
    if (records_[i].gaze.t_ns < records_[i - 1].gaze.t_ns)
      throw std::invalid_argument("ReplaySource: record " + std::to_string(i) + " is earlier than the one before it");
  labels_.resize(records_.size(), GazeLabel::unknown);
  IvtClassifier ivt(options_.ivt);
  std::vector<LabeledSample> out;
  auto drain = [&] {
    for (const auto& ls : out) labels_[ls.index] = ls.label;
    out.clear();
  };
  for (const auto& r : records_) {
    ivt.push(r.gaze, out);
    drain();
  }
  ivt.finish(out);
  drain();
  if (records_.empty()) status_ = "trace is empty";
}

std::vector<TraceRecord> ReplaySource::load(RecordStream& stream) {
  std::vector<TraceRecord> out;
  TraceRecord r;
  while (stream.next(r)) out.push_back(r);
  return out;
}

std::optional<std::size_t> ReplaySource::locate(std::int64_t t) {
  if (records_.empty() || t < records_.front().gaze.t_ns) return std::nullopt;
  // Frame loops query increasing times: walk forward a few steps, else binary search.
  if (records_[cursor_].gaze.t_ns <= t) {
    for (int steps = 0; steps < 8; ++steps) {
      if (cursor_ + 1 >= records_.size() || records_[cursor_ + 1].gaze.t_ns > t) return cursor_;
      ++cursor_;
    }
  }
  auto it = std::upper_bound(records_.begin(), records_.end(), t,
                             [](std::int64_t v, const TraceRecord& r) { return v < r.gaze.t_ns; });
  cursor_ = static_cast<std::size_t>(it - records_.begin()) - 1;
  return cursor_;
}

std::optional<GazeSample> ReplaySource::sample_at(std::int64_t t_ns) {
  const std::int64_t t = t_ns - options_.time_offset_ns;
  const auto found = locate(t);
  if (!found) {
    status_ = records_.empty() ? "trace is empty" : "before the start of the trace";
    return std::nullopt;
  }
  const std::size_t i = *found;
  const GazeSample& a = records_[i].gaze;
  if (a.valid && i + 1 < records_.size()) {
    const GazeSample& b = records_[i + 1].gaze;
    const std::int64_t span = b.t_ns - a.t_ns;
    if (b.valid && span > 0 && span <= options_.max_interp_gap_ns && t > a.t_ns && labels_[i] != GazeLabel::saccade &&
        labels_[i + 1] != GazeLabel::saccade) {
      const double f = static_cast<double>(t - a.t_ns) / static_cast<double>(span);
      GazeSample s = a;
      s.t_ns = t_ns;
      s.direction = aux::slerp_direction(glm::normalize(a.direction), glm::normalize(b.direction), f);
      s.origin_m = a.origin_m + (b.origin_m - a.origin_m) * f;
      s.confidence = std::min(a.confidence, b.confidence);
      status_ = "ok";
      return s;
    }
  }
  // Hold the last valid sample, bounded in time (scan back at most hold_max of samples).
  for (std::size_t j = i + 1; j-- > 0;) {
    const GazeSample& g = records_[j].gaze;
    if (t - g.t_ns > options_.hold_max_ns) break;
    if (g.valid) {
      GazeSample s = g;
      s.t_ns = g.t_ns + options_.time_offset_ns;
      status_ = "ok";
      return s;
    }
  }
  status_ = "no valid gaze within " + std::to_string(aux::whole_ms_from_ns(options_.hold_max_ns)) + " ms";
  return std::nullopt;
}

std::optional<HeadSample> ReplaySource::head_at(std::int64_t t_ns) {
  const std::int64_t t = t_ns - options_.time_offset_ns;
  const auto found = locate(t);
  if (!found) return std::nullopt;
  const std::size_t i = *found;
  const TraceRecord& a = records_[i];
  if (a.has_head && a.head.valid && i + 1 < records_.size()) {
    const TraceRecord& b = records_[i + 1];
    const std::int64_t span = b.gaze.t_ns - a.gaze.t_ns;
    if (b.has_head && b.head.valid && span > 0 && span <= options_.max_interp_gap_ns && t > a.gaze.t_ns) {
      const double f = static_cast<double>(t - a.gaze.t_ns) / static_cast<double>(span);
      HeadSample h = a.head;
      h.t_ns = t_ns;
      glm::dquat qb = b.head.orientation;
      if (glm::dot(a.head.orientation, qb) < 0.0) qb = -qb;  // shortest path
      h.orientation = glm::normalize(glm::slerp(a.head.orientation, qb, f));
      h.position_m = a.head.position_m + (b.head.position_m - a.head.position_m) * f;
      return h;
    }
  }
  for (std::size_t j = i + 1; j-- > 0;) {
    const TraceRecord& r = records_[j];
    if (t - r.gaze.t_ns > options_.hold_max_ns) break;
    if (r.has_head && r.head.valid) {
      HeadSample h = r.head;
      h.t_ns = r.gaze.t_ns + options_.time_offset_ns;
      return h;
    }
  }
  return std::nullopt;
}

}  // namespace gazelod::gaze
