// Summary of a trace, computed in one streaming pass (the `gazelod trace stats` numbers).
#pragma once

#include "gaze/gaze_events.hpp"
#include "gaze/record_stream.hpp"

#include <cstddef>
#include <cstdint>

namespace gazelod::gaze {

struct TraceStats {
  std::size_t samples = 0;
  std::size_t invalid = 0;
  std::size_t with_head = 0;
  std::int64_t first_ns = 0, last_ns = 0;
  double duration_s = 0.0;        // last - first sample time
  double rate_hz = 0.0;           // (samples - 1) / duration; 0 with < 2 samples
  double invalid_fraction = 0.0;  // invalid / samples; 0 when empty
  std::size_t saccades = 0;
  std::size_t fixations = 0;      // runs of at least EventOptions::min_fixation_ns
  double mean_saccade_amplitude_deg = 0.0;
  double max_saccade_peak_velocity_deg_s = 0.0;
};

// Reads `stream` to its end (TraceError propagates in strict mode).
TraceStats compute_trace_stats(RecordStream& stream, IvtOptions ivt = {}, EventOptions events = {});

}  // namespace gazelod::gaze
