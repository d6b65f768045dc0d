// SPDX-License-Identifier: Apache-2.0
// The switch policy (see switch_policy.hpp): one pass over the objects, each decided from its
// own state entry and this frame's perceptual level.
#include "lod/switch_policy.hpp"

#include "lod/switch_hold.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::lod {
namespace {

// "" when every span of state has n entries.
[[nodiscard]] std::string check_state(const char* function, const SwitchState& state, std::size_t n) {
  if (state.drawn.size() != n) return switch_length_error(function, "state.drawn", state.drawn.size(), n);
  if (state.finest_allowed.size() != n)
    return switch_length_error(function, "state.finest_allowed", state.finest_allowed.size(), n);
  if (state.window_start_s.size() != n)
    return switch_length_error(function, "state.window_start_s", state.window_start_s.size(), n);
  return {};
}

}  // namespace

const char* to_string(HoldReason r) {
  switch (r) {
    case HoldReason::none:
      return "none";
    case HoldReason::hold_time:
      return "hold_time";
    case HoldReason::awaiting_suppression:
      return "awaiting_suppression";
    case HoldReason::no_time:
      return "no_time";
  }
  return "unknown";
}

std::string validate_switch_config(const SwitchPolicyConfig& config) {
  if (!(std::isfinite(config.coarsen_hold_s) && config.coarsen_hold_s >= 0.0))
    return "coarsen_hold_s must be finite and >= 0";
  if (!(std::isfinite(config.max_deferral_s) && config.max_deferral_s >= 0.0))
    return "max_deferral_s must be finite and >= 0";
  if (!(std::isfinite(config.suppressed_hold_s) && config.suppressed_hold_s >= 0.0))
    return "suppressed_hold_s must be finite and >= 0";
  return {};
}

std::string apply_switch_policy(const SwitchPolicyConfig& config, double t_s, bool suppressed,
                                std::span<const std::uint8_t> perceptual, const SwitchState& state,
                                std::span<std::uint8_t> held) {
  return apply_switch_policy(config, t_s, suppressed, perceptual, {}, state, held);
}

std::string apply_switch_policy(const SwitchPolicyConfig& config, double t_s, bool suppressed,
                                std::span<const std::uint8_t> perceptual, std::span<const std::uint8_t> motion_level,
                                const SwitchState& state, std::span<std::uint8_t> held) {
  if (std::string err = validate_switch_config(config); !err.empty()) return "apply_switch_policy: " + err;
  const std::size_t n = perceptual.size();
  if (std::string err = check_state("apply_switch_policy", state, n); !err.empty()) return err;
  if (!held.empty() && held.size() != n) return switch_length_error("apply_switch_policy", "held", held.size(), n);
  if (!motion_level.empty() && motion_level.size() != n)
    return switch_length_error("apply_switch_policy", "motion_level", motion_level.size(), n);

  const SwitchHold st = switch_hold(config, t_s, suppressed);
  // Only in timed frames, like every other coarsening (a frame without time changes nothing).
  const bool by_motion = config.release_by_motion && !motion_level.empty() && st.timed;

  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t p = perceptual[i];
    std::uint8_t d = state.drawn[i];
    HoldReason why = HoldReason::none;
    if (by_motion && p > d) {
      // The part of the coarsening that size and motion alone justify needs no hold: it is not
      // a guess about the gaze, so the gaze estimate's noise cannot make it flicker.
      const std::uint8_t m = std::min(p, motion_level[i]);
      if (m > d) state.drawn[i] = d = m;
    }
    if (p <= d) {
      // Same or finer: draw it now; no coarser level allowed, so any window closes.
      state.drawn[i] = p;
      state.finest_allowed[i] = p;
      state.window_start_s[i] = kNoSwitchWindow;
    } else {
      // A coarser level is allowed. An entry whose finest is not coarser than the drawn level
      // cannot come from a window (only from a caller's write): it counts as none open.
      double start = state.window_start_s[i];
      std::uint8_t finest = state.finest_allowed[i];
      const bool open = std::isfinite(start) && finest > d;
      if (open) finest = std::min(finest, p);
      if (!st.timed) {
        why = HoldReason::no_time;
        if (open) state.finest_allowed[i] = finest;
      } else {
        if (!open || t_s < start) start = t_s, finest = p;
        const double elapsed = t_s - start;  // both finite: no NaN (at worst +inf)
        why = HoldReason::hold_time;
        if (elapsed >= st.hold_s) {
          if (st.release_without_deadline || elapsed >= st.deadline_s) {
            d = finest;  // > drawn: every level since the window opened was coarser
            state.drawn[i] = d;
            if (p > d) {
              finest = p, start = t_s;  // still coarser allowed: a new window from now
            } else {
              finest = d, start = kNoSwitchWindow, why = HoldReason::none;
            }
          } else {
            why = HoldReason::awaiting_suppression;
          }
        }
        state.finest_allowed[i] = finest;
        state.window_start_s[i] = start;
      }
    }
    if (!held.empty()) held[i] = static_cast<std::uint8_t>(why);
  }
  return {};
}

std::string reset_switch_state(const SwitchState& state, std::uint8_t level) {
  if (std::string err = check_state("reset_switch_state", state, state.drawn.size()); !err.empty()) return err;
  std::fill(state.drawn.begin(), state.drawn.end(), level);
  std::fill(state.finest_allowed.begin(), state.finest_allowed.end(), level);
  std::fill(state.window_start_s.begin(), state.window_start_s.end(), kNoSwitchWindow);
  return {};
}

}  // namespace gazelod::lod
