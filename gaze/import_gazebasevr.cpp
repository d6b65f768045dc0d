// SPDX-License-Identifier: Apache-2.0
#include "gaze/import_gazebasevr.hpp"

#include "auxiliary/time.hpp"
#include "gaze/trace_reader.hpp"

#include <cmath>
#include <string>

namespace gazelod::gaze {

GazeBaseVrReader::GazeBaseVrReader(std::istream& in, std::string file, ReadOptions options)
    : CsvRecordStream(in, std::move(file), options) {
  if (!cursor_.next_row()) cursor_.fail_no_header();
  const CsvHeader h(cursor_);
  fields_ = h.size();
  std::string missing;
  for (const char* name : {"n", "x", "y"})
    if (!h.find(name)) missing += std::string(missing.empty() ? "" : ",") + name;
  if (!missing.empty()) cursor_.fail(0, "missing required GazeBaseVR column(s): " + missing);
  n_ = *h.find("n");
  x_ = *h.find("x");
  y_ = *h.find("y");
  time_field_ = n_;
}

void GazeBaseVrReader::parse_row(TraceRecord& out) {
  const CsvCursor& c = cursor_;
  if (c.fields().size() != fields_)
    c.fail(0, "row has " + std::to_string(c.fields().size()) + " fields, header has " + std::to_string(fields_));
  const double n_ms = c.number(n_, "n");
  const auto t_ns = seconds_to_ns(aux::seconds_from_ms(n_ms));
  if (!t_ns) c.fail(c.fields()[n_].column, "n: out of range");
  out.gaze.t_ns = *t_ns;
  const auto x = c.number_or_missing(x_, "x");
  const auto y = c.number_or_missing(y_, "y");
  out.gaze.valid = x.has_value() && y.has_value();
  out.gaze.confidence = out.gaze.valid ? 1.0f : 0.0f;
  if (out.gaze.valid) {
    if (std::fabs(*x) > 180.0) c.fail(c.fields()[x_].column, "x: must be in [-180, 180] deg");
    if (std::fabs(*y) > 90.0) c.fail(c.fields()[y_].column, "y: must be in [-90, 90] deg");
    out.gaze.direction = direction_from_yaw_pitch_deg(*x, *y);
  }
  out.has_head = false;
}

}  // namespace gazelod::gaze
