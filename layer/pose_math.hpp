// SPDX-License-Identifier: Apache-2.0
// The layer's poses: the shared rigid-pose math (xr/pose_math.hpp) in this namespace, and the
// eye-gaze pose of a gaze sample.
#pragma once

#include "layer/xr_headers.hpp"
#include "xr/pose_math.hpp"

#include "gaze/gaze_sample.hpp"

#include <optional>

namespace gazelod::layer {

// The shared names, unqualified here as in the rest of this namespace.
using namespace gazelod::xr;

// The sample as a pose in the tracker's frame (-Z along the gaze, no roll); nullopt for an
// invalid or degenerate sample (no NaN reaches a pose).
inline std::optional<Pose> eye_pose(const gaze::GazeSample& s) {
  if (!s.valid) return std::nullopt;
  return gaze_ray_pose(s.direction, s.origin_m);
}

}  // namespace gazelod::layer
