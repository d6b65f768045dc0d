// SPDX-License-Identifier: Apache-2.0
// The OpenXR headers as the simulated runtime compiles them: Vulkan and timespec platform
// types enabled. The loader-runtime negotiation structures, which the Debian 1.0.20 headers do
// not install, are xr/loader_negotiation.hpp (shared with the eye-gaze layer); XR_KHR_locate_spaces,
// which they lack, is xr/khr_locate_spaces.h.
#pragma once

#include <time.h>
#include <vulkan/vulkan.h>

#define XR_USE_GRAPHICS_API_VULKAN 1
#define XR_USE_TIMESPEC 1
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include "xr/khr_locate_spaces.h"
#include "sim/runtime/simulator_state_ext.h"
