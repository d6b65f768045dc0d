// SPDX-License-Identifier: Apache-2.0
// An object's chain of levels of detail, as the selection and the budget see it.
// Level 0 is full detail; each coarser level says how much detail it removes (Reddy 1998, 3.2).
#pragma once

#include <cstdint>

namespace gazelod::lod {

// How a level's removed detail is described. Either way it has a size in metres (geometric
// error e, or r / c for c cycles across a diameter 2r: half a cycle), and the selection sees
// that size from the nearest point of the object's bounding sphere (lod/select.hpp), where it
// subtends the most: the centre's distance would under-state it by d / (d - r), without bound
// for a large object the viewer stands in or next to.
enum class DetailKind : std::uint8_t {
  // Highest spatial frequency removed, in cycles per object diameter (Reddy's measure,
  // from rendering the level against the full model).
  removed_cycles_per_diameter,
  // Geometric error in object units (metres); a stand-in: an error subtending angle a removes
  // detail of about 1 / (2a) cycles/deg.
  geometric_error_m,
};

// Nearest-point distances are floored here (metres): an eye inside a sphere (or within this of
// it) sees its detail from this distance, so no visible detail goes by size there.
inline constexpr double kNearestPointFloorM = 1e-6;

struct LodLevel {
  std::uint32_t triangles = 0;
  std::uint32_t vertices = 0;
  DetailKind detail_kind = DetailKind::removed_cycles_per_diameter;
  double detail = 0.0;  // 0 for the full-detail level
};

}  // namespace gazelod::lod
