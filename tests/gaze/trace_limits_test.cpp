// SPDX-License-Identifier: Apache-2.0
// What the trace readers read at most, and what they say about input that is not a trace: a
// directory, a device, a pipe (read as a stream), a line without end (over-long lines),
// CR-only line ends, NUL bytes, an empty file and one of blank lines.
#include "gaze/import_gazebasevr.hpp"
#include "gaze/import_pupil.hpp"
#include "gaze/trace_error.hpp"
#include "gaze/trace_open.hpp"
#include "gaze/trace_reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace gazelod::gaze {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

template <class Reader = TraceReader>
std::string error_of(const std::string& text, bool lenient = false) {
  std::istringstream in(text);
  try {
    Reader r(in, "t.csv", ReadOptions{lenient});
    TraceRecord rec;
    while (r.next(rec)) {
    }
  } catch (const TraceError& e) {
    return e.what();
  }
  return "";
}

std::string open_error(const std::string& path) {
  try {
    auto s = open_trace(path, TraceFormat::gazelod);
    TraceRecord r;
    while (s->next(r)) {
    }
  } catch (const TraceError& e) {
    return e.what();
  }
  return "";
}

const std::string kHeader = "t_ns,gaze_x,gaze_y,gaze_z\n";

TEST(TraceLimits, LinesAreBounded) {
  const std::string long_line = kHeader + "0,0,0,-1\n" + std::string(CsvCursor::kMaxLineBytes + 1, '1') + "\n";
  EXPECT_EQ(error_of(long_line),
            "t.csv:3:65537: line longer than 65536 bytes: not a CSV text trace (binary data, "
            "or a file without line ends)");
  EXPECT_THAT(error_of(long_line, /*lenient=*/true), HasSubstr("t.csv:3:65537: line longer than 65536 bytes"))
      << "fatal in lenient mode too: nothing after it is a row";
  // No line ends at all: refused after kMaxLineBytes, not after reading everything.
  EXPECT_THAT(error_of(std::string(4 << 20, ',')), HasSubstr("t.csv:1:65537: line longer than"));
  EXPECT_THAT(error_of<GazeBaseVrReader>(std::string(1 << 17, 'n')), HasSubstr("t.csv:1:65537: line longer"));
  EXPECT_THAT(error_of<PupilReader>(std::string(1 << 17, 'p')), HasSubstr("t.csv:1:65537: line longer"));
  // Exactly the limit is a line.
  EXPECT_THAT(error_of(kHeader + std::string(CsvCursor::kMaxLineBytes, '1') + "\n"), HasSubstr("t.csv:2:"));
  EXPECT_THAT(error_of(kHeader + std::string(CsvCursor::kMaxLineBytes, '1') + "\n"),
              ::testing::Not(HasSubstr("longer")));
}

TEST(TraceLimits, LineEndsAndBinaryData) {
  EXPECT_EQ(error_of("t_ns,gaze_x,gaze_y,gaze_z\r0,0,0,-1\r1,0,0,-1\r"),
            "t.csv:1:26: carriage return (CR) inside a line: the file has CR-only line ends; convert them to LF");
  EXPECT_EQ(error_of("t_ns,gaze_x,gaze_y,gaze_z\r\n0,0,0,-1\r\n"), "") << "CRLF is fine";
  EXPECT_EQ(error_of("\r\r\r"), "t.csv: no header row: the file's 1 line(s) are all blank or comments");
  EXPECT_EQ(error_of(kHeader + "0,0,0,-1\n" + std::string("1,0\0,0,-1\n", 10)),
            "t.csv:3:4: NUL byte: binary data, not a CSV text trace");
  EXPECT_EQ(error_of(std::string(1000, '\0')), "t.csv:1:1: NUL byte: binary data, not a CSV text trace");
  EXPECT_EQ(error_of(""), "t.csv: empty file (0 bytes): no header row");
  EXPECT_EQ(error_of("\n\n# only a comment\n  \n"),
            "t.csv: no header row: the file's 4 line(s) are all blank or comments");
  EXPECT_EQ(error_of<GazeBaseVrReader>(""), "t.csv: empty file (0 bytes): no header row");
  EXPECT_EQ(error_of<PupilReader>("\n"), "t.csv: no header row: the file's 1 line(s) are all blank or comments");
}

TEST(TraceLimits, OpenSaysWhatIsThere) {
  const fs::path dir = fs::path(::testing::TempDir()) / "gazelod_trace_limits";
  fs::create_directories(dir);
  EXPECT_EQ(open_error(dir.string()), dir.string() + ": is a directory, not a trace file");
  if (fs::exists("/dev/zero")) {
    EXPECT_EQ(open_error("/dev/zero"), "/dev/zero: is a device, not a trace file (give a regular file or a pipe)");
  }
  EXPECT_EQ(open_error((dir / "none.csv").string()),
            (dir / "none.csv").string() + ": cannot open file for reading: No such file or directory");
}

TEST(TraceLimits, APipeIsReadAsAStream) {
  const fs::path fifo = fs::path(::testing::TempDir()) / ("gazelod_trace_fifo_" + std::to_string(::getpid()));
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] {
    std::ofstream out(fifo);
    out << kHeader;
    for (int i = 0; i < 10000; ++i) out << i << ",0,0,-1\n";
  });
  std::size_t rows = 0;
  {
    auto s = open_trace(fifo.string(), TraceFormat::gazelod);
    TraceRecord r;
    while (s->next(r)) ++rows;
  }
  writer.join();
  fs::remove(fifo);
  EXPECT_EQ(rows, 10000u);
}

}  // namespace
}  // namespace gazelod::gaze
