// Writes gazelod's own gaze-trace CSV format (versioned; documented in docs/gaze.md and the
// README). The reader (trace_reader.hpp) reads back exactly what this writes.
#pragma once

#include "gaze/gaze_sample.hpp"

#include <ostream>

namespace gazelod::gaze {

struct TraceWriterOptions {
  bool time_in_ns = true;   // column t_ns (exact) rather than t_s
  bool write_head = true;   // head_q*, head_p* columns
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

}  // namespace gazelod::gaze
