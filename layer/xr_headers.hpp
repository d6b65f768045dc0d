// SPDX-License-Identifier: Apache-2.0
// The OpenXR headers as the layer compiles them: with XR_KHR_convert_timespec_time's types
// (the HID source puts its samples on the runtime's clock through it), and XR_KHR_locate_spaces
// (core xrLocateSpaces in OpenXR 1.1), which Debian's 1.0.20 headers lack
// (xr/khr_locate_spaces.h).
#pragma once

#include <time.h>

#ifndef XR_USE_TIMESPEC
#define XR_USE_TIMESPEC 1
#endif
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include "xr/khr_locate_spaces.h"

#ifndef XR_VERSION_1_1
// OpenXR 1.1's core command: the extension's signature (its structures are the same).
typedef PFN_xrLocateSpacesKHR PFN_xrLocateSpaces;
#endif

// The layer's name and its implicit manifest's variables come from layer/CMakeLists.txt, which
// also writes the manifests: one place for each name.
#if !defined(GAZELOD_LAYER_NAME) || !defined(GAZELOD_LAYER_ENABLE_ENV) || !defined(GAZELOD_LAYER_DISABLE_ENV)
#error "link gazelod_layer_core: it defines GAZELOD_LAYER_NAME, GAZELOD_LAYER_ENABLE_ENV, GAZELOD_LAYER_DISABLE_ENV"
#endif

namespace gazelod::layer {

inline constexpr const char* kLayerName = GAZELOD_LAYER_NAME;
inline constexpr const char* kLayerEnableEnv = GAZELOD_LAYER_ENABLE_ENV;
inline constexpr const char* kLayerDisableEnv = GAZELOD_LAYER_DISABLE_ENV;

}  // namespace gazelod::layer
