// SPDX-License-Identifier: Apache-2.0
// Writer for gazelod's gaze-trace CSV (spec: docs/gaze.md). Numbers are written with
// std::to_chars' shortest round-trip form, so reading them back yields the same doubles.
#include "gaze/trace_writer.hpp"

#include "auxiliary/time.hpp"
#include "gaze/trace_format.hpp"

#include <array>
#include <charconv>
#include <string>
#include <system_error>

namespace gazelod::gaze {
namespace {

namespace tf = trace_format;

// Appends the shortest decimal text that parses back to exactly `v`.
template <typename T>
void append_number(std::string& line, T v) {
  std::array<char, 64> buf{};
  auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  if (ec != std::errc{}) {  // cannot happen for 64 chars; keep the row parseable anyway
    line += "nan";
    return;
  }
  line.append(buf.data(), end);
}

}  // namespace

TraceWriter::TraceWriter(std::ostream& out, TraceWriterOptions options) : out_(out), options_(options) {
  std::string header;
  header += tf::kMagic;
  header += ' ';
  header += std::to_string(tf::kVersion);
  header += '\n';
  header += options_.time_in_ns ? tf::kTimeNs : tf::kTimeS;
  for (auto name : {tf::kGazeX, tf::kGazeY, tf::kGazeZ, tf::kEyeX, tf::kEyeY, tf::kEyeZ, tf::kValid, tf::kConfidence}) {
    header += ',';
    header += name;
  }
  if (options_.write_head) {
    for (auto name :
         {tf::kHeadQw, tf::kHeadQx, tf::kHeadQy, tf::kHeadQz, tf::kHeadPx, tf::kHeadPy, tf::kHeadPz, tf::kHeadValid}) {
      header += ',';
      header += name;
    }
  }
  header += '\n';
  out_ << header;
}

void TraceWriter::write(const TraceRecord& record) {
  std::string line;
  line.reserve(256);
  const GazeSample& g = record.gaze;
  if (options_.time_in_ns) {
    append_number(line, g.t_ns);
  } else {
    append_number(line, aux::seconds_from_ns(g.t_ns));
  }
  for (double v : {g.direction.x, g.direction.y, g.direction.z, g.origin_m.x, g.origin_m.y, g.origin_m.z}) {
    line += ',';
    append_number(line, v);
  }
  line += g.valid ? ",1," : ",0,";
  append_number(line, g.confidence);
  if (options_.write_head) {
    if (record.has_head) {
      const HeadSample& h = record.head;
      for (double v : {h.orientation.w, h.orientation.x, h.orientation.y, h.orientation.z, h.position_m.x,
                       h.position_m.y, h.position_m.z}) {
        line += ',';
        append_number(line, v);
      }
      line += h.valid ? ",1" : ",0";
    } else {
      line += ",,,,,,,,";  // empty cells: this row has no head pose
    }
  }
  line += '\n';
  out_ << line;
}

TraceFileWriter::TraceFileWriter(const std::string& path, TraceWriterOptions options, aux::AtomicFileFaults faults)
    : file_(path, faults), writer_(file_.stream(), options) {}

}  // namespace gazelod::gaze
