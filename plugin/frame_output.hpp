// SPDX-License-Identifier: Apache-2.0
// What the plugin returns each frame: the levels to draw (FrameDecisions) and, for reports
// and debugging, how it got there (FrameDiagnostics). Spans are indexed by object id and stay
// valid until the next begin_frame or registration (add_object, add_cluster_mesh: the arrays
// behind them grow).
#pragma once

#include "gaze/gaze_conditioner.hpp"
#include "lod/cone.hpp"
#include "lod/criterion.hpp"
#include "lod/select.hpp"
#include "lod/switch_policy.hpp"
#include "plugin/gaze_source_kind.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>

namespace gazelod {

struct FrameDecisions {
  // The level to draw (0 = full detail), after the frame budget if one is set.
  std::span<const std::uint8_t> lod;
  // Why the perceptual level is what it is: a lod::Criterion value (lod/criterion.hpp):
  //   0 none          level 0, no criterion allows a coarser one
  //   1 size          the object's angular size alone allows the level
  //   2 eccentricity  eccentricity (with size) allows it
  //   3 velocity      retinal velocity (with size) allows it
  //   4 combined      only velocity and eccentricity together allow it
  //   5 invalid_input the object's data were not finite: level 0 kept
  // A frame budget may draw coarser than this level (FrameDiagnostics::lod_perceptual).
  std::span<const std::uint8_t> limited_by;
  // Why a finer level than the perceptual one is still drawn: a lod::HoldReason value
  // (lod/switch_policy.hpp): 0 none, 1 hold_time (the coarser level is not yet allowed
  // for the hold time), 2 awaiting_suppression (waiting for a saccade or blink, at most the
  // maximum deferral), 3 no_time (the frame's time was not usable). Empty without the policy.
  std::span<const std::uint8_t> held;
  // Cluster meshes (LodPlugin::add_cluster_mesh), their clusters back to back in registration
  // order: mesh m's cluster c is entry cluster_first[m] + c. cluster_drawn is 1 for the
  // clusters of this frame's cut (after the switch policy), which covers every mesh exactly
  // once, without cracks; cluster_limited_by the criterion that let the cluster's own error go
  // (values as limited_by); cluster_held why a coarser cut waits (values as held; empty
  // without the policy). With a frame budget, cluster_drawn is the budgeted cut (below).
  std::span<const std::uint8_t> cluster_drawn;
  std::span<const std::uint8_t> cluster_limited_by;
  std::span<const std::uint8_t> cluster_held;
  std::span<const std::uint32_t> cluster_first;
  // With a frame budget (PluginConfig::budget_ms > 0; empty without), per cluster mesh in
  // registration order: the coarsening step the budget chose (0 = the cut above as the
  // perceptual rule and the switch policy give it; k > 0: the perceptual rule with every error
  // of the mesh divided by cluster_detail_scale = 2^(k/2), budget/cluster_cut_cost.hpp) and
  // that scale. cluster_drawn already is that cut. A renderer that selects the cut itself (on
  // the GPU) applies it by dividing the mesh's error factor by the scale (lod::detail::
  // make_cluster_mesh_frame's detail_scale: ClusterMeshFrame::error_factor); docs/cluster-budget.md.
  std::span<const std::uint8_t> cluster_budget_step;
  std::span<const float> cluster_detail_scale;
  GazeSourceKind gaze_source = GazeSourceKind::head_fixed;
  bool gaze_valid = false;  // false: head-fixed gaze with the widened cone
};

struct FrameDiagnostics {
  std::span<const std::uint8_t>
      lod_perceptual;  // this frame's perceptual choice (before the switch policy and the budget)
  std::span<const std::uint8_t> cluster_drawn_perceptual;  // the same for clusters: this frame's cut before the policy
  std::span<const std::uint8_t> lod_size_only;             // what each criterion (with size) allows
  std::span<const std::uint8_t> lod_eccentricity_only;
  std::span<const std::uint8_t> lod_velocity_only;
  std::span<const std::uint8_t> lod_size_eccentricity;  // empty unless compute_breakdown
  std::span<const std::uint8_t> lod_size_velocity;      // empty unless compute_breakdown
  glm::dvec3 gaze_direction_world{0.0, 0.0, -1.0};
  glm::dvec3 gaze_direction_head{0.0, 0.0, -1.0};  // as the source gave it (head space)
  glm::dvec3 eye_position_world{0.0};
  glm::dvec3 head_angular_velocity_rad_s{0.0};          // base space
  glm::dvec3 head_linear_velocity_m_s{0.0};             // base space
  glm::dvec3 gaze_angular_velocity_in_head_rad_s{0.0};  // the eye's rotation in the head (base axes)
  bool head_valid = false;
  // The conditioned gaze: how the eye moves (loss without a usable source) and whether vision
  // is suppressed now (saccade, blink, shortly after a saccade), which releases coarsening.
  gaze::EyeMotion eye_motion = gaze::EyeMotion::loss;
  bool gaze_suppressed = false;
  bool gaze_carried = false;  // a fixation carried by the moving head (ConditionedGaze::carried)
  // Samples the conditioning refused so far (NaN, zero length, backwards in time), all sources.
  std::int64_t gaze_bad_samples = 0;
  // The gaze's angular uncertainty (deg: the source's accuracy, grown with the sample's age
  // and the eye's speed) and the foveal cone it widens (Reddy 1995): apex at the eye, along
  // the gaze, half-angle the foveal eccentricity plus the uncertainty.
  double gaze_error_deg = 0.0;
  lod::Cone foveal_cone;
  double xi_cpd = 0.0;  // the display limit used this frame (lod/display.hpp)
  // The viewer this frame's selection used (objects and clusters alike): what a GPU-driven
  // cluster selection (render/cluster_select_frame.hpp) needs to choose the same cut.
  lod::Viewer viewer;
  // With a frame budget: the frame time the cost model predicts for FrameDecisions::lod, and
  // whether even the coarsest levels were predicted over the budget.
  double predicted_ms = 0.0;
  bool budget_infeasible = false;
  // With a frame budget, per cluster mesh: the triangles the budget predicted for its chosen
  // step and those its drawn cut has (the prediction's error, docs/cluster-budget.md).
  std::span<const double> cluster_triangles_predicted;
  std::span<const double> cluster_triangles_drawn;
};

}  // namespace gazelod
