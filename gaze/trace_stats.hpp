// SPDX-License-Identifier: Apache-2.0
// Summary of a trace, computed in one streaming pass (the `gazelod trace stats` numbers).
#pragma once

#include "gaze/gaze_agreement.hpp"
#include "gaze/gaze_conditioner.hpp"
#include "gaze/gaze_events.hpp"
#include "gaze/record_stream.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gazelod::gaze {

// One classifier against the reference classification a trace carries. Ours, per sample:
// fixation = in a fixation run of at least EventOptions::min_fixation_ns (the fixations
// TraceStats counts); blink = an invalid sample (I-VT label `invalid`, I-VDT motion `loss`),
// each run of them one event.
struct ClassifierAgreement {
  std::optional<EventAgreement> fixation;  // nullopt: the trace has no reference fixation ids
  std::optional<EventAgreement> blink;     // nullopt: no reference blink ids
};

// For Pupil Cloud traces (import_pupil_cloud.hpp): agreement with its `fixation id` /
// `blink id`. Its blinks file, when there is one, made those samples invalid before either
// classifier saw them, so blink agreement then checks that import, not a blink detector.
struct ReferenceAgreement {
  std::string blinks_file;  // "" = none beside the trace
  std::size_t blinks_in_file = 0;
  std::size_t samples_in_blinks = 0;  // marked invalid from the blinks file
  ClassifierAgreement ivt;            // trace stats' classifier (IvtClassifier)
  ClassifierAgreement ivdt;           // the plugin's (GazeConditioner's I-VDT; pursuit is not fixation)
};

struct TraceStats {
  std::size_t samples = 0;
  std::size_t invalid = 0;
  std::size_t with_head = 0;  // samples with a valid head pose
  std::int64_t first_ns = 0, last_ns = 0;
  double duration_s = 0.0;        // last - first sample time
  double rate_hz = 0.0;           // (samples - 1) / duration; 0 with < 2 samples
  double invalid_fraction = 0.0;  // invalid / samples; 0 when empty
  // Saccades and fixations are classified in the world from the first valid head pose on (the
  // eye-in-head gaze turned by the last pose; the classifier restarts there, so no velocity is
  // taken across the switch), in the head before it. In the head, the reflex that keeps the
  // eyes on a point while the head turns reads as eye motion.
  bool classified_in_world = false;    // some samples were (the trace has head poses)
  std::size_t classified_in_head = 0;  // samples before the first head pose
  std::size_t saccades = 0;
  std::size_t fixations = 0;  // runs of at least EventOptions::min_fixation_ns
  double mean_saccade_amplitude_deg = 0.0;
  double max_saccade_peak_velocity_deg_s = 0.0;
  // Only for traces with a reference classification (Pupil Cloud); it keeps 6 ids per sample
  // (24 bytes: 17 MB for an hour at 200 Hz), the rest of the pass streams.
  std::optional<ReferenceAgreement> agreement;
};

// The per-sample classification behind TraceStats's counts (the Python binding's classify):
// one label and velocity per sample in stream order, and the events the counts count.
struct TraceClassification {
  std::vector<GazeLabel> label;
  std::vector<double> velocity_deg_s;  // 0 unless fixation or saccade
  std::vector<SaccadeEvent> saccades;
  std::vector<FixationEvent> fixations;  // runs of at least EventOptions::min_fixation_ns
};

// Reads `stream` to its end (TraceError propagates in strict mode). `conditioner`: the I-VDT
// settings for the agreement (the plugin's defaults; settings validate_conditioner_config refuses
// throw std::invalid_argument before reading). `classification`: also filled when given.
TraceStats compute_trace_stats(RecordStream& stream, IvtOptions ivt = {}, EventOptions events = {},
                               ConditionerConfig conditioner = {}, TraceClassification* classification = nullptr);

}  // namespace gazelod::gaze
