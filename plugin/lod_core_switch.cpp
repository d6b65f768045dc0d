// SPDX-License-Identifier: Apache-2.0
// LodCore's switch policy step (plugin/lod_core.hpp): between the perceptual choice and what is
// drawn (lod/switch_policy.hpp), with the motion bound and the levels' costs it may use.
#include "plugin/lod_core.hpp"

#include <algorithm>

namespace gazelod::plugin {

// Refinement at once, coarsening after the hold and preferably while vision is suppressed.
void LodCore::apply_switch_policy(const lod::Viewer& v, std::int64_t t_ns, bool suppressed) {
  if (!config_.switch_policy) return;
  const double t_s = frame_seconds(t_ns);
  // An object's first frame draws its perceptual level: nothing was drawn before, so there is
  // no switch to hide.
  if (switch_unstarted_) {  // objects registered since the last frame
    for (std::size_t i = 0; i < lod_.size(); ++i)
      if (!switch_started_[i]) {
        switch_drawn_[i] = lod_[i];
        switch_started_[i] = 1;
      }
    switch_unstarted_ = false;
  }
  const lod::SwitchState state{switch_drawn_, switch_finest_, switch_window_s_};
  // What size and motion alone allow the objects about to be held (lod/motion_bound.hpp). A
  // refusal (only for a viewer select_lods refused too, when lod_ is all 0) releases nothing.
  std::span<const std::uint8_t> motion_level;
  if (config_.switching.release_by_motion) {
    motion_level_.resize(lod_.size());
    const bool any_eye = !config_.switching.motion_trusts_eye_velocity;
    const lod::EyeHypotheses also{any_eye, any_eye && config_.switching.motion_eye_may_hold_world};
    if (lod::motion_bound_levels(v, store_.view(), lod_, switch_drawn_, motion_scratch_, motion_level_, also).empty())
      motion_level = motion_level_;
  }
  const lod::SwitchCosts costs =
      config_.switching.release_regret_s > 0.0 ? switch_costs_.costs(chains_) : lod::SwitchCosts{};
  if (!lod::apply_switch_policy(config_.switching, t_s, suppressed, lod_, motion_level, costs, state, held_).empty()) {
    // Cannot happen (the constructor checked the configuration, resize_outputs keeps the sizes
    // equal, the costs come from the registered chains, whose levels the selection and the
    // policy never pass); were it refused, draw the perceptual choice.
    std::copy(lod_.begin(), lod_.end(), switch_drawn_.begin());
    std::fill(held_.begin(), held_.end(), 0);
  }
}

// The levels the policy passes on (the perceptual ones without it).
std::span<const std::uint8_t> LodCore::policy_lod() const {
  return config_.switch_policy ? std::span<const std::uint8_t>(switch_drawn_) : std::span<const std::uint8_t>(lod_);
}

}  // namespace gazelod::plugin
