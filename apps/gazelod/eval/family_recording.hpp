// SPDX-License-Identifier: Apache-2.0
// gazelod eval family --recording FILE: a real person's eyes (and head, when the trace has
// poses) under the family's displays, trackers and object fields. Each seed's scenario keeps
// its display, its tracker (rate, latency, noise, dropouts, a calibration offset) and its
// field; its scripted head motion, eye movements and blinks give way to the recording, replayed
// by head_track and gaze_track (sim/scenarios/README.md), and a walking seed's field stops
// coming toward the viewer (the recorded head moves as it moved). The truth is then the recording's:
// see docs/evaluation.md, "Real eyes", for what that does and does not measure.
#pragma once

#include "gaze/trace_open.hpp"

#include <string>

namespace gazelod::cli {

struct FamilyRecording {
  std::string path;  // absolute, so that the seeds' scenario files can name it
  gaze::TraceFormat format = gaze::TraceFormat::automatic;
  bool has_head = false;  // head poses: head_track replays them too
  double span_s = 0.0;    // first to last row
};

// Reads the whole trace once: refuses (UsageError, exit 1, the reader's file:line message) a
// file that cannot be read, and one without two valid gaze samples.
FamilyRecording read_family_recording(const std::string& path, gaze::TraceFormat format);

// The seconds a seed runs with the recording: at most duration_s and the recording's span, in
// whole tenths (past the recording's end its eye would stand still).
double recording_duration_s(double duration_s, const FamilyRecording& recording);

// The seed's scenario (sim::family_scenario's JSON) with its head and eye effects replaced by
// the recording's, over at most the recording's span.
std::string with_recording(const std::string& scenario_json, const FamilyRecording& recording);

// The seed's one-line summary with its head and eye parts replaced ("recorded eyes and head,
// questpro, 142 Hz 33 ms 0.56 deg, open field").
std::string recording_summary(const std::string& summary, const FamilyRecording& recording);

}  // namespace gazelod::cli
