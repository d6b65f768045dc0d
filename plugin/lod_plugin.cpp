// SPDX-License-Identifier: Apache-2.0
// The plugin's OpenXR front (plugin/lod_plugin.hpp): reads head, views and eye gaze through the
// application's function pointers and hands them to the engine (plugin/lod_core.hpp).
#include "plugin/lod_plugin.hpp"

#include "auxiliary/time.hpp"
#include "plugin/head_motion.hpp"
#include "plugin/lod_core.hpp"
#include "plugin/xr_check.hpp"
#include "plugin/xr_dispatch.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace gazelod {

const char* to_string(GazeSourceKind kind) {
  switch (kind) {
    case GazeSourceKind::openxr:
      return "openxr";
    case GazeSourceKind::external:
      return "external";
    case GazeSourceKind::head_fixed:
      return "head-fixed";
    case GazeSourceKind::pushed:
      return "pushed";
  }
  return "?";
}

namespace {

void check(XrResult r, const char* call) {
  xr_check(r, call, "gazelod: ");
}

// The old configuration's meaning: the runtime's eye gaze, with our set attached by us unless
// the application attaches sets itself.
OpenXrGazeInput resolve(OpenXrGazeInput in, const PluginConfig& c) {
  if (in != OpenXrGazeInput::from_config) return in;
  if (!c.use_openxr_eye_gaze) return OpenXrGazeInput::none;
  return c.application_attaches_action_sets ? OpenXrGazeInput::merge_binding : OpenXrGazeInput::plugin_actions;
}

class LodPluginImpl final : public LodPlugin {
 public:
  LodPluginImpl(plugin::XrDispatch xr, XrInstance instance, XrSystemId system, XrSession session, XrSpace base,
                PluginConfig config, OpenXrOptions options)
      : xr_(xr),
        instance_(instance),
        system_(system),
        session_(session),
        base_(base),
        options_(options),
        core_(config),
        pushed_(heads_, aux::ns_from_seconds(config.max_pushed_sample_age_s)) {
    XrReferenceSpaceCreateInfo view_info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    view_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
    view_info.poseInReferenceSpace.orientation.w = 1.0f;
    check(xr_.create_reference_space(session_, &view_info, &view_space_), "xrCreateReferenceSpace(VIEW)");
    head_ = std::make_unique<plugin::HeadTracker>(xr_, view_space_, base_);
    try {
      init_gaze(resolve(options.gaze_input, config));
      init_views();
    } catch (...) {
      release();
      throw;
    }
  }

  ~LodPluginImpl() override { release(); }

  XrActionSet action_set() const override { return xr_gaze_ ? xr_gaze_->action_set() : XR_NULL_HANDLE; }
  XrAction gaze_action() const override { return xr_gaze_ ? xr_gaze_->action() : XR_NULL_HANDLE; }
  void action_sets_attached() override {
    if (xr_gaze_) xr_gaze_->action_sets_attached();
  }

  std::uint32_t add_object(const ObjectDesc& d) override { return core_.add_object(d); }
  void set_object_motion(std::uint32_t id, const glm::dvec3& c, const glm::dvec3& v) override {
    core_.set_object_motion(id, c, v);
  }
  std::size_t object_count() const override { return core_.object_count(); }
  std::uint32_t add_cluster_mesh(const ClusterMeshDesc& d) override { return core_.add_cluster_mesh(d); }
  void set_cluster_mesh_motion(std::uint32_t id, const lod::InstanceTransform& pose, const glm::dvec3& v) override {
    core_.set_cluster_mesh_motion(id, pose, v);
  }
  std::size_t cluster_mesh_count() const override { return core_.cluster_mesh_count(); }

  void on_session_state(XrSessionState state, XrTime time) override {
    core_.session_state(state == XR_SESSION_STATE_FOCUSED, static_cast<std::int64_t>(time));
  }

  void set_base_space(XrSpace base) override {
    if (base == XR_NULL_HANDLE) throw std::invalid_argument("gazelod: the base space must be a valid XrSpace");
    base_ = base;
    head_->set_base(base);
  }

  void set_view_resolution(std::uint32_t view, int width_px, int height_px) override {
    if (view >= view_pixels_.size())
      throw std::out_of_range("gazelod: view " + std::to_string(view) + " out of range: the view configuration has " +
                              std::to_string(view_pixels_.size()) + " views");
    if (width_px <= 0 || height_px <= 0 || width_px > 65536 || height_px > 65536)
      throw std::invalid_argument("gazelod: a view's resolution must be 1..65536 pixels on each side");
    view_pixels_[view] = {width_px, height_px};
  }

  void set_gaze_space(XrSpace gaze_space, XrAction gaze_action) override {
    if (gaze_input_ != OpenXrGazeInput::app_space || !xr_gaze_)
      throw std::invalid_argument("gazelod: a gaze space is given only with GZL_GAZE_INPUT_APP_SPACE");
    xr_gaze_->set_app_space(gaze_space, gaze_action);
    core_.restart_primary();
  }

  std::uint32_t view_count() const override { return static_cast<std::uint32_t>(view_pixels_.size()); }
  int max_view_height_px() const override {
    // With quad views the primary pair (views 0 and 1) is what a share of "the screen" means.
    int h = 0;
    for (std::size_t i = 0; i < view_pixels_.size() && i < 2; ++i) h = std::max(h, view_pixels_[i].second);
    return h;
  }

  plugin::PushResult push_gaze(const plugin::PushedSample& s, std::string& why) override {
    if (gaze_input_ != OpenXrGazeInput::pushed) {
      why = "gazelod: gaze samples are pushed only with GZL_GAZE_INPUT_PUSHED (this plugin reads the eye-gaze action)";
      return plugin::PushResult::invalid;
    }
    return pushed_.push(s, why);
  }

  const FrameDecisions& begin_frame(XrTime t) override {
    plugin::FrameInput in;
    in.t_ns = static_cast<std::int64_t>(t);
    if (!shut_down_) {
      in.head = head_->locate(t);
      locate_views(t, in);
    }
    if (in.head.valid) heads_.push(in.t_ns, in.head.orientation);
    pushed_.frame_time(in.t_ns);
    return core_.decide(in);
  }

  const FrameDiagnostics& diagnostics() const override { return core_.diagnostics(); }
  void end_frame(double measured_frame_ms) override { core_.end_frame(measured_frame_ms); }

  void shutdown() override {
    release();
    shut_down_ = true;
  }
  bool is_shut_down() const override { return shut_down_; }

  GazeSourceKind active_source() const override { return core_.active_source(); }
  void on_source_changed(SourceChanged cb) override { core_.on_source_changed(std::move(cb)); }
  plugin::LodCore& core() override { return core_; }
  const plugin::LodCore& core() const override { return core_; }

 private:
  void init_gaze(OpenXrGazeInput input) {
    gaze_input_ = input;
    std::string why_none;
    switch (input) {
      case OpenXrGazeInput::from_config:
      case OpenXrGazeInput::none:
        why_none = "eye gaze not asked for (GZL_GAZE_INPUT_NONE)";
        break;
      case OpenXrGazeInput::pushed:
        core_.set_primary(&pushed_, GazeSourceKind::pushed, "");
        core_.set_orientation_at([this](std::int64_t t_ns) {
          if (auto q = pushed_.head_at_last_sample()) return q;
          return head_->orientation_at(static_cast<XrTime>(t_ns));
        });
        return;
      case OpenXrGazeInput::app_space:
        // A null space is given later (gzl_set_gaze_space); until then the source has nothing.
        xr_gaze_ = std::make_unique<plugin::OpenXrGazeSource>(
            xr_, instance_, session_, plugin::GazeInputMode::app_space, options_.gaze_space, options_.gaze_action);
        break;
      case OpenXrGazeInput::merge_binding:
      case OpenXrGazeInput::plugin_actions:
        if (!plugin::system_supports_eye_gaze(xr_, instance_, system_)) {
          why_none =
              "the system reports no eye-gaze interaction: enable XR_EXT_eye_gaze_interaction on the instance "
              "(xrCreateInstance) on a runtime that has it, or push samples (GZL_GAZE_INPUT_PUSHED)";
          break;
        }
        xr_gaze_ = std::make_unique<plugin::OpenXrGazeSource>(xr_, instance_, session_,
                                                              input == OpenXrGazeInput::merge_binding
                                                                  ? plugin::GazeInputMode::merge_binding
                                                                  : plugin::GazeInputMode::plugin_actions);
        if (input == OpenXrGazeInput::plugin_actions) xr_gaze_->attach_and_own_sync();
        break;
    }
    core_.set_primary(xr_gaze_.get(), GazeSourceKind::openxr, why_none);
    core_.set_orientation_at([this](std::int64_t t_ns) { return head_->orientation_at(static_cast<XrTime>(t_ns)); });
  }

  void init_views() {
    std::uint32_t n = 0;
    const XrViewConfigurationType type = options_.view_configuration;
    const XrResult r = xr_.enumerate_view_configuration_views(instance_, system_, type, 0, &n, nullptr);
    if (r == XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED)
      throw XrCallError("gazelod: the system does not support view configuration " + std::to_string(type) +
                            "; pass the one the session was begun with (PRIMARY_STEREO, PRIMARY_MONO or "
                            "PRIMARY_QUAD_VARJO)",
                        r);
    check(r, "xrEnumerateViewConfigurationViews");
    if (n == 0 || n > plugin::kMaxViews)
      throw XrCallError("gazelod: view configuration " + std::to_string(type) + " has " + std::to_string(n) +
                        " views; gazelod takes 1 to 4");
    std::vector<XrViewConfigurationView> cv(n, {XR_TYPE_VIEW_CONFIGURATION_VIEW});
    check(xr_.enumerate_view_configuration_views(instance_, system_, type, n, &n, cv.data()),
          "xrEnumerateViewConfigurationViews");
    view_pixels_.clear();
    for (const auto& c : cv)
      view_pixels_.push_back(
          {static_cast<int>(c.recommendedImageRectWidth), static_cast<int>(c.recommendedImageRectHeight)});
    views_.assign(n, {XR_TYPE_VIEW});
  }

  // The views' FOV and pose in the head at t (their resolution: set_view_resolution, else the
  // runtime's recommendation). A failed locate keeps the previous frame's views.
  void locate_views(XrTime t, plugin::FrameInput& in) {
    XrViewLocateInfo info{XR_TYPE_VIEW_LOCATE_INFO};
    info.viewConfigurationType = options_.view_configuration;
    info.displayTime = t;
    info.space = view_space_;
    XrViewState vs{XR_TYPE_VIEW_STATE};
    std::uint32_t n = static_cast<std::uint32_t>(views_.size());
    if (XR_FAILED(xr_.locate_views(session_, &info, &vs, n, &n, views_.data()))) return;
    in.view_count = std::min<std::uint32_t>(n, static_cast<std::uint32_t>(view_pixels_.size()));
    for (std::uint32_t i = 0; i < in.view_count; ++i) {
      plugin::ViewInput& v = in.views[i];
      const XrView& x = views_[i];
      v.fov = {x.fov.angleLeft, x.fov.angleRight, x.fov.angleUp, x.fov.angleDown};
      v.orientation_in_head =
          glm::dquat(x.pose.orientation.w, x.pose.orientation.x, x.pose.orientation.y, x.pose.orientation.z);
      v.position_in_head_m = {x.pose.position.x, x.pose.position.y, x.pose.position.z};
      v.width_px = view_pixels_[i].first;
      v.height_px = view_pixels_[i].second;
    }
  }

  void release() {
    if (xr_gaze_) xr_gaze_->release();
    if (view_space_ != XR_NULL_HANDLE) xr_.destroy_space(view_space_);
    view_space_ = XR_NULL_HANDLE;
  }

  plugin::XrDispatch xr_;
  XrInstance instance_;
  XrSystemId system_;
  XrSession session_;
  XrSpace base_;
  OpenXrOptions options_;
  OpenXrGazeInput gaze_input_ = OpenXrGazeInput::none;
  XrSpace view_space_ = XR_NULL_HANDLE;
  bool shut_down_ = false;
  plugin::LodCore core_;
  plugin::HeadHistory heads_;
  plugin::PushedGazeSource pushed_;
  std::unique_ptr<plugin::HeadTracker> head_;
  std::unique_ptr<plugin::OpenXrGazeSource> xr_gaze_;
  std::vector<std::pair<int, int>> view_pixels_;
  std::vector<XrView> views_;
};

}  // namespace

std::unique_ptr<LodPlugin> LodPlugin::create(PFN_xrGetInstanceProcAddr gipa, XrInstance instance, XrSystemId system,
                                             XrSession session, XrSpace base_space, PluginConfig config,
                                             OpenXrOptions options) {
  if (instance == XR_NULL_HANDLE || session == XR_NULL_HANDLE || base_space == XR_NULL_HANDLE)
    throw std::invalid_argument("gazelod: instance, session and base space must be valid handles");
  return std::make_unique<LodPluginImpl>(plugin::load_xr_dispatch(gipa, instance), instance, system, session,
                                         base_space, std::move(config), options);
}

}  // namespace gazelod
