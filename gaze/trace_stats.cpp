#include "gaze/trace_stats.hpp"

#include <algorithm>
#include <vector>

namespace gazelod::gaze {

TraceStats compute_trace_stats(RecordStream& stream, IvtOptions ivt, EventOptions events) {
  TraceStats st;
  IvtClassifier classifier(ivt);
  EventTracker tracker(events);
  std::vector<LabeledSample> labeled;
  double amplitude_sum = 0.0;
  auto take = [&](const EventTracker::Finished& f) {
    if (f.saccade) {
      ++st.saccades;
      amplitude_sum += f.saccade->amplitude_deg;
      st.max_saccade_peak_velocity_deg_s =
          std::max(st.max_saccade_peak_velocity_deg_s, f.saccade->peak_velocity_deg_s);
    }
    if (f.fixation) ++st.fixations;
  };
  auto drain = [&] {
    for (const auto& ls : labeled) take(tracker.push(ls));
    labeled.clear();
  };
  TraceRecord r;
  while (stream.next(r)) {
    if (st.samples == 0) st.first_ns = r.gaze.t_ns;
    st.last_ns = r.gaze.t_ns;
    ++st.samples;
    st.invalid += !r.gaze.valid;
    st.with_head += r.has_head;
    classifier.push(r.gaze, labeled);
    drain();
  }
  classifier.finish(labeled);
  drain();
  take(tracker.finish());
  st.duration_s = static_cast<double>(st.last_ns - st.first_ns) * 1e-9;
  if (st.samples >= 2 && st.duration_s > 0.0)
    st.rate_hz = static_cast<double>(st.samples - 1) / st.duration_s;
  if (st.samples > 0)
    st.invalid_fraction = static_cast<double>(st.invalid) / static_cast<double>(st.samples);
  if (st.saccades > 0) st.mean_saccade_amplitude_deg = amplitude_sum / static_cast<double>(st.saccades);
  return st;
}

}  // namespace gazelod::gaze
