// SPDX-License-Identifier: Apache-2.0
// Ctrl-C and SIGTERM during `gazelod run`: the first asks the run to stop at the next frame
// boundary (end the session, write the report of the frames done, marked interrupted, remove
// temporaries); a second one ends the process at once with the signal's default action.
// Stoppers nest (`gazelod eval family` holds one around its runs): the outermost owns the
// handlers, and every one sees the same request. Not for use from several threads.
#pragma once

namespace gazelod::cli {

class StopOnSignal {
 public:
  StopOnSignal();   // installs the handlers for SIGINT and SIGTERM
  ~StopOnSignal();  // restores the ones before (a Python interpreter's, say)
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

  // The signal that asked to stop (SIGINT, SIGTERM), 0 while none has.
  int requested() const;
  // The run acted on it. One that arrived but was not acted on (after the last frame, while the
  // report is written) is raised again when the handlers are restored, so it is not lost.
  void acted_on() { acted_ = true; }
  // "SIGINT", "SIGTERM".
  static const char* name(int signal);

 private:
  bool acted_ = false;
};

}  // namespace gazelod::cli
