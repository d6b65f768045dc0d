// SPDX-License-Identifier: Apache-2.0
#include "sim/record_trace.hpp"

#include "auxiliary/atomic_file.hpp"
#include "auxiliary/time.hpp"
#include "gaze/trace_writer.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace gazelod::sim {

RecordStats record_trace(Simulator& sim, std::ostream& out, const RecordOptions& options) {
  const double step_hz = options.step_hz > 0.0 ? options.step_hz : sim.scenario().frame_rate_hz;
  const double duration_s = options.duration_s > 0.0 ? options.duration_s : sim.scenario().duration_s;
  const auto end_ns = aux::ns_from_seconds(duration_s);
  if (!(duration_s * step_hz <= kMaxRecordSteps)) {
    char why[160];
    std::snprintf(why, sizeof why,
                  "duration x rate asks the tracker %.3g times; at most 1e8 (a shorter --duration "
                  "or a lower --rate)",
                  duration_s * step_hz);
    throw std::invalid_argument(why);
  }
  gaze::TraceWriter writer(out);
  RecordStats stats;
  bool any = false;
  std::int64_t last_ns = 0;
  for (std::int64_t k = 0;; ++k) {
    // Integer frame times from the index (no accumulated rounding).
    const auto t_ns = aux::ns_rounded(static_cast<double>(k) * static_cast<double>(aux::kNsPerSecond) / step_hz);
    if (t_ns >= end_ns) break;
    if (options.progress && (k & 0xffff) == 0 && k > 0 && !options.progress(aux::seconds_from_ns(t_ns), duration_s))
      throw RecordStopped{};
    if (!options.true_gaze && t_ns < sim.first_tracker_sample_ns()) continue;  // nothing delivered yet
    const gaze::GazeSample g = options.true_gaze ? sim.true_gaze_at(t_ns) : sim.tracker_at(t_ns);
    if (any && g.t_ns <= last_ns) continue;  // the tracker has nothing newer
    any = true;
    last_ns = g.t_ns;
    gaze::TraceRecord r;
    r.gaze = g;
    const HeadState h = sim.head_at(g.t_ns);
    r.has_head = true;
    r.head.t_ns = g.t_ns;
    r.head.orientation = h.orientation;
    r.head.position_m = h.position_m;
    r.head.valid = true;
    writer.write(r);
    ++stats.rows;
    stats.invalid_rows += !g.valid;
  }
  return stats;
}

RecordStats record_trace_file(Simulator& sim, const std::string& path, const RecordOptions& options) {
  aux::AtomicFile file(path);
  const RecordStats stats = record_trace(sim, file.stream(), options);
  file.commit();
  return stats;
}

}  // namespace gazelod::sim
