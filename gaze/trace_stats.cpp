// SPDX-License-Identifier: Apache-2.0
#include "gaze/trace_stats.hpp"

#include "auxiliary/time.hpp"
#include "gaze/import_pupil_cloud.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace gazelod::gaze {
namespace {

// Per-sample event ids from per-sample labels given in sample order: each fixation run of at
// least min_fixation_ns gets an id (EventTracker's rule for counting one), each run of invalid
// samples one.
class EventIdBuilder {
 public:
  explicit EventIdBuilder(std::int64_t min_fixation_ns) : min_fixation_ns_(min_fixation_ns) {}
  void push(bool fixation, bool blink, std::int64_t t_ns) {
    if (!fixation) {
      close_fixation();
    } else if (!in_fixation_) {
      in_fixation_ = true;
      run_start_ = fixation_ids.size();
      run_first_ns_ = t_ns;
    }
    if (fixation) run_last_ns_ = t_ns;
    if (blink && !in_blink_) ++blinks_;
    in_blink_ = blink;
    fixation_ids.push_back(0);  // set when the run closes
    blink_ids.push_back(blink ? blinks_ : 0);
  }
  void finish() { close_fixation(); }

  std::vector<std::uint32_t> fixation_ids, blink_ids;

 private:
  void close_fixation() {
    if (!in_fixation_) return;
    in_fixation_ = false;
    if (run_last_ns_ - run_first_ns_ < min_fixation_ns_) return;
    ++fixations_;
    std::fill(fixation_ids.begin() + static_cast<std::ptrdiff_t>(run_start_), fixation_ids.end(), fixations_);
  }
  std::int64_t min_fixation_ns_;
  bool in_fixation_ = false, in_blink_ = false;
  std::size_t run_start_ = 0;
  std::int64_t run_first_ns_ = 0, run_last_ns_ = 0;
  std::uint32_t fixations_ = 0, blinks_ = 0;
};

ClassifierAgreement agreement_of(const EventIdBuilder& ours, const PupilCloudReader& pupil,
                                 const std::vector<std::uint32_t>& fixation_ids,
                                 const std::vector<std::uint32_t>& blink_ids) {
  ClassifierAgreement a;
  if (pupil.has_fixation_ids()) a.fixation = compare_events(ours.fixation_ids, fixation_ids);
  if (pupil.has_blink_ids()) a.blink = compare_events(ours.blink_ids, blink_ids);
  return a;
}

}  // namespace

TraceStats compute_trace_stats(RecordStream& stream, IvtOptions ivt, EventOptions events, ConditionerConfig conditioner,
                               TraceClassification* classification) {
  TraceStats st;
  IvtClassifier classifier(ivt);
  EventTracker tracker(events);
  std::vector<LabeledSample> labeled;
  double amplitude_sum = 0.0;

  // The agreement: only when the trace carries Pupil Cloud's own classification.
  const auto* pupil = dynamic_cast<const PupilCloudReader*>(&stream);
  EventIdBuilder ivt_ids(events.min_fixation_ns), ivdt_ids(events.min_fixation_ns);
  std::vector<std::uint32_t> pupil_fixation_ids, pupil_blink_ids;
  GazeConditioner ivdt(conditioner);

  auto take = [&](const EventTracker::Finished& f) {
    if (f.saccade) {
      ++st.saccades;
      amplitude_sum += f.saccade->amplitude_deg;
      st.max_saccade_peak_velocity_deg_s = std::max(st.max_saccade_peak_velocity_deg_s, f.saccade->peak_velocity_deg_s);
    }
    if (f.fixation) ++st.fixations;
    if (classification) {
      if (f.saccade) classification->saccades.push_back(*f.saccade);
      if (f.fixation) classification->fixations.push_back(*f.fixation);
    }
  };
  auto drain = [&] {
    for (const auto& ls : labeled) {
      // The classifier emits in stream order, also across its restart at the first head pose.
      if (classification) {
        classification->label.push_back(ls.label);
        classification->velocity_deg_s.push_back(ls.velocity_deg_s);
      }
      take(tracker.push(ls));
      if (pupil) ivt_ids.push(ls.label == GazeLabel::fixation, ls.label == GazeLabel::invalid, ls.sample.t_ns);
    }
    labeled.clear();
  };
  // In the world where the trace has head poses: a row without a valid pose holds the last one
  // (rows before the first stay in the head).
  std::optional<glm::dquat> last_head;
  TraceRecord r;
  while (stream.next(r)) {
    if (st.samples == 0) st.first_ns = r.gaze.t_ns;
    st.last_ns = r.gaze.t_ns;
    ++st.samples;
    st.invalid += !r.gaze.valid;
    // A valid pose only: a row whose head cells say head_valid = 0 is no pose, and counting it
    // printed "with head pose 1665" beside "in the head: no head poses".
    st.with_head += r.has_head && r.head.valid;
    if (r.has_head && r.head.valid) {
      if (!last_head && st.samples > 1) {  // from head to world: no velocity across the switch
        classifier.finish(labeled);
        drain();
        classifier = IvtClassifier(ivt);
      }
      last_head = r.head.orientation;
    }
    GazeSample classified = r.gaze;
    if (last_head)
      classified.direction = glm::normalize(*last_head * r.gaze.direction);
    else
      ++st.classified_in_head;
    classifier.push(classified, labeled);
    drain();
    if (pupil) {
      const PupilCloudEventIds ids = pupil->last_ids();
      pupil_fixation_ids.push_back(ids.fixation_id);
      pupil_blink_ids.push_back(ids.blink_id);
      // As the plugin runs it: every sample, then the estimate at that sample's time.
      const glm::dquat head = r.has_head && r.head.valid ? r.head.orientation : glm::dquat(1, 0, 0, 0);
      ivdt.push(r.gaze, head);
      const ConditionedGaze g = ivdt.at(r.gaze.t_ns, head);
      const EyeMotion motion = g.valid ? g.motion : EyeMotion::loss;
      ivdt_ids.push(motion == EyeMotion::fixation, motion == EyeMotion::loss, r.gaze.t_ns);
    }
  }
  st.classified_in_world = last_head.has_value();
  classifier.finish(labeled);
  drain();
  take(tracker.finish());
  st.duration_s = aux::seconds_from_ns(st.last_ns - st.first_ns);
  if (st.samples >= 2 && st.duration_s > 0.0) st.rate_hz = static_cast<double>(st.samples - 1) / st.duration_s;
  if (st.samples > 0) st.invalid_fraction = static_cast<double>(st.invalid) / static_cast<double>(st.samples);
  if (st.saccades > 0) st.mean_saccade_amplitude_deg = amplitude_sum / static_cast<double>(st.saccades);
  if (pupil) {
    ivt_ids.finish();
    ivdt_ids.finish();
    ReferenceAgreement& a = st.agreement.emplace();
    a.blinks_file = pupil->blinks().file;
    a.blinks_in_file = pupil->blinks().intervals.size();
    a.samples_in_blinks = pupil->samples_in_blinks();
    a.ivt = agreement_of(ivt_ids, *pupil, pupil_fixation_ids, pupil_blink_ids);
    a.ivdt = agreement_of(ivdt_ids, *pupil, pupil_fixation_ids, pupil_blink_ids);
  }
  return st;
}

}  // namespace gazelod::gaze
