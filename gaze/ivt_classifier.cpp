// SPDX-License-Identifier: Apache-2.0
#include "gaze/ivt_classifier.hpp"

#include "auxiliary/time.hpp"
#include "auxiliary/angles.hpp"

#include <cmath>

namespace gazelod::gaze {

IvtClassifier::IvtClassifier(IvtOptions options) : options_(options) {
  if (options_.half_window < 1) options_.half_window = 1;
}

void IvtClassifier::push(const GazeSample& sample, std::vector<LabeledSample>& out) {
  window_.push_back(sample);
  const auto k = static_cast<std::size_t>(options_.half_window);
  while (window_.size() > centre_ + k) emit_front(out);
}

void IvtClassifier::finish(std::vector<LabeledSample>& out) {
  while (centre_ < window_.size()) emit_front(out);
}

void IvtClassifier::emit_front(std::vector<LabeledSample>& out) {
  const auto k = static_cast<std::size_t>(options_.half_window);
  const GazeSample& c = window_[centre_];
  LabeledSample ls{c, next_index_ + centre_, GazeLabel::invalid, 0.0};
  if (c.valid) {
    // Contiguous valid neighbours, stopping at an invalid sample or a gap.
    std::size_t lo = centre_, hi = centre_;
    while (lo > 0 && centre_ - (lo - 1) <= k && window_[lo - 1].valid &&
           window_[lo].t_ns - window_[lo - 1].t_ns <= options_.max_gap_ns)
      --lo;
    while (hi + 1 < window_.size() && (hi + 1) - centre_ <= k && window_[hi + 1].valid &&
           window_[hi + 1].t_ns - window_[hi].t_ns <= options_.max_gap_ns)
      ++hi;
    ls.label = GazeLabel::unknown;
    // A one-sided stub of a window (trace ends, next to blinks) has far noisier slopes: such
    // samples stay 'unknown' rather than risk a false saccade.
    if (hi - lo + 1 >= 2 * k) {
      glm::dvec3 e1, e2;
      const glm::dvec3 cd = glm::normalize(c.direction);
      aux::tangent_basis(cd, e1, e2);
      // Least-squares slope of each angular component against time (seconds from centre).
      double st = 0, sx = 0, sy = 0, stt = 0, stx = 0, sty = 0;
      const double n = static_cast<double>(hi - lo + 1);
      for (std::size_t j = lo; j <= hi; ++j) {
        const double t = aux::seconds_from_ns(window_[j].t_ns - c.t_ns);
        const glm::dvec2 a = aux::angular_offset_rad(window_[j].direction, cd, e1, e2);
        st += t;
        sx += a.x;
        sy += a.y;
        stt += t * t;
        stx += t * a.x;
        sty += t * a.y;
      }
      const double denom = n * stt - st * st;
      if (denom > 1e-18) {  // not all at the same time stamp
        const double vx = (n * stx - st * sx) / denom, vy = (n * sty - st * sy) / denom;
        ls.velocity_deg_s = std::hypot(vx, vy) * aux::kDegPerRad;
        ls.label = ls.velocity_deg_s > options_.saccade_threshold_deg_s ? GazeLabel::saccade : GazeLabel::fixation;
      }
    }
  }
  out.push_back(ls);
  ++centre_;
  // Keep k samples to the left of the centre.
  while (centre_ > k) {
    window_.pop_front();
    --centre_;
    ++next_index_;
  }
}

std::vector<LabeledSample> classify_ivt(const std::vector<GazeSample>& samples, IvtOptions options) {
  IvtClassifier c(options);
  std::vector<LabeledSample> out;
  out.reserve(samples.size());
  for (const auto& s : samples) c.push(s, out);
  c.finish(out);
  return out;
}

}  // namespace gazelod::gaze
