// SPDX-License-Identifier: Apache-2.0
// Opening a trace file in any supported layout as a RecordStream (the stream owns the file).
#pragma once

#include "gaze/record_stream.hpp"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gazelod::gaze {

// `automatic` reads the header row first and picks the layout (detect_trace_format).
enum class TraceFormat { gazelod, gazebasevr, pupil, pupil_cloud, sranipal, automatic };

// "gazelod", "gazebasevr", "pupil" (Pupil Core gaze_positions.csv), "pupil_cloud" (Pupil
// Cloud gaze.csv: Invisible, Neon), "sranipal" (HTC Vive Pro Eye, SRanipal logged from Unity;
// semicolon-separated), "auto".
std::optional<TraceFormat> parse_trace_format(std::string_view name);
std::string_view trace_format_name(TraceFormat format);

// The layout a header row names, never `automatic`: `timestamp [ns]` with `azimuth [deg]` or
// `gaze x [px]` -> pupil_cloud; `time(100ns)` with `gaze_direct_L.x` (a semicolon-separated
// header) -> sranipal; `gaze_timestamp` -> pupil; `n`, `x`, `y` without `t_ns` / `t_s`
// -> gazebasevr; anything else -> gazelod (whose reader names what is missing).
// `gazelod_magic`: a `# gazelod-trace` line came before the header (then always gazelod).
TraceFormat detect_trace_format(const std::vector<std::string>& header_columns, bool gazelod_magic);

// Opens `path` (a regular file or a pipe); throws TraceError naming the file: missing or
// unreadable (with the system's reason), a directory, a device or a socket, a bad header.
// Reading is streamed, one line of at most CsvCursor::kMaxLineBytes at a time; `automatic`
// reads at most 2 * kMaxLineBytes ahead to find the header and reads them again (a pipe too).
// pupil_cloud also reads the blinks file beside `path` when there is one
// (pupil_cloud_blinks_path in import_pupil_cloud.hpp; errors name that file).
std::unique_ptr<RecordStream> open_trace(const std::string& path, TraceFormat format, ReadOptions options = {});

// The layout of a stream open_trace returned (after `automatic`: the one detected).
std::optional<TraceFormat> opened_trace_format(const RecordStream& stream);

}  // namespace gazelod::gaze
