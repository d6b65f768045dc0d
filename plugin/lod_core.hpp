// SPDX-License-Identifier: Apache-2.0
// The plugin's engine without OpenXR: given a frame's head motion, views and gaze input, it
// conditions the gaze, builds the foveal cone and picks every object's (and cluster's) level.
// Both fronts feed it: the OpenXR front (plugin/lod_plugin.cpp) reads these inputs from the
// runtime; data mode (plugin/data_front.hpp) takes them from the application. The same inputs
// give the same decisions either way.
#pragma once

#include "budget/frame_budget.hpp"
#include "gaze/gaze_conditioner.hpp"
#include "gaze/gaze_source.hpp"
#include "lod/display.hpp"
#include "lod/motion_bound.hpp"
#include "lod/object_set.hpp"
#include "lod/select.hpp"
#include "plugin/cluster_meshes.hpp"
#include "plugin/gaze_arbiter.hpp"
#include "plugin/frame_output.hpp"
#include "plugin/object_desc.hpp"
#include "plugin/head_motion.hpp"
#include "plugin/plugin_config.hpp"
#include "plugin/switch_costs.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gazelod::plugin {

inline constexpr std::size_t kMaxViews = 4;  // XR_VARJO_quad_views: primary pair + inset pair

// One rendered view, in the head (VIEW space): its field of view, its pose and the resolution
// actually rendered.
struct ViewInput {
  lod::FovRad fov;
  glm::dquat orientation_in_head{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 position_in_head_m{0.0};
  int width_px = 0, height_px = 0;
};

struct FrameInput {
  std::int64_t t_ns = 0;         // display time
  HeadMotion head;               // the head in the base space
  std::uint32_t view_count = 0;  // 0: the previous frame's views
  std::array<ViewInput, kMaxViews> views{};
};

// What the frame read from its primary gaze input, in data mode's terms (gzl_frame_record).
struct GazeRead {
  bool present = false;
  gaze::GazeSample sample;                          // head space
  glm::dquat head_orientation{1.0, 0.0, 0.0, 0.0};  // the head at the sample's time
};

class LodCore {
 public:
  using SourceChanged = std::function<void(GazeSourceKind now, const std::string& why)>;
  using OrientationAt = std::function<std::optional<glm::dquat>(std::int64_t t_ns)>;

  // Throws std::invalid_argument for a configuration validate_plugin_config refuses (its reason)
  // or an unknown hmd_override preset. decide() then never throws for configuration.
  explicit LodCore(PluginConfig config);
  ~LodCore();
  LodCore(const LodCore&) = delete;
  LodCore& operator=(const LodCore&) = delete;

  // The primary gaze input (not owned; OpenXR's eye gaze or the application's pushed samples)
  // and, when there is none, why ("" = none was asked for). Call before the first frame.
  void set_primary(gaze::GazeSource* primary, GazeSourceKind kind, std::string why_none);
  // The primary input was given anew (its space): trust it afresh.
  void restart_primary() { arbiter_->restart_primary(); }
  // The head's orientation at a gaze sample's time (nullopt: the frame's own is used).
  void set_orientation_at(OrientationAt f) { orientation_at_ = std::move(f); }

  // Objects are dense: ids 0..n-1; remove_object moves the last object into the freed id
  // and returns the id it had (== id when it was the last).
  std::uint32_t add_object(const ObjectDesc& desc);  // throws std::invalid_argument
  std::uint32_t remove_object(std::uint32_t id);
  void set_object_enabled(std::uint32_t id, bool enabled);
  void set_object_motion(std::uint32_t id, const glm::dvec3& center_m, const glm::dvec3& velocity_m_s);
  std::size_t object_count() const;
  const std::vector<lod::LodLevel>& object_levels(std::uint32_t id) const { return chains_[id]; }
  bool object_enabled(std::uint32_t id) const { return enabled_[id] != 0; }

  std::uint32_t add_cluster_mesh(const ClusterMeshDesc& desc);
  void set_cluster_mesh_motion(std::uint32_t id, const lod::InstanceTransform& pose, const glm::dvec3& velocity_m_s);
  std::size_t cluster_mesh_count() const;

  void session_state(bool focused, std::int64_t t_ns);
  const FrameDecisions& decide(const FrameInput& in);
  const FrameDiagnostics& diagnostics() const { return diag_; }
  void end_frame(double measured_frame_ms);

  GazeSourceKind active_source() const { return active_; }
  void on_source_changed(SourceChanged cb) { changed_ = std::move(cb); }

  // The views of the last frame (count and geometry) and what it read from the gaze input.
  std::uint32_t view_count() const { return view_count_; }
  const std::array<ViewInput, kMaxViews>& views() const { return views_; }
  const GazeRead& gaze_read() const { return gaze_read_; }
  const HeadMotion& head() const { return head_; }  // the last frame's head input
  // The largest vertical resolution among the views (engine-style level conversions).
  int max_view_height_px() const;
  double xi_cpd() const { return xi_cpd_; }

 private:
  double frame_seconds(std::int64_t t_ns);
  void condition_gaze(const HeadMotion& head, std::int64_t t_ns, lod::Viewer& v);
  void publish_clusters();
  void apply_switch_policy(const lod::Viewer& v, std::int64_t t_ns, bool suppressed);
  std::span<const std::uint8_t> policy_lod() const;
  void apply_budget(const lod::Viewer& v);
  void update_display(const FrameInput& in);
  void resize_outputs();

  PluginConfig config_;
  OrientationAt orientation_at_;
  SourceChanged changed_;
  GazeSourceKind active_ = GazeSourceKind::head_fixed;
  gaze::GazeSource* primary_ = nullptr;
  GazeSourceKind primary_kind_ = GazeSourceKind::openxr;
  std::unique_ptr<GazeArbiter> arbiter_;
  FrameDecisions frame_;
  FrameDiagnostics diag_;
  GazeRead gaze_read_;
  HeadMotion head_;
  std::array<ViewInput, kMaxViews> views_{};
  std::uint32_t view_count_ = 0;
  double xi_cpd_ = 30.0;
  bool xi_fixed_ = false;

  lod::ObjectStore store_;
  ClusterMeshes clusters_;
  std::vector<std::vector<lod::LodLevel>> chains_;
  std::vector<double> importance_;
  std::vector<std::uint8_t> enabled_;
  std::vector<std::uint8_t> lod_, limited_, size_only_, ecc_only_, vel_only_, se_, sv_;
  std::vector<std::uint8_t> scratch_a_, scratch_b_, scratch_c_, scratch_d_;
  lod::Decisions decisions_out_, breakdown_se_out_, breakdown_sv_out_;
  std::vector<float> angular_radius_deg_;
  std::vector<std::uint8_t> switch_drawn_, switch_finest_, held_, switch_started_;
  bool switch_unstarted_ = false;  // some switch_started_ entry is 0 (an object added since)
  std::vector<double> switch_window_s_;
  // release_by_motion: each frame's size-and-motion level of the policy's candidates.
  std::vector<std::uint8_t> motion_level_;
  lod::MotionBoundScratch motion_scratch_;
  SwitchCostTable switch_costs_;  // release_regret_s: the levels' triangles
  bool have_t0_ = false;
  std::int64_t t0_ns_ = 0;
  std::vector<std::uint8_t> budget_lod_;
  std::vector<budget::BudgetObjectView> budget_view_;
  std::unique_ptr<budget::FrameBudget> budget_;
  // Cluster meshes in the budget: per mesh its item, the chosen step, the predicted triangles.
  std::vector<budget::BudgetClusterView> cluster_view_;
  std::vector<std::uint8_t> cluster_step_;
  std::vector<double> cluster_predicted_tris_;

  glm::dquat last_head_orientation_{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 last_head_position_{0.0};
  gaze::GazeConditioner primary_conditioner_, external_conditioner_;
  GazeSourceKind conditioned_source_ = GazeSourceKind::head_fixed;
};

}  // namespace gazelod::plugin
