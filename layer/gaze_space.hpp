// SPDX-License-Identifier: Apache-2.0
// Locating through a gaze space (gaze_space.cpp), shared by every command that takes a space:
// xrLocateSpace, xrLocateSpaces(KHR) and xrLocateViews (locate_spaces.cpp), and
// xrEndFrame's composition layers (end_frame.cpp). A gaze space's handle is a VIEW space on the
// runtime, so what the runtime answers for it is the head; these put the eye in that head.
#pragma once

#include "layer/layer_state.hpp"

#include <cstdint>
#include <optional>

namespace gazelod::layer {

// A space's eye pose in its head (VIEW) space at a time, when it is a gaze space that has one.
struct EyeAt {
  bool is_gaze = false;
  std::optional<Pose> eye;  // tracker offset * sample * poseInActionSpace; none: not located
  std::int64_t sample_time_ns = 0;
};

// Called with layer_state().mutex held. Not a gaze space: is_gaze false. A gaze space without a
// fresh sample at t_ns (or whose action is not active as of the last xrSyncActions): no eye.
EyeAt eye_at(EmulatedInstance& e, XrSpace space, std::int64_t t_ns);

// xrLocateSpace of (space, base) at `time` through `next` (the runtime's xrLocateSpace), given
// what eye_at said of each: neither a gaze space, passed down as is; otherwise the runtime's
// head pose(s) composed with the eye pose(s), the chain filled (sample time; no velocity).
// Called without the lock.
XrResult locate_pair(PFN_xrLocateSpace next, XrSpace space, XrSpace base, XrTime time, const EyeAt& of_space,
                     const EyeAt& of_base, XrSpaceLocation* location);

}  // namespace gazelod::layer
