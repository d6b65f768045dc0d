// SPDX-License-Identifier: Apache-2.0
// The switch policy between the perceptual choice and what is drawn. select_lods (lod/select.hpp)
// picks each frame the coarsest level whose removed detail is invisible; drawing that level
// directly makes a noisy gaze flip an object between two levels every frame. The policy, per
// object:
//   - refines (a finer level, smaller number) at once: detail the viewer could see is never
//     withheld;
//   - coarsens only after a coarser level has been allowed continuously for coarsen_hold_s
//     (the "window": it opens at the first frame a coarser level than the drawn one is
//     allowed, and closes at any frame that allows none). It then goes to the finest level
//     allowed throughout the window, never coarser than anything allowed during it;
//   - with prefer_suppression, once the hold has passed, waits for a frame in which vision is
//     suppressed (the caller's flag: a saccade, up to ~60 ms after it, or a blink) and
//     coarsens then, or anyway once max_deferral_s more has passed, or (release_regret_s)
//     once waiting has kept as many triangles as a switch is worth.
// So the drawn level is never coarser than this frame's perceptual level, coarsenings of one
// object (without release_by_motion) are at least coarsen_hold_s apart on a monotonic clock
// (at most 1 / coarsen_hold_s per object-second; refinements are not limited), and a
// coarsening comes at most hold + deferral after the window opened. docs/perceptual-model.md
// ("Switch policy") has the defaults' sources.
//
// API (plain data in, caller-owned arrays, no allocation, no hidden state, linear time):
//   std::vector<std::uint8_t> drawn(n), finest(n), held(n);  std::vector<double> start(n);
//   SwitchState state{drawn, finest, start};
//   reset_switch_state(state);                                  // at registration: level 0
//   each frame: select_lods(...) -> lod;
//     std::string err = apply_switch_policy(config, t_s, suppressed, lod, state, held);
//     draw drawn[i]; held[i] says why it differs from lod[i] (HoldReason).
//   with release_by_motion: apply_switch_policy(config, t_s, suppressed, lod, motion_level, state,
//     held), motion_level from lod/motion_bound.hpp; with release_regret_s, the overload with
//     SwitchCosts (the levels' triangles).
// One new object: reset_switch_state on a SwitchState of one-entry subspans.
// Validation: apply_switch_policy and reset_switch_state refuse an invalid config or spans of
// different lengths with a message and write nothing; with release_regret_s > 0 so are costs
// that do not cover the levels in use. A non-finite t_s is a frame in which no
// time passes (see apply_switch_policy); no NaN reaches a decision.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <string>

namespace gazelod::lod {

// Why the drawn level differs from this frame's perceptual level (one byte per object).
enum class HoldReason : std::uint8_t {
  none = 0,                  // drawn == perceptual: nothing held (refined, coarsened or steady)
  hold_time = 1,             // a coarser level is allowed, but not yet for coarsen_hold_s
                             // without a break: drawn stays finer
  awaiting_suppression = 2,  // the hold has passed; prefer_suppression waits for a suppressed
                             // frame (saccade or blink), at most max_deferral_s, or with
                             // release_regret_s until waiting has cost what a switch is worth
  no_time = 3,               // a coarser level is allowed, but this frame's t_s is not finite:
                             // nothing coarsens and no window opens in it
};
const char* to_string(HoldReason r);

struct SwitchPolicyConfig {
  // How long a coarser level must be allowed without a break before it is drawn. 200 ms: well
  // above the frame-to-frame flips of tracker noise (one to a few frames, tens of ms), below
  // the ~330 ms mean fixation in scene viewing (Rayner 1998), so a level allowed through most
  // of a fixation is reached in it; caps coarsening at 5 per object-second. 0 turns the policy
  // into "draw the perceptual level" (coarsening at once).
  double coarsen_hold_s = 0.2;
  // After the hold, how much longer a coarsening may wait for a suppressed frame. With ~3
  // saccades a second in free viewing (Rayner 1998) the next one usually comes within a few
  // hundred ms; 0.6 s is past most fixations, so it runs out in long fixations, smooth pursuit
  // or without saccade labels. Waiting keeps detail (costs triangles, not quality). Chosen with
  // scripts/tune_family.py on the scenario family's tuning seeds (docs/evaluation.md,
  // "Scenario family"): 0.3 s let the worst seed's degradations pass 0.5 %, 1 s kept more
  // triangles under long pursuits; the optimum is flat (median triangles / oracle within 1 %).
  double max_deferral_s = 0.6;
  // Coarsen inside saccadic suppression or a blink where one comes in time: changes up to
  // ~60 ms after a saccade go unnoticed (Loschky & Wolverton 2007), vision is suppressed in
  // blinks (Volkmann, Riggs & Moore 1980).
  bool prefer_suppression = true;
  // The hold in a suppressed frame (the shorter of this and coarsen_hold_s; with
  // prefer_suppression only). 0: a change made
  // while vision is suppressed goes unseen, so it need not wait out the noise, and the level a
  // saccade's landing allows is drawn in the same suppression window. (Measured with the
  // audit of `gazelod run`: a 30 ms hold here keeps ~25 % more triangles than the eye needs,
  // because the window has often closed before the hold is over.)
  double suppressed_hold_s = 0.0;
  // Draw at once a coarsening that motion alone justifies (the overload of apply_switch_policy
  // with motion_level): up to the level the object's size and retinal speed allow with the
  // eccentricity criterion off, which no gaze direction can make finer. The hold and the
  // deferral are there for the gaze estimate's noise; this level does not depend on the gaze
  // direction, and while the head sweeps the field is blurred, so a pop is masked. What it
  // still depends on is the eye's estimated rotation (lod/motion_bound.hpp). Such a coarsening
  // is not bound by the hold's rate limit. Off by default: on the scenario family it saved
  // almost nothing, and where it trusted the eye's estimated motion it broke the degradation
  // target (docs/evaluation.md, "Scenario family").
  bool release_by_motion = false;
  // With release_by_motion: take the motion level at the conditioner's estimate of the eye's
  // rotation only (true), or the finer of that and an eye at rest in the head (false), so that a
  // late or wrong eye-velocity estimate (a pursuit's end, a saccade read as motion) releases
  // nothing the head's own motion does not also blur (lod/motion_bound.hpp).
  bool motion_trusts_eye_velocity = false;
  // Without motion_trusts_eye_velocity: also the level with the eye at rest in the world (a
  // vestibulo-ocular reflex holding the world still while the head turns, which the tracker
  // reports a latency late), so that only motion blurring every eye motion is released.
  bool motion_eye_may_hold_world = true;
  // After the hold, release a coarsening outside suppression too once waiting has cost what a
  // switch is worth: once the triangles it saves (drawn level minus the level it would go to)
  // times the time the window has been open reach release_regret_s times
  // SwitchCosts::unit_triangles (the plugin: the mean full-detail triangles per object, so the
  // rule does not depend on the scene's scale). The ski-rental rule (Karlin, Manasse, Rudolph &
  // Sleator 1988): an object whose coarsening saves much goes soon after the hold, one that
  // saves little waits for suppression as before. The product never exceeds the triangles the
  // window actually kept (its level to release only gets finer). Needs the levels' triangle
  // counts (the overload with SwitchCosts); 0, or without them: off. 0.15 s chosen on the
  // scenario family's tuning seeds (docs/evaluation.md, "Scenario family", item 12): 0.1 and
  // 0.12 let a seed's degradations pass 0.5 %, 0.2 saved less. Not for cluster cuts: their
  // nesting (lod/cluster/cluster_switch_policy.hpp) needs a release that depends on time and
  // suppression alone.
  double release_regret_s = 0.15;
};

// What each object's levels cost, for release_regret_s (plain data, caller-owned): the
// triangles of object i's level l are level_triangles[level_first[i] + l]; a switch is worth
// release_regret_s * unit_triangles triangle-seconds (0: no release by regret). The policy
// checks that every level in use has an entry, not where one object's chain ends: the levels
// passed must lie within each object's chain, and the counts must not increase along it (as
// lod::validate_chain requires), else the regret can exceed what the window kept.
struct SwitchCosts {
  std::span<const std::uint32_t> level_triangles;
  std::span<const std::uint32_t> level_first;  // one entry per object, or empty: no costs
  double unit_triangles = 0.0;                 // finite, >= 0
};

// "" when valid (every time and release_regret_s finite and >= 0), else which field and why.
[[nodiscard]] std::string validate_switch_config(const SwitchPolicyConfig& config);

// No window open (window_start_s); any non-finite value reads the same.
inline constexpr double kNoSwitchWindow = std::numeric_limits<double>::quiet_NaN();

// Caller-owned, one entry per object in each span (resize at registration, reset_switch_state).
struct SwitchState {
  std::span<std::uint8_t> drawn;           // the level drawn (the output)
  std::span<std::uint8_t> finest_allowed;  // finest level allowed since the window opened
  std::span<double> window_start_s;        // when the window opened; non-finite: none open
};

// One frame. t_s: monotonic seconds; suppressed: vision is suppressed in this frame (a saccade
// or up to ~60 ms after one, or a blink). perceptual[i]: this frame's perceptual level. Updates
// state (drawn[i] is what to draw) and writes held[i] (a HoldReason; held may be empty to skip).
// Returns "" or, for an invalid config or a span whose length differs from perceptual's, a
// message, writing nothing. A non-finite t_s: refinement still happens and an open window
// still takes this frame's level into its finest, but no window opens and nothing coarsens.
// t_s before an open window's start (the clock went back) restarts that window at t_s.
[[nodiscard]] std::string apply_switch_policy(const SwitchPolicyConfig& config, double t_s, bool suppressed,
                                              std::span<const std::uint8_t> perceptual, const SwitchState& state,
                                              std::span<std::uint8_t> held);

// The same, with motion_level[i] (empty: none) the level that size and motion alone allow object
// i this frame, independent of the gaze direction (lod/motion_bound.hpp). With
// config.release_by_motion, a coarser perceptual level is drawn at once up to min(perceptual[i],
// motion_level[i]) in any timed frame; what lies beyond keeps the hold and the deferral (its
// window, if one is open, goes on). Refused, writing nothing, where motion_level is neither empty
// nor perceptual's length.
[[nodiscard]] std::string apply_switch_policy(const SwitchPolicyConfig& config, double t_s, bool suppressed,
                                              std::span<const std::uint8_t> perceptual,
                                              std::span<const std::uint8_t> motion_level, const SwitchState& state,
                                              std::span<std::uint8_t> held);

// The same, with what each level costs (release_regret_s). With release_regret_s > 0, refused,
// writing nothing, where costs.level_first is neither empty nor perceptual's length,
// costs.unit_triangles is negative or not finite, or an object's drawn or perceptual level lies
// past level_triangles; at 0 the costs are not read.
[[nodiscard]] std::string apply_switch_policy(const SwitchPolicyConfig& config, double t_s, bool suppressed,
                                              std::span<const std::uint8_t> perceptual,
                                              std::span<const std::uint8_t> motion_level, const SwitchCosts& costs,
                                              const SwitchState& state, std::span<std::uint8_t> held);

// Every object: draw `level`, no window open (registration, reset). Returns "" or, for spans
// of different lengths, a message, writing nothing.
[[nodiscard]] std::string reset_switch_state(const SwitchState& state, std::uint8_t level = 0);

}  // namespace gazelod::lod
