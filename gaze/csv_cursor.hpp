// SPDX-License-Identifier: Apache-2.0
// Line-at-a-time CSV reading shared by the trace reader and the importers: one reused line
// buffer (streaming, a one-hour trace never sits in memory), field splitting that remembers
// each field's column, number parsing with errors that name file:line:column, and the
// lenient-mode bookkeeping (skipped lines are counted and listed, never silently dropped).
#pragma once

#include "gaze/trace_error.hpp"

#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gazelod::gaze {

struct CsvField {
  std::string_view text;   // trimmed, surrounding quotes removed
  std::size_t column = 1;  // 1-based column where the field starts
};

class CsvCursor {
 public:
  // The longest line read (bytes, without the line end): a longer one is not a trace row (a
  // binary file, a file without line ends) and ends the reading with an error.
  static constexpr std::size_t kMaxLineBytes = std::size_t{1} << 16;

  // `delimiter`: ',' (gazelod's format, most exports) or ';' (HTC's SRanipal Unity logs).
  CsvCursor(std::istream& in, std::string file, char delimiter = ',');

  // Advances to the next line that is neither blank nor a '#' comment and splits it.
  // Returns false at end of input. Throws TraceError (in lenient mode too) for a line longer
  // than kMaxLineBytes, a NUL byte, or a carriage return inside a line (CR-only line ends).
  bool next_row();
  // Throws the readers' "no header row" error: an empty file, or one of blank / comment lines only.
  [[noreturn]] void fail_no_header() const;

  const std::vector<CsvField>& fields() const { return fields_; }
  std::size_t line() const { return line_; }
  const std::string& file() const { return file_; }
  // The most recent comment line before the current row (e.g. the format version line).
  const std::vector<std::string>& leading_comments() const { return comments_; }

  // Throws TraceError at this line and the given 1-based column (0 = whole line).
  [[noreturn]] void fail(std::size_t column, const std::string& message) const;
  TraceIssue issue(std::size_t column, const std::string& message) const;

  // Field `index` of the current row; fails naming `name` when the row is too short.
  const CsvField& field(std::size_t index, std::string_view name) const;
  // Finite double; fails on empty text, a non-number, trailing junk, NaN or infinity.
  double number(std::size_t index, std::string_view name) const;
  // Like number(), but NaN / empty / "nan" give nullopt (layouts that mark missing data so).
  std::optional<double> number_or_missing(std::size_t index, std::string_view name) const;
  std::int64_t integer(std::size_t index, std::string_view name) const;
  bool is_empty(std::size_t index) const;

 private:
  std::istream& in_;
  std::string file_;
  std::string buffer_;
  std::vector<CsvField> fields_;
  std::vector<std::string> comments_;
  std::size_t line_ = 0;
  char delimiter_ = ',';
  std::uint64_t bytes_ = 0;  // read so far
  bool seen_row_ = false;
  // One line into buffer_ (without '\n'), at most kMaxLineBytes; false at end of input.
  bool read_line();
};

// Column name -> index, built from a header row. Names are matched exactly (after trimming).
class CsvHeader {
 public:
  // Reads the header from the cursor's current row; fails on duplicate names.
  explicit CsvHeader(const CsvCursor& cursor);
  std::optional<std::size_t> find(std::string_view name) const;
  std::size_t size() const { return names_.size(); }

 private:
  std::vector<std::string> names_;
};

// Lenient-mode bookkeeping: how many lines were skipped and why (the first `kept` in full).
struct SkipReport {
  std::size_t skipped = 0;
  std::vector<TraceIssue> first;
  static constexpr std::size_t kKept = 100;
  void add(const TraceIssue& issue);
};

// Seconds (finite, within +-292 years) to integer nanoseconds, or nullopt when out of range.
std::optional<std::int64_t> seconds_to_ns(double t_s);

}  // namespace gazelod::gaze
