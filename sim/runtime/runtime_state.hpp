// SPDX-License-Identifier: Apache-2.0
// The simulated OpenXR runtime's objects (instance, session, space, action set, action,
// swapchain) and the handle registry that turns handles into objects, so that an invalid or
// destroyed handle gets XR_ERROR_HANDLE_INVALID as the OpenXR 1.0 specification requires.
#pragma once

#include "sim/runtime/xr_headers.hpp"
#include "sim/runtime/path_table.hpp"
#include "sim/runtime/scenario_source.hpp"
#include "sim/runtime/sim_clock.hpp"
#include "sim/simulator.hpp"

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

namespace gazelod::xrrt {

// One lock for the whole runtime: calls are short, and xrWaitFrame sleeps without it.
std::mutex& runtime_mutex();

struct Instance {
  std::uint64_t id = 0;
  bool ext_vulkan = false, ext_vulkan2 = false, ext_headless = false, ext_eye_gaze = false, ext_automation = false,
       ext_timespec = false, ext_simulator_state = false, ext_locate_spaces = false;
  std::string app_name;
  std::unique_ptr<sim::Simulator> simulator;
  SimClock clock;
  RuntimeFaults faults;  // injected from the environment (scenario_source.hpp)
  PathTable paths;
  std::deque<XrEventDataBuffer> events;
  bool graphics_requirements_queried = false;
  VkInstance vk_instance = VK_NULL_HANDLE;  // from xrGetVulkanGraphicsDevice(2)KHR
  VkPhysicalDevice vk_physical_device = VK_NULL_HANDLE;
  bool system_queried = false;
  // Suggested bindings per interaction profile path: (action id, binding path).
  std::map<XrPath, std::vector<std::pair<std::uint64_t, XrPath>>> suggested;
};

struct InputDevice {  // one top-level user path, as XR_EXT_conformance_automation drives it
  bool active = false;
  XrPath profile = XR_NULL_PATH;  // current interaction profile, XR_NULL_PATH when none
  // A change asked for (xrSetInputDeviceActiveEXT, an eye tracker found at attach); the
  // current profile changes, with its event, only in xrSyncActions (OpenXR 1.0 section 11.4).
  bool change_pending = false;
  bool pending_active = false;
  XrPath pending_profile = XR_NULL_PATH;
  // Whether the device is switched on now: tracking follows this at once, the current
  // interaction profile only at the next xrSyncActions.
  bool switched_on() const { return change_pending ? pending_active : active; }
  std::map<XrPath, bool> bools;
  std::map<XrPath, float> floats;
  std::map<XrPath, XrVector2f> vec2s;
  struct Location {
    std::uint64_t space_id = 0;
    XrPosef pose{};
  };
  std::map<XrPath, Location> locations;
};

struct SourceValue {   // one bound input source's value at a sync
  float value = 0.0f;  // bool as 0 / 1, float as is
  XrVector2f vec2{0.0f, 0.0f};
};

struct ActionState {  // one action after xrSyncActions: a value per active bound source
  std::map<XrPath, SourceValue> current, previous;
  XrTime last_change_time = 0;
};

struct Session {
  std::uint64_t id = 0;
  std::uint64_t instance_id = 0;
  XrSessionState state = XR_SESSION_STATE_UNKNOWN;
  XrTime last_event_time = 0;
  bool running = false;
  bool exit_requested = false;  // xrRequestExitSession or the scenario's end
  bool headless = false;
  bool scenario_ended = false;  // the stop was started by the scenario's end
  bool lost = false;            // injected session loss (RuntimeFaults): frame calls fail
  XrViewConfigurationType view_config = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  // Vulkan binding (XR_KHR_vulkan_enable(2)); null when headless.
  VkInstance vk_instance = VK_NULL_HANDLE;
  VkPhysicalDevice vk_physical_device = VK_NULL_HANDLE;
  VkDevice vk_device = VK_NULL_HANDLE;
  std::uint32_t vk_queue_family = 0, vk_queue_index = 0;
  // Frame loop.
  std::int64_t last_vsync_index = -1;  // index k of the last xrWaitFrame (display at k + 1)
  std::uint64_t wait_frame_calls = 0;
  int waited_frames = 0;  // xrWaitFrame calls not yet matched by xrBeginFrame
  bool frame_begun = false;
  XrTime last_predicted_time = 0;
  std::uint64_t frames_submitted = 0;  // successful xrEndFrame calls
  std::uint64_t layers_submitted = 0;
  std::vector<XrSubmittedLayerGAZELOD> last_layers;  // of the last successful xrEndFrame
  // Actions.
  bool actions_attached = false;
  std::vector<std::uint64_t> attached_sets;
  std::map<XrPath, InputDevice> devices;               // by top-level user path
  std::map<std::uint64_t, ActionState> action_states;  // by action id
  XrTime last_sync_time = 0;
  std::vector<std::uint64_t> synced_sets;  // active sets of the last xrSyncActions
};

// What a space is attached to.
enum class SpaceKind : std::uint8_t { reference, action };

struct Space {
  std::uint64_t id = 0;
  std::uint64_t session_id = 0;
  SpaceKind kind = SpaceKind::reference;
  XrReferenceSpaceType reference = XR_REFERENCE_SPACE_TYPE_LOCAL;
  std::uint64_t action_id = 0;
  XrPath subaction = XR_NULL_PATH;
  XrPosef offset{};  // pose in the reference or action space
  // The input source an action space follows, chosen when it is first located: it keeps
  // following that device (the conformance suite expects a space to stick to one device), and
  // stays locatable through it after its action is destroyed. A cache of locating, hence mutable.
  mutable XrPath followed_source = XR_NULL_PATH;
};

struct ActionSet {
  std::uint64_t id = 0;
  std::uint64_t instance_id = 0;
  std::string name, localized_name;
  std::uint32_t priority = 0;
  bool attached = false;  // to any session: the set and its actions are then immutable
  // Every subaction path its actions declared, destroyed actions' too (xrSyncActions accepts
  // exactly these for the set).
  std::vector<XrPath> subaction_paths;
};

struct Action {
  std::uint64_t id = 0;
  std::uint64_t set_id = 0;
  std::uint64_t instance_id = 0;
  std::string name, localized_name;
  XrActionType type = XR_ACTION_TYPE_BOOLEAN_INPUT;
  std::vector<XrPath> subaction_paths;
};

struct SwapchainImage {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  bool laid_out = false;  // moved to the attachment layout (at its first acquire)
};

struct Swapchain {
  std::uint64_t id = 0;
  std::uint64_t session_id = 0;
  XrSwapchainCreateInfo info{};
  std::vector<SwapchainImage> images;
  std::deque<std::uint32_t> acquired;  // acquired, oldest first
  bool waited = false;                 // the oldest acquired image has been waited on
  std::uint32_t next_index = 0;
  bool released_once = false;
  bool static_acquired = false;  // XR_SWAPCHAIN_CREATE_STATIC_IMAGE_BIT used up
};

// Handle registry. Handles are opaque integers (never pointers), so a stale handle can never
// be dereferenced; each type has its own table.
template <class T>
struct Registry {
  std::unordered_map<std::uint64_t, std::unique_ptr<T>> live;
  T* find(std::uint64_t id) const {
    auto it = live.find(id);
    return it == live.end() ? nullptr : it->second.get();
  }
};

struct Runtime {
  std::uint64_t next_id = 1;
  Registry<Instance> instances;
  Registry<Session> sessions;
  Registry<Space> spaces;
  Registry<ActionSet> action_sets;
  Registry<Action> actions;
  Registry<Swapchain> swapchains;
};
Runtime& runtime();  // callers hold runtime_mutex()

template <class H>
std::uint64_t handle_id(H handle) {
  return static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(handle));
}
template <class H>
H to_handle(std::uint64_t id) {
  return reinterpret_cast<H>(static_cast<std::uintptr_t>(id));
}

Instance* find_instance(XrInstance h);
Session* find_session(XrSession h);
Space* find_space(XrSpace h);
ActionSet* find_action_set(XrActionSet h);
Action* find_action(XrAction h);
Swapchain* find_swapchain(XrSwapchain h);
Instance* instance_of(const Session& session);

// Destroys an object and every child the specification says goes with it.
void destroy_swapchain(std::uint64_t id);
void destroy_session(std::uint64_t id);
void destroy_action_set(std::uint64_t id);
void destroy_instance(std::uint64_t id);

// Runs an entry point's body, turning any C++ exception into XR_ERROR_RUNTIME_FAILURE so none
// crosses the C ABI.
template <class F>
XrResult guarded(F&& body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return XR_ERROR_OUT_OF_MEMORY;
  } catch (...) {
    return XR_ERROR_RUNTIME_FAILURE;
  }
}

// The two-call idiom (capacity 0 asks for the count; too small a buffer is
// XR_ERROR_SIZE_INSUFFICIENT with the count written).
template <class T>
XrResult two_call(std::uint32_t capacity, std::uint32_t* count, T* out, const std::vector<T>& items) {
  if (count == nullptr) return XR_ERROR_VALIDATION_FAILURE;
  *count = static_cast<std::uint32_t>(items.size());
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < items.size()) return XR_ERROR_SIZE_INSUFFICIENT;
  if (out == nullptr) return XR_ERROR_VALIDATION_FAILURE;
  for (std::size_t i = 0; i < items.size(); ++i) out[i] = items[i];
  return XR_SUCCESS;
}
XrResult two_call_string(std::uint32_t capacity, std::uint32_t* count, char* out, const std::string& s);

}  // namespace gazelod::xrrt
