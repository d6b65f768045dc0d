// SPDX-License-Identifier: Apache-2.0
// The simulated system's fixed facts (one HMD, its limits) and the view configuration it
// offers: stereo, or mono for a one-view display.
#pragma once

#include "sim/runtime/runtime_state.hpp"

namespace gazelod::xrrt {

inline constexpr XrSystemId kSystemId = 1;
inline constexpr std::uint32_t kMaxImageSize = 8192;
inline constexpr std::uint32_t kMaxLayerCount = 16;
// Interpupillary distance used by xrLocateViews (the scenario format has no IPD).
inline constexpr double kIpdM = 0.063;

XrViewConfigurationType primary_view_configuration(const Instance& inst);
std::uint32_t view_count(const Instance& inst);
// XR_ERROR_HANDLE_INVALID for no instance, XR_ERROR_SYSTEM_INVALID for another system id.
XrResult check_system(const Instance* inst, XrSystemId systemId);

}  // namespace gazelod::xrrt
