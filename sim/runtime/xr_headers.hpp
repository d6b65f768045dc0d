// SPDX-License-Identifier: Apache-2.0
// The OpenXR headers as the simulated runtime compiles them: Vulkan and timespec platform
// types enabled, plus the loader-runtime negotiation structures (OpenXR loader specification,
// "Runtime Negotiation"), which the Debian 1.0.20 headers do not install.
#pragma once

#include <time.h>
#include <vulkan/vulkan.h>

#define XR_USE_GRAPHICS_API_VULKAN 1
#define XR_USE_TIMESPEC 1
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include "sim/runtime/simulator_state_ext.h"

#include <cstddef>
#include <cstdint>

namespace gazelod::xrrt {

// Loader interface, version 1 (loader_interfaces.h of the OpenXR SDK 1.0.x).
enum XrLoaderInterfaceStructs : std::int32_t {
  XR_LOADER_INTERFACE_STRUCT_UNINTIALIZED = 0,
  XR_LOADER_INTERFACE_STRUCT_LOADER_INFO = 1,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST = 2,
  XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST = 3,
};
inline constexpr std::uint32_t kLoaderInfoStructVersion = 1;
inline constexpr std::uint32_t kRuntimeInfoStructVersion = 1;
inline constexpr std::uint32_t kLoaderRuntimeInterfaceVersion = 1;

struct XrNegotiateLoaderInfo {
  XrLoaderInterfaceStructs structType;
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t minInterfaceVersion;
  std::uint32_t maxInterfaceVersion;
  XrVersion minApiVersion;
  XrVersion maxApiVersion;
};

struct XrNegotiateRuntimeRequest {
  XrLoaderInterfaceStructs structType;
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t runtimeInterfaceVersion;
  XrVersion runtimeApiVersion;
  PFN_xrGetInstanceProcAddr getInstanceProcAddr;
};

}  // namespace gazelod::xrrt
