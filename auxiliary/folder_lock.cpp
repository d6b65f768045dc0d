// SPDX-License-Identifier: Apache-2.0
// folder_lock.hpp: flock on the folder's own descriptor (Linux allows it on directories).
#include "auxiliary/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <utility>
#include <vector>

namespace gazelod::aux {
namespace {

// The folders this process holds, so that a refusal can say whose hold it is: flock refuses a
// second open of the same folder within one process as it does another process's.
std::mutex g_held_mutex;
std::vector<std::pair<std::uint64_t, std::uint64_t>>& held_folders() {
  static std::vector<std::pair<std::uint64_t, std::uint64_t>> held;
  return held;
}

bool identity(int fd, std::uint64_t& device, std::uint64_t& inode) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) return false;
  device = static_cast<std::uint64_t>(st.st_dev);
  inode = static_cast<std::uint64_t>(st.st_ino);
  return true;
}

}  // namespace

FolderLock::FolderLock(const std::string& dir) {
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw FolderLockError("cannot lock '" + dir + "': " + std::strerror(errno));
  int r;
  do {
    r = ::flock(fd_, LOCK_EX | LOCK_NB);
  } while (r != 0 && errno == EINTR);
  if (r == 0) {
    if (identity(fd_, device_, inode_)) {
      const std::lock_guard<std::mutex> lock(g_held_mutex);
      held_folders().emplace_back(device_, inode_);
    }
    return;
  }
  const int err = errno;
  bool ours = false;
  if (std::uint64_t device = 0, inode = 0; err == EWOULDBLOCK && identity(fd_, device, inode)) {
    const std::lock_guard<std::mutex> lock(g_held_mutex);
    const auto& held = held_folders();
    ours = std::find(held.begin(), held.end(), std::pair{device, inode}) != held.end();
  }
  ::close(fd_);
  fd_ = -1;
  if (err == EWOULDBLOCK && ours)
    throw FolderLockError("'" + dir +
                          "' is being written by this gazelod command already (two of its folders are the same: "
                          "an output inside its work folder?); choose another folder");
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
  if (fd_ < 0) return;
  {
    const std::lock_guard<std::mutex> lock(g_held_mutex);
    auto& held = held_folders();
    const auto it = std::find(held.begin(), held.end(), std::pair{device_, inode_});
    if (it != held.end()) held.erase(it);
  }
  ::close(fd_);  // closing the last descriptor releases the lock
}

}  // namespace gazelod::aux
