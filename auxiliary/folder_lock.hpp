// SPDX-License-Identifier: Apache-2.0
// One writer per output folder. Two `gazelod run`s (or a run and a `compare`) given the same
// --out wrote the same report files at once: each file is atomic, but the folder ended as a
// mix of both runs. A FolderLock holds an advisory lock (flock) on the folder itself for its
// lifetime: no lock file is left in the folder, and the kernel releases the lock when the
// process ends, however it ends. A second holder in any process is refused at once.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace gazelod::aux {

// "'DIR' is being written by another gazelod process (...)", or "... by this gazelod command"
// where this process holds it already (one command given overlapping folders: an `eval family`
// whose --out is one of its seeds' folders under --work); or the system's reason the folder
// could not be locked.
class FolderLockError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class FolderLock {
 public:
  // Locks the existing folder `dir`. Throws FolderLockError when another open of it holds the
  // lock, or when it cannot be opened as a folder. Where the file system cannot lock a folder
  // (NFS emulates flock with fcntl locks, which need a file open for writing: EBADF; or
  // ENOLCK, EOPNOTSUPP), it goes on unlocked: locked() is false and why_not_locked() says so,
  // for the caller to print.
  explicit FolderLock(const std::string& dir);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  bool locked() const { return fd_ >= 0; }
  const std::string& why_not_locked() const { return why_not_; }

 private:
  int fd_ = -1;
  std::uint64_t device_ = 0, inode_ = 0;  // the folder, while locked: this process's holds
  std::string why_not_;
};

}  // namespace gazelod::aux
