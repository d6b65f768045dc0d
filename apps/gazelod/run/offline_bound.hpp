// SPDX-License-Identifier: Apache-2.0
// The offline optimum of a run, bracketed: how few triangles a switch policy could have drawn,
// knowing the whole run in advance, never coarser than a given ceiling per object-frame, with at
// most a given number of switches outside suppression. It answers what the audit's breakdown cannot:
// of the triangles the switch policy kept above its own perceptual levels, how many a better
// policy could have saved at the same pop rate (the session's ceiling: the finer of the plugin's
// perceptual level and the oracle's, so that nothing is bought with a degradation), and what a
// perfect tracker would allow on top (ceiling = the oracle's levels). Neither is reachable
// online: the policy does not know how long a coarser level will stay allowed.
//
// Method. The switches counted and the triangles summed are the audit's (run/audit.hpp): in-view
// object-frames only, a switch where the level differs from the previous frame's in a frame that
// is in view and outside suppression. Objects are independent, so for a price per counted switch
// (in triangles) each object's cheapest sequence is a shortest path over (frame, level): stay,
// or switch from the cheapest level of the previous frame. The price is then bisected until the
// switch count fits the budget: a Lagrangian relaxation. The sequence returned is achievable
// within the budget and is the exact optimum for its own switch count (a corner of the trade-off's
// lower convex hull), so the exact optimum at the budget is at most it; the prices tried also
// give a lower bound (OfflinePoint::lower_triangles). The two can be apart where many objects
// trade at the same price. Drawing level 0 throughout is feasible with no switch, so a budget of
// 0 is always met.
//
// Cost: one pass over frames x objects x levels per price, about 25 prices (about a second per
// million object-frames of five levels, twice for the session's two ceilings). The caller keeps
// the frames' levels in memory (3 bytes per object-frame); kMaxOfflineObjectFrames bounds it.
#pragma once

#include "lod/lod_chain.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gazelod::cli {

// The most object-frames a run keeps for the bound (about 48 MB); a longer run has none.
inline constexpr std::size_t kMaxOfflineObjectFrames = std::size_t{16} << 20;

struct OfflineBoundInput {
  std::size_t objects = 0;                                          // per frame
  const std::vector<std::vector<lod::LodLevel>>* chains = nullptr;  // object i's levels
  std::span<const std::uint8_t> ceiling;     // frames x objects, frame-major: the coarsest level allowed
  std::span<const std::uint8_t> in_view;     // frames x objects: 1 where the object is in view
  std::span<const std::uint8_t> suppressed;  // per frame: 1 inside a suppression window
  // Optional (empty: not counted), frames x objects: the oracle's levels, to count the degraded
  // object-frames of the sequence found (coarser than the oracle, in view, outside suppression;
  // the audit's visible degradations). The bound does not avoid them: under a ceiling coarser
  // than the oracle it draws the ceiling wherever that saves triangles.
  std::span<const std::uint8_t> oracle;
};

struct OfflinePoint {
  bool available = false;
  std::string reason;            // why not, when not available
  std::uint64_t triangles = 0;   // in view, over the run (the audit's drawn triangles' twin)
  std::int64_t switches = 0;     // outside suppression, in view
  std::int64_t degraded = 0;     // with `oracle`: object-frames drawn coarser than it
  double price_triangles = 0.0;  // the Lagrange price per switch that gave this point
  // offline_bound only: no sequence within the budget draws fewer triangles than this (the best
  // Lagrangian lower bound over the prices tried); the exact optimum lies in [this, triangles].
  double lower_triangles = 0.0;
};

// The cheapest sequence for one price per counted switch (>= 0, finite). Refuses (available
// false, reason) input whose spans do not match objects x frames or whose chains are missing.
[[nodiscard]] OfflinePoint offline_optimum(const OfflineBoundInput& in, double price_triangles);

// The fewest triangles with at most max_switches switches (>= 0), by bisecting the price.
[[nodiscard]] OfflinePoint offline_bound(const OfflineBoundInput& in, std::int64_t max_switches);

}  // namespace gazelod::cli
