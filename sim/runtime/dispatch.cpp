// SPDX-License-Identifier: Apache-2.0
// Loader negotiation (the runtime's one exported symbol) and xrGetInstanceProcAddr: name ->
// function, refusing extension commands whose extension the instance did not enable
// (XR_ERROR_FUNCTION_UNSUPPORTED) and non-global commands without an instance.
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/runtime_state.hpp"
#include "xr/loader_negotiation.hpp"

#include <cstring>
#include <string_view>

namespace gazelod::xrrt {
namespace {

enum class Needs : std::uint8_t { global, core, vulkan, vulkan2, timespec, automation, simulator_state, locate_spaces };

struct Entry {
  const char* name;
  PFN_xrVoidFunction fn;
  Needs needs;
};

// static_cast to the PFN type checks each signature against the headers.
#define XRRT_ENTRY(name, needs)                                                               \
  Entry {                                                                                     \
    "xr" #name, reinterpret_cast<PFN_xrVoidFunction>(static_cast<PFN_xr##name>(&name)), needs \
  }

const Entry kEntries[] = {
    XRRT_ENTRY(GetInstanceProcAddr, Needs::core),
    XRRT_ENTRY(EnumerateApiLayerProperties, Needs::global),
    XRRT_ENTRY(EnumerateInstanceExtensionProperties, Needs::global),
    XRRT_ENTRY(CreateInstance, Needs::global),
    XRRT_ENTRY(DestroyInstance, Needs::core),
    XRRT_ENTRY(GetInstanceProperties, Needs::core),
    XRRT_ENTRY(PollEvent, Needs::core),
    XRRT_ENTRY(ResultToString, Needs::core),
    XRRT_ENTRY(StructureTypeToString, Needs::core),
    XRRT_ENTRY(GetSystem, Needs::core),
    XRRT_ENTRY(GetSystemProperties, Needs::core),
    XRRT_ENTRY(EnumerateEnvironmentBlendModes, Needs::core),
    XRRT_ENTRY(CreateSession, Needs::core),
    XRRT_ENTRY(DestroySession, Needs::core),
    XRRT_ENTRY(EnumerateReferenceSpaces, Needs::core),
    XRRT_ENTRY(CreateReferenceSpace, Needs::core),
    XRRT_ENTRY(GetReferenceSpaceBoundsRect, Needs::core),
    XRRT_ENTRY(CreateActionSpace, Needs::core),
    XRRT_ENTRY(LocateSpace, Needs::core),
    XRRT_ENTRY(DestroySpace, Needs::core),
    XRRT_ENTRY(EnumerateViewConfigurations, Needs::core),
    XRRT_ENTRY(GetViewConfigurationProperties, Needs::core),
    XRRT_ENTRY(EnumerateViewConfigurationViews, Needs::core),
    XRRT_ENTRY(EnumerateSwapchainFormats, Needs::core),
    XRRT_ENTRY(CreateSwapchain, Needs::core),
    XRRT_ENTRY(DestroySwapchain, Needs::core),
    XRRT_ENTRY(EnumerateSwapchainImages, Needs::core),
    XRRT_ENTRY(AcquireSwapchainImage, Needs::core),
    XRRT_ENTRY(WaitSwapchainImage, Needs::core),
    XRRT_ENTRY(ReleaseSwapchainImage, Needs::core),
    XRRT_ENTRY(BeginSession, Needs::core),
    XRRT_ENTRY(EndSession, Needs::core),
    XRRT_ENTRY(RequestExitSession, Needs::core),
    XRRT_ENTRY(WaitFrame, Needs::core),
    XRRT_ENTRY(BeginFrame, Needs::core),
    XRRT_ENTRY(EndFrame, Needs::core),
    XRRT_ENTRY(LocateViews, Needs::core),
    XRRT_ENTRY(StringToPath, Needs::core),
    XRRT_ENTRY(PathToString, Needs::core),
    XRRT_ENTRY(CreateActionSet, Needs::core),
    XRRT_ENTRY(DestroyActionSet, Needs::core),
    XRRT_ENTRY(CreateAction, Needs::core),
    XRRT_ENTRY(DestroyAction, Needs::core),
    XRRT_ENTRY(SuggestInteractionProfileBindings, Needs::core),
    XRRT_ENTRY(AttachSessionActionSets, Needs::core),
    XRRT_ENTRY(GetCurrentInteractionProfile, Needs::core),
    XRRT_ENTRY(GetActionStateBoolean, Needs::core),
    XRRT_ENTRY(GetActionStateFloat, Needs::core),
    XRRT_ENTRY(GetActionStateVector2f, Needs::core),
    XRRT_ENTRY(GetActionStatePose, Needs::core),
    XRRT_ENTRY(SyncActions, Needs::core),
    XRRT_ENTRY(EnumerateBoundSourcesForAction, Needs::core),
    XRRT_ENTRY(GetInputSourceLocalizedName, Needs::core),
    XRRT_ENTRY(ApplyHapticFeedback, Needs::core),
    XRRT_ENTRY(StopHapticFeedback, Needs::core),
    XRRT_ENTRY(GetVulkanInstanceExtensionsKHR, Needs::vulkan),
    XRRT_ENTRY(GetVulkanDeviceExtensionsKHR, Needs::vulkan),
    XRRT_ENTRY(GetVulkanGraphicsDeviceKHR, Needs::vulkan),
    XRRT_ENTRY(GetVulkanGraphicsRequirementsKHR, Needs::vulkan),
    XRRT_ENTRY(CreateVulkanInstanceKHR, Needs::vulkan2),
    XRRT_ENTRY(CreateVulkanDeviceKHR, Needs::vulkan2),
    XRRT_ENTRY(GetVulkanGraphicsDevice2KHR, Needs::vulkan2),
    // Same signature as the v1 query; the v2 name is served by the same function.
    Entry{"xrGetVulkanGraphicsRequirements2KHR",
          reinterpret_cast<PFN_xrVoidFunction>(
              static_cast<PFN_xrGetVulkanGraphicsRequirements2KHR>(&GetVulkanGraphicsRequirementsKHR)),
          Needs::vulkan2},
    XRRT_ENTRY(ConvertTimespecTimeToTimeKHR, Needs::timespec),
    XRRT_ENTRY(ConvertTimeToTimespecTimeKHR, Needs::timespec),
    XRRT_ENTRY(SetInputDeviceActiveEXT, Needs::automation),
    XRRT_ENTRY(SetInputDeviceStateBoolEXT, Needs::automation),
    XRRT_ENTRY(SetInputDeviceStateFloatEXT, Needs::automation),
    XRRT_ENTRY(SetInputDeviceStateVector2fEXT, Needs::automation),
    XRRT_ENTRY(SetInputDeviceLocationEXT, Needs::automation),
    XRRT_ENTRY(GetSimulatorStateGAZELOD, Needs::simulator_state),
    XRRT_ENTRY(EnumerateSubmittedLayersGAZELOD, Needs::simulator_state),
    XRRT_ENTRY(LocateSpacesKHR, Needs::locate_spaces),
};
#undef XRRT_ENTRY

bool enabled(const Instance& inst, Needs needs) {
  switch (needs) {
    case Needs::global:
    case Needs::core:
      return true;
    case Needs::vulkan:
      return inst.ext_vulkan;
    case Needs::vulkan2:
      return inst.ext_vulkan2;
    case Needs::simulator_state:
      return inst.ext_simulator_state;
    case Needs::timespec:
      return inst.ext_timespec;
    case Needs::automation:
      return inst.ext_automation;
    case Needs::locate_spaces:
      return inst.ext_locate_spaces;
  }
  return false;
}

}  // namespace

XrResult GetInstanceProcAddr(XrInstance instance, const char* name, PFN_xrVoidFunction* function) {
  return guarded([&] {
    if (name == nullptr || function == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *function = nullptr;
    const std::string_view wanted(name);
    for (const Entry& e : kEntries) {
      if (wanted != e.name) continue;
      if (instance == XR_NULL_HANDLE) {
        if (e.needs != Needs::global) return XR_ERROR_HANDLE_INVALID;
        *function = e.fn;
        return XR_SUCCESS;
      }
      std::lock_guard lock(runtime_mutex());
      const Instance* inst = find_instance(instance);
      if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
      if (!enabled(*inst, e.needs)) return XR_ERROR_FUNCTION_UNSUPPORTED;
      *function = e.fn;
      return XR_SUCCESS;
    }
    if (instance == XR_NULL_HANDLE) return XR_ERROR_HANDLE_INVALID;
    std::lock_guard lock(runtime_mutex());
    if (find_instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    return XR_ERROR_FUNCTION_UNSUPPORTED;
  });
}

}  // namespace gazelod::xrrt

// The only exported symbol (the library is built with hidden visibility).
extern "C" __attribute__((visibility("default"))) XrResult xrNegotiateLoaderRuntimeInterface(
    const gazelod::xr::XrNegotiateLoaderInfo* loaderInfo, gazelod::xr::XrNegotiateRuntimeRequest* runtimeRequest) {
  using namespace gazelod::xrrt;
  using namespace gazelod::xr;
  if (loaderInfo == nullptr || runtimeRequest == nullptr ||
      loaderInfo->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
      loaderInfo->structVersion != kLoaderInfoStructVersion ||
      loaderInfo->structSize != sizeof(XrNegotiateLoaderInfo) ||
      runtimeRequest->structType != XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST ||
      runtimeRequest->structVersion != kRuntimeInfoStructVersion ||
      runtimeRequest->structSize != sizeof(XrNegotiateRuntimeRequest))
    return XR_ERROR_INITIALIZATION_FAILED;
  if (loaderInfo->minInterfaceVersion > kLoaderRuntimeInterfaceVersion ||
      loaderInfo->maxInterfaceVersion < kLoaderRuntimeInterfaceVersion)
    return XR_ERROR_INITIALIZATION_FAILED;
  // We implement 1.0: the loader's range must include some 1.0.x.
  if (XR_VERSION_MAJOR(loaderInfo->maxApiVersion) < 1 || XR_VERSION_MAJOR(loaderInfo->minApiVersion) > 1)
    return XR_ERROR_INITIALIZATION_FAILED;
  runtimeRequest->runtimeInterfaceVersion = kLoaderRuntimeInterfaceVersion;
  runtimeRequest->runtimeApiVersion = XR_CURRENT_API_VERSION;
  runtimeRequest->getInstanceProcAddr = &GetInstanceProcAddr;
  return XR_SUCCESS;
}
