// SPDX-License-Identifier: Apache-2.0
// A stream of trace records read one at a time from a CSV file: gazelod's own format or an
// imported layout. Strict mode throws TraceError at the first bad line; lenient mode skips bad
// lines and lists them in skipped() (never silent). Time must never go backwards, and stays
// within +-kMaxTraceTimeNs.
#pragma once

#include "gaze/csv_cursor.hpp"
#include "gaze/gaze_sample.hpp"

#include <cstdint>
#include <istream>
#include <string>

namespace gazelod::gaze {

// 2^62 ns, about 146 years: times a reader accepts lie strictly within it, so the difference
// of any two fits in 64 bits.
inline constexpr std::int64_t kMaxTraceTimeNs = std::int64_t{1} << 62;

struct ReadOptions {
  bool lenient = false;  // skip bad lines (counted and listed) instead of failing
};

class RecordStream {
 public:
  virtual ~RecordStream() = default;
  // The next record, false at end of input. Strict mode: throws TraceError on a bad line.
  virtual bool next(TraceRecord& out) = 0;
  // Lines skipped in lenient mode and why.
  virtual const SkipReport& skipped() const = 0;
  // Whether records carry a head pose (the file has head columns).
  virtual bool has_head() const = 0;
};

// The shared loop of the CSV readers: row iteration, lenient skipping, time monotonicity.
class CsvRecordStream : public RecordStream {
 public:
  bool next(TraceRecord& out) final;
  const SkipReport& skipped() const final { return skipped_; }

 protected:
  CsvRecordStream(std::istream& in, std::string file, ReadOptions options, char delimiter = ',');
  // Parses the cursor's current row into `out`; throws TraceError (via cursor_.fail) if bad.
  virtual void parse_row(TraceRecord& out) = 0;

  CsvCursor cursor_;
  ReadOptions options_;
  std::size_t time_field_ = 0;  // index of the time column, for the "backwards" error

 private:
  SkipReport skipped_;
  bool have_last_ = false;
  std::int64_t last_t_ns_ = 0;
};

}  // namespace gazelod::gaze
