// SPDX-License-Identifier: Apache-2.0
// The OpenXR loader's interface, version 1, to runtimes and API layers (OpenXR loader
// specification: "Runtime Negotiation", "API Layer Negotiation", "xrCreateApiLayerInstance";
// loader_interfaces.h of the OpenXR SDK 1.0.x). Debian's OpenXR 1.0.20 packages install no
// loader_interfaces.h / openxr_loader_negotiation.h, so the structures are declared here with
// the layout the specification gives; the loader fills them, the simulated runtime
// (sim/runtime/) and the eye-gaze layer (layer/) only read and answer. One declaration for both.
// Needs only <openxr/openxr.h>; include the caller's own OpenXR header set first when it enables
// platform types.
#pragma once

#include <openxr/openxr.h>

#include <cstddef>
#include <cstdint>

namespace gazelod::xr {

enum XrLoaderInterfaceStructs : std::int32_t {
  XR_LOADER_INTERFACE_STRUCT_UNINTIALIZED = 0,
  XR_LOADER_INTERFACE_STRUCT_LOADER_INFO = 1,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST = 2,
  XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST = 3,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_CREATE_INFO = 4,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_NEXT_INFO = 5,
};

inline constexpr std::uint32_t kLoaderInfoStructVersion = 1;
inline constexpr std::uint32_t kRuntimeInfoStructVersion = 1;
inline constexpr std::uint32_t kApiLayerInfoStructVersion = 1;
inline constexpr std::uint32_t kApiLayerNextInfoStructVersion = 1;
inline constexpr std::uint32_t kApiLayerCreateInfoStructVersion = 1;
inline constexpr std::uint32_t kLoaderRuntimeInterfaceVersion = 1;
inline constexpr std::uint32_t kLoaderApiLayerInterfaceVersion = 1;
inline constexpr std::size_t kApiLayerMaxSettingsPathSize = 512;

// What the loader offers, to a runtime or a layer.
struct XrNegotiateLoaderInfo {
  XrLoaderInterfaceStructs structType;  // LOADER_INFO
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t minInterfaceVersion;
  std::uint32_t maxInterfaceVersion;
  XrVersion minApiVersion;
  XrVersion maxApiVersion;
};

// ---- runtimes -------------------------------------------------------------------------------

struct XrNegotiateRuntimeRequest {
  XrLoaderInterfaceStructs structType;  // RUNTIME_REQUEST
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t runtimeInterfaceVersion;
  XrVersion runtimeApiVersion;
  PFN_xrGetInstanceProcAddr getInstanceProcAddr;
};

// ---- API layers -----------------------------------------------------------------------------

struct XrApiLayerCreateInfo;
using PFN_xrCreateApiLayerInstance = XrResult(XRAPI_PTR*)(const XrInstanceCreateInfo* info,
                                                          const XrApiLayerCreateInfo* apiLayerInfo,
                                                          XrInstance* instance);

struct XrNegotiateApiLayerRequest {
  XrLoaderInterfaceStructs structType;  // API_LAYER_REQUEST
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t layerInterfaceVersion;
  XrVersion layerApiVersion;
  PFN_xrGetInstanceProcAddr getInstanceProcAddr;
  PFN_xrCreateApiLayerInstance createApiLayerInstance;
};

struct XrApiLayerNextInfo {
  XrLoaderInterfaceStructs structType;  // API_LAYER_NEXT_INFO
  std::uint32_t structVersion;
  std::size_t structSize;
  char layerName[XR_MAX_API_LAYER_NAME_SIZE];  // the layer this entry is meant for
  PFN_xrGetInstanceProcAddr nextGetInstanceProcAddr;
  PFN_xrCreateApiLayerInstance nextCreateApiLayerInstance;
  XrApiLayerNextInfo* next;  // the entry of the layer below the next one
};

struct XrApiLayerCreateInfo {
  XrLoaderInterfaceStructs structType;  // API_LAYER_CREATE_INFO
  std::uint32_t structVersion;
  std::size_t structSize;
  void* loaderInstance;  // unused by the loader (1.0.20 passes null)
  char settings_file_location[kApiLayerMaxSettingsPathSize];
  XrApiLayerNextInfo* nextInfo;
};

}  // namespace gazelod::xr
