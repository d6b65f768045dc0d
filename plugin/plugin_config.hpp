// SPDX-License-Identifier: Apache-2.0
// What an application configures when it creates the plugin (gazelod.hpp). Plain data.
#pragma once

#include "budget/frame_budget_options.hpp"
#include "gaze/gaze_conditioner.hpp"
#include "gaze/gaze_source.hpp"
#include "lod/switch_policy.hpp"

#include <memory>
#include <string>

namespace gazelod {

// Which of Reddy's (1998) criteria may coarsen a level; all three by default.
struct EnabledCriteria {
  bool size = true;
  bool eccentricity = true;
  bool velocity = true;
};

struct PluginConfig {
  // Try the runtime's XR_EXT_eye_gaze_interaction first (the instance must have enabled it).
  bool use_openxr_eye_gaze = true;
  // Set when the application attaches action sets of its own: it must then include
  // action_set() in its xrAttachSessionActionSets and xrSyncActions calls and call
  // action_sets_attached(). Otherwise the plugin attaches and syncs its own set.
  bool application_attaches_action_sets = false;
  // A further source tried when the runtime gives no gaze (a HID tracker, a trace replay).
  std::shared_ptr<gaze::GazeSource> external_source;
  // Display preset name overriding what the runtime reports ("" = from xrLocateViews and
  // the swapchain size).
  std::string hmd_override;
  EnabledCriteria criteria;
  // A runtime that advertises eye gaze but has delivered nothing this long after the
  // session became focused is not trusted any more (seconds).
  double gaze_silence_timeout_s = 1.0;
  // Samples the application pushes (data mode, OpenXrGazeInput::pushed): a frame uses the
  // newest one at most this old (seconds); older means the application's tracker is silent.
  double max_pushed_sample_age_s = 0.1;
  // Angular error (accuracy) assumed for each source (degrees): the floor of the gaze's
  // uncertainty, which widens the foveal cone (ConditionerConfig::accuracy_deg per source).
  double openxr_gaze_error_deg = 1.5;
  double external_gaze_error_deg = 2.0;
  // How each source's samples are classified, smoothed, predicted to the display time and
  // given an uncertainty (gaze/gaze_conditioner.hpp has the defaults and their sources);
  // accuracy_deg is replaced by the source's error above.
  gaze::ConditionerConfig conditioning;
  // Without eye tracking gaze is head-fixed (straight ahead) and the cone is widened to
  // cover where the eyes usually are relative to the head (degrees).
  double head_fixed_cone_deg = 20.0;
  // Also select with the criteria sets size+eccentricity and size+velocity each frame, so a
  // report can split the reduction between the criteria (two more selections per frame;
  // FrameDiagnostics::lod_size_eccentricity and lod_size_velocity).
  bool compute_breakdown = false;
  // Between the perceptual choice and what is drawn: refinement at once, coarsening only
  // after the coarser level has been allowed for a hold time, preferably inside a saccade or
  // blink (lod/switch_policy.hpp has the defaults and their sources). Off: draw each frame's
  // perceptual choice (levels then flip with the tracker's noise).
  bool switch_policy = true;
  lod::SwitchPolicyConfig switching;
  // Off: cluster meshes draw each frame's perceptual cut without the switch policy (objects keep
  // it). For a renderer that selects the cut itself on the GPU (shaders/cluster_select.comp,
  // docs/gpu-selection.md): the shader keeps no history, so the CPU's decisions match what it
  // draws only without the hold.
  bool cluster_switch_policy = true;
  // Frame budget (ms, 0 = none): after the perceptual selection, Mason's (1999) incremental
  // solver coarsens levels so the predicted frame time (a cost model fit online from
  // end_frame's measured times) stays under the budget. Never finer than the perceptual choice.
  double budget_ms = 0.0;
  budget::FrameBudgetOptions budget;
};

// "" when every setting is usable, else the first bad one by name with its value
// ("conditioning.pursuit_exit_fraction must be in [0, 1], got 2"); nothing is replaced by a
// default. LodCore's constructor (so every plugin create) refuses what this refuses.
[[nodiscard]] std::string validate_plugin_config(const PluginConfig& config);

}  // namespace gazelod
