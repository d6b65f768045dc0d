// Opening a trace file in any supported layout as a RecordStream (the stream owns the file).
#pragma once

#include "gaze/record_stream.hpp"

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace gazelod::gaze {

enum class TraceFormat { gazelod, gazebasevr, pupil };

std::optional<TraceFormat> parse_trace_format(std::string_view name);  // "gazelod", ...
std::string_view trace_format_name(TraceFormat format);

// Opens `path` (a regular file or a pipe); throws TraceError naming the file: missing or
// unreadable (with the system's reason), a directory, a device or a socket, a bad header.
// Reading is streamed, one line of at most CsvCursor::kMaxLineBytes at a time.
std::unique_ptr<RecordStream> open_trace(const std::string& path, TraceFormat format,
                                         ReadOptions options = {});

}  // namespace gazelod::gaze
