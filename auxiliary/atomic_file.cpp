// SPDX-License-Identifier: Apache-2.0
// Atomic output files (see atomic_file.hpp): a file-descriptor stream buffer that keeps the
// errno of the first failed write, a temporary created with O_EXCL beside the destination,
// fsync + close + rename on commit.
#include "auxiliary/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <streambuf>

namespace gazelod::aux {
namespace {

class FdBuf final : public std::streambuf {
 public:
  FdBuf() { setp(buf_, buf_ + sizeof buf_); }
  int fd = -1;
  int error = 0;  // errno of the first failed write
  AtomicFileFaults faults;

  bool drain() {
    const char* p = pbase();
    auto n = static_cast<std::size_t>(pptr() - pbase());
    while (n > 0) {
      if (error != 0) return false;
      std::size_t chunk = n;
      if (written_ + chunk > faults.fail_after_bytes) {
        const std::uint64_t allowed = faults.fail_after_bytes > written_ ? faults.fail_after_bytes - written_ : 0;
        if (allowed == 0) {
          error = faults.write_errno != 0 ? faults.write_errno : ENOSPC;
          return false;
        }
        chunk = static_cast<std::size_t>(allowed);
      }
      const ssize_t w = ::write(fd, p, chunk);
      if (w < 0) {
        if (errno == EINTR) continue;
        error = errno;
        return false;
      }
      p += w;
      n -= static_cast<std::size_t>(w);
      written_ += static_cast<std::uint64_t>(w);
    }
    setp(buf_, buf_ + sizeof buf_);
    return true;
  }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
    return c;
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  char buf_[1 << 16];
  std::uint64_t written_ = 0;
};

std::string reason(int e) {
  return std::strerror(e);
}

std::atomic<unsigned> g_counter{0};

}  // namespace

WriteError::WriteError(std::string path, std::string why)
    : std::runtime_error("cannot write '" + path + "': " + why), path_(std::move(path)), reason_(std::move(why)) {}

struct AtomicFile::Impl {
  std::string path, target, temp;
  FdBuf buf;
  std::ostream os{&buf};
  bool in_place = false;
  bool committed = false;

  void close_fd() {
    if (buf.fd >= 0) ::close(buf.fd);
    buf.fd = -1;
  }
  void discard() {
    close_fd();
    if (!temp.empty()) ::unlink(temp.c_str());
  }
  [[noreturn]] void fail(const std::string& why) {
    discard();
    committed = true;  // nothing left to clean up
    throw WriteError(path, why);
  }
};

AtomicFile::AtomicFile(std::string path, AtomicFileFaults faults) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.path = std::move(path);
  m.buf.faults = faults;
  if (m.path.empty()) throw WriteError(m.path, "no file name");
  m.target = m.path;
  struct stat st {};
  if (::lstat(m.path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
    char resolved[PATH_MAX];
    if (::realpath(m.path.c_str(), resolved) != nullptr) m.target = resolved;
  }
  mode_t mode = 0666;  // minus the umask (open applies it)
  bool replacing = false;
  if (::stat(m.target.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw WriteError(m.path, "is a directory");
    if (!S_ISREG(st.st_mode)) {  // a device or a pipe: written in place
      m.in_place = true;
      m.buf.fd = ::open(m.target.c_str(), O_WRONLY | O_CLOEXEC);
      if (m.buf.fd < 0) throw WriteError(m.path, reason(errno));
      return;
    }
    mode = st.st_mode & 07777;
    replacing = true;
  }
  const std::string::size_type slash = m.target.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : m.target.substr(0, slash);
  const std::string name = slash == std::string::npos ? m.target : m.target.substr(slash + 1);
  if (name.empty()) throw WriteError(m.path, "no file name (ends with '/')");
  for (int attempt = 0;; ++attempt) {
    m.temp = (dir == "/" ? std::string("/") : dir + "/") + "." + name + ".tmp-" + std::to_string(::getpid()) + "-" +
             std::to_string(g_counter.fetch_add(1));
    m.buf.fd = ::open(m.temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (m.buf.fd >= 0) break;
    const int e = errno;
    if (e == EEXIST && attempt < 100) continue;
    m.temp.clear();
    throw WriteError(m.path, reason(e) + " (creating a temporary file in '" + dir + "')");
  }
  if (replacing) (void)::fchmod(m.buf.fd, mode);
}

AtomicFile::~AtomicFile() {
  if (impl_ && !impl_->committed) impl_->discard();
}

std::ostream& AtomicFile::stream() {
  return impl_->os;
}
const std::string& AtomicFile::path() const {
  return impl_->path;
}
const std::string& AtomicFile::temp_path() const {
  return impl_->temp;
}

void AtomicFile::commit() {
  Impl& m = *impl_;
  if (m.committed) throw std::logic_error("AtomicFile::commit: called twice");
  m.os.flush();
  if (m.buf.error != 0) m.fail(reason(m.buf.error));
  if (!m.os) m.fail("the output stream failed");
  if (!m.in_place) {
    const int fsync_error = m.buf.faults.fsync_errno != 0 ? m.buf.faults.fsync_errno
                            : ::fsync(m.buf.fd) != 0      ? errno
                                                          : 0;
    // EINVAL: a file system without fsync (some pipes, /proc); nothing to wait for.
    if (fsync_error != 0 && fsync_error != EINVAL) m.fail(reason(fsync_error));
  }
  const int fd = m.buf.fd;
  m.buf.fd = -1;
  if (::close(fd) != 0) m.fail(reason(errno));
  if (!m.in_place) {
    const int rename_error = m.buf.faults.rename_errno != 0                    ? m.buf.faults.rename_errno
                             : ::rename(m.temp.c_str(), m.target.c_str()) != 0 ? errno
                                                                               : 0;
    if (rename_error != 0) m.fail(reason(rename_error) + " (renaming '" + m.temp + "' over it)");
  }
  m.committed = true;
}

void write_file_atomic(const std::string& path, std::string_view bytes) {
  AtomicFile f(path);
  f.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  f.commit();
}

}  // namespace gazelod::aux
