// SPDX-License-Identifier: Apache-2.0
#include "gaze/record_stream.hpp"

#include <utility>

namespace gazelod::gaze {

CsvRecordStream::CsvRecordStream(std::istream& in, std::string file, ReadOptions options, char delimiter)
    : cursor_(in, std::move(file), delimiter), options_(options) {}

bool CsvRecordStream::next(TraceRecord& out) {
  while (cursor_.next_row()) {
    try {
      TraceRecord rec;
      parse_row(rec);
      const std::size_t col = time_field_ < cursor_.fields().size() ? cursor_.fields()[time_field_].column : 0;
      // Within +-2^62 ns (146 years) any two times' difference fits in 64 bits: every reader
      // downstream subtracts them.
      if (rec.gaze.t_ns >= kMaxTraceTimeNs || rec.gaze.t_ns <= -kMaxTraceTimeNs)
        cursor_.fail(col, "time " + std::to_string(rec.gaze.t_ns) + " ns is not within +-2^62 ns (146 years)");
      if (have_last_ && rec.gaze.t_ns < last_t_ns_) {
        cursor_.fail(col, "time goes backwards: " + std::to_string(rec.gaze.t_ns) + " ns after " +
                              std::to_string(last_t_ns_) + " ns");
      }
      have_last_ = true;
      last_t_ns_ = rec.gaze.t_ns;
      out = rec;
      return true;
    } catch (const TraceError& e) {
      if (!options_.lenient) throw;
      skipped_.add(e.issue());
    }
  }
  return false;
}

}  // namespace gazelod::gaze
