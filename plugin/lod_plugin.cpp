// The plugin: a thin adapter from OpenXR (head, views, eye gaze) to the core's selection.
#include "plugin/gazelod.hpp"

#include "budget/frame_budget.hpp"
#include "lod/acuity.hpp"
#include "lod/angles.hpp"
#include "lod/display.hpp"
#include "lod/object_set.hpp"
#include "lod/select.hpp"
#include "gaze/gaze_conditioner.hpp"
#include "plugin/cluster_meshes.hpp"
#include "plugin/gaze_arbiter.hpp"
#include "plugin/head_motion.hpp"
#include "plugin/openxr_gaze_source.hpp"
#include "plugin/xr_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gazelod {

const char* to_string(GazeSourceKind kind) {
  switch (kind) {
    case GazeSourceKind::openxr: return "openxr";
    case GazeSourceKind::external: return "external";
    case GazeSourceKind::head_fixed: return "head-fixed";
  }
  return "?";
}

namespace {

using lod::kDegPerRad;

void check(XrResult r, const char* call) { xr_check(r, call, "gazelod plugin: "); }

class LodPluginImpl final : public LodPlugin {
 public:
  LodPluginImpl(XrInstance instance, XrSystemId system, XrSession session, XrSpace base, PluginConfig config)
      : instance_(instance), system_(system), session_(session), base_(base), config_(std::move(config)) {
    XrReferenceSpaceCreateInfo view_info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    view_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
    view_info.poseInReferenceSpace.orientation.w = 1.0f;
    check(xrCreateReferenceSpace(session_, &view_info, &view_space_), "xrCreateReferenceSpace(VIEW)");
    head_ = std::make_unique<plugin::HeadTracker>(view_space_, base_);
    gaze::ConditionerConfig cc = config_.conditioning;
    cc.accuracy_deg = config_.openxr_gaze_error_deg;
    openxr_conditioner_ = gaze::GazeConditioner(cc);
    cc.accuracy_deg = config_.external_gaze_error_deg;
    external_conditioner_ = gaze::GazeConditioner(cc);

    if (config_.use_openxr_eye_gaze && plugin::system_supports_eye_gaze(instance_, system_)) {
      xr_gaze_ = std::make_unique<plugin::OpenXrGazeSource>(instance_, session_);
      if (!config_.application_attaches_action_sets) xr_gaze_->attach_and_own_sync();
    }
    plugin::ArbiterConfig ac;
    ac.silence_timeout_ns = static_cast<std::int64_t>(config_.gaze_silence_timeout_s * 1e9);
    arbiter_ = std::make_unique<plugin::GazeArbiter>(xr_gaze_.get(), config_.external_source.get(), ac);
    arbiter_->on_change([this](GazeSourceKind s, const std::string& why) {
      active_ = s;
      if (changed_) changed_(active_, why);
    });

    init_display();
  }

  ~LodPluginImpl() override {
    xr_gaze_.reset();
    if (view_space_ != XR_NULL_HANDLE) xrDestroySpace(view_space_);
  }

  XrActionSet action_set() const override { return xr_gaze_ ? xr_gaze_->action_set() : XR_NULL_HANDLE; }
  void action_sets_attached() override {
    if (xr_gaze_) xr_gaze_->action_sets_attached();
  }

  std::uint32_t add_object(const ObjectDesc& d) override {
    const std::uint32_t id = store_.add(d.center_m, d.radius_m, d.velocity_m_s, d.lods);
    chains_.push_back(d.lods);
    importance_.push_back(d.importance);
    budget_.reset();  // rebuilt with the new object at the next frame
    resize_outputs();
    return id;
  }
  void set_object_motion(std::uint32_t id, const glm::dvec3& c, const glm::dvec3& v) override {
    store_.set_motion(id, c, v);
  }
  std::size_t object_count() const override { return store_.size(); }

  std::uint32_t add_cluster_mesh(const ClusterMeshDesc& d) override {
    const std::uint32_t id = clusters_.add(d);
    publish_clusters();
    return id;
  }
  void set_cluster_mesh_motion(std::uint32_t id, const lod::InstanceTransform& pose, const glm::dvec3& v) override {
    clusters_.set_motion(id, pose, v);
  }
  std::size_t cluster_mesh_count() const override { return clusters_.mesh_count(); }

  void on_session_state(XrSessionState state, XrTime time) override {
    arbiter_->session_state(state == XR_SESSION_STATE_FOCUSED, static_cast<std::int64_t>(time));
  }

  const FrameDecisions& begin_frame(XrTime t) override {
    const plugin::HeadMotion head = head_->locate(t);
    const plugin::ArbiterResult gaze = arbiter_->update(static_cast<std::int64_t>(t));
    update_display(t);

    lod::Viewer v;
    v.xi_cpd = xi_cpd_;
    v.use_size = config_.criteria.size;
    v.use_eccentricity = config_.criteria.eccentricity;
    v.use_velocity = config_.criteria.velocity;
    const glm::dquat q = head.valid ? head.orientation : last_head_orientation_;
    if (head.valid) {
      last_head_orientation_ = head.orientation;
      last_head_position_ = head.position_m;
    }
    v.eye_position_m = last_head_position_;
    v.eye_velocity_m_s = head.valid ? head.linear_velocity_m_s : glm::dvec3(0.0);
    v.head_angular_velocity_rad_s = head.valid ? head.angular_velocity_rad_s : glm::dvec3(0.0);

    // The gaze at the display time, conditioned per source (gaze/gaze_conditioner.hpp):
    // classified in the world, smoothed in fixations, predicted to t; its uncertainty widens
    // the foveal cone, and only a classified pursuit moves the gaze in the world.
    glm::dvec3 gaze_head(0.0, 0.0, -1.0);
    glm::dvec3 gaze_world = q * gaze_head;
    glm::dvec3 gaze_omega_world(0.0);
    double error_deg = config_.head_fixed_cone_deg;
    bool gaze_suppressed = false;
    diag_.eye_motion = gaze::EyeMotion::loss;
    GazeSourceKind used = GazeSourceKind::head_fixed;
    if (gaze.source != GazeSourceKind::head_fixed) {
      gaze::GazeConditioner& c = gaze.source == GazeSourceKind::openxr ? openxr_conditioner_ : external_conditioner_;
      if (gaze.source != conditioned_source_) c.reset();  // a new source: no history across it
      conditioned_source_ = gaze.source;
      const glm::dquat q_sample = head_->orientation_at(static_cast<XrTime>(gaze.sample.t_ns)).value_or(q);
      c.push(gaze.sample, q_sample);
      const gaze::ConditionedGaze cg = c.at(static_cast<std::int64_t>(t), q);
      if (cg.valid) {
        used = gaze.source;
        gaze_head = cg.direction_head;
        gaze_world = cg.direction_world;
        gaze_omega_world = cg.angular_velocity_world_rad_s;
        error_deg = cg.uncertainty_deg;
        gaze_suppressed = cg.suppressed;
        diag_.eye_motion = cg.motion;
      }
    } else {
      conditioned_source_ = GazeSourceKind::head_fixed;
    }
    // The selection takes the eye-in-head rotation: the eye's rotation in the world minus the
    // head's (a fixation held through a head turn counter-rotates the eye).
    v.gaze_angular_velocity_in_head_rad_s = gaze_omega_world - v.head_angular_velocity_rad_s;
    if (used == GazeSourceKind::head_fixed) v.gaze_angular_velocity_in_head_rad_s = glm::dvec3(0.0);
    v.gaze_direction = gaze_world;
    v.tracker_error_deg = error_deg;

    const std::string err = lod::select_lods(v, store_.view(), decisions_out_);
    if (!err.empty()) {
      // The core refused this frame's viewer: keep full detail rather than guess.
      std::fill(lod_.begin(), lod_.end(), 0);
      std::fill(limited_.begin(), limited_.end(), static_cast<std::uint8_t>(lod::Criterion::invalid_input));
    }
    if (config_.compute_breakdown) {
      lod::Viewer se = v;
      se.use_velocity = false;
      lod::select_lods(se, store_.view(), breakdown_se_out_);
      lod::Viewer sv = v;
      sv.use_eccentricity = false;
      lod::select_lods(sv, store_.view(), breakdown_sv_out_);
    }

    apply_switch_policy(t, gaze_suppressed);
    apply_budget();
    // Cluster meshes: the same viewer, per cluster; the same hysteresis on their records.
    clusters_.update(v, config_.switch_policy ? &config_.switching : nullptr, frame_seconds(t), gaze_suppressed);
    publish_clusters();

    frame_.gaze_source = used;
    frame_.gaze_valid = used != GazeSourceKind::head_fixed;
    diag_.gaze_suppressed = gaze_suppressed;
    diag_.gaze_bad_samples = openxr_conditioner_.bad_samples() + external_conditioner_.bad_samples();
    diag_.gaze_direction_world = v.gaze_direction;
    diag_.gaze_direction_head = gaze_head;
    diag_.eye_position_world = v.eye_position_m;
    diag_.head_angular_velocity_rad_s = v.head_angular_velocity_rad_s;
    diag_.gaze_error_deg = error_deg;
    // Reddy 1995's foveal cone: out to where M(E) leaves 1 (the fovea), widened by the error.
    diag_.foveal_cone = lod::make_foveal_cone(v.eye_position_m, v.gaze_direction,
                                              lod::kEccentricitySeamDeg, error_deg);
    diag_.xi_cpd = xi_cpd_;
    diag_.head_valid = head.valid;
    return frame_;
  }

  const FrameDiagnostics& diagnostics() const override { return diag_; }

  void end_frame(double measured_frame_ms) override {
    if (budget_) budget_->observe(measured_frame_ms);
  }

  GazeSourceKind active_source() const override { return active_; }
  void on_source_changed(SourceChanged cb) override { changed_ = std::move(cb); }

 private:
  // Refinement at once, coarsening after the hold and preferably while vision is suppressed.
  // Seconds since the first frame (the switch policies' clock).
  double frame_seconds(XrTime t) {
    if (!have_t0_) {
      have_t0_ = true;
      t0_ = t;
    }
    return static_cast<double>(t - t0_) * 1e-9;
  }

  void publish_clusters() {
    frame_.cluster_drawn = clusters_.drawn();
    frame_.cluster_limited_by = clusters_.limited_by();
    frame_.cluster_held = config_.switch_policy ? clusters_.held() : std::span<const std::uint8_t>();
    frame_.cluster_first = clusters_.first_cluster();
    diag_.cluster_drawn_perceptual = clusters_.perceptual();
  }

  void apply_switch_policy(XrTime t, bool suppressed) {
    if (!config_.switch_policy) return;
    const double t_s = frame_seconds(t);
    // An object's first frame draws its perceptual level: nothing was drawn before, so there is
    // no switch to hide.
    for (std::size_t i = switch_started_; i < lod_.size(); ++i) switch_drawn_[i] = lod_[i];
    switch_started_ = lod_.size();
    const lod::SwitchState state{switch_drawn_, switch_finest_, switch_window_s_};
    if (!lod::apply_switch_policy(config_.switching, t_s, suppressed, lod_, state, held_).empty()) {
      // Refused (it validates sizes and the configuration): draw the perceptual choice.
      std::copy(lod_.begin(), lod_.end(), switch_drawn_.begin());
      std::fill(held_.begin(), held_.end(), 0);
    }
  }

  // The levels the policy passes on (the perceptual ones without it).
  std::span<const std::uint8_t> policy_lod() const {
    return config_.switch_policy ? std::span<const std::uint8_t>(switch_drawn_) : std::span<const std::uint8_t>(lod_);
  }

  // The budget pass: the perceptual levels are the finest worth drawing; the solver coarsens
  // them until the predicted frame time fits. Benefit grows with projected area (pixels).
  void apply_budget() {
    diag_.predicted_ms = 0.0;
    diag_.budget_infeasible = false;
    if (!(config_.budget_ms > 0.0) || store_.size() == 0) return;
    if (!budget_) budget_ = std::make_unique<budget::FrameBudget>(chains_, config_.budget_ms, config_.budget);
    const double px_per_deg = 2.0 * xi_cpd_;  // xi = pixels / (2 * FOV)
    for (std::size_t i = 0; i < store_.size(); ++i) {
      const double r_px = static_cast<double>(angular_radius_deg_[i]) * px_per_deg;
      budget_view_[i].size_px = std::isfinite(r_px) ? std::numbers::pi * r_px * r_px : 0.0;
      budget_view_[i].importance = std::clamp(importance_[i], 0.0, 1.0);
    }
    try {
      diag_.budget_infeasible = !budget_->choose(policy_lod(), budget_view_, budget_lod_);
      diag_.predicted_ms = budget_->predicted_ms();
    } catch (const std::exception&) {
      // Inputs the solver refuses: draw the perceptual choice rather than guess.
      std::copy(policy_lod().begin(), policy_lod().end(), budget_lod_.begin());
    }
  }

  void init_display() {
    if (!config_.hmd_override.empty()) {
      const lod::DisplaySpec* preset = lod::find_display_preset(config_.hmd_override);
      if (!preset) throw std::runtime_error("gazelod plugin: unknown HMD preset '" + config_.hmd_override + "'");
      xi_cpd_ = lod::xi_cpd(*preset);
      xi_fixed_ = true;
      return;
    }
    std::uint32_t n = 0;
    const auto stereo = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    check(xrEnumerateViewConfigurationViews(instance_, system_, stereo, 0, &n, nullptr), "xrEnumerateViewConfigurationViews");
    std::vector<XrViewConfigurationView> cv(n, {XR_TYPE_VIEW_CONFIGURATION_VIEW});
    check(xrEnumerateViewConfigurationViews(instance_, system_, stereo, n, &n, cv.data()), "xrEnumerateViewConfigurationViews");
    view_pixels_.clear();
    for (const auto& c : cv)
      view_pixels_.push_back({static_cast<int>(c.recommendedImageRectWidth), static_cast<int>(c.recommendedImageRectHeight)});
    views_.assign(n, {XR_TYPE_VIEW});
  }

  // xi from the views' FOV (as the runtime locates them) and the recommended resolution.
  void update_display(XrTime t) {
    if (xi_fixed_ || views_.empty()) return;
    XrViewLocateInfo info{XR_TYPE_VIEW_LOCATE_INFO};
    info.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    info.displayTime = t;
    info.space = view_space_;
    XrViewState vs{XR_TYPE_VIEW_STATE};
    std::uint32_t n = static_cast<std::uint32_t>(views_.size());
    if (XR_FAILED(xrLocateViews(session_, &info, &vs, n, &n, views_.data()))) return;
    double xi = 0.0;
    for (std::uint32_t i = 0; i < n && i < view_pixels_.size(); ++i) {
      lod::ViewSpec spec;
      spec.width_px = view_pixels_[i].first;
      spec.height_px = view_pixels_[i].second;
      spec.fov = {views_[i].fov.angleLeft, views_[i].fov.angleRight, views_[i].fov.angleUp, views_[i].fov.angleDown};
      if (lod::validate_view(spec).empty()) xi = std::max(xi, lod::xi_cpd(spec));
    }
    if (xi > 0.0) xi_cpd_ = xi;
  }

  void resize_outputs() {
    const std::size_t n = store_.size();
    for (auto* v : {&lod_, &limited_, &size_only_, &ecc_only_, &vel_only_, &se_, &sv_, &scratch_a_, &scratch_b_, &scratch_c_, &scratch_d_})
      v->resize(n);
    angular_radius_deg_.resize(n);
    // New objects start at full detail with no coarsening window open.
    switch_drawn_.resize(n, 0);
    switch_finest_.resize(n, 0);
    switch_window_s_.resize(n, lod::kNoSwitchWindow);
    held_.resize(n, 0);
    budget_lod_.resize(n);
    budget_view_.resize(n);
    const bool budget = config_.budget_ms > 0.0;
    decisions_out_ = {lod_, limited_, size_only_, ecc_only_, vel_only_, {}, {},
                      budget ? std::span<float>(angular_radius_deg_) : std::span<float>()};
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

  XrInstance instance_;
  XrSystemId system_;
  XrSession session_;
  XrSpace base_;
  PluginConfig config_;
  XrSpace view_space_ = XR_NULL_HANDLE;
  std::unique_ptr<plugin::HeadTracker> head_;
  std::unique_ptr<plugin::OpenXrGazeSource> xr_gaze_;
  std::unique_ptr<plugin::GazeArbiter> arbiter_;
  SourceChanged changed_;
  GazeSourceKind active_ = GazeSourceKind::head_fixed;

  lod::ObjectStore store_;
  plugin::ClusterMeshes clusters_;
  std::vector<std::uint8_t> lod_, limited_, size_only_, ecc_only_, vel_only_, se_, sv_;
  std::vector<std::uint8_t> scratch_a_, scratch_b_, scratch_c_, scratch_d_;
  lod::Decisions decisions_out_, breakdown_se_out_, breakdown_sv_out_;
  FrameDecisions frame_;
  FrameDiagnostics diag_;

  double xi_cpd_ = 30.0;
  bool xi_fixed_ = false;
  std::vector<std::pair<int, int>> view_pixels_;
  std::vector<XrView> views_;
  glm::dquat last_head_orientation_{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 last_head_position_{0.0};
  gaze::GazeConditioner openxr_conditioner_, external_conditioner_;
  GazeSourceKind conditioned_source_ = GazeSourceKind::head_fixed;

  std::vector<std::vector<lod::LodLevel>> chains_;
  std::vector<double> importance_;
  std::vector<float> angular_radius_deg_;
  std::vector<std::uint8_t> switch_drawn_, switch_finest_, held_;
  std::vector<double> switch_window_s_;
  std::size_t switch_started_ = 0;  // objects [0, this) have had their first frame
  bool have_t0_ = false;
  XrTime t0_ = 0;
  std::vector<std::uint8_t> budget_lod_;
  std::vector<budget::BudgetObjectView> budget_view_;
  std::unique_ptr<budget::FrameBudget> budget_;
};

}  // namespace

std::unique_ptr<LodPlugin> LodPlugin::create(XrInstance instance, XrSystemId system, XrSession session,
                                             XrSpace base_space, PluginConfig config) {
  if (instance == XR_NULL_HANDLE || session == XR_NULL_HANDLE || base_space == XR_NULL_HANDLE)
    throw std::invalid_argument("gazelod plugin: instance, session and base space must be valid handles");
  return std::make_unique<LodPluginImpl>(instance, system, session, base_space, std::move(config));
}

}  // namespace gazelod
