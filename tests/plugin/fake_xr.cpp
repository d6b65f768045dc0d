// SPDX-License-Identifier: Apache-2.0
// The fake OpenXR runtime behind tests/plugin/fake_xr.hpp: each fake counts its call, returns
// the script's failure if there is one, checks the handles it is given, then answers from the
// script.
#include "tests/plugin/fake_xr.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <set>

namespace gazelod::test {
namespace {

constexpr std::uint64_t kInstance = FakeXr::kInstance, kSystem = FakeXr::kSystem, kSession = FakeXr::kSession;
constexpr std::uint64_t kLocal = FakeXr::kLocal, kStage = FakeXr::kStage, kAppGazeSpace = FakeXr::kAppGazeSpace;
constexpr std::uint64_t kAppGazeAction = FakeXr::kAppGazeAction;
constexpr std::uint64_t kFirstCreated = 0x10000;  // the plugin's handles count from here

template <typename H>
std::uint64_t value(H h) {
  return static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(h));
}

enum class SpaceKind { base, view, gaze };

// What the plugin created and what the fake knows by name; reset with the script.
struct World {
  std::uint64_t next = kFirstCreated;
  std::map<std::uint64_t, SpaceKind> created_spaces;
  std::set<std::uint64_t> action_sets, actions;
  std::vector<std::string> paths;  // XrPath p is paths[p - 1]
  bool plugin_attached = false;
};

World& world() {
  static World w;
  return w;
}

FakeXrScript& script() {
  return FakeXr::get().script;
}
FakeXrLog& log() {
  return FakeXr::get().log;
}

void misuse(const std::string& what) {
  log().misuse.push_back(what);
}

bool known_action(XrAction a);

// Each fake starts here: counts the call, gives the script's failure for it, then checks the
// handle the call takes (XR_SUCCESS: go on).
XrResult enter(XrFn f) {
  ++log().calls[static_cast<std::size_t>(f)];
  return script().fail[static_cast<std::size_t>(f)];
}
XrResult refuse(XrFn f, const char* what) {
  misuse(std::string(xr_fn_name(f)) + ": " + what);
  return XR_ERROR_HANDLE_INVALID;
}
XrResult enter(XrFn f, XrInstance i) {
  const XrResult r = enter(f);
  if (XR_FAILED(r) || value(i) == kInstance) return r;
  return refuse(f, "not the application's XrInstance");
}
XrResult enter(XrFn f, XrSession s) {
  const XrResult r = enter(f);
  if (XR_FAILED(r) || value(s) == kSession) return r;
  return refuse(f, "not the application's XrSession");
}
XrResult enter(XrFn f, XrSession s, XrAction a) {
  const XrResult r = enter(f, s);
  if (XR_FAILED(r) || known_action(a)) return r;
  return refuse(f, "an action neither the plugin nor the application created");
}

// The kind of a live space, or a misuse.
bool space_kind(XrSpace s, const char* call, SpaceKind& kind) {
  const std::uint64_t v = value(s);
  const auto it = world().created_spaces.find(v);
  if (v == kLocal || v == kStage)
    kind = SpaceKind::base;
  else if (v == kAppGazeSpace)
    kind = SpaceKind::gaze;
  else if (it != world().created_spaces.end())
    kind = it->second;
  else
    misuse(std::string(call) + ": space " + std::to_string(v) + " was never created or is destroyed");
  return v == kLocal || v == kStage || v == kAppGazeSpace || it != world().created_spaces.end();
}

XrSpace new_space(SpaceKind kind) {
  const std::uint64_t v = world().next++;
  world().created_spaces[v] = kind;
  ++log().live_spaces;
  return FakeXr::handle<XrSpace>(v);
}

bool known_action(XrAction a) {
  return value(a) == kAppGazeAction || world().actions.count(value(a)) != 0;
}

// The XrStructureType a `next` chain entry starts with, or null.
template <typename T>
T* find_next(const void* next, XrStructureType type) {
  for (auto* s = static_cast<const XrBaseInStructure*>(next); s != nullptr; s = s->next)
    if (s->type == type) return reinterpret_cast<T*>(const_cast<XrBaseInStructure*>(s));
  return nullptr;
}

XRAPI_ATTR XrResult XRAPI_CALL get_system_properties(XrInstance instance, XrSystemId system, XrSystemProperties* p) {
  if (XrResult r = enter(XrFn::get_system_properties, instance); XR_FAILED(r)) return r;
  if (system != kSystem) return XR_ERROR_SYSTEM_INVALID;
  p->systemId = system;
  auto* eye =
      find_next<XrSystemEyeGazeInteractionPropertiesEXT>(p->next, XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT);
  if (eye != nullptr) eye->supportsEyeGazeInteraction = script().system_eye_gaze ? XR_TRUE : XR_FALSE;
  return XR_SUCCESS;
}

// The views of a configuration, by OpenXR's two-call idiom: the count always, the elements when
// `capacity` asks for them (XR_SUCCESS with capacity > 0: write *count of them).
XrResult count_views(XrViewConfigurationType type, std::uint32_t capacity, std::uint32_t* count) {
  const bool stereo = type == XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  if (!stereo && type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
  *count = stereo ? 2 : 1;
  return capacity != 0 && capacity < *count ? XR_ERROR_SIZE_INSUFFICIENT : XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL enumerate_view_configuration_views(XrInstance instance, XrSystemId system,
                                                                  XrViewConfigurationType type, std::uint32_t capacity,
                                                                  std::uint32_t* count, XrViewConfigurationView* out) {
  if (XrResult r = enter(XrFn::enumerate_view_configuration_views, instance); XR_FAILED(r)) return r;
  if (system != kSystem) return XR_ERROR_SYSTEM_INVALID;
  if (XrResult r = count_views(type, capacity, count); XR_FAILED(r) || capacity == 0) return r;
  for (std::uint32_t i = 0; i < *count; ++i) {
    out[i].recommendedImageRectWidth = script().recommended_width_px;
    out[i].recommendedImageRectHeight = script().recommended_height_px;
    out[i].recommendedSwapchainSampleCount = 1;
  }
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL create_reference_space(XrSession session, const XrReferenceSpaceCreateInfo* info,
                                                      XrSpace* space) {
  if (XrResult r = enter(XrFn::create_reference_space, session); XR_FAILED(r)) return r;
  *space = new_space(info->referenceSpaceType == XR_REFERENCE_SPACE_TYPE_VIEW ? SpaceKind::view : SpaceKind::base);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL destroy_space(XrSpace space) {
  if (XrResult r = enter(XrFn::destroy_space); XR_FAILED(r)) return r;
  const std::uint64_t v = value(space);
  if (v == kLocal || v == kStage || v == kAppGazeSpace) {
    misuse("xrDestroySpace: destroyed a space the application lent (" + std::to_string(v) + ")");
    return XR_SUCCESS;
  }
  if (world().created_spaces.erase(v) == 0) {
    misuse("xrDestroySpace: space " + std::to_string(v) + " was never created or is destroyed");
    return XR_ERROR_HANDLE_INVALID;
  }
  --log().live_spaces;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL locate_space(XrSpace space, XrSpace base, XrTime time, XrSpaceLocation* loc) {
  if (XrResult r = enter(XrFn::locate_space); XR_FAILED(r)) return r;
  SpaceKind what{}, in{};
  if (!space_kind(space, "xrLocateSpace(space)", what) || !space_kind(base, "xrLocateSpace(baseSpace)", in))
    return XR_ERROR_HANDLE_INVALID;
  const FakeXrScript& s = script();
  if (what == SpaceKind::view && in == SpaceKind::base) {
    log().head_locate_times.push_back(time);
    loc->pose = s.head;
    loc->locationFlags = s.head_flags;
    if (auto* v = find_next<XrSpaceVelocity>(loc->next, XR_TYPE_SPACE_VELOCITY)) {
      v->velocityFlags = s.head_velocity ? XR_SPACE_VELOCITY_LINEAR_VALID_BIT | XR_SPACE_VELOCITY_ANGULAR_VALID_BIT : 0;
      v->angularVelocity = s.head_angular_velocity;
      v->linearVelocity = s.head_linear_velocity;
    }
    return XR_SUCCESS;
  }
  if (what == SpaceKind::gaze && in == SpaceKind::view) {
    loc->pose = s.gaze;
    loc->locationFlags = s.gaze_flags;
    if (auto* t = find_next<XrEyeGazeSampleTimeEXT>(loc->next, XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT))
      t->time = (s.gaze_flags & XR_SPACE_LOCATION_ORIENTATION_VALID_BIT) ? time - s.gaze_latency_ns : 0;
    return XR_SUCCESS;
  }
  misuse("xrLocateSpace: a pair of spaces the plugin has no reason to relate");
  return XR_ERROR_VALIDATION_FAILURE;
}

XRAPI_ATTR XrResult XRAPI_CALL locate_views(XrSession session, const XrViewLocateInfo* info, XrViewState* state,
                                            std::uint32_t capacity, std::uint32_t* count, XrView* views) {
  if (XrResult r = enter(XrFn::locate_views, session); XR_FAILED(r)) return r;
  SpaceKind in{};
  if (!space_kind(info->space, "xrLocateViews(space)", in)) return XR_ERROR_HANDLE_INVALID;
  if (XrResult r = count_views(info->viewConfigurationType, capacity, count); XR_FAILED(r) || capacity == 0) return r;
  const std::uint32_t n = *count;
  state->viewStateFlags = kPoseTracked;
  for (std::uint32_t i = 0; i < n; ++i) {
    views[i].fov = script().fov;
    views[i].pose = pose_looking_at(0.0);
    views[i].pose.position.x = n == 1 ? 0.0f : (i == 0 ? -0.032f : 0.032f);  // in VIEW space: the eyes
  }
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL string_to_path(XrInstance instance, const char* s, XrPath* path) {
  if (XrResult r = enter(XrFn::string_to_path, instance); XR_FAILED(r)) return r;
  std::vector<std::string>& paths = world().paths;
  auto it = std::find(paths.begin(), paths.end(), s);
  if (it == paths.end()) it = paths.insert(it, s);
  *path = static_cast<XrPath>(it - paths.begin()) + 1;
  return XR_SUCCESS;
}

std::string path_string(XrPath p) {
  return p >= 1 && p <= world().paths.size() ? world().paths[p - 1] : "(unknown path)";
}

XRAPI_ATTR XrResult XRAPI_CALL create_action_set(XrInstance instance, const XrActionSetCreateInfo*, XrActionSet* set) {
  if (XrResult r = enter(XrFn::create_action_set, instance); XR_FAILED(r)) return r;
  const std::uint64_t v = world().next++;
  world().action_sets.insert(v);
  ++log().live_action_sets;
  *set = FakeXr::handle<XrActionSet>(v);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL destroy_action_set(XrActionSet set) {
  if (XrResult r = enter(XrFn::destroy_action_set); XR_FAILED(r)) return r;
  if (world().action_sets.erase(value(set)) == 0) {
    misuse("xrDestroyActionSet: an action set never created or destroyed already");
    return XR_ERROR_HANDLE_INVALID;
  }
  --log().live_action_sets;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL create_action(XrActionSet set, const XrActionCreateInfo* info, XrAction* action) {
  if (XrResult r = enter(XrFn::create_action); XR_FAILED(r)) return r;
  if (world().action_sets.count(value(set)) == 0) {
    misuse("xrCreateAction: an action set never created");
    return XR_ERROR_HANDLE_INVALID;
  }
  if (info->actionType != XR_ACTION_TYPE_POSE_INPUT) misuse("xrCreateAction: eye gaze is a pose action");
  const std::uint64_t v = world().next++;
  world().actions.insert(v);
  *action = FakeXr::handle<XrAction>(v);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL suggest_bindings(XrInstance instance, const XrInteractionProfileSuggestedBinding* s) {
  if (XrResult r = enter(XrFn::suggest_interaction_profile_bindings, instance); XR_FAILED(r)) return r;
  if (script().app_attached_action_sets) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
  // A runtime without the extension enabled does not know the eye-gaze profile.
  if (!script().system_eye_gaze) return XR_ERROR_PATH_UNSUPPORTED;
  for (std::uint32_t i = 0; i < s->countSuggestedBindings; ++i)
    log().suggested_bindings.push_back(path_string(s->interactionProfile) + " " +
                                       path_string(s->suggestedBindings[i].binding));
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL attach_action_sets(XrSession session, const XrSessionActionSetsAttachInfo* info) {
  if (XrResult r = enter(XrFn::attach_session_action_sets, session); XR_FAILED(r)) return r;
  if (script().app_attached_action_sets || world().plugin_attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
  for (std::uint32_t i = 0; i < info->countActionSets; ++i)
    if (world().action_sets.count(value(info->actionSets[i])) == 0) misuse("xrAttachSessionActionSets: unknown set");
  world().plugin_attached = true;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL sync_actions(XrSession session, const XrActionsSyncInfo* info) {
  if (XrResult r = enter(XrFn::sync_actions, session); XR_FAILED(r)) return r;
  if (!world().plugin_attached) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
  for (std::uint32_t i = 0; i < info->countActiveActionSets; ++i)
    if (world().action_sets.count(value(info->activeActionSets[i].actionSet)) == 0)
      misuse("xrSyncActions: unknown action set");
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL get_action_state_pose(XrSession session, const XrActionStateGetInfo* info,
                                                     XrActionStatePose* state) {
  if (XrResult r = enter(XrFn::get_action_state_pose, session, info->action); XR_FAILED(r)) return r;
  state->isActive = script().gaze_action_active ? XR_TRUE : XR_FALSE;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL create_action_space(XrSession session, const XrActionSpaceCreateInfo* info,
                                                   XrSpace* space) {
  if (XrResult r = enter(XrFn::create_action_space, session, info->action); XR_FAILED(r)) return r;
  *space = new_space(SpaceKind::gaze);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL enumerate_bound_sources(XrSession session, const XrBoundSourcesForActionEnumerateInfo*,
                                                       std::uint32_t, std::uint32_t* count, XrPath*) {
  if (XrResult r = enter(XrFn::enumerate_bound_sources_for_action, session); XR_FAILED(r)) return r;
  *count = script().gaze_action_active ? 1 : 0;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL get_current_interaction_profile(XrSession session, XrPath,
                                                               XrInteractionProfileState* state) {
  if (XrResult r = enter(XrFn::get_current_interaction_profile, session); XR_FAILED(r)) return r;
  state->interactionProfile = XR_NULL_PATH;
  return XR_SUCCESS;
}

template <typename F>
PFN_xrVoidFunction fn(F f) {
  return reinterpret_cast<PFN_xrVoidFunction>(f);
}

// XrFn's names and fakes, in its order.
struct Entry {
  const char* name;
  PFN_xrVoidFunction function;
};
const Entry kEntries[kXrFnCount] = {
    {"xrGetSystemProperties", fn(get_system_properties)},
    {"xrEnumerateViewConfigurationViews", fn(enumerate_view_configuration_views)},
    {"xrCreateReferenceSpace", fn(create_reference_space)},
    {"xrDestroySpace", fn(destroy_space)},
    {"xrLocateSpace", fn(locate_space)},
    {"xrLocateViews", fn(locate_views)},
    {"xrStringToPath", fn(string_to_path)},
    {"xrCreateActionSet", fn(create_action_set)},
    {"xrDestroyActionSet", fn(destroy_action_set)},
    {"xrCreateAction", fn(create_action)},
    {"xrSuggestInteractionProfileBindings", fn(suggest_bindings)},
    {"xrAttachSessionActionSets", fn(attach_action_sets)},
    {"xrSyncActions", fn(sync_actions)},
    {"xrGetActionStatePose", fn(get_action_state_pose)},
    {"xrCreateActionSpace", fn(create_action_space)},
    {"xrEnumerateBoundSourcesForAction", fn(enumerate_bound_sources)},
    {"xrGetCurrentInteractionProfile", fn(get_current_interaction_profile)},
};

XRAPI_ATTR XrResult XRAPI_CALL fake_get_instance_proc_addr(XrInstance instance, const char* name,
                                                           PFN_xrVoidFunction* function) {
  *function = nullptr;
  if (value(instance) != kInstance) {
    misuse("xrGetInstanceProcAddr: not the application's XrInstance");
    return XR_ERROR_HANDLE_INVALID;
  }
  for (std::size_t i = 0; i < kXrFnCount; ++i) {
    if (std::strcmp(name, kEntries[i].name) != 0) continue;
    if (script().missing[i]) return script().missing_result;
    *function = kEntries[i].function;
    return XR_SUCCESS;
  }
  return XR_ERROR_FUNCTION_UNSUPPORTED;  // a function the plugin should not need
}

}  // namespace

const char* xr_fn_name(XrFn f) {
  return kEntries[static_cast<std::size_t>(f)].name;
}

XrPosef pose_looking_at(double yaw_deg, double pitch_deg) {
  const double to_rad = std::numbers::pi / 180.0;
  const glm::dquat q =
      glm::angleAxis(yaw_deg * to_rad, glm::dvec3(0, 1, 0)) * glm::angleAxis(pitch_deg * to_rad, glm::dvec3(1, 0, 0));
  XrPosef p{};
  p.orientation = {static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z), static_cast<float>(q.w)};
  return p;
}

FakeXr& FakeXr::get() {
  static FakeXr fake;
  return fake;
}

void FakeXr::reset() {
  script = FakeXrScript{};
  log = FakeXrLog{};
  world() = World{};
}

PFN_xrGetInstanceProcAddr FakeXr::get_instance_proc_addr() const {
  return fake_get_instance_proc_addr;
}

}  // namespace gazelod::test
