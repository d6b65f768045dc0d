// SPDX-License-Identifier: Apache-2.0
// Writes gazelod's own gaze-trace CSV format (versioned; documented in docs/gaze.md and the
// README). The reader (trace_reader.hpp) reads back exactly what this writes.
#pragma once

#include "auxiliary/atomic_file.hpp"
#include "gaze/gaze_sample.hpp"

#include <ostream>
#include <string>

namespace gazelod::gaze {

struct TraceWriterOptions {
  bool time_in_ns = true;  // column t_ns (exact) rather than t_s
  bool write_head = true;  // head_q*, head_p* columns
};

class TraceWriter {
 public:
  // Writes the header (with the format version) immediately.
  explicit TraceWriter(std::ostream& out, TraceWriterOptions options = {});
  // One row. Values are written so that reading them back gives the same doubles.
  void write(const TraceRecord& record);

 private:
  std::ostream& out_;
  TraceWriterOptions options_;
};

// A trace file written atomically (auxiliary/atomic_file.hpp): rows go to a temporary file in the
// destination's folder; commit() renames it over `path`. Without commit() (an error while
// reading the input, say) nothing is left behind. Throws aux::WriteError with the system's reason.
class TraceFileWriter {
 public:
  explicit TraceFileWriter(const std::string& path, TraceWriterOptions options = {}, aux::AtomicFileFaults faults = {});
  void write(const TraceRecord& record) { writer_.write(record); }
  void commit() { file_.commit(); }
  // The temporary being written ("" when written in place), for a caller that must remove it
  // from a signal handler.
  const std::string& temp_path() const { return file_.temp_path(); }

 private:
  aux::AtomicFile file_;
  TraceWriter writer_;
};

}  // namespace gazelod::gaze
