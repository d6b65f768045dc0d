#include "gaze/trace_open.hpp"

#include "gaze/import_gazebasevr.hpp"
#include "gaze/import_pupil.hpp"
#include "gaze/trace_reader.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace gazelod::gaze {
namespace {

// Keeps the file alive as long as the reader that reads it (members built in order).
template <typename Reader>
class OwningStream : public RecordStream {
 public:
  OwningStream(std::unique_ptr<std::ifstream> file, const std::string& path, ReadOptions o)
      : file_(std::move(file)), reader_(*file_, path, o) {}
  bool next(TraceRecord& out) override { return reader_.next(out); }
  const SkipReport& skipped() const override { return reader_.skipped(); }
  bool has_head() const override { return reader_.has_head(); }

 private:
  std::unique_ptr<std::ifstream> file_;
  Reader reader_;
};

}  // namespace

std::optional<TraceFormat> parse_trace_format(std::string_view name) {
  if (name == "gazelod") return TraceFormat::gazelod;
  if (name == "gazebasevr") return TraceFormat::gazebasevr;
  if (name == "pupil") return TraceFormat::pupil;
  return std::nullopt;
}

std::string_view trace_format_name(TraceFormat format) {
  switch (format) {
    case TraceFormat::gazelod: return "gazelod";
    case TraceFormat::gazebasevr: return "gazebasevr";
    case TraceFormat::pupil: return "pupil";
  }
  return "?";
}

std::unique_ptr<RecordStream> open_trace(const std::string& path, TraceFormat format,
                                         ReadOptions options) {
  // What is at `path` first: a directory or a device opens, then reads as nothing (a
  // directory) or forever (/dev/zero). A pipe is read as a stream (lines are bounded).
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw TraceError({path, 0, 0, std::string("cannot open file for reading: ") + std::strerror(errno)});
  if (S_ISDIR(st.st_mode)) throw TraceError({path, 0, 0, "is a directory, not a trace file"});
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode))
    throw TraceError({path, 0, 0, "is a device, not a trace file (give a regular file or a pipe)"});
  if (S_ISSOCK(st.st_mode)) throw TraceError({path, 0, 0, "is a socket, not a trace file"});
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*file)
    throw TraceError({path, 0, 0, std::string("cannot open file for reading: ") + std::strerror(errno)});
  switch (format) {
    case TraceFormat::gazelod:
      return std::make_unique<OwningStream<TraceReader>>(std::move(file), path, options);
    case TraceFormat::gazebasevr:
      return std::make_unique<OwningStream<GazeBaseVrReader>>(std::move(file), path, options);
    case TraceFormat::pupil:
      return std::make_unique<OwningStream<PupilReader>>(std::move(file), path, options);
  }
  throw TraceError({path, 0, 0, "unknown trace format"});
}

}  // namespace gazelod::gaze
