// SPDX-License-Identifier: Apache-2.0
// Writing what a scenario simulated as a gazelod gaze trace (gaze/trace_writer.hpp), so a
// simulated session can be replayed: one row per distinct tracker sample (at its sample time),
// with the head pose at that time.
#pragma once

#include "sim/simulator.hpp"

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>

namespace gazelod::sim {

struct RecordOptions {
  double step_hz = 0.0;     // how often the tracker is asked; 0: the scenario's frame rate
  bool true_gaze = false;   // the eye itself (no tracker effects) instead of the tracker
  double duration_s = 0.0;  // 0: the scenario's duration
  // Called about every 2^16 steps with the simulated seconds done and to do; returning false
  // stops the recording (record_trace_file then writes nothing).
  std::function<bool(double done_s, double total_s)> progress;
};

// At most this many tracker requests (duration x rate): 27 hours at 1 kHz, ~15 GB of CSV.
inline constexpr double kMaxRecordSteps = 1e8;

// Thrown when `progress` stopped the recording.
struct RecordStopped {};

struct RecordStats {
  std::size_t rows = 0;
  std::size_t invalid_rows = 0;
};

// Throws std::invalid_argument for more than kMaxRecordSteps steps (before writing anything),
// RecordStopped when `progress` returns false.
RecordStats record_trace(Simulator& sim, std::ostream& out, const RecordOptions& options = {});

// The same into a file, written atomically (auxiliary/atomic_file.hpp): a failure (full disk,
// missing folder, a directory in the way) throws aux::WriteError with the system's reason and
// leaves no file, partial or temporary, behind.
RecordStats record_trace_file(Simulator& sim, const std::string& path, const RecordOptions& options = {});

}  // namespace gazelod::sim
