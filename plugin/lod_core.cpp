// SPDX-License-Identifier: Apache-2.0
// The plugin's engine without OpenXR (plugin/lod_core.hpp): gaze conditioning, the viewer, the
// selection, the switch policy, the budget and the cluster cut, from one frame's inputs.
#include "plugin/lod_core.hpp"

#include "auxiliary/time.hpp"
#include "lod/acuity.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gazelod::plugin {

namespace {

// Configuration is refused here, once, with the reason (docs/error-policy.md): what passes
// cannot make a frame fail (the switch policy's config, the budget's options and budget_ms).
PluginConfig checked(PluginConfig config) {
  if (std::string e = validate_plugin_config(config); !e.empty()) throw std::invalid_argument("gazelod: config: " + e);
  return config;
}

}  // namespace

LodCore::LodCore(PluginConfig config) : config_(checked(std::move(config))) {
  gaze::ConditionerConfig cc = config_.conditioning;
  cc.accuracy_deg = config_.openxr_gaze_error_deg;
  primary_conditioner_ = gaze::GazeConditioner(cc);
  cc.accuracy_deg = config_.external_gaze_error_deg;
  external_conditioner_ = gaze::GazeConditioner(cc);
  if (!config_.hmd_override.empty()) {
    const lod::DisplaySpec* preset = lod::find_display_preset(config_.hmd_override);
    if (!preset)
      throw std::invalid_argument("gazelod: unknown HMD preset '" + config_.hmd_override +
                                  "'; `gazelod hmds` lists the presets");
    xi_cpd_ = lod::xi_cpd(*preset);
    xi_fixed_ = true;
  }
  set_primary(nullptr, GazeSourceKind::openxr, "");
  resize_outputs();
}

LodCore::~LodCore() = default;

void LodCore::set_primary(gaze::GazeSource* primary, GazeSourceKind kind, std::string why_none) {
  primary_ = primary;
  primary_kind_ = kind;
  ArbiterConfig ac;
  ac.silence_timeout_ns = aux::ns_from_seconds(config_.gaze_silence_timeout_s);
  ac.blink_bridge_ns = config_.conditioning.loss_hold_max_ns;
  ac.primary_kind = kind;
  ac.why_no_primary = std::move(why_none);
  arbiter_ = std::make_unique<GazeArbiter>(primary, config_.external_source.get(), ac);
  arbiter_->on_change([this](GazeSourceKind s, const std::string& why) {
    active_ = s;
    if (changed_) changed_(active_, why);
  });
}

std::uint32_t LodCore::add_object(const ObjectDesc& d) {
  const std::uint32_t id = store_.add(d.center_m, d.radius_m, d.velocity_m_s, d.lods);
  try {
    chains_.push_back(d.lods);
    importance_.push_back(d.importance);
    resize_outputs();
  } catch (...) {
    // Out of memory part-way: undone, so that the store and every per-object array keep one
    // length (the C ABI's handle tables are sized by it). Shrinking allocates nothing.
    chains_.resize(id);
    importance_.resize(id);
    store_.remove(id);
    resize_outputs();
    throw;
  }
  budget_.reset();  // rebuilt with the new object at the next frame
  switch_costs_.mark_stale();
  switch_unstarted_ = true;
  return id;
}

std::uint32_t LodCore::remove_object(std::uint32_t id) {
  if (id >= store_.size()) throw std::out_of_range("object id out of range");
  const std::uint32_t last = static_cast<std::uint32_t>(store_.size() - 1);
  store_.remove(id);  // moves `last` into `id`
  // Every per-object array follows the store's move, so the moved object keeps its state
  // (drawn level, hold windows, first-frame flag).
  auto move_last = [&](auto& v) {
    v[id] = std::move(v[last]);
    v.pop_back();
  };
  move_last(chains_), move_last(importance_), move_last(enabled_);
  move_last(switch_drawn_), move_last(switch_finest_), move_last(switch_window_s_);
  move_last(held_), move_last(switch_started_);
  budget_.reset();
  switch_costs_.mark_stale();
  resize_outputs();
  return last;
}

void LodCore::set_object_enabled(std::uint32_t id, bool enabled) {
  if (id >= store_.size()) throw std::out_of_range("object id out of range");
  enabled_[id] = enabled ? 1 : 0;
}

void LodCore::set_object_motion(std::uint32_t id, const glm::dvec3& c, const glm::dvec3& v) {
  store_.set_motion(id, c, v);
}
std::size_t LodCore::object_count() const {
  return store_.size();
}

std::uint32_t LodCore::add_cluster_mesh(const ClusterMeshDesc& d) {
  const std::uint32_t id = clusters_.add(d);
  publish_clusters();
  return id;
}
void LodCore::set_cluster_mesh_motion(std::uint32_t id, const lod::InstanceTransform& pose, const glm::dvec3& v) {
  clusters_.set_motion(id, pose, v);
}
std::size_t LodCore::cluster_mesh_count() const {
  return clusters_.mesh_count();
}

void LodCore::session_state(bool focused, std::int64_t t_ns) {
  arbiter_->session_state(focused, t_ns);
}

void LodCore::end_frame(double measured_frame_ms) {
  // A time that is no time (non-finite, negative) is left out of the cost fit: the fit keeps
  // its coefficients, which is all a refused measurement can mean here.
  if (budget_) (void)budget_->observe(measured_frame_ms);
}

int LodCore::max_view_height_px() const {
  int h = 0;
  for (std::uint32_t i = 0; i < view_count_; ++i) h = std::max(h, views_[i].height_px);
  return h;
}

// The gaze at the display time, conditioned per source (gaze/gaze_conditioner.hpp):
// classified in the world, smoothed in fixations, predicted to t; its uncertainty widens the
// foveal cone, and only a classified pursuit moves the gaze in the world.
void LodCore::condition_gaze(const HeadMotion& head, std::int64_t t_ns, lod::Viewer& v) {
  const ArbiterResult gaze = arbiter_->update(t_ns);
  const glm::dquat q = last_head_orientation_;
  glm::dvec3 gaze_head(0.0, 0.0, -1.0);
  glm::dvec3 gaze_world = q * gaze_head;
  glm::dvec3 gaze_omega_world(0.0);
  double error_deg = config_.head_fixed_cone_deg;
  bool suppressed = false;
  bool carried = false;
  diag_.eye_motion = gaze::EyeMotion::loss;
  GazeSourceKind used = GazeSourceKind::head_fixed;
  gaze_read_.present = false;
  if (gaze.source != GazeSourceKind::head_fixed) {
    gaze::GazeConditioner& c = gaze.source == GazeSourceKind::external ? external_conditioner_ : primary_conditioner_;
    if (gaze.source != conditioned_source_) c.reset();  // a new source: no history across it
    conditioned_source_ = gaze.source;
    std::optional<glm::dquat> at_sample = orientation_at_ ? orientation_at_(gaze.sample.t_ns) : std::nullopt;
    const glm::dquat q_sample = at_sample.value_or(q);
    if (gaze.source == primary_kind_) {
      gaze_read_.present = true;
      gaze_read_.sample = gaze.sample;
      gaze_read_.head_orientation = q_sample;
    }
    c.push(gaze.sample, q_sample);
    const gaze::ConditionedGaze cg = c.at(t_ns, q);
    if (cg.valid) {
      used = gaze.source;
      gaze_head = cg.direction_head;
      gaze_world = cg.direction_world;
      gaze_omega_world = cg.angular_velocity_world_rad_s;
      error_deg = cg.uncertainty_deg;
      suppressed = cg.suppressed;
      carried = cg.carried;
      diag_.eye_motion = cg.motion;
    }
  } else {
    conditioned_source_ = GazeSourceKind::head_fixed;
  }
  // The selection takes the eye-in-head rotation: the eye's rotation in the world minus the
  // head's (a fixation held through a head turn counter-rotates the eye).
  v.gaze_angular_velocity_in_head_rad_s = gaze_omega_world - v.head_angular_velocity_rad_s;
  // A fixation carried by the head (no VOR): the eye holds still in the head. Without gaze
  // (head-fixed) the eye is taken to hold the world, as the reflex does for whatever it fixates
  // during a head turn: head rotation alone then coarsens nothing. Taking the eye as still in
  // the head would sweep the whole field across the retina at the head's rate and coarsen what
  // the viewer holds in focus (measured: a third of the degradations of family seed 2012 were
  // its first four frames, before the first gaze sample, during a 63 deg/s sweep).
  if (carried) v.gaze_angular_velocity_in_head_rad_s = glm::dvec3(0.0);
  v.gaze_direction = gaze_world;
  v.tracker_error_deg = error_deg;
  frame_.gaze_source = used;
  frame_.gaze_valid = used != GazeSourceKind::head_fixed;
  diag_.gaze_suppressed = suppressed;
  diag_.gaze_carried = carried;
  diag_.gaze_direction_head = gaze_head;
  diag_.gaze_error_deg = error_deg;
  (void)head;
}

const FrameDecisions& LodCore::decide(const FrameInput& in) {
  const HeadMotion& head = in.head;
  head_ = head;
  update_display(in);
  lod::Viewer v;
  v.xi_cpd = xi_cpd_;
  v.use_size = config_.criteria.size;
  v.use_eccentricity = config_.criteria.eccentricity;
  v.use_velocity = config_.criteria.velocity;
  if (head.valid) {
    last_head_orientation_ = head.orientation;
    last_head_position_ = head.position_m;
  }
  v.eye_position_m = last_head_position_;
  v.eye_velocity_m_s = head.valid ? head.linear_velocity_m_s : glm::dvec3(0.0);
  v.head_angular_velocity_rad_s = head.valid ? head.angular_velocity_rad_s : glm::dvec3(0.0);
  condition_gaze(head, in.t_ns, v);

  const std::string err = lod::select_lods(v, store_.view(), decisions_out_);
  if (!err.empty()) {
    // The core refused this frame's viewer: keep full detail rather than guess.
    std::fill(lod_.begin(), lod_.end(), 0);
    std::fill(limited_.begin(), limited_.end(), static_cast<std::uint8_t>(lod::Criterion::invalid_input));
  }
  if (config_.compute_breakdown) {
    // Ignored on purpose: these viewers are the one above with a criterion off, so they are
    // refused only when it was, and that frame's refusal is already handled (diagnostics only).
    lod::Viewer se = v;
    se.use_velocity = false;
    (void)lod::select_lods(se, store_.view(), breakdown_se_out_);
    lod::Viewer sv = v;
    sv.use_eccentricity = false;
    (void)lod::select_lods(sv, store_.view(), breakdown_sv_out_);
  }

  apply_switch_policy(v, in.t_ns, diag_.gaze_suppressed);
  // Cluster meshes: the same viewer, per cluster; the same hysteresis on their records.
  const bool cluster_policy = config_.switch_policy && config_.cluster_switch_policy;
  clusters_.update(v, cluster_policy ? &config_.switching : nullptr, frame_seconds(in.t_ns), diag_.gaze_suppressed);
  // Objects and cluster meshes under one budget: after the cluster cut, which it may coarsen.
  apply_budget(v);
  publish_clusters();

  diag_.gaze_bad_samples = primary_conditioner_.bad_samples() + external_conditioner_.bad_samples();
  diag_.gaze_direction_world = v.gaze_direction;
  diag_.eye_position_world = v.eye_position_m;
  diag_.head_angular_velocity_rad_s = v.head_angular_velocity_rad_s;
  diag_.head_linear_velocity_m_s = v.eye_velocity_m_s;
  diag_.gaze_angular_velocity_in_head_rad_s = v.gaze_angular_velocity_in_head_rad_s;
  // Reddy 1995's foveal cone: out to where M(E) leaves 1 (the fovea), widened by the error.
  diag_.foveal_cone =
      lod::make_foveal_cone(v.eye_position_m, v.gaze_direction, lod::kEccentricitySeamDeg, diag_.gaze_error_deg);
  diag_.xi_cpd = xi_cpd_;
  diag_.viewer = v;
  diag_.head_valid = head.valid;
  return frame_;
}

// Seconds since the first frame (the switch policies' clock).
double LodCore::frame_seconds(std::int64_t t_ns) {
  if (!have_t0_) {
    have_t0_ = true;
    t0_ns_ = t_ns;
  }
  return aux::seconds_from_ns(t_ns - t0_ns_);
}

void LodCore::publish_clusters() {
  frame_.cluster_drawn = clusters_.drawn();
  frame_.cluster_limited_by = clusters_.limited_by();
  frame_.cluster_held =
      config_.switch_policy && config_.cluster_switch_policy ? clusters_.held() : std::span<const std::uint8_t>();
  frame_.cluster_first = clusters_.first_cluster();
  diag_.cluster_drawn_perceptual = clusters_.perceptual();
}

// The budget pass: the perceptual levels are the finest worth drawing; the solver coarsens
// them until the predicted frame time fits. Benefit grows with projected area (pixels); a
// disabled object is not drawn, so it has none. Cluster meshes are items of the same solve
// (docs/cluster-budget.md): each mesh's coarsening steps, predicted from its hierarchy, and
// the chosen step's cut selected in this frame (ClusterMeshes::apply_steps).
void LodCore::apply_budget(const lod::Viewer& v) {
  diag_.predicted_ms = 0.0;
  diag_.budget_infeasible = false;
  const std::size_t meshes = clusters_.mesh_count();
  if (!(config_.budget_ms > 0.0) || (store_.size() == 0 && meshes == 0)) return;
  // Built at the first frame after a registration (one rebuild for many add_object calls). It
  // cannot throw: budget_ms and the options passed the constructor's check, every chain
  // ObjectStore::add's (1 to 255 levels).
  if (budget_ && budget_->cluster_mesh_count() != meshes) budget_.reset();  // a mesh was added
  if (!budget_) budget_ = std::make_unique<budget::FrameBudget>(chains_, config_.budget_ms, config_.budget, meshes);
  const double px_per_deg = 2.0 * xi_cpd_;  // xi = pixels / (2 * FOV)
  for (std::size_t i = 0; i < store_.size(); ++i) {
    const double r_px = static_cast<double>(angular_radius_deg_[i]) * px_per_deg;
    budget_view_[i].size_px = std::isfinite(r_px) && enabled_[i] ? std::numbers::pi * r_px * r_px : 0.0;
    budget_view_[i].importance = std::clamp(importance_[i], 0.0, 1.0);
  }
  // A cluster mesh's projected area is at most a view's pixels (one filling the view).
  double view_px = 0.0;
  for (std::uint32_t i = 0; i < view_count_; ++i)
    view_px = std::max(view_px, double(views_[i].width_px) * double(views_[i].height_px));
  clusters_.measure();
  cluster_view_.resize(meshes);  // grows at registration's first frame only
  cluster_step_.resize(meshes);
  for (std::uint32_t m = 0; m < meshes; ++m)
    cluster_view_[m] = clusters_.budget_view(m, v.eye_position_m, px_per_deg, view_px > 0.0 ? view_px : 1e12);
  if (!budget_->choose(policy_lod(), budget_view_, budget_lod_, cluster_view_, cluster_step_).empty()) {
    // Cannot happen (every span has the store's size, every level comes from its own chain);
    // were it refused, draw the perceptual choice rather than guess.
    std::copy(policy_lod().begin(), policy_lod().end(), budget_lod_.begin());
    clusters_.clear_steps();
    return;
  }
  // A refused scaled selection (the viewer passed the same check in update()) keeps the cut
  // update() drew: the cost fit then sees those triangles.
  (void)clusters_.apply_steps(v, cluster_step_);
  (void)budget_->record_cluster_triangles(clusters_.drawn_triangles());  // sizes match: one per mesh
  diag_.budget_infeasible = budget_->infeasible();
  diag_.predicted_ms = budget_->predicted_ms();
  cluster_predicted_tris_.resize(meshes);
  for (std::uint32_t m = 0; m < meshes; ++m) cluster_predicted_tris_[m] = budget_->cluster_predicted_triangles(m);
  frame_.cluster_budget_step = clusters_.steps();
  frame_.cluster_detail_scale = clusters_.detail_scale();
  diag_.cluster_triangles_predicted = cluster_predicted_tris_;
  diag_.cluster_triangles_drawn = clusters_.drawn_triangles();
}

// xi from the views' FOV and the resolution rendered: the finest view decides (an inset's
// density is the display's limit where the inset is; elsewhere this is conservative).
void LodCore::update_display(const FrameInput& in) {
  if (in.view_count > 0) {
    view_count_ = std::min<std::uint32_t>(in.view_count, kMaxViews);
    std::copy(in.views.begin(), in.views.begin() + view_count_, views_.begin());
  }
  if (xi_fixed_) return;
  double xi = 0.0;
  for (std::uint32_t i = 0; i < view_count_; ++i) {
    lod::ViewSpec spec;
    spec.width_px = views_[i].width_px;
    spec.height_px = views_[i].height_px;
    spec.fov = views_[i].fov;
    if (lod::validate_view(spec).empty()) xi = std::max(xi, lod::xi_cpd(spec));
  }
  if (xi > 0.0) xi_cpd_ = xi;
}

void LodCore::resize_outputs() {
  const std::size_t n = store_.size();
  for (auto* v : {&lod_, &limited_, &size_only_, &ecc_only_, &vel_only_, &se_, &sv_, &scratch_a_, &scratch_b_,
                  &scratch_c_, &scratch_d_})
    v->resize(n);
  angular_radius_deg_.resize(n);
  // New objects start at full detail with no coarsening window open, enabled.
  switch_drawn_.resize(n, 0);
  switch_finest_.resize(n, 0);
  switch_window_s_.resize(n, lod::kNoSwitchWindow);
  held_.resize(n, 0);
  switch_started_.resize(n, 0);
  enabled_.resize(n, 1);
  budget_lod_.resize(n);
  budget_view_.resize(n);
  const bool budget = config_.budget_ms > 0.0;
  decisions_out_ = {
      lod_,      limited_, size_only_, ecc_only_,
      vel_only_, {},       {},         budget ? std::span<float>(angular_radius_deg_) : std::span<float>()};
  breakdown_se_out_ = {se_, scratch_a_, scratch_b_, scratch_c_, scratch_d_, {}, {}, {}};
  breakdown_sv_out_ = {sv_, scratch_a_, scratch_b_, scratch_c_, scratch_d_, {}, {}, {}};
  frame_.lod = budget ? std::span<const std::uint8_t>(budget_lod_) : policy_lod();
  frame_.held = config_.switch_policy ? std::span<const std::uint8_t>(held_) : std::span<const std::uint8_t>();
  frame_.limited_by = limited_;
  diag_.lod_perceptual = lod_;
  diag_.lod_size_only = size_only_;
  diag_.lod_eccentricity_only = ecc_only_;
  diag_.lod_velocity_only = vel_only_;
  if (config_.compute_breakdown) {
    diag_.lod_size_eccentricity = se_;
    diag_.lod_size_velocity = sv_;
  }
}

}  // namespace gazelod::plugin
