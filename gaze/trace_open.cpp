// SPDX-License-Identifier: Apache-2.0
#include "gaze/trace_open.hpp"

#include "gaze/import_gazebasevr.hpp"
#include "gaze/import_pupil.hpp"
#include "gaze/import_pupil_cloud.hpp"
#include "gaze/import_sranipal.hpp"
#include "gaze/trace_format.hpp"
#include "gaze/trace_reader.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <streambuf>

namespace gazelod::gaze {
namespace {

// Reads through the file's buffer and keeps what was read until rewind(), so the header can
// be read once to detect the layout and again by the reader (a pipe cannot seek back).
class RewindableBuf final : public std::streambuf {
 public:
  explicit RewindableBuf(std::streambuf* source) : source_(source) {}
  void rewind() {
    recording_ = false;
    setg(data_.data(), data_.data(), data_.data() + data_.size());
  }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (!recording_) data_.clear();
    const std::size_t kept = data_.size();
    data_.resize(kept + kChunk);
    const std::streamsize n = source_->sgetn(data_.data() + kept, static_cast<std::streamsize>(kChunk));
    data_.resize(kept + static_cast<std::size_t>(std::max<std::streamsize>(n, 0)));
    setg(data_.data(), data_.data() + kept, data_.data() + data_.size());
    return gptr() < egptr() ? traits_type::to_int_type(*gptr()) : traits_type::eof();
  }

 private:
  static constexpr std::size_t kChunk = std::size_t{1} << 16;
  std::streambuf* source_;
  std::string data_;
  bool recording_ = true;
};

// The open file and the stream the reader reads; a base of OwningStream so that it is built
// before the reader (and the stream is the reader: opened_trace_format can ask its type).
struct InputFile {
  explicit InputFile(std::unique_ptr<std::ifstream> f) : file(std::move(f)), buf(file->rdbuf()), in(&buf) {}
  std::unique_ptr<std::ifstream> file;
  RewindableBuf buf;
  std::istream in;
};

struct FileHolder {
  std::unique_ptr<InputFile> input;
};

template <typename Reader>
class OwningStream final : private FileHolder, public Reader {
 public:
  template <typename... Extra>
  OwningStream(std::unique_ptr<InputFile> opened, const std::string& path, ReadOptions o, Extra&&... extra)
      : FileHolder{std::move(opened)}, Reader(FileHolder::input->in, path, o, std::forward<Extra>(extra)...) {}
};

std::string_view trim(std::string_view s) {
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return s;
}

// Reads lines up to the header row (skipping blank and '#' lines, like CsvCursor) and names
// the layout; gives up as gazelod after 2 * kMaxLineBytes (the reader then says what is wrong).
TraceFormat sniff(std::streambuf& buf) {
  const std::size_t max_bytes = 2 * CsvCursor::kMaxLineBytes;
  std::size_t bytes_read = 0;
  bool magic = false, first = true;
  std::string line;
  for (bool eof = false; !eof;) {
    line.clear();
    for (;;) {
      const auto c = buf.sbumpc();
      if (c == std::streambuf::traits_type::eof()) {
        eof = true;
        break;
      }
      if (++bytes_read > max_bytes) return TraceFormat::gazelod;
      if (c == '\n') break;
      line.push_back(static_cast<char>(c));
    }
    std::string_view v(line);
    if (first && v.substr(0, 3) == "\xEF\xBB\xBF") v.remove_prefix(3);  // UTF-8 BOM
    first = false;
    v = trim(v);
    if (v.empty()) continue;
    if (v.front() == '#') {
      magic = magic || v.substr(0, trace_format::kMagic.size()) == trace_format::kMagic;
      continue;
    }
    // Semicolons and no comma: a semicolon-separated header (SRanipal's Unity logs).
    const char delimiter = v.find(',') == std::string_view::npos && v.find(';') != std::string_view::npos ? ';' : ',';
    std::vector<std::string> columns;
    for (std::size_t start = 0;;) {
      const std::size_t comma = v.find(delimiter, start);
      columns.emplace_back(trim(v.substr(start, comma == std::string_view::npos ? v.npos : comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    return detect_trace_format(columns, magic);
  }
  return TraceFormat::gazelod;
}

PupilCloudBlinks blinks_beside(const std::string& gaze_path) {
  const auto path = pupil_cloud_blinks_path(gaze_path);
  struct stat st {};
  if (!path || ::stat(path->c_str(), &st) != 0) return {};  // no blinks file: none applied
  if (!S_ISREG(st.st_mode))
    throw TraceError({*path, 0, 0, "is not a regular file (the blinks file beside the gaze file)"});
  std::ifstream in(*path, std::ios::binary);
  if (!in) throw TraceError({*path, 0, 0, std::string("cannot open file for reading: ") + std::strerror(errno)});
  return read_pupil_cloud_blinks(in, *path);
}

}  // namespace

std::optional<TraceFormat> parse_trace_format(std::string_view name) {
  for (auto f : {TraceFormat::gazelod, TraceFormat::gazebasevr, TraceFormat::pupil, TraceFormat::pupil_cloud,
                 TraceFormat::sranipal, TraceFormat::automatic})
    if (name == trace_format_name(f)) return f;
  return std::nullopt;
}

std::string_view trace_format_name(TraceFormat format) {
  switch (format) {
    case TraceFormat::gazelod:
      return "gazelod";
    case TraceFormat::gazebasevr:
      return "gazebasevr";
    case TraceFormat::pupil:
      return "pupil";
    case TraceFormat::pupil_cloud:
      return "pupil_cloud";
    case TraceFormat::sranipal:
      return "sranipal";
    case TraceFormat::automatic:
      return "auto";
  }
  return "?";
}

TraceFormat detect_trace_format(const std::vector<std::string>& header_columns, bool gazelod_magic) {
  if (gazelod_magic) return TraceFormat::gazelod;
  auto has = [&](std::string_view name) {
    return std::find(header_columns.begin(), header_columns.end(), name) != header_columns.end();
  };
  if (has("timestamp [ns]") && (has("azimuth [deg]") || has("gaze x [px]"))) return TraceFormat::pupil_cloud;
  if (has("time(100ns)") && has("gaze_direct_L.x")) return TraceFormat::sranipal;
  if (has("gaze_timestamp")) return TraceFormat::pupil;
  if (has("n") && has("x") && has("y") && !has(trace_format::kTimeNs) && !has(trace_format::kTimeS))
    return TraceFormat::gazebasevr;
  return TraceFormat::gazelod;
}

std::unique_ptr<RecordStream> open_trace(const std::string& path, TraceFormat format, ReadOptions options) {
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
  if (!*file) throw TraceError({path, 0, 0, std::string("cannot open file for reading: ") + std::strerror(errno)});
  auto input = std::make_unique<InputFile>(std::move(file));
  if (format == TraceFormat::automatic) format = sniff(input->buf);
  input->buf.rewind();
  switch (format) {
    case TraceFormat::gazelod:
      return std::make_unique<OwningStream<TraceReader>>(std::move(input), path, options);
    case TraceFormat::gazebasevr:
      return std::make_unique<OwningStream<GazeBaseVrReader>>(std::move(input), path, options);
    case TraceFormat::pupil:
      return std::make_unique<OwningStream<PupilReader>>(std::move(input), path, options);
    case TraceFormat::pupil_cloud:
      return std::make_unique<OwningStream<PupilCloudReader>>(std::move(input), path, options, blinks_beside(path));
    case TraceFormat::sranipal:
      return std::make_unique<OwningStream<SranipalReader>>(std::move(input), path, options);
    case TraceFormat::automatic:
      break;  // replaced by the detected layout above
  }
  throw TraceError({path, 0, 0, "unknown trace format"});
}

std::optional<TraceFormat> opened_trace_format(const RecordStream& stream) {
  if (dynamic_cast<const TraceReader*>(&stream)) return TraceFormat::gazelod;
  if (dynamic_cast<const GazeBaseVrReader*>(&stream)) return TraceFormat::gazebasevr;
  if (dynamic_cast<const PupilReader*>(&stream)) return TraceFormat::pupil;
  if (dynamic_cast<const PupilCloudReader*>(&stream)) return TraceFormat::pupil_cloud;
  if (dynamic_cast<const SranipalReader*>(&stream)) return TraceFormat::sranipal;
  return std::nullopt;
}

}  // namespace gazelod::gaze
