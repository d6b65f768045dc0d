// SPDX-License-Identifier: Apache-2.0
// gaze_track: the true eye direction replayed from a recorded trace (gazelod's trace format, or
// any layout gaze/trace_open.hpp reads), so that a real person's eye movements, not the
// simulator's model of them, are what the plugin is audited against. Trace time `offset_s`
// (default: its first row) plays at scenario time `start_s` (default 0), as head_track counts
// it, so the two effects on the same file stay together. Between two valid samples the
// direction is interpolated along the great circle; in a run of invalid samples (a blink or a
// loss) the last valid direction holds, and after the last row the last one.
//
// The ground truth the audit needs comes from the recording too, labelled once when the effect
// is made: a saccade wherever the recording's own I-VT labels (Salvucci & Goldberg 2000;
// gaze/ivt_classifier.hpp, at `saccade_threshold_deg_s`) call one, classified in the world
// when the trace has head poses, since in the head a reflex holding the world still through a
// head turn moves as fast as a small saccade; a blink over each run of invalid samples, with a
// saccade in it where the eye reopens more than `blink_saccade_deg` (2) away, in the head and
// in the world (people often blink as they make a saccade; post-saccadic suppression then runs
// from the reopening, as the audit counts it after any saccade). The
// tracker effects then act on this gaze; a tracker sample taken inside an invalid run is
// invalid, as the recording was.
//
// What the recording is not: noise-free. Its own tracker's noise and latency are in it, so the
// truth the audit holds the plugin to is that device's view of the eye (docs/evaluation.md,
// "Real eyes").
#include "auxiliary/time.hpp"
#include "gaze/ivt_classifier.hpp"
#include "gaze/trace_error.hpp"
#include "gaze/trace_open.hpp"
#include "sim/effects/effects.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace gazelod::sim::effects {
namespace {

// [start, end) in scenario time.
struct Interval {
  std::int64_t start_ns = 0, end_ns = 0;
};

class GazeTrack final : public Effect {
 public:
  explicit GazeTrack(EffectInit& in) {
    const TraceParam trace = trace_param(in);
    const std::string& file = trace.name;
    const bool has_offset = in.params.has("offset_s");
    const double offset_s = in.params.number("offset_s", 0.0, -1e9, 1e9);
    const double start_s = in.params.number("start_s", 0.0, -1e6, 1e6);
    gaze::IvtOptions ivt;
    ivt.saccade_threshold_deg_s =
        in.params.number("saccade_threshold_deg_s", gaze::main_sequence::kIvtThreshold_deg_s, 5.0, 1000.0);
    const double blink_saccade_deg = in.params.number("blink_saccade_deg", 2.0, 0.1, 90.0);
    std::vector<gaze::GazeSample> rows;   // in the head: what the eye did
    std::vector<gaze::GazeSample> world;  // the same in the world, for the labels
    std::size_t poses = 0;
    try {
      std::unique_ptr<gaze::RecordStream> stream = gaze::open_trace(trace.path, trace.format);
      gaze::TraceRecord r;
      while (stream->next(r)) {
        gaze::GazeSample s = r.gaze;
        const double len = glm::length(s.direction);
        s.valid = s.valid && std::isfinite(len) && len > 1e-9;
        if (s.valid) s.direction /= len;
        gaze::GazeSample w = s;
        const bool posed = r.has_head && r.head.valid;
        if (posed) w.direction = glm::normalize(r.head.orientation) * s.direction;
        w.valid = s.valid && posed;  // no pose: no world direction to label
        // Strictly increasing times (the reader refuses a time going back): of two rows at one
        // time, a valid one wins, so that a duplicate makes no blink the recording has not.
        if (!rows.empty() && s.t_ns <= rows.back().t_ns) {
          if (!s.valid || rows.back().valid) continue;
          poses -= world.back().valid ? 1 : 0;
          rows.pop_back(), world.pop_back();
        }
        poses += w.valid ? 1 : 0;
        rows.push_back(s);
        world.push_back(w);
      }
    } catch (const gaze::TraceError& e) {
      in.params.fail("file", e.what());
    }
    // Without two posed samples there is no world to label in: the head it is (a recording
    // whose head stood still, or one with head columns but no pose).
    if (poses < 2) world = rows;
    const auto valid = [](const gaze::GazeSample& s) { return s.valid; };
    if (std::none_of(rows.begin(), rows.end(), valid)) in.params.fail("file", file + ": no valid gaze sample");
    const std::int64_t origin = has_offset ? aux::ns_from_seconds(offset_s) : rows.front().t_ns;
    const std::int64_t start = aux::ns_from_seconds(start_s);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      std::int64_t t = rows[i].t_ns;
      if (__builtin_sub_overflow(t, origin, &t) || __builtin_add_overflow(t, start, &t))
        in.params.fail("file", file + ": trace times beyond +-292 years of offset_s");
      rows[i].t_ns = world[i].t_ns = t;
    }
    label(world, ivt);
    // Keep the valid samples for the direction; invalid ones only mark their runs.
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (!rows[i].valid) continue;
      t_ns_.push_back(rows[i].t_ns);
      dir_.push_back(rows[i].direction);
      next_valid_.push_back(i + 1 < rows.size() && rows[i + 1].valid);
    }
    for (std::size_t i = 0; i < rows.size();) {
      if (rows[i].valid) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < rows.size() && !rows[j].valid) ++j;
      // Closed from the first invalid sample to the next valid one (or on, after the last row).
      blinks_.push_back({rows[i].t_ns, j < rows.size() ? rows[j].t_ns : INT64_MAX});
      // The eye moved while closed, in the head and in the world alike (a reflex or a head
      // carrying the eye moves it in only one): a saccade in the blink, over when it reopens.
      if (i > 0 && j < rows.size() && rows[i - 1].valid && world[i - 1].valid && world[j].valid &&
          angle_deg(rows[i - 1].direction, rows[j].direction) > blink_saccade_deg &&
          angle_deg(world[i - 1].direction, world[j].direction) > blink_saccade_deg)
        blink_saccade_ends_.push_back(rows[j].t_ns);
      i = j;
    }
  }

  unsigned stages() const override { return kStageGaze | kStageTrackerSample; }

  void apply_gaze(std::int64_t t_ns, const EffectContext&, glm::dvec3& dir) const override { dir = direction_at(t_ns); }

  void apply_sample(gaze::GazeSample& s) const override {
    if (inside(blinks_, s.t_ns)) {
      s.valid = false;
      s.confidence = 0.0f;
    }
  }

  void apply_truth(std::int64_t t_ns, const EffectContext&, EyeTruth& truth) const override {
    truth.in_saccade = inside(saccades_, t_ns);
    if (inside(blinks_, t_ns)) truth.in_blink = true;
    // The latest saccade that has ended by t (the recording's own events only).
    const auto it = std::upper_bound(saccades_.begin(), saccades_.end(), t_ns,
                                     [](std::int64_t t, const Interval& s) { return t < s.end_ns; });
    truth.last_saccade_end_ns = it == saccades_.begin() ? INT64_MIN : std::prev(it)->end_ns;
    const auto b = std::upper_bound(blink_saccade_ends_.begin(), blink_saccade_ends_.end(), t_ns);
    if (b != blink_saccade_ends_.begin())
      truth.last_saccade_end_ns = std::max(truth.last_saccade_end_ns, *std::prev(b));
  }

 private:
  // Saccades: each run of saccade labels, from its first sample to the sample after its last
  // (the eye is at the landing by then), so that a one-sample saccade still has a length.
  void label(const std::vector<gaze::GazeSample>& world, const gaze::IvtOptions& ivt) {
    const std::vector<gaze::LabeledSample> labels = gaze::classify_ivt(world, ivt);
    for (std::size_t i = 0; i < labels.size();) {
      if (labels[i].label != gaze::GazeLabel::saccade) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < labels.size() && labels[j].label == gaze::GazeLabel::saccade) ++j;
      const std::int64_t end = j < world.size() ? world[j].t_ns : world.back().t_ns + 1;
      saccades_.push_back({world[i].t_ns, end});
      i = j;
    }
  }

  static bool inside(const std::vector<Interval>& v, std::int64_t t_ns) {
    const auto it =
        std::upper_bound(v.begin(), v.end(), t_ns, [](std::int64_t t, const Interval& s) { return t < s.start_ns; });
    return it != v.begin() && t_ns < std::prev(it)->end_ns;
  }

  glm::dvec3 direction_at(std::int64_t t_ns) const {
    const auto it = std::upper_bound(t_ns_.begin(), t_ns_.end(), t_ns);
    if (it == t_ns_.begin()) return dir_.front();
    const std::size_t i = static_cast<std::size_t>(it - t_ns_.begin()) - 1;
    // After the last sample, or from the last valid sample before an invalid run to the next
    // valid one: the last valid direction holds (not drifting toward where the eye reopens).
    if (it == t_ns_.end() || !next_valid_[i]) return dir_[i];
    const double f = static_cast<double>(t_ns - t_ns_[i]) / static_cast<double>(t_ns_[i + 1] - t_ns_[i]);
    return slerp_unit(dir_[i], dir_[i + 1], f);
  }

  static double angle_deg(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / std::numbers::pi;
  }

  // Great-circle interpolation between unit vectors (atan2 for the angle: exact near 0).
  static glm::dvec3 slerp_unit(const glm::dvec3& a, const glm::dvec3& b, double f) {
    const glm::dvec3 axis = glm::cross(a, b);
    const double s = glm::length(axis);
    const double angle = std::atan2(s, glm::dot(a, b));
    if (s < 1e-12) return a;
    const glm::dvec3 k = axis / s;
    const double t = angle * f;
    // Rodrigues: a rotated by t about k (a is perpendicular to k).
    return glm::normalize(a * std::cos(t) + glm::cross(k, a) * std::sin(t));
  }

  std::vector<std::int64_t> t_ns_;  // valid samples only, increasing
  std::vector<glm::dvec3> dir_;     // unit, head space
  std::vector<bool> next_valid_;    // the recording's next row is valid too: interpolate to it
  std::vector<Interval> saccades_, blinks_;
  std::vector<std::int64_t> blink_saccade_ends_;  // where a blink with a saccade in it reopens
};

}  // namespace

std::unique_ptr<Effect> make_gaze_track(EffectInit& init) {
  return std::make_unique<GazeTrack>(init);
}

}  // namespace gazelod::sim::effects
