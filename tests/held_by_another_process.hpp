// SPDX-License-Identifier: Apache-2.0
// A folder locked as another gazelod process would lock its --out (auxiliary/folder_lock.hpp):
// by a child process, until this object is destroyed. A FolderLock taken in the test's own
// process now reads as the command's own hold ("by this gazelod command already").
#pragma once

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

namespace gazelod::test {

class HeldByAnotherProcess {
 public:
  explicit HeldByAnotherProcess(const std::string& dir) {
    int ready[2], release[2];
    if (::pipe(ready) != 0) return;
    if (::pipe(release) != 0) {
      ::close(ready[0]), ::close(ready[1]);
      return;
    }
    pid_ = ::fork();
    if (pid_ == 0) {  // the child: async-signal-safe calls only (the parent has threads)
      ::close(ready[0]);
      ::close(release[1]);
      const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
      char c = fd >= 0 && ::flock(fd, LOCK_EX | LOCK_NB) == 0 ? '1' : '0';
      if (::write(ready[1], &c, 1) != 1) ::_exit(1);
      while (::read(release[0], &c, 1) > 0) {
      }
      ::_exit(0);  // the lock goes with the process
    }
    ::close(ready[1]);
    ::close(release[0]);
    release_fd_ = release[1];
    char c = '0';
    if (pid_ > 0 && ::read(ready[0], &c, 1) == 1) locked_ = c == '1';
    ::close(ready[0]);
  }
  ~HeldByAnotherProcess() {
    if (release_fd_ >= 0) ::close(release_fd_);  // the child reads end of file and leaves
    if (pid_ > 0) ::waitpid(pid_, nullptr, 0);
  }
  HeldByAnotherProcess(const HeldByAnotherProcess&) = delete;
  HeldByAnotherProcess& operator=(const HeldByAnotherProcess&) = delete;
  bool locked() const { return locked_; }

 private:
  pid_t pid_ = -1;
  int release_fd_ = -1;
  bool locked_ = false;
};

}  // namespace gazelod::test
