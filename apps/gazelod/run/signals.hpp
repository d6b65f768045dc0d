// SPDX-License-Identifier: Apache-2.0
// Ctrl-C and SIGTERM during `gazelod run`: the first asks the run to stop at the next frame
// boundary (end the session, write the report of the frames done, marked interrupted, remove
// temporaries); a second one ends the process at once with the signal's default action.
// Stoppers nest (`gazelod eval family` holds one around its runs): the outermost owns the
// handlers, and every one sees the same request. Not for use from several threads.
//
// The temporaries of the files being written (AtomicRunFile: the decisions files, the report
// file in progress) are removed by the second signal before it ends the process: it left
// them behind (".frames.csv.tmp-PID-N" beside the report).
#pragma once

#include "auxiliary/atomic_file.hpp"

#include <ostream>
#include <string>
#include <string_view>

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

// A temporary file that the second signal removes (unlink, async-signal-safe) before the
// process ends: held from hold() to release() or destruction. Up to kHeldTemporaries at once,
// each path up to 4095 bytes; one past those is not held (its file is still removed on every
// other way out, by its AtomicFile).
class TemporaryOnSignal {
 public:
  static constexpr int kHeldTemporaries = 16;
  TemporaryOnSignal() = default;
  ~TemporaryOnSignal() { release(); }
  TemporaryOnSignal(const TemporaryOnSignal&) = delete;
  TemporaryOnSignal& operator=(const TemporaryOnSignal&) = delete;
  void hold(const std::string& path);  // "" holds nothing
  void release();
  bool held() const { return slot_ >= 0; }

 private:
  int slot_ = -1;
};

// aux::AtomicFile whose temporary a second signal removes too (TemporaryOnSignal).
class AtomicRunFile {
 public:
  // Throws aux::WriteError, as AtomicFile does.
  explicit AtomicRunFile(std::string path);
  std::ostream& stream() { return file_.stream(); }
  void commit() { file_.commit(); }
  const std::string& path() const { return file_.path(); }
  const std::string& temp_path() const { return file_.temp_path(); }

 private:
  // Released after the file is gone (members go in reverse): a signal in between unlinks a
  // name that no longer exists, never one that is left.
  TemporaryOnSignal temporary_;
  aux::AtomicFile file_;
};

// aux::write_file_atomic through an AtomicRunFile. Throws aux::WriteError.
void write_run_file(const std::string& path, std::string_view bytes);

}  // namespace gazelod::cli
