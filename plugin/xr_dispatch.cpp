// SPDX-License-Identifier: Apache-2.0
// Looks the plugin's OpenXR functions up through the application's xrGetInstanceProcAddr.
#include "plugin/xr_dispatch.hpp"

#include "plugin/xr_check.hpp"

#include <string>

namespace gazelod::plugin {
namespace {

template <typename Pfn>
void load(PFN_xrGetInstanceProcAddr gipa, XrInstance instance, const char* name, Pfn& out) {
  PFN_xrVoidFunction f = nullptr;
  const XrResult r = gipa(instance, name, &f);
  if (XR_FAILED(r) || f == nullptr)
    throw XrCallError(std::string("gazelod: xrGetInstanceProcAddr(\"") + name + "\") gave no function (" +
                          xr_result_name(r) +
                          "); pass the application's own xrGetInstanceProcAddr and a live XrInstance",
                      XR_FAILED(r) ? r : XR_ERROR_FUNCTION_UNSUPPORTED);
  out = reinterpret_cast<Pfn>(f);
}

}  // namespace

XrDispatch load_xr_dispatch(PFN_xrGetInstanceProcAddr gipa, XrInstance instance) {
  if (gipa == nullptr)
    throw XrCallError("gazelod: no xrGetInstanceProcAddr given; pass the application's (or the engine's) pointer",
                      XR_ERROR_VALIDATION_FAILURE);
  XrDispatch d;
  d.get_instance_proc_addr = gipa;
  load(gipa, instance, "xrGetSystemProperties", d.get_system_properties);
  load(gipa, instance, "xrEnumerateViewConfigurationViews", d.enumerate_view_configuration_views);
  load(gipa, instance, "xrCreateReferenceSpace", d.create_reference_space);
  load(gipa, instance, "xrDestroySpace", d.destroy_space);
  load(gipa, instance, "xrLocateSpace", d.locate_space);
  load(gipa, instance, "xrLocateViews", d.locate_views);
  load(gipa, instance, "xrStringToPath", d.string_to_path);
  load(gipa, instance, "xrCreateActionSet", d.create_action_set);
  load(gipa, instance, "xrDestroyActionSet", d.destroy_action_set);
  load(gipa, instance, "xrCreateAction", d.create_action);
  load(gipa, instance, "xrSuggestInteractionProfileBindings", d.suggest_interaction_profile_bindings);
  load(gipa, instance, "xrAttachSessionActionSets", d.attach_session_action_sets);
  load(gipa, instance, "xrSyncActions", d.sync_actions);
  load(gipa, instance, "xrGetActionStatePose", d.get_action_state_pose);
  load(gipa, instance, "xrCreateActionSpace", d.create_action_space);
  load(gipa, instance, "xrEnumerateBoundSourcesForAction", d.enumerate_bound_sources_for_action);
  load(gipa, instance, "xrGetCurrentInteractionProfile", d.get_current_interaction_profile);
  return d;
}

}  // namespace gazelod::plugin
