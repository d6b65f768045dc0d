// SPDX-License-Identifier: Apache-2.0
// The switch policy (lod/switch_policy.hpp) for cluster cuts (lod/cluster/cluster_select.hpp).
// Per object, the policy holds back a coarser level; a cluster cut has no levels, and holding
// clusters one by one could draw a coarse cluster beside its own finer children (an overlap) or
// neither (a crack). So the hysteresis acts on what the cut is made of: the records (a group's
// bounds and error), each of which is invisible or not. Per record:
//   - refinement at once: a record the selection finds visible is drawn as visible in the same
//     frame (the cut is never coarser than this frame's perceptual cut);
//   - coarsening after a hold: a record the selection finds invisible is drawn as invisible only
//     once it has been so for coarsen_hold_s without a break, with prefer_suppression then in a
//     suppressed frame (saccade or blink; suppressed_hold_s there) or anyway after
//     max_deferral_s more (the same SwitchPolicyConfig, the same rules as for objects, except
//     that release_regret_s and release_by_motion are not used here: the consistency argument
//     below needs a release that depends on time and suppression alone);
//   - a cluster is drawn when its self record is held invisible and its parent record not.
// Why the held cut stays consistent: a group's record is held in every cluster that carries it
// (as self in the clusters it produced, as parent in its members); those copies see identical
// inputs (select_clusters decides identical records identically) and so evolve identically.
// And holding keeps the nesting: a record invisible at a frame implies its children's records
// invisible then (cluster_select.hpp), so a child's run of invisible frames started no later
// than its parent's, its hold ends no later, and any frame that releases the parent releases
// the child (the same suppressed flag, an elapsed time no shorter). So "parent held invisible"
// implies "child held invisible", and along every leaf's ancestor path the held-invisible
// records form a prefix: exactly one cluster drawn over each leaf, at most as coarse as the
// perceptual cut.
//
// API (caller-owned state, one entry per cluster in each span, no allocation):
//   reset_cluster_switch_state(state, clusters.self_error_m, clusters.parent_error_m);  // finest cut
//   each frame: select_clusters(viewer, clusters, {drawn_now, why, ..., record_invisible});
//     apply_cluster_switch_policy(config, t_s, suppressed, record_invisible, state, drawn, held);
//     draw cluster i when drawn[i] == 1; held[i] (HoldReason) says why a coarser cut waits.
//   or, with a selector that rewrites only what changed (ClusterSelector's incremental bytes),
//     apply_cluster_switch_policy_listed over the clusters it evaluated this frame and the last
//     and those left pending: the same result in time proportional to the change.
// Validation: an invalid config or spans of different lengths are refused with a message,
// nothing written. A non-finite t_s is a frame in which no time passes (as for objects).
#pragma once

#include "lod/switch_policy.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gazelod::lod {

struct ClusterSwitchState {
  // Bit 0: the self record is drawn as invisible; bit 1: the parent record is.
  std::span<std::uint8_t> record_held;
  // When each record's current run of invisible, not yet held frames began (non-finite: none).
  std::span<double> self_window_start_s, parent_window_start_s;
};

// The finest consistent cut: a record is held invisible exactly when its error is 0 (every
// source cluster drawn, unless its parent's error is 0 too). Call at registration (or with
// subspans for one mesh's clusters). "" or a length message, nothing written.
[[nodiscard]] std::string reset_cluster_switch_state(const ClusterSwitchState& state,
                                                     std::span<const float> self_error_m,
                                                     std::span<const float> parent_error_m);

// One frame. record_invisible: select_clusters' ClusterDecisions::record_invisible (bit 0 self,
// bit 1 parent). Updates state, writes drawn (0/1) and held (HoldReason: of the parent record
// when its coarsening waits, else of the self record's; none when neither waits). held may be
// empty. Returns "" or, for an invalid config or spans of other lengths, a message.
[[nodiscard]] std::string apply_cluster_switch_policy(const SwitchPolicyConfig& config, double t_s, bool suppressed,
                                                      std::span<const std::uint8_t> record_invisible,
                                                      const ClusterSwitchState& state, std::span<std::uint8_t> drawn,
                                                      std::span<std::uint8_t> held);

// The same step for the listed clusters only (each at most once), in time proportional to the
// list: every other cluster keeps its state, drawn and held, which is exactly what the full pass
// gives a cluster whose record_invisible equals its held bits (its windows then are closed).
// So listing every cluster whose record_invisible changed since the last frame plus those left
// pending (a record invisible, not yet held) gives the full pass's result. Appends to pending
// the listed clusters left pending after this frame. "" or a message (an id out of range, or as
// apply_cluster_switch_policy), nothing written then.
[[nodiscard]] std::string apply_cluster_switch_policy_listed(
    const SwitchPolicyConfig& config, double t_s, bool suppressed, std::span<const std::uint8_t> record_invisible,
    const ClusterSwitchState& state, std::span<std::uint8_t> drawn, std::span<std::uint8_t> held,
    std::span<const std::uint32_t> clusters, std::vector<std::uint32_t>& pending);

}  // namespace gazelod::lod
