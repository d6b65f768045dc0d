// SPDX-License-Identifier: Apache-2.0
// folder_lock.hpp: flock on the folder's own descriptor (Linux allows it on directories).
#include "auxiliary/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace gazelod::aux {

FolderLock::FolderLock(const std::string& dir) {
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw FolderLockError("cannot lock '" + dir + "': " + std::strerror(errno));
  int r;
  do {
    r = ::flock(fd_, LOCK_EX | LOCK_NB);
  } while (r != 0 && errno == EINTR);
  if (r == 0) return;
  const int err = errno;
  ::close(fd_);
  fd_ = -1;
  if (err == EWOULDBLOCK)
    throw FolderLockError("'" + dir +
                          "' is being written by another gazelod process; wait for it to end or choose another folder");
  if (err == EBADF || err == ENOLCK || err == EOPNOTSUPP || err == ENOSYS || err == EINVAL) {
    why_not_ = "'" + dir + "' is not locked against another gazelod writing there (" + std::strerror(err) +
               ": the file system cannot lock a folder)";
    return;
  }
  throw FolderLockError("cannot lock '" + dir + "': " + std::strerror(err));
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the lock
}

}  // namespace gazelod::aux
