// SPDX-License-Identifier: Apache-2.0
// What the two switch policies share (lod/switch_policy.cpp for objects,
// lod/cluster/cluster_switch_policy.cpp for cluster records): one frame's constants of the
// hold rule and the message for a span of the wrong length. One copy, so the two policies
// cannot drift apart in the hold and the deadline. (The object policy alone also releases by
// regret, release_regret_s, and by motion, release_by_motion.)
#pragma once

#include "lod/switch_policy.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

namespace gazelod::lod {

// This frame's constants of the hold rule (switch_policy.hpp), the same for every object or
// record in it.
struct SwitchHold {
  bool timed;                     // t_s is finite: time passes in this frame (else nothing opens or releases)
  double hold_s;                  // how long a coarser choice must last before it is drawn
  double deadline_s;              // hold + deferral: released then even without suppression (finite or +inf)
  bool release_without_deadline;  // no need to wait for suppression (not preferred, or in it)
};

inline SwitchHold switch_hold(const SwitchPolicyConfig& config, double t_s, bool suppressed) {
  // Inside suppression a change goes unseen, so a shorter hold suffices there.
  return SwitchHold{std::isfinite(t_s),
                    suppressed && config.prefer_suppression ? std::min(config.coarsen_hold_s, config.suppressed_hold_s)
                                                            : config.coarsen_hold_s,
                    config.coarsen_hold_s + config.max_deferral_s, !config.prefer_suppression || suppressed};
}

// "<function>: <name> has <got> entries, expected <want>".
[[nodiscard]] inline std::string switch_length_error(const char* function, const char* name, std::size_t got,
                                                     std::size_t want) {
  return std::string(function) + ": " + name + " has " + std::to_string(got) + " entries, expected " +
         std::to_string(want);
}

}  // namespace gazelod::lod
