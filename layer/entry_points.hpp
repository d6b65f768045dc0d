// SPDX-License-Identifier: Apache-2.0
// Every OpenXR command the layer implements, with the exact signature of its PFN_xr* type
// (negotiate.cpp checks each at compile time). One file per concept defines them: instance and
// system (instance.cpp), sessions and frames (session.cpp), actions and bindings (actions.cpp),
// action states (action_state.cpp), gaze spaces (gaze_space.cpp) and the other commands that
// take a space (locate_spaces.cpp, end_frame.cpp).
#pragma once

#include "layer/xr_headers.hpp"
#include "xr/loader_negotiation.hpp"

namespace gazelod::layer {

// negotiate.cpp
XrResult GetInstanceProcAddr(XrInstance instance, const char* name, PFN_xrVoidFunction* function);

// instance.cpp
XrResult CreateApiLayerInstance(const XrInstanceCreateInfo* info, const xr::XrApiLayerCreateInfo* layer_info,
                                XrInstance* instance);
XrResult EnumerateInstanceExtensionProperties(const char* layerName, uint32_t capacity, uint32_t* count,
                                              XrExtensionProperties* props);
XrResult DestroyInstance(XrInstance instance);
XrResult GetSystemProperties(XrInstance instance, XrSystemId systemId, XrSystemProperties* properties);
XrResult PollEvent(XrInstance instance, XrEventDataBuffer* eventData);

// session.cpp
XrResult CreateSession(XrInstance instance, const XrSessionCreateInfo* createInfo, XrSession* session);
XrResult DestroySession(XrSession session);
XrResult WaitFrame(XrSession session, const XrFrameWaitInfo* frameWaitInfo, XrFrameState* frameState);

// actions.cpp
XrResult CreateActionSet(XrInstance instance, const XrActionSetCreateInfo* createInfo, XrActionSet* actionSet);
XrResult DestroyActionSet(XrActionSet actionSet);
XrResult CreateAction(XrActionSet actionSet, const XrActionCreateInfo* createInfo, XrAction* action);
XrResult DestroyAction(XrAction action);
XrResult SuggestInteractionProfileBindings(XrInstance instance,
                                           const XrInteractionProfileSuggestedBinding* suggestedBindings);
XrResult AttachSessionActionSets(XrSession session, const XrSessionActionSetsAttachInfo* attachInfo);
XrResult SyncActions(XrSession session, const XrActionsSyncInfo* syncInfo);

// action_state.cpp
XrResult GetActionStatePose(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStatePose* state);
XrResult GetActionStateBoolean(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateBoolean* state);
XrResult GetActionStateFloat(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateFloat* state);
XrResult GetActionStateVector2f(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateVector2f* state);

// actions.cpp
XrResult GetCurrentInteractionProfile(XrSession session, XrPath topLevelUserPath,
                                      XrInteractionProfileState* interactionProfile);
XrResult EnumerateBoundSourcesForAction(XrSession session, const XrBoundSourcesForActionEnumerateInfo* enumerateInfo,
                                        uint32_t capacity, uint32_t* count, XrPath* sources);
XrResult GetInputSourceLocalizedName(XrSession session, const XrInputSourceLocalizedNameGetInfo* getInfo,
                                     uint32_t capacity, uint32_t* count, char* buffer);

// gaze_space.cpp
XrResult CreateActionSpace(XrSession session, const XrActionSpaceCreateInfo* createInfo, XrSpace* space);
XrResult LocateSpace(XrSpace space, XrSpace baseSpace, XrTime time, XrSpaceLocation* location);
XrResult DestroySpace(XrSpace space);

// locate_spaces.cpp: xrLocateSpaces(KHR) and xrLocateViews with gaze spaces
XrResult LocateSpacesKHR(XrSession session, const XrSpacesLocateInfoKHR* locateInfo,
                         XrSpaceLocationsKHR* spaceLocations);
XrResult LocateSpaces(XrSession session, const XrSpacesLocateInfoKHR* locateInfo, XrSpaceLocationsKHR* spaceLocations);
XrResult LocateViews(XrSession session, const XrViewLocateInfo* viewLocateInfo, XrViewState* viewState,
                     uint32_t viewCapacityInput, uint32_t* viewCountOutput, XrView* views);

// end_frame.cpp: composition layers in gaze spaces
XrResult EndFrame(XrSession session, const XrFrameEndInfo* frameEndInfo);

}  // namespace gazelod::layer
