// SPDX-License-Identifier: Apache-2.0
#include "gaze/trace_error.hpp"

#include <utility>

namespace gazelod::gaze {

std::string TraceIssue::to_string() const {
  std::string s = file.empty() ? std::string("<stream>") : file;
  if (line > 0) {
    s += ':' + std::to_string(line);
    if (column > 0) s += ':' + std::to_string(column);
  }
  return s + ": " + message;
}

TraceError::TraceError(TraceIssue issue) : std::runtime_error(issue.to_string()), issue_(std::move(issue)) {}

}  // namespace gazelod::gaze
