// SPDX-License-Identifier: Apache-2.0
// Writing an output file atomically: the bytes go to a temporary file in the destination's
// folder, which commit() flushes, fsyncs and renames over the destination. A failure (full
// disk, missing or read-only folder, a directory in the way) throws WriteError with the
// system's reason and leaves neither a partial destination nor the temporary behind; an
// AtomicFile destroyed without commit() removes its temporary.
//
// A destination that exists and is not a regular file (a character device such as /dev/null
// or /dev/stdout, a pipe) is written in place: renaming over it would replace the device.
// A symbolic link is followed: the file it points to is replaced, the link kept.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gazelod::aux {

// "cannot write 'PATH': No space left on device" (what(), with the reason), and both parts.
class WriteError : public std::runtime_error {
 public:
  WriteError(std::string path, std::string reason);
  const std::string& path() const { return path_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string path_, reason_;
};

// Failures to inject (tests): the write that would take the file past `fail_after_bytes`
// fails with `write_errno`; fsync / rename fail with their errno when non-zero.
struct AtomicFileFaults {
  std::uint64_t fail_after_bytes = std::numeric_limits<std::uint64_t>::max();
  int write_errno = 0;  // used when fail_after_bytes is reached (0: ENOSPC)
  int fsync_errno = 0;
  int rename_errno = 0;
};

class AtomicFile {
 public:
  // Creates the temporary ("<folder>/.<name>.tmp-<pid>-<n>", mode 0666 minus the umask, or
  // the mode of the file it replaces). Throws WriteError when it cannot (the reason names the
  // folder: missing, not writable; or the destination is a directory).
  explicit AtomicFile(std::string path, AtomicFileFaults faults = {});
  ~AtomicFile();  // without commit(): the temporary is removed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Where to write. After a failed write the stream is bad and commit() throws the reason.
  std::ostream& stream();
  // Flush, fsync, close and rename over the destination. Throws WriteError (the temporary is
  // removed). Calling it twice is an error.
  void commit();

  const std::string& path() const;       // the destination as given
  const std::string& temp_path() const;  // "" when written in place

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The whole file at once, atomically. Throws WriteError.
void write_file_atomic(const std::string& path, std::string_view bytes);

}  // namespace gazelod::aux
