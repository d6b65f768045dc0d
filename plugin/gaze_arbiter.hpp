// SPDX-License-Identifier: Apache-2.0
// Chooses the gaze source each frame: the runtime's eye gaze, else an external tracker or
// trace, else head-fixed gaze with a widened cone. Reports each change once, with why.
// A runtime that advertises gaze but never delivers it loses trust after a timeout.
#pragma once

#include "auxiliary/time.hpp"
#include "gaze/gaze_source.hpp"
#include "plugin/gaze_source_kind.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace gazelod::plugin {

struct ArbiterConfig {
  // Until the primary source has delivered once, it is given this long from the moment the
  // session became focused (from the first update when the application reports no session
  // states) before it is distrusted for the rest of the session (ns). Gaps after it has
  // delivered (blinks, lost tracking) fall back only while they last.
  std::int64_t silence_timeout_ns = aux::ns_from_seconds(1.0);
  // A source that has delivered and now marks its samples invalid (a blink, a short loss)
  // stays the source this long after its last usable sample: the invalid samples go to the
  // conditioner, which holds its estimate as suppressed (blink suppression) rather than the
  // head-fixed fallback widening the cone to every object in a blink and back after it
  // (measured with gazelod eval family: a refinement and a coarsening per object per blink,
  // outside the true suppression because the tracker reports the blink late). The plugin sets
  // it to the conditioner's loss_hold_max.
  std::int64_t blink_bridge_ns = 300'000'000;
  // What the primary source is (the runtime's eye gaze, or samples the application pushes),
  // and why there is none when it is null ("" = none was asked for).
  GazeSourceKind primary_kind = GazeSourceKind::openxr;
  std::string why_no_primary;
};

struct ArbiterResult {
  GazeSourceKind source = GazeSourceKind::head_fixed;
  gaze::GazeSample sample;  // valid only when source != head_fixed
};

class GazeArbiter {
 public:
  using Changed = std::function<void(GazeSourceKind now, const std::string& why)>;

  // Either source may be null (primary: the runtime's eye gaze, GazeSourceKind::openxr;
  // secondary: the external source). The arbiter does not own them.
  GazeArbiter(gaze::GazeSource* primary, gaze::GazeSource* secondary, ArbiterConfig config = {});

  void on_change(Changed callback) { changed_ = std::move(callback); }

  // Called once per frame at the predicted display time. The change callback fires on each
  // change of source, and once more when the primary is distrusted.
  ArbiterResult update(std::int64_t t_ns);

  // A session state change from the application's event loop: once any is reported, the
  // silence timer runs only while the session is focused, from when it became focused.
  void session_state(bool focused, std::int64_t t_ns);

  // The primary source was replaced (an application's gaze space given late): trust it afresh,
  // with the silence timer restarted at the next update.
  void restart_primary() {
    primary_distrusted_ = false;
    primary_ever_ = false;
    restart_pending_ = true;
  }

  // True once the primary source was judged silent (advertised but never delivered).
  bool primary_distrusted() const { return primary_distrusted_; }

 private:
  void switch_to(GazeSourceKind s, const std::string& why, bool force_report);

  gaze::GazeSource* primary_;
  gaze::GazeSource* secondary_;
  ArbiterConfig config_;
  Changed changed_;
  GazeSourceKind current_ = GazeSourceKind::head_fixed;
  bool started_ = false;
  bool reported_initial_ = false;
  std::int64_t first_t_ns_ = 0;
  bool states_reported_ = false;
  bool focused_ = false;
  std::int64_t focused_t_ns_ = 0;
  bool primary_ever_ = false;
  std::int64_t last_usable_t_ns_ = 0;  // frame time of the primary's last usable sample
  bool primary_distrusted_ = false;
  bool restart_pending_ = false;
};

}  // namespace gazelod::plugin
