// SPDX-License-Identifier: Apache-2.0
// The next layer's (or the runtime's) commands the layer calls, looked up once through the
// next xrGetInstanceProcAddr when the instance is created. Only what the eye-gaze emulation
// needs; everything else the application reaches directly (xrGetInstanceProcAddr hands out
// the next pointers unchanged).
#pragma once

#include "layer/xr_headers.hpp"

#include <string>

namespace gazelod::layer {

// X(name) for each core command the layer calls: one list, so the table, its lookup and the
// check that nothing is missing cannot drift apart. Not clang-formatted: it reflows the list
// differently on each run.
// clang-format off
#define GAZELOD_LAYER_NEXT_COMMANDS(X)                                                                     \
  X(DestroyInstance) X(GetSystemProperties) X(PollEvent) X(StringToPath)                                   \
  X(CreateSession) X(DestroySession) X(WaitFrame) X(EndFrame)                                              \
  X(CreateReferenceSpace) X(CreateActionSpace) X(LocateSpace) X(LocateViews) X(DestroySpace)               \
  X(CreateActionSet) X(DestroyActionSet) X(CreateAction) X(DestroyAction)                                  \
  X(SuggestInteractionProfileBindings) X(AttachSessionActionSets) X(SyncActions)                           \
  X(GetActionStatePose) X(GetActionStateBoolean) X(GetActionStateFloat) X(GetActionStateVector2f)          \
  X(GetCurrentInteractionProfile) X(EnumerateBoundSourcesForAction) X(GetInputSourceLocalizedName)
// clang-format on

struct NextDispatch {
  PFN_xrGetInstanceProcAddr GetInstanceProcAddr = nullptr;
#define GAZELOD_LAYER_NEXT_FIELD(name) PFN_xr##name name = nullptr;
  GAZELOD_LAYER_NEXT_COMMANDS(GAZELOD_LAYER_NEXT_FIELD)
#undef GAZELOD_LAYER_NEXT_FIELD
  // XR_KHR_convert_timespec_time, when the layer enabled it (the HID source's clock).
  PFN_xrConvertTimespecTimeToTimeKHR ConvertTimespecTimeToTimeKHR = nullptr;
  // Commands the application may have (XR_KHR_locate_spaces enabled; an OpenXR 1.1 instance):
  // null when the next layer does not give them. The layer intercepts each only when it is here.
  PFN_xrLocateSpacesKHR LocateSpacesKHR = nullptr;
  PFN_xrLocateSpaces LocateSpaces = nullptr;
};

// Fills `table` from `next_gipa` for `instance`. Returns "" or the first command the next
// layer does not give (the instance is then unusable for the emulation).
std::string load_next_dispatch(PFN_xrGetInstanceProcAddr next_gipa, XrInstance instance, bool want_timespec,
                               NextDispatch& table);

}  // namespace gazelod::layer
