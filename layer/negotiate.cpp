// SPDX-License-Identifier: Apache-2.0
// The loader negotiation (the library's one exported symbol) and xrGetInstanceProcAddr: for an
// instance the layer emulates eye gaze for, its own commands; for everything else (and every
// instance it passes through) the next layer's pointers, unchanged.
#include "layer/entry_points.hpp"
#include "layer/layer_state.hpp"

#include <cstring>
#include <string_view>

namespace gazelod::layer {
namespace {

struct Entry {
  const char* name;
  PFN_xrVoidFunction fn;
};

// static_cast to the PFN type checks each signature against the headers.
#define GAZELOD_LAYER_ENTRY(name)                                                      \
  Entry {                                                                              \
    "xr" #name, reinterpret_cast<PFN_xrVoidFunction>(static_cast<PFN_xr##name>(&name)) \
  }

// Commands the emulation takes over (instance.cpp, session.cpp, actions.cpp, action_state.cpp,
// gaze_space.cpp, locate_spaces.cpp, end_frame.cpp).
const Entry kEmulated[] = {
    GAZELOD_LAYER_ENTRY(GetSystemProperties),
    GAZELOD_LAYER_ENTRY(PollEvent),
    GAZELOD_LAYER_ENTRY(CreateSession),
    GAZELOD_LAYER_ENTRY(DestroySession),
    GAZELOD_LAYER_ENTRY(WaitFrame),
    GAZELOD_LAYER_ENTRY(CreateActionSet),
    GAZELOD_LAYER_ENTRY(DestroyActionSet),
    GAZELOD_LAYER_ENTRY(CreateAction),
    GAZELOD_LAYER_ENTRY(DestroyAction),
    GAZELOD_LAYER_ENTRY(SuggestInteractionProfileBindings),
    GAZELOD_LAYER_ENTRY(AttachSessionActionSets),
    GAZELOD_LAYER_ENTRY(SyncActions),
    GAZELOD_LAYER_ENTRY(GetActionStatePose),
    GAZELOD_LAYER_ENTRY(GetActionStateBoolean),
    GAZELOD_LAYER_ENTRY(GetActionStateFloat),
    GAZELOD_LAYER_ENTRY(GetActionStateVector2f),
    GAZELOD_LAYER_ENTRY(GetCurrentInteractionProfile),
    GAZELOD_LAYER_ENTRY(EnumerateBoundSourcesForAction),
    GAZELOD_LAYER_ENTRY(GetInputSourceLocalizedName),
    GAZELOD_LAYER_ENTRY(CreateActionSpace),
    GAZELOD_LAYER_ENTRY(LocateSpace),
    GAZELOD_LAYER_ENTRY(DestroySpace),
    GAZELOD_LAYER_ENTRY(LocateViews),
    GAZELOD_LAYER_ENTRY(EndFrame),
};

// Commands the runtime may lack (an extension the application did not enable, a 1.0 runtime):
// taken over only when the next layer gives them, else left to it (which refuses them).
struct OptionalEntry {
  Entry entry;
  PFN_xrLocateSpacesKHR NextDispatch::*next;
};
const OptionalEntry kEmulatedIfBelow[] = {
    {GAZELOD_LAYER_ENTRY(LocateSpacesKHR), &NextDispatch::LocateSpacesKHR},
    {GAZELOD_LAYER_ENTRY(LocateSpaces), &NextDispatch::LocateSpaces},
};
#undef GAZELOD_LAYER_ENTRY

PFN_xrVoidFunction own(std::string_view name) {
  if (name == "xrGetInstanceProcAddr")
    return reinterpret_cast<PFN_xrVoidFunction>(static_cast<PFN_xrGetInstanceProcAddr>(&GetInstanceProcAddr));
  if (name == "xrEnumerateInstanceExtensionProperties")
    return reinterpret_cast<PFN_xrVoidFunction>(
        static_cast<PFN_xrEnumerateInstanceExtensionProperties>(&EnumerateInstanceExtensionProperties));
  // Every instance: the layer forgets it (and stops its source) on the way down.
  if (name == "xrDestroyInstance")
    return reinterpret_cast<PFN_xrVoidFunction>(static_cast<PFN_xrDestroyInstance>(&DestroyInstance));
  if (name == "xrCreateApiLayerInstance")
    return reinterpret_cast<PFN_xrVoidFunction>(static_cast<xr::PFN_xrCreateApiLayerInstance>(&CreateApiLayerInstance));
  return nullptr;
}

}  // namespace

XrResult GetInstanceProcAddr(XrInstance instance, const char* name, PFN_xrVoidFunction* function) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    if (name == nullptr || function == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *function = nullptr;
    const std::string_view wanted(name);
    if (PFN_xrVoidFunction fn = own(wanted)) {
      *function = fn;
      return XR_SUCCESS;
    }
    PFN_xrGetInstanceProcAddr next = nullptr;
    {
      LayerState& st = layer_state();
      std::lock_guard lock(st.mutex);
      if (st.emulated && st.emulated->handle == instance && instance != XR_NULL_HANDLE) {
        for (const Entry& e : kEmulated)
          if (wanted == e.name) {
            *function = e.fn;
            return XR_SUCCESS;
          }
        for (const OptionalEntry& o : kEmulatedIfBelow)
          if (wanted == o.entry.name && st.emulated->next.*o.next != nullptr) {
            *function = o.entry.fn;
            return XR_SUCCESS;
          }
        next = st.emulated->next.GetInstanceProcAddr;
      } else if (auto it = st.passed_through.find(instance); it != st.passed_through.end()) {
        next = it->second;
      } else {
        next = st.last_next_gipa;
      }
    }
    if (next == nullptr) return XR_ERROR_HANDLE_INVALID;
    return next(instance, name, function);
  });
}

}  // namespace gazelod::layer

// The only exported symbol (hidden visibility and a version script hide the rest).
extern "C" __attribute__((visibility("default"))) XrResult xrNegotiateLoaderApiLayerInterface(
    const gazelod::xr::XrNegotiateLoaderInfo* loaderInfo, const char* layerName,
    gazelod::xr::XrNegotiateApiLayerRequest* apiLayerRequest) {
  using namespace gazelod::layer;
  using namespace gazelod::xr;
  if (loaderInfo == nullptr || apiLayerRequest == nullptr ||
      loaderInfo->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
      loaderInfo->structVersion != kLoaderInfoStructVersion ||
      loaderInfo->structSize != sizeof(XrNegotiateLoaderInfo) ||
      apiLayerRequest->structType != XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST ||
      apiLayerRequest->structVersion != kApiLayerInfoStructVersion ||
      apiLayerRequest->structSize != sizeof(XrNegotiateApiLayerRequest))
    return XR_ERROR_INITIALIZATION_FAILED;
  // One library, one layer: a manifest naming another layer is someone else's mistake.
  if (layerName == nullptr || std::strcmp(layerName, kLayerName) != 0) return XR_ERROR_INITIALIZATION_FAILED;
  if (loaderInfo->minInterfaceVersion > kLoaderApiLayerInterfaceVersion ||
      loaderInfo->maxInterfaceVersion < kLoaderApiLayerInterfaceVersion)
    return XR_ERROR_INITIALIZATION_FAILED;
  // Written against OpenXR 1.0: the loader's range must include some 1.0.x.
  if (XR_VERSION_MAJOR(loaderInfo->maxApiVersion) < 1 || XR_VERSION_MAJOR(loaderInfo->minApiVersion) > 1)
    return XR_ERROR_INITIALIZATION_FAILED;
  apiLayerRequest->layerInterfaceVersion = kLoaderApiLayerInterfaceVersion;
  apiLayerRequest->layerApiVersion = XR_CURRENT_API_VERSION;
  apiLayerRequest->getInstanceProcAddr = &GetInstanceProcAddr;
  apiLayerRequest->createApiLayerInstance = &CreateApiLayerInstance;
  return XR_SUCCESS;
}
