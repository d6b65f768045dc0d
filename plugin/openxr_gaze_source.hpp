// SPDX-License-Identifier: Apache-2.0
// Eye gaze from the OpenXR runtime through XR_EXT_eye_gaze_interaction, as a GazeSource.
// The application owns actions (a session attaches action sets once; a second suggestion for a
// profile replaces the first), so the source works in the mode the application chooses:
//   app_space       the application's own eye-gaze action space: only located here
//   merge_binding   an action set and pose action of ours, whose binding the application
//                   merges into its own suggestion, attach and sync calls
//   plugin_actions  for applications without actions: we suggest, attach and sync our set
// Gaze is located in VIEW space (head space) at the requested time.
#pragma once

#include "gaze/gaze_source.hpp"
#include "plugin/xr_dispatch.hpp"

#include <openxr/openxr.h>

#include <cstdint>
#include <optional>
#include <string>

namespace gazelod::plugin {

// Whether the system advertises eye-gaze interaction (XrSystemEyeGazeInteractionPropertiesEXT).
bool system_supports_eye_gaze(const XrDispatch& xr, XrInstance instance, XrSystemId system);

enum class GazeInputMode { app_space, merge_binding, plugin_actions };

class OpenXrGazeSource final : public gaze::GazeSource {
 public:
  // app_space: gaze_space (and optionally gaze_action) are the application's, not owned.
  // Otherwise creates the action set "gazelod_eye_gaze" with one pose action; plugin_actions
  // also suggests its binding. Throws XrCallError naming the failing call and the remedy.
  OpenXrGazeSource(const XrDispatch& xr, XrInstance instance, XrSession session, GazeInputMode mode,
                   XrSpace gaze_space = XR_NULL_HANDLE, XrAction gaze_action = XR_NULL_HANDLE);
  ~OpenXrGazeSource() override;
  OpenXrGazeSource(const OpenXrGazeSource&) = delete;
  OpenXrGazeSource& operator=(const OpenXrGazeSource&) = delete;

  GazeInputMode mode() const { return mode_; }
  // merge_binding: the set and action to merge (XR_NULL_HANDLE in app_space mode).
  XrActionSet action_set() const { return action_set_; }
  XrAction action() const { return gaze_action_; }
  // merge_binding: after the application's xrAttachSessionActionSets (creates the action space).
  void action_sets_attached();
  // plugin_actions: attaches our set (fails with the remedy when the application attached
  // sets already) and syncs it before each locate.
  void attach_and_own_sync();
  // app_space: the application's gaze space (and action) given or replaced after creation.
  void set_app_space(XrSpace gaze_space, XrAction gaze_action);
  // Releases what we created (spaces, the action set). Safe twice.
  void release();

  std::string name() const override { return "openxr"; }
  std::optional<gaze::GazeSample> sample_at(std::int64_t t_ns) override;
  std::string status() const override { return status_; }

  // How the runtime fills XrEyeGazeSampleTimeEXT, as last seen: "true sample time",
  // "zero (untrusted; using the requested time)" or "requested time (untrusted)".
  const std::string& sample_time_quality() const { return sample_time_quality_; }

 private:
  void create(XrSpace gaze_space, XrAction gaze_action);  // the constructor's OpenXR calls
  void create_space();
  void check_binding();

  const XrDispatch& xr_;
  XrInstance instance_;
  XrSession session_;
  GazeInputMode mode_;
  XrActionSet action_set_ = XR_NULL_HANDLE;
  XrAction gaze_action_ = XR_NULL_HANDLE;
  XrSpace gaze_space_ = XR_NULL_HANDLE;
  XrSpace view_space_ = XR_NULL_HANDLE;
  bool own_sync_ = false;
  bool attached_ = false;
  bool ever_delivered_ = false;
  int inactive_calls_ = 0;
  bool binding_lost_ = false;
  std::string status_ = "not attached";
  std::string sample_time_quality_ = "unknown";
};

}  // namespace gazelod::plugin
