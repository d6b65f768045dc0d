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

// "" when costs is empty or valid: a finite unit_triangles >= 0 and an entry for every object's
// drawn and perceptual level. Branch-free over the objects (it runs every frame); the offender
// is looked up only if there is one.
[[nodiscard]] std::string check_costs(const SwitchCosts& costs, std::span<const std::uint8_t> perceptual,
                                      std::span<const std::uint8_t> drawn) {
  if (costs.level_first.empty()) return {};
  const std::size_t n = perceptual.size();
  if (costs.level_first.size() != n)
    return switch_length_error("apply_switch_policy", "costs.level_first", costs.level_first.size(), n);
  if (!(std::isfinite(costs.unit_triangles) && costs.unit_triangles >= 0.0))
    return "apply_switch_policy: costs.unit_triangles must be finite and >= 0";
  const std::size_t levels = costs.level_triangles.size();
  bool covered = true;
  for (std::size_t i = 0; i < n; ++i)
    covered &= std::size_t{costs.level_first[i]} + std::max(perceptual[i], drawn[i]) < levels;
  if (!covered)
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint8_t top = std::max(perceptual[i], drawn[i]);
      if (std::size_t{costs.level_first[i]} + top >= levels)
        return "apply_switch_policy: costs.level_triangles has no entry for object " + std::to_string(i) + "'s level " +
               std::to_string(top);
    }
  return {};
}

// Triangles saved by drawing level `to` instead of `from` of the object whose levels start at
// `first` (0 where `to` is not cheaper).
double saved_triangles(std::span<const std::uint32_t> level_triangles, std::size_t first, std::uint8_t from,
                       std::uint8_t to) {
  const std::uint32_t a = level_triangles[first + from], b = level_triangles[first + to];
  return a > b ? static_cast<double>(a - b) : 0.0;
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
  if (!(std::isfinite(config.release_regret_s) && config.release_regret_s >= 0.0))
    return "release_regret_s must be finite and >= 0";
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
  return apply_switch_policy(config, t_s, suppressed, perceptual, motion_level, SwitchCosts{}, state, held);
}

std::string apply_switch_policy(const SwitchPolicyConfig& config, double t_s, bool suppressed,
                                std::span<const std::uint8_t> perceptual, std::span<const std::uint8_t> motion_level,
                                const SwitchCosts& costs, const SwitchState& state, std::span<std::uint8_t> held) {
  if (std::string err = validate_switch_config(config); !err.empty()) return "apply_switch_policy: " + err;
  const std::size_t n = perceptual.size();
  if (std::string err = check_state("apply_switch_policy", state, n); !err.empty()) return err;
  if (!held.empty() && held.size() != n) return switch_length_error("apply_switch_policy", "held", held.size(), n);
  if (!motion_level.empty() && motion_level.size() != n)
    return switch_length_error("apply_switch_policy", "motion_level", motion_level.size(), n);

  if (config.release_regret_s > 0.0)
    if (std::string err = check_costs(costs, perceptual, state.drawn); !err.empty()) return err;

  const SwitchHold st = switch_hold(config, t_s, suppressed);
  // The triangle-seconds a switch is worth (release_regret_s); none without costs.
  const double switch_worth = config.release_regret_s * costs.unit_triangles;
  const bool by_regret = !costs.level_first.empty() && switch_worth > 0.0;
  // Only in timed frames, like every other coarsening (a frame without time changes nothing).
  const bool by_motion = config.release_by_motion && !motion_level.empty() && st.timed;

  // Local copies of the spans: a byte store may alias any object, so through `state` every
  // pointer would be reloaded after each write.
  const std::span<std::uint8_t> drawn = state.drawn, finest_allowed = state.finest_allowed;
  const std::span<double> window_start_s = state.window_start_s;
  const std::span<const std::uint32_t> level_triangles = costs.level_triangles, level_first = costs.level_first;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t p = perceptual[i];
    std::uint8_t d = drawn[i];
    HoldReason why = HoldReason::none;
    if (by_motion && p > d) {
      // The part of the coarsening that size and motion alone justify needs no hold: it is not
      // a guess about the gaze, so the gaze estimate's noise cannot make it flicker.
      const std::uint8_t m = std::min(p, motion_level[i]);
      if (m > d) drawn[i] = d = m;
    }
    if (p <= d) {
      // Same or finer: draw it now; no coarser level allowed, so any window closes.
      drawn[i] = p;
      finest_allowed[i] = p;
      window_start_s[i] = kNoSwitchWindow;
    } else {
      // A coarser level is allowed. An entry whose finest is not coarser than the drawn level
      // cannot come from a window (only from a caller's write): it counts as none open.
      double start = window_start_s[i];
      std::uint8_t finest = finest_allowed[i];
      const bool open = std::isfinite(start) && finest > d;
      if (open) finest = std::min(finest, p);
      if (!st.timed) {
        why = HoldReason::no_time;
        if (open) finest_allowed[i] = finest;
      } else {
        if (!open || t_s < start) start = t_s, finest = p;
        const double elapsed = t_s - start;  // both finite: no NaN (at worst +inf)
        why = HoldReason::hold_time;
        if (elapsed >= st.hold_s) {
          if (st.release_without_deadline || elapsed >= st.deadline_s ||
              (by_regret && saved_triangles(level_triangles, level_first[i], d, finest) * elapsed >= switch_worth)) {
            d = finest;  // > drawn: every level since the window opened was coarser
            drawn[i] = d;
            if (p > d) {
              finest = p, start = t_s;  // still coarser allowed: a new window from now
            } else {
              finest = d, start = kNoSwitchWindow, why = HoldReason::none;
            }
          } else {
            why = HoldReason::awaiting_suppression;
          }
        }
        finest_allowed[i] = finest;
        window_start_s[i] = start;
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
