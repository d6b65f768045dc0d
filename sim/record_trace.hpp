// SPDX-License-Identifier: Apache-2.0
// Writing what a scenario simulated as a gazelod gaze trace (gaze/trace_writer.hpp), so a
// simulated session can be replayed: one row per distinct tracker sample (at its sample time),
// with the head pose at that time.
#pragma once

#include "sim/simulator.hpp"

#include <cstddef>
#include <ostream>
#include <string>

namespace gazelod::sim {

struct RecordOptions {
  double step_hz = 0.0;     // how often the tracker is asked; 0: the scenario's frame rate
  bool true_gaze = false;   // the eye itself (no tracker effects) instead of the tracker
  double duration_s = 0.0;  // 0: the scenario's duration
};

struct RecordStats {
  std::size_t rows = 0;
  std::size_t invalid_rows = 0;
};

RecordStats record_trace(Simulator& sim, std::ostream& out, const RecordOptions& options = {});

// The same into a file, written atomically (auxiliary/atomic_file.hpp): a failure (full disk,
// missing folder, a directory in the way) throws aux::WriteError with the system's reason and
// leaves no file, partial or temporary, behind.
RecordStats record_trace_file(Simulator& sim, const std::string& path, const RecordOptions& options = {});

}  // namespace gazelod::sim
