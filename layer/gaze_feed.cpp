// SPDX-License-Identifier: Apache-2.0
#include "layer/gaze_feed.hpp"

#include "auxiliary/time.hpp"
#include "gaze/hid/enumerate.hpp"
#include "gaze/hid/hid_gaze_source.hpp"
#include "gaze/replay_source.hpp"

#include <sstream>
#include <stdexcept>

namespace gazelod::layer {

TraceFeed::TraceFeed(std::string path, std::vector<gaze::TraceRecord> records, std::int64_t freshness_ns)
    : path_(std::move(path)), samples_(records.size()) {
  if (!records.empty()) {
    first_sample_ns_ = records.front().gaze.t_ns;
    span_ns_ = records.back().gaze.t_ns - first_sample_ns_;
  }
  gaze::ReplayOptions options;
  options.hold_max_ns = freshness_ns;
  replay_ = std::make_unique<gaze::ReplaySource>(std::move(records), options);
}

std::string TraceFeed::describe() const {
  std::ostringstream s;
  s << "trace " << path_ << " (" << samples_ << " samples over " << aux::seconds_from_ns(span_ns_)
    << " s, replayed from the session's first frame)";
  return s.str();
}

void TraceFeed::on_frame(std::int64_t predicted_display_time_ns, bool first_of_session) {
  if (first_of_session) {
    offset_ns_ = predicted_display_time_ns - first_sample_ns_;
    mapped_ = true;
  }
  now_ns_ = predicted_display_time_ns;
}

std::optional<gaze::GazeSample> TraceFeed::sample_at(std::int64_t t_ns) {
  if (!mapped_) return std::nullopt;  // no frame yet: the trace has no place on the clock
  auto s = replay_->sample_at(t_ns - offset_ns_);
  if (s) s->t_ns += offset_ns_;
  return s;
}

bool TraceFeed::fresh() {
  return mapped_ && sample_at(now_ns_).has_value();
}

std::string TraceFeed::status() const {
  return mapped_ ? replay_->status() : "waiting for the session's first frame";
}

std::unique_ptr<TraceFeed> open_trace_feed(const LayerConfig& config) {
  auto stream = gaze::open_trace(config.trace_path, config.trace_format);
  auto records = gaze::ReplaySource::load(*stream);
  if (records.empty()) throw std::runtime_error(config.trace_path + ": the trace has no samples");
  return std::make_unique<TraceFeed>(config.trace_path, std::move(records), config.effective_freshness_ns());
}

namespace {

class HidFeed final : public GazeFeed {
 public:
  HidFeed(gaze::hid::HidTrackerConfig tracker, std::int64_t freshness_ns, std::function<std::int64_t()> now_ns)
      : now_ns_(std::move(now_ns)), source_(std::move(tracker), freshness_ns) {}
  std::string describe() const override { return "HID eye tracker (usage page 0x12)"; }
  void on_frame(std::int64_t, bool) override {}
  std::optional<gaze::GazeSample> sample_at(std::int64_t t_ns) override { return source_.sample_at(t_ns); }
  bool fresh() override { return source_.sample_at(now_ns_()).has_value(); }
  std::string status() const override { return source_.status(); }

 private:
  std::function<std::int64_t()> now_ns_;
  gaze::hid::HidGazeSource source_;  // last: its thread stops before now_ns_ goes
};

}  // namespace

std::string describe_hid_trackers(const LayerConfig& config) {
  std::string out;
  for (const auto& t : gaze::hid::list_trackers()) {
    if (t.usage != gaze::hid::kUsageEyeTracker) continue;
    if (!config.hid_path.empty() && t.path != config.hid_path) continue;
    out += (out.empty() ? "" : ", ") + t.path;
    const std::string name = t.manufacturer + (t.manufacturer.empty() ? "" : " ") + t.product;
    if (!name.empty()) out += " (" + name + ")";
  }
  return out;
}

std::unique_ptr<GazeFeed> open_hid_feed(const LayerConfig& config, HidFeedOptions options, std::string& note) {
  note.clear();
  if (describe_hid_trackers(config).empty())
    note = (config.hid_path.empty() ? std::string("no HID eye tracker (usage page 0x12) found")
                                    : "no HID eye tracker at " + config.hid_path) +
           "; eye gaze stays inactive until one is plugged in";
  gaze::hid::HidTrackerConfig tracker;
  tracker.path = config.hid_path;
  tracker.layout = config.hid_layout == "dmf" ? gaze::hid::kLayoutGazeHidDmf : gaze::hid::kLayoutGazeHidPacked;
  tracker.screen.width_m = config.hid_screen_width_m;
  tracker.screen.height_m = config.hid_screen_height_m;
  tracker.host_now_ns = options.now_ns;
  const bool said_absent = !note.empty();
  auto log = options.log;
  tracker.log = [log, said_absent](const std::string& line) {
    static const std::string kPrefix = "gazelod hid: ";
    std::string l = line.rfind(kPrefix, 0) == 0 ? line.substr(kPrefix.size()) : line;
    // The note already said it: one line per misconfiguration.
    if (said_absent && l.rfind("no eye tracker", 0) == 0) return;
    if (log) log("hid: " + l);
  };
  return std::make_unique<HidFeed>(std::move(tracker), config.effective_freshness_ns(), std::move(options.now_ns));
}

}  // namespace gazelod::layer
