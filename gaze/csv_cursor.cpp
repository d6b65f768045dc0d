// SPDX-License-Identifier: Apache-2.0
#include "gaze/csv_cursor.hpp"

#include "auxiliary/time.hpp"

#include <charconv>
#include <cmath>
#include <system_error>
#include <utility>

namespace gazelod::gaze {
namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

std::string_view trim(std::string_view s, std::size_t& offset) {
  std::size_t b = 0;
  while (b < s.size() && is_space(s[b])) ++b;
  std::size_t e = s.size();
  while (e > b && is_space(s[e - 1])) --e;
  offset += b;
  return s.substr(b, e - b);
}

std::string quoted(std::string_view s) {
  constexpr std::size_t kMax = 40;  // keep messages readable for garbage lines
  std::string out = "'";
  out += s.size() > kMax ? std::string(s.substr(0, kMax)) + "..." : std::string(s);
  return out + "'";
}

}  // namespace

CsvCursor::CsvCursor(std::istream& in, std::string file, char delimiter)
    : in_(in), file_(std::move(file)), delimiter_(delimiter) {}

bool CsvCursor::read_line() {
  buffer_.clear();
  std::streambuf* sb = in_.rdbuf();
  if (sb == nullptr || !in_.good()) return false;
  ++line_;
  bool any = false;
  for (;;) {
    const int c = sb->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in_.setstate(std::ios::eofbit);
      if (!any) --line_;
      return any;
    }
    any = true;
    ++bytes_;
    if (c == '\n') break;
    if (buffer_.size() == kMaxLineBytes)
      fail(kMaxLineBytes + 1, "line longer than " + std::to_string(kMaxLineBytes) +
                                  " bytes: not a CSV text trace (binary data, or a file without line ends)");
    buffer_.push_back(static_cast<char>(c));
  }
  return true;
}

void CsvCursor::fail_no_header() const {
  if (bytes_ == 0) throw TraceError({file_, 0, 0, "empty file (0 bytes): no header row"});
  throw TraceError(
      {file_, 0, 0, "no header row: the file's " + std::to_string(line_) + " line(s) are all blank or comments"});
}

bool CsvCursor::next_row() {
  comments_.clear();
  while (read_line()) {
    std::string_view view(buffer_);
    // A NUL byte: binary data. A carriage return before the end: CR-only (classic Mac) line
    // ends, the whole file read as one line. Both stop the reading, lenient or not.
    if (const auto nul = view.find('\0'); nul != std::string_view::npos)
      fail(nul + 1, "NUL byte: binary data, not a CSV text trace");
    std::string_view body = view;
    while (!body.empty() && body.back() == '\r') body.remove_suffix(1);  // CRLF line ends
    if (const auto cr = body.find('\r'); cr != std::string_view::npos)
      fail(cr + 1, "carriage return (CR) inside a line: the file has CR-only line ends; convert them to LF");
    if (line_ == 1 && view.substr(0, 3) == "\xEF\xBB\xBF") view.remove_prefix(3);  // UTF-8 BOM
    std::size_t lead = 0;
    std::string_view t = trim(view, lead);
    if (t.empty()) continue;
    if (t.front() == '#') {
      comments_.emplace_back(t);
      continue;
    }
    // Split on the delimiter outside double quotes; columns are 1-based offsets into the raw line.
    fields_.clear();
    const std::size_t base = static_cast<std::size_t>(view.data() - buffer_.data());
    std::size_t start = 0;
    bool in_quotes = false;
    for (std::size_t i = 0; i <= view.size(); ++i) {
      if (i < view.size() && view[i] == '"') in_quotes = !in_quotes;
      if (i == view.size() || (view[i] == delimiter_ && !in_quotes)) {
        std::size_t off = base + start;
        std::string_view f = trim(view.substr(start, i - start), off);
        if (f.size() >= 2 && f.front() == '"' && f.back() == '"') {
          f = f.substr(1, f.size() - 2);
          ++off;
        }
        fields_.push_back({f, off + 1});
        start = i + 1;
      }
    }
    seen_row_ = true;
    return true;
  }
  return false;
}

TraceIssue CsvCursor::issue(std::size_t column, const std::string& message) const {
  return TraceIssue{file_, line_, column, message};
}

void CsvCursor::fail(std::size_t column, const std::string& message) const {
  throw TraceError(issue(column, message));
}

const CsvField& CsvCursor::field(std::size_t index, std::string_view name) const {
  if (index >= fields_.size()) {
    const std::size_t col = buffer_.size() + 1;
    fail(col, "missing field for column '" + std::string(name) + "' (row has " + std::to_string(fields_.size()) +
                  " fields)");
  }
  return fields_[index];
}

bool CsvCursor::is_empty(std::size_t index) const {
  return index >= fields_.size() || fields_[index].text.empty();
}

std::optional<double> CsvCursor::number_or_missing(std::size_t index, std::string_view name) const {
  const CsvField& f = field(index, name);
  if (f.text.empty()) return std::nullopt;
  double v = 0.0;
  const char* end = f.text.data() + f.text.size();
  auto [p, ec] = std::from_chars(f.text.data(), end, v);
  if (ec == std::errc::result_out_of_range)
    fail(f.column, std::string(name) + ": " + quoted(f.text) + " is out of range");
  if (ec != std::errc{} || p != end) fail(f.column, std::string(name) + ": " + quoted(f.text) + " is not a number");
  if (std::isnan(v)) return std::nullopt;
  if (!std::isfinite(v)) fail(f.column, std::string(name) + ": infinite value");
  return v;
}

double CsvCursor::number(std::size_t index, std::string_view name) const {
  const CsvField& f = field(index, name);
  if (f.text.empty()) fail(f.column, std::string(name) + ": empty field, expected a number");
  std::optional<double> v = number_or_missing(index, name);
  if (!v) fail(f.column, std::string(name) + ": NaN is not allowed");
  return *v;
}

std::int64_t CsvCursor::integer(std::size_t index, std::string_view name) const {
  const CsvField& f = field(index, name);
  std::int64_t v = 0;
  const char* end = f.text.data() + f.text.size();
  auto [p, ec] = std::from_chars(f.text.data(), end, v);
  if (f.text.empty()) fail(f.column, std::string(name) + ": empty field, expected an integer");
  if (ec == std::errc::result_out_of_range)
    fail(f.column, std::string(name) + ": " + quoted(f.text) + " is out of range");
  if (ec != std::errc{} || p != end) fail(f.column, std::string(name) + ": " + quoted(f.text) + " is not an integer");
  return v;
}

CsvHeader::CsvHeader(const CsvCursor& cursor) {
  for (const CsvField& f : cursor.fields()) {
    for (const std::string& n : names_)
      if (n == f.text) cursor.fail(f.column, "duplicate column '" + n + "'");
    names_.emplace_back(f.text);
  }
}

std::optional<std::size_t> CsvHeader::find(std::string_view name) const {
  for (std::size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return i;
  return std::nullopt;
}

void SkipReport::add(const TraceIssue& issue) {
  ++skipped;
  if (first.size() < kKept) first.push_back(issue);
}

std::optional<std::int64_t> seconds_to_ns(double t_s) {
  // |t| < 9.2e9 s keeps t * 1e9 inside int64; a time beyond is an error in a trace, not clamped.
  if (!std::isfinite(t_s) || std::fabs(t_s) > 9.0e9) return std::nullopt;
  return aux::ns_from_seconds(t_s);
}

}  // namespace gazelod::gaze
