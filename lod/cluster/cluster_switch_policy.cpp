// SPDX-License-Identifier: Apache-2.0
// The cluster switch policy (see cluster_switch_policy.hpp): one pass over the clusters, each
// of its two records stepped by the same rule from its own state.
#include "lod/cluster/cluster_switch_policy.hpp"

#include "lod/switch_hold.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::lod {
namespace {

// "" when every span of state has n entries.
[[nodiscard]] std::string check_state(const char* function, const ClusterSwitchState& s, std::size_t n) {
  if (s.record_held.size() != n) return switch_length_error(function, "state.record_held", s.record_held.size(), n);
  if (s.self_window_start_s.size() != n)
    return switch_length_error(function, "state.self_window_start_s", s.self_window_start_s.size(), n);
  if (s.parent_window_start_s.size() != n)
    return switch_length_error(function, "state.parent_window_start_s", s.parent_window_start_s.size(), n);
  return {};
}

// One record: returns whether it is held invisible after this frame; updates its window and
// says why a perceptually invisible record is not yet held. The frame's constants are the
// object policy's (lod/switch_hold.hpp), for one record instead of a level.
bool step_record(const SwitchHold& st, double t_s, bool invisible, bool held, double& window_start_s, HoldReason& why) {
  why = HoldReason::none;
  if (!invisible) {  // visible: at once (refinement), any window closes
    window_start_s = kNoSwitchWindow;
    return false;
  }
  if (held) return true;  // stays invisible while it is
  if (!st.timed) {        // no time passes: nothing opens, nothing is released
    why = HoldReason::no_time;
    return false;
  }
  double start = window_start_s;
  if (!std::isfinite(start) || t_s < start) start = t_s;  // opens, or the clock went back
  const double elapsed = t_s - start;
  if (elapsed >= st.hold_s && (st.release_without_deadline || elapsed >= st.deadline_s)) {
    window_start_s = kNoSwitchWindow;
    return true;
  }
  window_start_s = start;
  why = elapsed >= st.hold_s ? HoldReason::awaiting_suppression : HoldReason::hold_time;
  return false;
}

// Cluster i's two records stepped; its drawn and held written. Returns whether a record is left
// invisible but not held (pending: its window is open).
bool step_cluster(const SwitchHold& st, double t_s, std::uint8_t bits, const ClusterSwitchState& state, std::size_t i,
                  std::span<std::uint8_t> drawn, std::span<std::uint8_t> held) {
  const std::uint8_t was = state.record_held[i];
  HoldReason why_self = HoldReason::none, why_parent = HoldReason::none;
  const bool self = step_record(st, t_s, (bits & 1) != 0, (was & 1) != 0, state.self_window_start_s[i], why_self);
  const bool parent = step_record(st, t_s, (bits & 2) != 0, (was & 2) != 0, state.parent_window_start_s[i], why_parent);
  const auto now = static_cast<std::uint8_t>((self ? 1 : 0) | (parent ? 2 : 0));
  state.record_held[i] = now;
  drawn[i] = self && !parent ? 1 : 0;
  if (!held.empty()) held[i] = static_cast<std::uint8_t>(why_parent != HoldReason::none ? why_parent : why_self);
  return (bits & 3 & ~now) != 0;
}

// "" when config, state, drawn and held fit n clusters.
[[nodiscard]] std::string check_frame(const char* fn, const SwitchPolicyConfig& config, const ClusterSwitchState& state,
                                      std::size_t n, std::span<std::uint8_t> drawn, std::span<std::uint8_t> held) {
  if (std::string e = validate_switch_config(config); !e.empty()) return std::string(fn) + ": " + e;
  if (std::string e = check_state(fn, state, n); !e.empty()) return e;
  if (drawn.size() != n) return switch_length_error(fn, "drawn", drawn.size(), n);
  if (!held.empty() && held.size() != n) return switch_length_error(fn, "held", held.size(), n);
  return {};
}

}  // namespace

std::string reset_cluster_switch_state(const ClusterSwitchState& state, std::span<const float> self_error_m,
                                       std::span<const float> parent_error_m) {
  const std::size_t n = self_error_m.size();
  if (parent_error_m.size() != n)
    return switch_length_error("reset_cluster_switch_state", "parent_error_m", parent_error_m.size(), n);
  if (std::string e = check_state("reset_cluster_switch_state", state, n); !e.empty()) return e;
  for (std::size_t i = 0; i < n; ++i)
    state.record_held[i] =
        static_cast<std::uint8_t>((self_error_m[i] == 0.0f ? 1 : 0) | (parent_error_m[i] == 0.0f ? 2 : 0));
  std::fill(state.self_window_start_s.begin(), state.self_window_start_s.end(), kNoSwitchWindow);
  std::fill(state.parent_window_start_s.begin(), state.parent_window_start_s.end(), kNoSwitchWindow);
  return {};
}

std::string apply_cluster_switch_policy(const SwitchPolicyConfig& config, double t_s, bool suppressed,
                                        std::span<const std::uint8_t> record_invisible, const ClusterSwitchState& state,
                                        std::span<std::uint8_t> drawn, std::span<std::uint8_t> held) {
  const std::size_t n = record_invisible.size();
  if (std::string e = check_frame("apply_cluster_switch_policy", config, state, n, drawn, held); !e.empty()) return e;
  const SwitchHold st = switch_hold(config, t_s, suppressed);
  for (std::size_t i = 0; i < n; ++i) (void)step_cluster(st, t_s, record_invisible[i], state, i, drawn, held);
  return {};
}

std::string apply_cluster_switch_policy_listed(const SwitchPolicyConfig& config, double t_s, bool suppressed,
                                               std::span<const std::uint8_t> record_invisible,
                                               const ClusterSwitchState& state, std::span<std::uint8_t> drawn,
                                               std::span<std::uint8_t> held, std::span<const std::uint32_t> clusters,
                                               std::vector<std::uint32_t>& pending) {
  const char* fn = "apply_cluster_switch_policy_listed";
  const std::size_t n = record_invisible.size();
  if (std::string e = check_frame(fn, config, state, n, drawn, held); !e.empty()) return e;
  for (std::uint32_t i : clusters)
    if (i >= n)
      return std::string(fn) + ": cluster " + std::to_string(i) + " is out of range (" + std::to_string(n) +
             " clusters)";
  const SwitchHold st = switch_hold(config, t_s, suppressed);
  for (std::uint32_t i : clusters)
    if (step_cluster(st, t_s, record_invisible[i], state, i, drawn, held)) pending.push_back(i);
  return {};
}

}  // namespace gazelod::lod
