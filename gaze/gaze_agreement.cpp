// SPDX-License-Identifier: Apache-2.0
#include "gaze/gaze_agreement.hpp"

#include <stdexcept>
#include <string>
#include <unordered_map>

namespace gazelod::gaze {
namespace {

// Event id -> whether one of its samples lies in an event of the other side.
using Overlaps = std::unordered_map<std::uint32_t, bool>;

std::size_t count_overlapped(const Overlaps& events) {
  std::size_t n = 0;
  for (const auto& [id, overlapped] : events) n += overlapped;
  return n;
}

}  // namespace

EventAgreement compare_events(std::span<const std::uint32_t> ours, std::span<const std::uint32_t> reference) {
  if (ours.size() != reference.size())
    throw std::invalid_argument("compare_events: " + std::to_string(ours.size()) + " samples of ours, " +
                                std::to_string(reference.size()) + " of the reference");
  EventAgreement a;
  ConfusionCounts& c = a.samples;
  Overlaps ours_events, reference_events;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    const bool o = ours[i] != 0, r = reference[i] != 0;
    if (o && r)
      ++c.both;
    else if (o)
      ++c.ours_only;
    else if (r)
      ++c.reference_only;
    else
      ++c.neither;
    if (o) ours_events[ours[i]] |= r;
    if (r) reference_events[reference[i]] |= o;
  }
  a.ours_events = ours_events.size();
  a.reference_events = reference_events.size();
  a.ours_overlapped = count_overlapped(ours_events);
  a.reference_overlapped = count_overlapped(reference_events);

  const std::size_t n = c.total();
  if (n == 0) return a;
  const double total = static_cast<double>(n);
  const double observed = static_cast<double>(c.both + c.neither) / total;
  const double p_ours = static_cast<double>(c.both + c.ours_only) / total;
  const double p_reference = static_cast<double>(c.both + c.reference_only) / total;
  const double chance = p_ours * p_reference + (1.0 - p_ours) * (1.0 - p_reference);
  a.agreement = observed;
  // chance == 1 only when both sides are constant and equal (then observed is 1 too).
  if (1.0 - chance > 1e-12) a.kappa = (observed - chance) / (1.0 - chance);
  return a;
}

}  // namespace gazelod::gaze
