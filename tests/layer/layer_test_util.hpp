// SPDX-License-Identifier: Apache-2.0
// Shared by the layer's integration tests: the environment that stacks the eye-gaze layer on
// the simulated runtime (with or without the runtime's own eye gaze), synthetic traces with a
// known answer, an eye-gaze-only client rig (suggest, attach, sync, locate), and stderr capture
// for the "one log line" checks.
#pragma once

#include "gaze/gaze_sample.hpp"
#include "tests/runtime/xr_client.hpp"

#include <glm/vec3.hpp>
#include <openxr/openxr.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gazelod::layer_test {

using xrrt_test::HeadlessSession;

struct LayerSetup {
  bool runtime_eye_gaze = false;  // GAZELOD_SIM_EYE_GAZE_EXTENSION
  bool layer = true;              // XR_API_LAYER_PATH + XR_ENABLE_API_LAYERS
  std::string layer_dir;          // "" = the build tree's manifest folder
  std::string trace;              // GAZELOD_LAYER_TRACE ("" = unset: the HID tracker)
  std::string config;             // GAZELOD_LAYER_CONFIG ("" = unset)
  double duration_s = 5.0;
  bool paced = false;
};
void apply(const LayerSetup& s);

// A fresh folder under the build tree named after the running test.
std::string scratch_dir();

// A slow gaze wander (a few degrees, sinusoidal) sampled at `rate_hz` for `seconds`, with the
// samples in [blink_from_s, blink_to_s) invalid; first sample at t = 0. Written as a gazelod
// trace to `path`; returns the records as the reader gives them back.
std::vector<gaze::TraceRecord> write_trace(const std::string& path, double seconds, double rate_hz = 200.0,
                                           double blink_from_s = -1.0, double blink_to_s = -1.0);

// What the layer must serve at XrTime t when the trace's first sample sits at `first_frame_ns`
// (gazelod's replay: interpolated, the last valid sample held 150 ms).
std::optional<gaze::GazeSample> expected_gaze(const std::vector<gaze::TraceRecord>& records,
                                              std::int64_t first_frame_ns, std::int64_t t_ns);

// Runs `body` with fd 2 going to a file; returns what was written there.
std::string capture_stderr(const std::function<void()>& body);
int count_lines_with(const std::string& text, const std::string& needle);

// An application that uses only the eye-gaze interaction profile.
struct GazeRig {
  HeadlessSession hs;
  XrActionSet set = XR_NULL_HANDLE;
  XrAction gaze = XR_NULL_HANDLE;
  XrSpace gaze_space = XR_NULL_HANDLE, view = XR_NULL_HANDLE, local = XR_NULL_HANDLE;
  XrPath eyes = XR_NULL_PATH, profile = XR_NULL_PATH, pose_path = XR_NULL_PATH;
  XrBool32 supported = XR_FALSE;
  XrTime first_frame = 0;

  // Enabled at create besides XR_EXT_eye_gaze_interaction (and XR_MND_headless).
  std::vector<const char*> extensions;

  // With `extras`: a boolean action and a pose action in the same set, neither bound to the
  // eye-gaze profile, both listing /user/eyes_ext and /user/hand/left as subaction paths.
  XrAction button = XR_NULL_HANDLE, other_pose = XR_NULL_HANDLE;

  // Instance (eye gaze + headless), system check, action set / action / binding, attach, spaces,
  // begin. `eyes_subaction`: the action lists /user/eyes_ext as a subaction path.
  void create(bool eyes_subaction = false, bool extras = false);
  XrResult sync(XrPath subaction);
  XrTime frame();  // wait, begin, end (no layers); records the first predicted display time
  XrResult sync();
  bool active(XrPath subaction = XR_NULL_PATH);
  struct Located {
    XrSpaceLocationFlags flags = 0;
    XrPosef pose{};
    XrTime sample_time = -1;
    XrSpaceVelocityFlags velocity_flags = 0;
  };
  Located locate(XrSpace space, XrSpace base, XrTime t);
  // Every event queued now; returns how many were XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED.
  int drain_profile_events();
  XrPath current_profile();
  void destroy() { hs.destroy(); }
};

glm::dvec3 direction_of(const XrPosef& pose);  // the pose's -Z
double angle_rad(const glm::dvec3& a, const glm::dvec3& b);

}  // namespace gazelod::layer_test
