// SPDX-License-Identifier: Apache-2.0
// Which input sources an action reads in a session: the suggested bindings of each active
// device's current interaction profile (OpenXR 1.0 section 11.4 "Suggested Bindings").
#pragma once

#include "sim/runtime/runtime_state.hpp"

#include <vector>

namespace gazelod::xrrt {

// Bound input paths of `action` on active devices; `subaction` XR_NULL_PATH means all.
std::vector<XrPath> bound_sources(const Instance& inst, const Session& session, const Action& action, XrPath subaction);
// True when the session has attached the action's set.
bool is_attached(const Session& session, const Action& action);
// XR_SUCCESS when `subaction` is XR_NULL_PATH or one of the action's subaction paths,
// XR_ERROR_PATH_INVALID for an unknown path, XR_ERROR_PATH_UNSUPPORTED otherwise.
XrResult check_subaction(const Instance& inst, const Action& action, XrPath subaction);

}  // namespace gazelod::xrrt
