// SPDX-License-Identifier: Apache-2.0
// Errors and skipped-line reports of the trace readers and importers: always with the file,
// line and column, so a user can open the file at the spot.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace gazelod::gaze {

struct TraceIssue {
  std::string file;
  std::size_t line = 0;    // 1-based physical line; 0 = the file as a whole
  std::size_t column = 0;  // 1-based character column; 0 = the line as a whole
  std::string message;

  // "file:line:column: message" (line/column left out when 0).
  std::string to_string() const;
};

class TraceError : public std::runtime_error {
 public:
  explicit TraceError(TraceIssue issue);
  const TraceIssue& issue() const { return issue_; }

 private:
  TraceIssue issue_;
};

}  // namespace gazelod::gaze
