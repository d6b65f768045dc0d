// SPDX-License-Identifier: Apache-2.0
// The plugin's C++ front for OpenXR applications (internal: applications outside this
// repository use the C ABI, <gazelod/gazelod.h>). Created from the application's
// xrGetInstanceProcAddr, XrInstance, XrSession and base XrSpace; each frame at the predicted
// display time it reads head pose and velocity, the views and eye gaze through the
// application's function pointers, and hands them to the OpenXR-free engine
// (plugin/lod_core.hpp), which picks a level of detail per object and per cluster.
//
//   auto plugin = gazelod::LodPlugin::create(xrGetInstanceProcAddr, instance, system, session, space, config);
//   for each object: plugin->add_object(desc);            (one level per object: LOD chains)
//   for each large mesh: plugin->add_cluster_mesh(desc);  (detail per region: a cluster hierarchy)
//   frame: xrWaitFrame -> plugin->begin_frame(predicted_display_time) -> draw decisions.lod
//          and the clusters with decisions.cluster_drawn -> xrEndFrame -> plugin->end_frame(ms)
// Threads: none of its own and no locking; the C ABI (plugin/capi/) serialises calls.
#pragma once

#include "plugin/frame_output.hpp"
#include "plugin/gaze_source_kind.hpp"
#include "plugin/object_desc.hpp"
#include "plugin/openxr_gaze_source.hpp"
#include "plugin/plugin_config.hpp"
#include "plugin/pushed_gaze.hpp"

#include <openxr/openxr.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace gazelod {

namespace plugin {
class LodCore;
}

// Where the eye gaze comes from in OpenXR mode (gzl_gaze_input).
enum class OpenXrGazeInput {
  from_config,     // PluginConfig: use_openxr_eye_gaze, application_attaches_action_sets
  app_space,       // OpenXrOptions::gaze_space, the application's action space
  merge_binding,   // our set and action, merged into the application's calls
  pushed,          // push_gaze
  plugin_actions,  // we suggest, attach and sync (applications without actions)
  none,            // head-fixed
};

struct OpenXrOptions {
  XrViewConfigurationType view_configuration = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  OpenXrGazeInput gaze_input = OpenXrGazeInput::from_config;
  XrSpace gaze_space = XR_NULL_HANDLE;    // app_space
  XrAction gaze_action = XR_NULL_HANDLE;  // app_space, optional
};

class LodPlugin {
 public:
  using SourceChanged = std::function<void(GazeSourceKind now, const std::string& why)>;

  // Throws XrCallError (plugin/xr_check.hpp) naming the failing OpenXR call and the remedy,
  // std::invalid_argument for bad handles or configuration.
  static std::unique_ptr<LodPlugin> create(PFN_xrGetInstanceProcAddr get_instance_proc_addr, XrInstance instance,
                                           XrSystemId system, XrSession session, XrSpace base_space,
                                           PluginConfig config, OpenXrOptions options = {});
  virtual ~LodPlugin() = default;

  // merge_binding (or from_config with application_attaches_action_sets): the set to include
  // in the application's xrAttachSessionActionSets and xrSyncActions; XR_NULL_HANDLE in the
  // other modes. Then action_sets_attached().
  virtual XrActionSet action_set() const = 0;
  virtual XrAction gaze_action() const = 0;
  virtual void action_sets_attached() = 0;

  // Registration (not per frame). Returns the object's id (0, 1, 2, ...).
  virtual std::uint32_t add_object(const ObjectDesc& desc) = 0;
  // Per-frame updates of moving objects; no allocation.
  virtual void set_object_motion(std::uint32_t id, const glm::dvec3& center_m, const glm::dvec3& velocity_m_s) = 0;
  virtual std::size_t object_count() const = 0;
  // Registration of a cluster mesh; returns its id (0, 1, 2, ...). Its clusters are
  // FrameDecisions::cluster_drawn[cluster_first[id] ...]. Throws std::invalid_argument with
  // the reason for an inconsistent hierarchy (lod::validate_cluster_hierarchy) or pose.
  virtual std::uint32_t add_cluster_mesh(const ClusterMeshDesc& desc) = 0;
  // A cluster mesh moved (per frame, no allocation; linear in its clusters): its new pose and
  // velocity, both in the base space, as in ClusterMeshDesc. Throws std::out_of_range for an
  // unknown id, std::invalid_argument for a pose or velocity that is not finite (or a zero
  // rotation, a scale <= 0); the mesh keeps its previous pose then.
  virtual void set_cluster_mesh_motion(std::uint32_t id, const lod::InstanceTransform& pose,
                                       const glm::dvec3& velocity_m_s) = 0;
  virtual std::size_t cluster_mesh_count() const = 0;

  // Called when the session state changes (from the application's xrPollEvent loop).
  virtual void on_session_state(XrSessionState state, XrTime time) = 0;
  // A new base space (recentring, a new application space): poses are read in it from the
  // next frame; the head's velocity restarts there.
  virtual void set_base_space(XrSpace base_space) = 0;
  // The resolution actually rendered for a view (default: the runtime's recommendation).
  // Throws std::out_of_range for a view the configuration does not have.
  virtual void set_view_resolution(std::uint32_t view, int width_px, int height_px) = 0;
  // The views of the view configuration and the largest vertical resolution among them.
  virtual std::uint32_t view_count() const = 0;
  virtual int max_view_height_px() const = 0;
  // app_space: the application's gaze space (and action) given or replaced after creation.
  // Throws std::invalid_argument in the other modes.
  virtual void set_gaze_space(XrSpace gaze_space, XrAction gaze_action) = 0;
  // pushed: a sample from the application's own gaze input (PushResult says why not).
  virtual plugin::PushResult push_gaze(const plugin::PushedSample& sample, std::string& why) = 0;

  // At the frame's predicted display time: gaze, head, views, selection. The returned
  // spans stay valid until the next begin_frame or registration. No allocation after the first
  // frame.
  virtual const FrameDecisions& begin_frame(XrTime predicted_display_time) = 0;
  // How the last begin_frame decided (valid until the next one).
  virtual const FrameDiagnostics& diagnostics() const = 0;
  // The measured frame time (for the budget's cost model).
  virtual void end_frame(double measured_frame_ms) = 0;

  // Releases every OpenXR handle the plugin created; later frames keep the last decisions.
  // Call before xrDestroySession / xrDestroyInstance. Safe twice.
  virtual void shutdown() = 0;
  virtual bool is_shut_down() const = 0;

  virtual GazeSourceKind active_source() const = 0;
  // Called once per change, with the reason ("openxr delivered no usable eye gaze in 1.0 s (...)",
  // "HID tracker unplugged", ...).
  virtual void on_source_changed(SourceChanged callback) = 0;

  // The engine underneath (objects by dense id, views, what the frame read).
  virtual plugin::LodCore& core() = 0;
  virtual const plugin::LodCore& core() const = 0;
};

}  // namespace gazelod
