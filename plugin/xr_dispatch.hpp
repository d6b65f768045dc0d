// SPDX-License-Identifier: Apache-2.0
// The OpenXR functions the plugin calls, looked up once through the application's
// xrGetInstanceProcAddr. Engines (Unity, Unreal, Godot) load or bundle their own loader,
// sometimes privately, and may hook functions: the plugin links no loader and calls only the
// pointers the application hands it, so it sees exactly what the application sees.
#pragma once

#include <openxr/openxr.h>

namespace gazelod::plugin {

struct XrDispatch {
  PFN_xrGetInstanceProcAddr get_instance_proc_addr = nullptr;
  PFN_xrGetSystemProperties get_system_properties = nullptr;
  PFN_xrEnumerateViewConfigurationViews enumerate_view_configuration_views = nullptr;
  PFN_xrCreateReferenceSpace create_reference_space = nullptr;
  PFN_xrDestroySpace destroy_space = nullptr;
  PFN_xrLocateSpace locate_space = nullptr;
  PFN_xrLocateViews locate_views = nullptr;
  PFN_xrStringToPath string_to_path = nullptr;
  PFN_xrCreateActionSet create_action_set = nullptr;
  PFN_xrDestroyActionSet destroy_action_set = nullptr;
  PFN_xrCreateAction create_action = nullptr;
  PFN_xrSuggestInteractionProfileBindings suggest_interaction_profile_bindings = nullptr;
  PFN_xrAttachSessionActionSets attach_session_action_sets = nullptr;
  PFN_xrSyncActions sync_actions = nullptr;
  PFN_xrGetActionStatePose get_action_state_pose = nullptr;
  PFN_xrCreateActionSpace create_action_space = nullptr;
  PFN_xrEnumerateBoundSourcesForAction enumerate_bound_sources_for_action = nullptr;
  PFN_xrGetCurrentInteractionProfile get_current_interaction_profile = nullptr;
};

// Looks every function up for `instance`. Throws XrCallError (plugin/xr_check.hpp) naming the
// first function the application's xrGetInstanceProcAddr does not give.
XrDispatch load_xr_dispatch(PFN_xrGetInstanceProcAddr get_instance_proc_addr, XrInstance instance);

}  // namespace gazelod::plugin
