// SPDX-License-Identifier: Apache-2.0
// Atomic output files (auxiliary/atomic_file.hpp) and the trace writer on top of them: a failure at
// any step (injected write / fsync / rename errors, a missing or unwritable folder, a
// directory in the way, a full device, a full file system) throws WriteError with the
// system's reason and leaves neither a partial destination nor a temporary file.
#include "auxiliary/atomic_file.hpp"
#include "gaze/trace_writer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace gazelod::gaze {
namespace {

using aux::AtomicFile;
using aux::AtomicFileFaults;
using aux::write_file_atomic;
using aux::WriteError;

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(::testing::TempDir()) / ("gazelod_atomic_" + std::string(info->name()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every entry of `dir`, by name: a temporary left behind shows up here.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const WriteError& e) {
    return e.what();
  }
  return "";
}

const std::string kBig(1 << 20, 'x');  // more than one stream buffer

TEST(AtomicFile, WritesAndReplacesWithNothingElseLeft) {
  const fs::path dir = test_dir(), out = dir / "out.csv";
  write_file_atomic(out.string(), "first\n");
  EXPECT_EQ(read(out), "first\n");
  ::chmod(out.c_str(), 0640);
  {
    AtomicFile f(out.string());
    EXPECT_THAT(f.temp_path(), HasSubstr((dir / ".out.csv.tmp-").string()));
    f.stream() << kBig;
    EXPECT_EQ(read(out), "first\n") << "the destination changes only at commit";
    f.commit();
  }
  EXPECT_EQ(read(out), kBig);
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out.csv"});
  struct stat st {};
  ASSERT_EQ(::stat(out.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u) << "a replaced file keeps its mode";
}

TEST(AtomicFile, WithoutCommitNothingIsLeft) {
  const fs::path dir = test_dir(), out = dir / "out.csv";
  {
    AtomicFile f(out.string());
    f.stream() << kBig;
  }
  EXPECT_TRUE(entries(dir).empty());
}

TEST(AtomicFile, InjectedFailuresNameTheReasonAndLeaveTheOldFile) {
  const fs::path dir = test_dir(), out = dir / "out.csv";
  write_file_atomic(out.string(), "old\n");
  const auto attempt = [&](AtomicFileFaults faults) {
    return error_of([&] {
      AtomicFile f(out.string(), faults);
      f.stream() << kBig;
      f.commit();
    });
  };
  EXPECT_EQ(attempt({.fail_after_bytes = 100}), "cannot write '" + out.string() + "': No space left on device");
  EXPECT_EQ(attempt({.fail_after_bytes = 0, .write_errno = EIO}),
            "cannot write '" + out.string() + "': Input/output error");
  EXPECT_EQ(attempt({.fsync_errno = EDQUOT}), "cannot write '" + out.string() + "': Disk quota exceeded");
  EXPECT_THAT(attempt({.rename_errno = EXDEV}), HasSubstr("Invalid cross-device link (renaming '"));
  EXPECT_EQ(read(out), "old\n");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out.csv"});
  // The trace writer on top: the same.
  EXPECT_EQ(error_of([&] {
              TraceFileWriter w(out.string(), {}, {.fail_after_bytes = 1000});
              TraceRecord r;
              for (int i = 0; i < 1000; ++i) w.write(r);
              w.commit();
            }),
            "cannot write '" + out.string() + "': No space left on device");
  EXPECT_EQ(read(out), "old\n");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out.csv"});
}

TEST(AtomicFile, MissingFolderAndDirectoryInTheWay) {
  const fs::path dir = test_dir();
  EXPECT_EQ(error_of([&] { write_file_atomic((dir / "no" / "t.csv").string(), "x"); }),
            "cannot write '" + (dir / "no" / "t.csv").string() +
                "': No such file or directory (creating a temporary file in '" + (dir / "no").string() + "')");
  fs::create_directory(dir / "adir.csv");
  EXPECT_EQ(error_of([&] { write_file_atomic((dir / "adir.csv").string(), "x"); }),
            "cannot write '" + (dir / "adir.csv").string() + "': is a directory");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"adir.csv"});
  EXPECT_TRUE(fs::is_empty(dir / "adir.csv"));
}

TEST(AtomicFile, FolderNotWritable) {
  const fs::path dir = test_dir(), ro = dir / "ro";
  fs::create_directory(ro);
  if (::geteuid() != 0) {
    ::chmod(ro.c_str(), 0555);
    EXPECT_THAT(error_of([&] { write_file_atomic((ro / "t.csv").string(), "x"); }),
                HasSubstr("': Permission denied (creating a temporary file in '"));
    ::chmod(ro.c_str(), 0755);
    EXPECT_TRUE(fs::is_empty(ro));
    return;
  }
  // Root writes through permissions: a read-only file system stops it.
  if (::mount("tmpfs", ro.c_str(), "tmpfs", MS_RDONLY, "size=64k") != 0)
    GTEST_SKIP() << "running as root, and cannot mount a read-only tmpfs (" << std::strerror(errno) << ")";
  struct Unmount {
    fs::path p;
    ~Unmount() { ::umount(p.c_str()); }
  } unmount{ro};
  EXPECT_EQ(error_of([&] { write_file_atomic((ro / "t.csv").string(), "x"); }),
            "cannot write '" + (ro / "t.csv").string() + "': Read-only file system (creating a temporary file in '" +
                ro.string() + "')");
  EXPECT_TRUE(fs::is_empty(ro));
}

TEST(AtomicFile, DevicesAreWrittenInPlace) {
  if (!fs::exists("/dev/full") || !fs::exists("/dev/null")) GTEST_SKIP() << "no /dev/full or /dev/null here";
  EXPECT_EQ(error_of([&] { write_file_atomic("/dev/full", kBig); }),
            "cannot write '/dev/full': No space left on device");
  EXPECT_EQ(error_of([&] { write_file_atomic("/dev/null", kBig); }), "");
  EXPECT_TRUE(fs::is_character_file("/dev/null")) << "never replaced by a regular file";
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

TEST(AtomicFile, SymlinkIsFollowedAndKept) {
  const fs::path dir = test_dir();
  write_file_atomic((dir / "real.csv").string(), "old");
  fs::create_symlink(dir / "real.csv", dir / "link.csv");
  write_file_atomic((dir / "link.csv").string(), "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
  EXPECT_EQ(read(dir / "real.csv"), "new");
}

// A real full file system: a 64 KiB tmpfs (needs CAP_SYS_ADMIN, e.g. root in a container
// that allows mounts; skipped otherwise).
TEST(AtomicFile, FullFileSystemLeavesNothing) {
  const fs::path dir = test_dir(), mnt = dir / "tiny";
  fs::create_directory(mnt);
  if (::mount("tmpfs", mnt.c_str(), "tmpfs", 0, "size=64k") != 0)
    GTEST_SKIP() << "cannot mount a 64 KiB tmpfs here (" << std::strerror(errno) << "): needs CAP_SYS_ADMIN";
  struct Unmount {
    fs::path p;
    ~Unmount() { ::umount(p.c_str()); }
  } unmount{mnt};
  write_file_atomic((mnt / "kept.csv").string(), "old");
  EXPECT_EQ(error_of([&] { write_file_atomic((mnt / "kept.csv").string(), kBig); }),
            "cannot write '" + (mnt / "kept.csv").string() + "': No space left on device");
  EXPECT_EQ(error_of([&] { write_file_atomic((mnt / "new.csv").string(), kBig); }),
            "cannot write '" + (mnt / "new.csv").string() + "': No space left on device");
  EXPECT_EQ(entries(mnt), std::vector<std::string>{"kept.csv"});
  EXPECT_EQ(read(mnt / "kept.csv"), "old");
}

}  // namespace
}  // namespace gazelod::gaze
