// SPDX-License-Identifier: Apache-2.0
// gazelod hid list | record: HID eye trackers (usage page 0x12, HUTRR74) through hidapi.
//   list             the usage-page-0x12 devices hidapi sees (--json for one array)
//   record           read gaze for --seconds into a gazelod trace CSV (--out)
#include "auxiliary/atomic_file.hpp"
#include "gaze/hid/enumerate.hpp"
#include "gaze/hid/hid_tracker.hpp"
#include "gaze/trace_writer.hpp"
#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/run/signals.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <charconv>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <optional>
#include <memory>
#include <sstream>
#include <thread>

namespace gazelod::cli {
namespace {

namespace hid = gaze::hid;

struct Options {
  bool json = false;
  std::string out, device, screen_mm, layout = "packed";
  double seconds = 0.0;
};

std::string hex4(unsigned v) {
  std::ostringstream s;
  s << "0x" << std::hex << std::setw(4) << std::setfill('0') << v;
  return s.str();
}

int run_list(const Options& o, Io io) {
  const auto found = hid::list_trackers();
  if (o.json) {
    nlohmann::json all = nlohmann::json::array();
    for (const auto& t : found)
      all.push_back({{"path", t.path},
                     {"vendor_id", t.vendor_id},
                     {"product_id", t.product_id},
                     {"usage_page", t.usage_page},
                     {"usage", t.usage},
                     {"kind", t.usage == hid::kUsageHeadTracker ? "head tracker" : "eye tracker"},
                     {"interface", t.interface_number},
                     {"manufacturer", t.manufacturer},
                     {"product", t.product},
                     {"serial", t.serial}});
    io.out << aux::json_text(all, 2) << "\n";
    return 0;
  }
  if (found.empty()) {
    io.out << "no HID eye tracker (usage page 0x12) found\n";
    return 0;
  }
  for (const auto& t : found)
    io.out << t.path << "  " << hex4(t.vendor_id) << ":" << hex4(t.product_id) << "  usage " << hex4(t.usage_page)
           << ":" << hex4(t.usage) << "  " << t.manufacturer << " " << t.product
           << (t.serial.empty() ? "" : " (serial " + t.serial + ")") << "\n";
  return 0;
}

double parse_positive(const std::string& option, const std::string& text, double max) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  auto [p, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc{} || p != end || !std::isfinite(v) || !(v > 0.0) || v > max)
    throw UsageError(option + ": expected a number in (0, " + std::to_string(static_cast<long>(max)) + "], got '" +
                     text + "'");
  return v;
}

int run_record(const Options& o, Io io) {
  if (o.out.empty()) throw UsageError("--out: required (the trace CSV to write)");
  check_output_file("--out", o.out);
  if (!(o.seconds > 0.0 && o.seconds <= 86400.0))
    throw UsageError("--seconds: must be in (0, 86400], got " + std::to_string(o.seconds));
  hid::HidTrackerConfig config;
  config.path = o.device;
  if (!o.device.empty())
    if (const std::string e = hid::check_hidraw_path(o.device); !e.empty()) throw UsageError("--device: " + e);
  if (o.layout == "dmf")
    config.layout = hid::kLayoutGazeHidDmf;
  else if (o.layout != "packed")
    throw UsageError("--layout: 'packed' or 'dmf', got '" + o.layout + "'");
  if (!o.screen_mm.empty()) {
    const auto x = o.screen_mm.find_first_of("xX");
    if (x == std::string::npos) throw UsageError("--screen-mm: expected WxH in mm, got '" + o.screen_mm + "'");
    config.screen.width_m = parse_positive("--screen-mm", o.screen_mm.substr(0, x), 10000) * 1e-3;
    config.screen.height_m = parse_positive("--screen-mm", o.screen_mm.substr(x + 1), 10000) * 1e-3;
  }
  // Atomic: a recording that fails (no tracker, a full disk) leaves no file, not a header alone;
  // a second Ctrl-C removes the temporary too (AtomicRunFile).
  std::optional<AtomicRunFile> out_file;
  try {
    out_file.emplace(o.out);
  } catch (const aux::WriteError& e) {
    throw UsageError(std::string("--out: ") + e.what());
  }
  std::ostream& file = out_file->stream();
  config.log = [&io](const std::string& line) { io.err << line << "\n"; };

  gaze::TraceWriterOptions wo;
  wo.write_head = false;
  gaze::TraceWriter writer(file, wo);
  hid::HidTracker tracker(config);
  tracker.start();
  std::vector<gaze::GazeSample> got;
  std::uint64_t written = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(o.seconds);
  auto flush = [&] {
    got.clear();
    tracker.drain(got);
    for (const auto& s : got) {
      gaze::TraceRecord r;
      r.gaze = s;
      writer.write(r);
      ++written;
    }
  };
  // Ctrl-C (or SIGTERM) ends the recording early, the usual way to stop one, and keeps what was
  // recorded; before, it killed the process and left the temporary file.
  StopOnSignal stop;
  while (std::chrono::steady_clock::now() < end && stop.requested() == 0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    flush();
  }
  tracker.stop();
  flush();
  file.flush();
  if (stop.requested() != 0) {
    stop.acted_on();
    io.err << "gazelod hid record: stopped by " << StopOnSignal::name(stop.requested())
           << " before --seconds ran out; the samples so far are kept\n";
  }
  const hid::HidCounters c = tracker.counters();
  io.err << "gazelod hid record: " << written << " samples (" << c.invalid_samples << " invalid) to " << o.out
         << "; skipped " << c.malformed << " malformed and " << c.unknown << " unknown reports; " << c.dropped
         << " dropped; " << c.disconnects << " disconnects\n";
  if (c.opens == 0)
    throw UsageError("no HID eye tracker could be opened (" + tracker.status() + "); nothing written", 1);
  try {
    out_file->commit();
  } catch (const aux::WriteError& e) {
    throw UsageError(std::string("--out: ") + e.what(), 1);
  }
  return 0;
}

Registrar reg("hid", "HID eye trackers (usage page 0x12): list them, record gaze to a trace",
              [](CLI::App& sub) -> Action {
                auto o = std::make_shared<Options>();
                auto seconds = std::make_shared<std::string>();
                sub.require_subcommand(1);
                CLI::App* list = sub.add_subcommand("list", "list usage page 0x12 devices");
                list->add_flag("--json", o->json, "one JSON array");
                CLI::App* rec = sub.add_subcommand("record", "record gaze samples to a trace CSV");
                rec->add_option("--out", o->out, "trace CSV to write")->required();
                rec->add_option("--seconds", *seconds, "how long to record")->required();
                rec->add_option("--device", o->device, "hidapi path (default: first tracker found)");
                rec->add_option("--screen-mm", o->screen_mm, "screen size WxH in mm (default: from the device)");
                rec->add_option("--layout", o->layout, "report layout: packed (default) or dmf");
                return [o, seconds, list](Io io) {
                  if (list->parsed()) return run_list(*o, io);
                  o->seconds = parse_positive("--seconds", *seconds, 86400.0);
                  return run_record(*o, io);
                };
              });

}  // namespace
}  // namespace gazelod::cli
