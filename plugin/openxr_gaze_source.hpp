// Eye gaze from the OpenXR runtime through XR_EXT_eye_gaze_interaction, as a GazeSource.
// Follows the extension's rules: the action set is attached before the action space is
// created; gaze is located in VIEW space (head space) at the requested time.
#pragma once

#include "gaze/gaze_source.hpp"

#include <openxr/openxr.h>

#include <cstdint>
#include <string>

namespace gazelod::plugin {

// Whether the system advertises eye-gaze interaction (XrSystemEyeGazeInteractionPropertiesEXT).
bool system_supports_eye_gaze(XrInstance instance, XrSystemId system);

class OpenXrGazeSource final : public gaze::GazeSource {
 public:
  // Creates the action set "gazelod_eye_gaze" with one pose action and suggests the
  // /interaction_profiles/ext/eye_gaze_interaction binding. The instance must have enabled
  // XR_EXT_eye_gaze_interaction. Throws std::runtime_error naming the failing call.
  OpenXrGazeSource(XrInstance instance, XrSession session);
  ~OpenXrGazeSource() override;
  OpenXrGazeSource(const OpenXrGazeSource&) = delete;
  OpenXrGazeSource& operator=(const OpenXrGazeSource&) = delete;

  // For applications with their own action sets: include this set in their single
  // xrAttachSessionActionSets call and in every xrSyncActions, then call
  // action_sets_attached(). Applications without actions call attach_and_own_sync(): the
  // source then attaches its set itself and calls xrSyncActions before each locate.
  XrActionSet action_set() const { return action_set_; }
  void action_sets_attached();
  void attach_and_own_sync();

  std::string name() const override { return "openxr"; }
  std::optional<gaze::GazeSample> sample_at(std::int64_t t_ns) override;
  std::string status() const override { return status_; }

  // True once the runtime delivered at least one valid gaze pose.
  // How the runtime fills XrEyeGazeSampleTimeEXT, as last seen: "true sample time",
  // "zero (untrusted; using the requested time)" or "requested time (untrusted)".
  const std::string& sample_time_quality() const { return sample_time_quality_; }

 private:
  void create_space();

  XrInstance instance_;
  XrSession session_;
  XrActionSet action_set_ = XR_NULL_HANDLE;
  XrAction gaze_action_ = XR_NULL_HANDLE;
  XrSpace gaze_space_ = XR_NULL_HANDLE;
  XrSpace view_space_ = XR_NULL_HANDLE;
  bool own_sync_ = false;
  bool ever_delivered_ = false;
  std::string status_ = "not attached";
  std::string sample_time_quality_ = "unknown";
};

}  // namespace gazelod::plugin
