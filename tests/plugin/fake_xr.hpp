// SPDX-License-Identifier: Apache-2.0
// A fake OpenXR runtime for the plugin's unit tests: a fake xrGetInstanceProcAddr that hands out
// fakes of exactly the functions the plugin looks up (plugin/xr_dispatch.cpp), driven by a
// script the test sets (head pose, eye gaze with its validity flags, views, failing results,
// functions withheld). No loader, no runtime, no Vulkan: the plugin takes only handles and
// xrGetInstanceProcAddr, as from an engine.
//
// The fake also checks the plugin's side: every handle it is given must be one it gave out (or
// the application's, below), a space the plugin created must be destroyed once, and one the
// application lent must never be; FakeXrLog::misuse lists each breach.
#pragma once

#include <openxr/openxr.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::test {

// The functions the plugin looks up, in plugin/xr_dispatch.cpp's order.
enum class XrFn : std::uint8_t {
  get_system_properties,
  enumerate_view_configuration_views,
  create_reference_space,
  destroy_space,
  locate_space,
  locate_views,
  string_to_path,
  create_action_set,
  destroy_action_set,
  create_action,
  suggest_interaction_profile_bindings,
  attach_session_action_sets,
  sync_actions,
  get_action_state_pose,
  create_action_space,
  enumerate_bound_sources_for_action,
  get_current_interaction_profile,
  count,
};
inline constexpr std::size_t kXrFnCount = static_cast<std::size_t>(XrFn::count);
const char* xr_fn_name(XrFn f);  // "xrLocateSpace", ...

inline constexpr XrSpaceLocationFlags kPoseTracked =
    XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT |
    XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT | XR_SPACE_LOCATION_POSITION_TRACKED_BIT;

// A pose at the origin whose -Z axis points yaw_deg to the left (+Y rotation) and pitch_deg up,
// as tests/capi/capi_test_util.hpp's object_at places objects.
XrPosef pose_looking_at(double yaw_deg, double pitch_deg = 0.0);

// What the fake runtime does; tests change it between frames.
struct FakeXrScript {
  // The head (VIEW space) in any of the application's spaces, and its velocities (given with
  // both velocity bits when head_velocity is set).
  XrPosef head = pose_looking_at(0.0);
  XrSpaceLocationFlags head_flags = kPoseTracked;
  bool head_velocity = true;
  XrVector3f head_angular_velocity{0, 0, 0};
  XrVector3f head_linear_velocity{0, 0, 0};

  // XR_EXT_eye_gaze_interaction: whether the system reports it (false: the application did not
  // enable the extension, and a suggestion for its profile is XR_ERROR_PATH_UNSUPPORTED), the
  // gaze located in VIEW space with its flags, how long before the requested time the sample was
  // taken (XrEyeGazeSampleTimeEXT), and whether the pose action is active (and bound).
  bool system_eye_gaze = true;
  XrPosef gaze = pose_looking_at(0.0);
  XrSpaceLocationFlags gaze_flags = kPoseTracked;
  XrTime gaze_latency_ns = 5'000'000;
  bool gaze_action_active = true;
  // The application attached its action sets already: suggesting and attaching are refused
  // (XR_ERROR_ACTIONSETS_ALREADY_ATTACHED).
  bool app_attached_action_sets = false;

  // PRIMARY_STEREO's views (PRIMARY_MONO has one; other configurations are unsupported).
  XrFovf fov{-0.785398f, 0.785398f, 0.785398f, -0.785398f};  // 90 x 90 deg
  std::uint32_t recommended_width_px = 1800, recommended_height_px = 1800;

  // A call whose entry is not XR_SUCCESS returns that result and does nothing else.
  std::array<XrResult, kXrFnCount> fail{};
  // Functions xrGetInstanceProcAddr does not give: it returns missing_result and a null
  // pointer (XR_SUCCESS here is an engine's hook that answers success with no function).
  std::array<bool, kXrFnCount> missing{};
  XrResult missing_result = XR_ERROR_FUNCTION_UNSUPPORTED;

  void fail_call(XrFn f, XrResult r) { fail[static_cast<std::size_t>(f)] = r; }
  void withhold(XrFn f) { missing[static_cast<std::size_t>(f)] = true; }
};

// What the plugin did.
struct FakeXrLog {
  std::array<int, kXrFnCount> calls{};
  int live_spaces = 0;                          // created by the plugin, not yet destroyed
  int live_action_sets = 0;                     // likewise
  std::vector<std::string> suggested_bindings;  // "<profile> <binding path>" per suggestion
  std::vector<std::string> misuse;              // handles the fake never gave, lent ones destroyed, ...
  std::vector<XrTime> head_locate_times;        // each head locate's time, in call order

  int count(XrFn f) const { return calls[static_cast<std::size_t>(f)]; }
};

// The fake runtime. OpenXR's entry points carry no user data, so there is one per process;
// each test starts with reset().
class FakeXr {
 public:
  static FakeXr& get();
  void reset();

  FakeXrScript script;
  FakeXrLog log;

  PFN_xrGetInstanceProcAddr get_instance_proc_addr() const;

  // The application's handles, as an engine would pass them: fixed values, so the fake tells
  // them from the ones the plugin creates.
  static constexpr std::uint64_t kInstance = 0x1001, kSystem = 0x3003, kSession = 0x2002;
  static constexpr std::uint64_t kLocal = 0x4001, kStage = 0x4002, kAppGazeSpace = 0x4003, kAppGazeAction = 0x5001;
  template <typename H>
  static H handle(std::uint64_t v) {
    return reinterpret_cast<H>(static_cast<std::uintptr_t>(v));
  }
  XrInstance instance() const { return handle<XrInstance>(kInstance); }
  XrSystemId system() const { return kSystem; }
  XrSession session() const { return handle<XrSession>(kSession); }
  XrSpace local_space() const { return handle<XrSpace>(kLocal); }  // a base space
  XrSpace stage_space() const { return handle<XrSpace>(kStage); }  // another (recentring)
  XrSpace app_gaze_space() const { return handle<XrSpace>(kAppGazeSpace); }
  XrAction app_gaze_action() const { return handle<XrAction>(kAppGazeAction); }

  // Every misuse, one a line (for a failing EXPECT's message).
  std::string misuse_text() const {
    std::string out;
    for (const std::string& m : log.misuse) out += m + "\n";
    return out;
  }
};

}  // namespace gazelod::test
