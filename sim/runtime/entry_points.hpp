// SPDX-License-Identifier: Apache-2.0
// Every OpenXR command the simulated runtime implements, one declaration each, with the exact
// signature of its PFN_xr* type (dispatch.cpp checks this at compile time). The definitions
// live in one file per concept: instance, system, session, spaces, views, frame loop, ...
#pragma once

#include "sim/runtime/xr_headers.hpp"

namespace gazelod::xrrt {

// dispatch.cpp
XrResult GetInstanceProcAddr(XrInstance instance, const char* name, PFN_xrVoidFunction* function);

// instance.cpp
XrResult EnumerateApiLayerProperties(uint32_t capacity, uint32_t* count, XrApiLayerProperties* props);
XrResult EnumerateInstanceExtensionProperties(const char* layerName, uint32_t capacity, uint32_t* count,
                                              XrExtensionProperties* props);
XrResult CreateInstance(const XrInstanceCreateInfo* createInfo, XrInstance* instance);
XrResult DestroyInstance(XrInstance instance);
XrResult GetInstanceProperties(XrInstance instance, XrInstanceProperties* props);
XrResult ResultToString(XrInstance instance, XrResult value, char buffer[XR_MAX_RESULT_STRING_SIZE]);
XrResult StructureTypeToString(XrInstance instance, XrStructureType value, char buffer[XR_MAX_STRUCTURE_NAME_SIZE]);

// paths.cpp
XrResult StringToPath(XrInstance instance, const char* pathString, XrPath* path);
XrResult PathToString(XrInstance instance, XrPath path, uint32_t capacity, uint32_t* count, char* buffer);

// events.cpp
XrResult PollEvent(XrInstance instance, XrEventDataBuffer* eventData);

// system.cpp
XrResult GetSystem(XrInstance instance, const XrSystemGetInfo* getInfo, XrSystemId* systemId);
XrResult GetSystemProperties(XrInstance instance, XrSystemId systemId, XrSystemProperties* properties);
XrResult EnumerateEnvironmentBlendModes(XrInstance instance, XrSystemId systemId,
                                        XrViewConfigurationType viewConfigurationType, uint32_t capacity,
                                        uint32_t* count, XrEnvironmentBlendMode* modes);
XrResult EnumerateViewConfigurations(XrInstance instance, XrSystemId systemId, uint32_t capacity, uint32_t* count,
                                     XrViewConfigurationType* types);
XrResult GetViewConfigurationProperties(XrInstance instance, XrSystemId systemId, XrViewConfigurationType type,
                                        XrViewConfigurationProperties* props);
XrResult EnumerateViewConfigurationViews(XrInstance instance, XrSystemId systemId, XrViewConfigurationType type,
                                         uint32_t capacity, uint32_t* count, XrViewConfigurationView* views);

// session.cpp
XrResult CreateSession(XrInstance instance, const XrSessionCreateInfo* createInfo, XrSession* session);
XrResult DestroySession(XrSession session);
XrResult BeginSession(XrSession session, const XrSessionBeginInfo* beginInfo);
XrResult EndSession(XrSession session);
XrResult RequestExitSession(XrSession session);

// spaces.cpp
XrResult EnumerateReferenceSpaces(XrSession session, uint32_t capacity, uint32_t* count, XrReferenceSpaceType* spaces);
XrResult CreateReferenceSpace(XrSession session, const XrReferenceSpaceCreateInfo* createInfo, XrSpace* space);
XrResult GetReferenceSpaceBoundsRect(XrSession session, XrReferenceSpaceType type, XrExtent2Df* bounds);
XrResult CreateActionSpace(XrSession session, const XrActionSpaceCreateInfo* createInfo, XrSpace* space);
XrResult LocateSpace(XrSpace space, XrSpace baseSpace, XrTime time, XrSpaceLocation* location);
XrResult DestroySpace(XrSpace space);
// (XR_KHR_locate_spaces)
XrResult LocateSpacesKHR(XrSession session, const XrSpacesLocateInfoKHR* locateInfo,
                         XrSpaceLocationsKHR* spaceLocations);

// views.cpp
XrResult LocateViews(XrSession session, const XrViewLocateInfo* info, XrViewState* viewState, uint32_t capacity,
                     uint32_t* count, XrView* views);

// frame_loop.cpp
XrResult WaitFrame(XrSession session, const XrFrameWaitInfo* frameWaitInfo, XrFrameState* frameState);
XrResult BeginFrame(XrSession session, const XrFrameBeginInfo* frameBeginInfo);
XrResult EndFrame(XrSession session, const XrFrameEndInfo* frameEndInfo);

// swapchain.cpp
XrResult EnumerateSwapchainFormats(XrSession session, uint32_t capacity, uint32_t* count, int64_t* formats);
XrResult CreateSwapchain(XrSession session, const XrSwapchainCreateInfo* createInfo, XrSwapchain* swapchain);
XrResult DestroySwapchain(XrSwapchain swapchain);
XrResult EnumerateSwapchainImages(XrSwapchain swapchain, uint32_t capacity, uint32_t* count,
                                  XrSwapchainImageBaseHeader* images);
XrResult AcquireSwapchainImage(XrSwapchain swapchain, const XrSwapchainImageAcquireInfo* info, uint32_t* index);
XrResult WaitSwapchainImage(XrSwapchain swapchain, const XrSwapchainImageWaitInfo* info);
XrResult ReleaseSwapchainImage(XrSwapchain swapchain, const XrSwapchainImageReleaseInfo* info);

// actions.cpp
XrResult CreateActionSet(XrInstance instance, const XrActionSetCreateInfo* createInfo, XrActionSet* actionSet);
XrResult DestroyActionSet(XrActionSet actionSet);
XrResult CreateAction(XrActionSet actionSet, const XrActionCreateInfo* createInfo, XrAction* action);
XrResult DestroyAction(XrAction action);
XrResult SuggestInteractionProfileBindings(XrInstance instance,
                                           const XrInteractionProfileSuggestedBinding* suggestedBindings);
XrResult AttachSessionActionSets(XrSession session, const XrSessionActionSetsAttachInfo* attachInfo);
XrResult GetCurrentInteractionProfile(XrSession session, XrPath topLevelUserPath,
                                      XrInteractionProfileState* interactionProfile);

// action_state.cpp
XrResult SyncActions(XrSession session, const XrActionsSyncInfo* syncInfo);
XrResult GetActionStateBoolean(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateBoolean* state);
XrResult GetActionStateFloat(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateFloat* state);
XrResult GetActionStateVector2f(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateVector2f* state);
XrResult GetActionStatePose(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStatePose* state);
XrResult EnumerateBoundSourcesForAction(XrSession session, const XrBoundSourcesForActionEnumerateInfo* info,
                                        uint32_t capacity, uint32_t* count, XrPath* sources);
XrResult GetInputSourceLocalizedName(XrSession session, const XrInputSourceLocalizedNameGetInfo* getInfo,
                                     uint32_t capacity, uint32_t* count, char* buffer);
XrResult ApplyHapticFeedback(XrSession session, const XrHapticActionInfo* info, const XrHapticBaseHeader* haptic);
XrResult StopHapticFeedback(XrSession session, const XrHapticActionInfo* info);

// vulkan_enable.cpp (XR_KHR_vulkan_enable and XR_KHR_vulkan_enable2)
XrResult GetVulkanInstanceExtensionsKHR(XrInstance instance, XrSystemId systemId, uint32_t capacity, uint32_t* count,
                                        char* buffer);
XrResult GetVulkanDeviceExtensionsKHR(XrInstance instance, XrSystemId systemId, uint32_t capacity, uint32_t* count,
                                      char* buffer);
XrResult GetVulkanGraphicsDeviceKHR(XrInstance instance, XrSystemId systemId, VkInstance vkInstance,
                                    VkPhysicalDevice* vkPhysicalDevice);
XrResult GetVulkanGraphicsRequirementsKHR(XrInstance instance, XrSystemId systemId,
                                          XrGraphicsRequirementsVulkanKHR* requirements);
XrResult CreateVulkanInstanceKHR(XrInstance instance, const XrVulkanInstanceCreateInfoKHR* createInfo,
                                 VkInstance* vulkanInstance, VkResult* vulkanResult);
XrResult CreateVulkanDeviceKHR(XrInstance instance, const XrVulkanDeviceCreateInfoKHR* createInfo,
                               VkDevice* vulkanDevice, VkResult* vulkanResult);
XrResult GetVulkanGraphicsDevice2KHR(XrInstance instance, const XrVulkanGraphicsDeviceGetInfoKHR* getInfo,
                                     VkPhysicalDevice* vulkanPhysicalDevice);

// time_conversion.cpp (XR_KHR_convert_timespec_time)
XrResult ConvertTimespecTimeToTimeKHR(XrInstance instance, const struct timespec* timespecTime, XrTime* time);
XrResult ConvertTimeToTimespecTimeKHR(XrInstance instance, XrTime time, struct timespec* timespecTime);

// conformance_automation.cpp (XR_EXT_conformance_automation)
XrResult SetInputDeviceActiveEXT(XrSession session, XrPath interactionProfile, XrPath topLevelPath, XrBool32 isActive);
XrResult SetInputDeviceStateBoolEXT(XrSession session, XrPath topLevelPath, XrPath inputSourcePath, XrBool32 state);
XrResult SetInputDeviceStateFloatEXT(XrSession session, XrPath topLevelPath, XrPath inputSourcePath, float state);
XrResult SetInputDeviceStateVector2fEXT(XrSession session, XrPath topLevelPath, XrPath inputSourcePath,
                                        XrVector2f state);
XrResult SetInputDeviceLocationEXT(XrSession session, XrPath topLevelPath, XrPath inputSourcePath, XrSpace space,
                                   XrPosef pose);

// simulator_state.cpp (XR_GAZELOD_simulator_state)
XrResult GetSimulatorStateGAZELOD(XrSession session, XrSimulatorStateGAZELOD* state);
XrResult EnumerateSubmittedLayersGAZELOD(XrSession session, uint32_t capacity, uint32_t* count,
                                         XrSubmittedLayerGAZELOD* layers);

}  // namespace gazelod::xrrt
