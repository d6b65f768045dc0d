// SPDX-License-Identifier: Apache-2.0
// Why an object got its level: the criterion of Reddy's rule (1998) that allows it. The
// selection writes one value per object (Decisions::limited_by), the plugin hands it on
// (FrameDecisions::limited_by), reports count it.
#pragma once

#include <cstdint>

namespace gazelod::lod {

enum class Criterion : std::uint8_t {
  none = 0,           // level 0: no criterion allows a coarser level
  size = 1,           // size alone (the object's angular size at s * min(60, xi)) allows it
  eccentricity = 2,   // eccentricity alone (M(E), with size) allows it
  velocity = 3,       // retinal velocity alone (G(v), with size) allows it
  combined = 4,       // only the product G(v) M(E) (with size) allows it
  invalid_input = 5,  // object data not finite or its chain out of range: level 0 kept
};
const char* to_string(Criterion c);

// The rule that names the criterion, from the levels each criterion allows on its own
// (size, size+eccentricity, size+velocity; a switched-off criterion allows 0) and the level
// chosen. The innermost choice first; each step is one two-way blend, so the vectorised
// selection kernel (Count = float, 16 objects a vector) and the scalar path (Count =
// unsigned) share it.
template <class Count>
[[gnu::always_inline]] inline Count limiting_criterion(Count chosen, Count size_only, Count eccentricity_only,
                                                       Count velocity_only) {
  Count why = chosen == velocity_only ? Count(Criterion::velocity) : Count(Criterion::combined);
  why = chosen == eccentricity_only ? Count(Criterion::eccentricity) : why;
  why = chosen == size_only ? Count(Criterion::size) : why;
  why = chosen == Count(0) ? Count(Criterion::none) : why;
  return why;
}

}  // namespace gazelod::lod
