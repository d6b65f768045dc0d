// SPDX-License-Identifier: Apache-2.0
// The simulated runtime's poses: the shared rigid-pose math (xr/pose_math.hpp) in this namespace.
#pragma once

#include "sim/runtime/xr_headers.hpp"
#include "xr/pose_math.hpp"

namespace gazelod::xrrt {

// The shared names, unqualified here as in the rest of this namespace.
using namespace gazelod::xr;

}  // namespace gazelod::xrrt
