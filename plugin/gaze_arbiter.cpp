// SPDX-License-Identifier: Apache-2.0
#include "plugin/gaze_arbiter.hpp"

#include "auxiliary/time.hpp"

#include <cmath>

namespace gazelod::plugin {
namespace {

// A sample the selection can use: marked valid, with a finite, non-zero direction. A source
// handing out NaN or a zero vector counts as not delivering (never reaches a decision).
std::optional<gaze::GazeSample> usable(std::optional<gaze::GazeSample> s) {
  if (!s || !s->valid) return std::nullopt;
  const glm::dvec3& d = s->direction;
  const double len2 = d.x * d.x + d.y * d.y + d.z * d.z;
  if (!std::isfinite(len2) || len2 < 1e-12) return std::nullopt;
  return s;
}

std::string seconds(std::int64_t ns) {
  return std::to_string(aux::seconds_from_ns(ns)).substr(0, 5) + " s";
}

}  // namespace

GazeArbiter::GazeArbiter(gaze::GazeSource* primary, gaze::GazeSource* secondary, ArbiterConfig config)
    : primary_(primary), secondary_(secondary), config_(config) {}

void GazeArbiter::switch_to(GazeSourceKind s, const std::string& why, bool force_report) {
  if (s == current_ && reported_initial_ && !force_report) return;
  current_ = s;
  reported_initial_ = true;
  if (changed_) changed_(s, why);
}

void GazeArbiter::session_state(bool focused, std::int64_t t_ns) {
  states_reported_ = true;
  if (focused && !focused_) focused_t_ns_ = t_ns;
  focused_ = focused;
}

ArbiterResult GazeArbiter::update(std::int64_t t_ns) {
  if (!started_ || restart_pending_) {
    started_ = true;
    first_t_ns_ = t_ns;
    if (restart_pending_ && focused_) focused_t_ns_ = t_ns;
    restart_pending_ = false;
  }
  ArbiterResult result;
  bool newly_distrusted = false;  // reported even if the active source stays the same
  // Reasons are only spelled out when a change is reported: no allocation in a steady frame.
  auto must_report = [&](GazeSourceKind s) { return s != current_ || !reported_initial_ || newly_distrusted; };

  if (primary_ && !primary_distrusted_) {
    const std::optional<gaze::GazeSample> raw = primary_->sample_at(t_ns);
    if (auto s = usable(raw)) {
      primary_ever_ = true;
      last_usable_t_ns_ = t_ns;
      result.source = config_.primary_kind;
      result.sample = *s;
      if (must_report(result.source)) switch_to(config_.primary_kind, primary_->name() + " eye gaze delivered", false);
      return result;
    }
    // A blink: bridged with the invalid samples themselves (ArbiterConfig::blink_bridge_ns).
    if (primary_ever_ && raw && !raw->valid && current_ == config_.primary_kind &&
        t_ns - last_usable_t_ns_ <= config_.blink_bridge_ns) {
      result.source = config_.primary_kind;
      result.sample = *raw;
      return result;
    }
    // Never delivered within the timeout: the runtime advertises gaze it does not have.
    const bool timing = states_reported_ ? focused_ : true;
    const std::int64_t since = states_reported_ ? focused_t_ns_ : first_t_ns_;
    if (!primary_ever_ && timing && t_ns - since > config_.silence_timeout_ns) {
      primary_distrusted_ = true;
      newly_distrusted = true;
    }
  }

  const std::optional<gaze::GazeSample> second = secondary_ ? usable(secondary_->sample_at(t_ns)) : std::nullopt;
  // Short gaps of a trusted primary (blinks) are bridged by the source's own hold; beyond
  // that the head-fixed fallback keeps detail with a widened cone.
  result.source = second ? GazeSourceKind::external : GazeSourceKind::head_fixed;
  if (second) result.sample = *second;
  if (!must_report(result.source)) return result;

  std::string why;
  if (!primary_) {
    why = config_.why_no_primary.empty() ? "no primary gaze source" : config_.why_no_primary;
  } else if (primary_distrusted_) {
    // The source's own status says whose fault it is (a binding the application replaced, a
    // runtime that advertises gaze it does not have).
    const std::string status = primary_->status();
    why = primary_->name() + " delivered no usable eye gaze in " + seconds(config_.silence_timeout_ns) + " (" +
          (status == "ok" ? "its samples were not finite or had zero length" : status) + ")";
  } else {
    why = primary_->name() + " gaze unavailable (" + primary_->status() + ")";
  }
  if (second) {
    why += "; using " + secondary_->name();
  } else {
    if (secondary_) why += "; " + secondary_->name() + " unavailable (" + secondary_->status() + ")";
    why += "; head-fixed gaze with a widened cone";
  }
  switch_to(result.source, why, newly_distrusted);
  return result;
}

}  // namespace gazelod::plugin
