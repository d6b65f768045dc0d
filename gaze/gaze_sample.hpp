// SPDX-License-Identifier: Apache-2.0
// Gaze and head samples: the plain data every gaze source, trace file and filter exchanges.
// Axes are OpenXR's: in head space -Z is forward, +Y up, +X right. Times are nanoseconds on
// the host clock the frame loop uses.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace gazelod::gaze {

struct GazeSample {
  std::int64_t t_ns = 0;                 // when the sample was actually taken
  glm::dvec3 direction{0.0, 0.0, -1.0};  // unit vector, head space
  glm::dvec3 origin_m{0.0, 0.0, 0.0};    // cyclopean eye position, head space
  bool valid = false;
  float confidence = 0.0f;  // 0..1
};

struct HeadSample {
  std::int64_t t_ns = 0;
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // head-to-world (w, x, y, z)
  glm::dvec3 position_m{0.0, 0.0, 0.0};
  bool valid = false;
};

// One row of a gaze trace: a gaze sample, and the head pose when the trace has one.
struct TraceRecord {
  GazeSample gaze;
  bool has_head = false;
  HeadSample head;
};

}  // namespace gazelod::gaze
