// SPDX-License-Identifier: Apache-2.0
// Agreement of two per-sample event classifications of one trace: gazelod's classifier
// ("ours") against a reference (Pupil Cloud's own `fixation id` / `blink id`). Plain data in
// and out; `gazelod trace stats` calls it (trace_stats.hpp).
//
// Per sample: in an event or not, for each side; the confusion counts, the share of samples
// on which both agree, and Cohen's (1960) kappa, (p_o - p_e) / (1 - p_e) with p_e the
// agreement expected by chance from each side's share of event samples. Per event: how many
// each side has (distinct ids) and how many of one side's share at least one sample with an
// event of the other.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace gazelod::gaze {

struct ConfusionCounts {
  std::size_t both = 0;  // in an event for both
  std::size_t ours_only = 0;
  std::size_t reference_only = 0;
  std::size_t neither = 0;
  std::size_t total() const { return both + ours_only + reference_only + neither; }
};

struct EventAgreement {
  ConfusionCounts samples;
  double agreement = 0.0;  // (both + neither) / total; 0 when there are no samples
  // nullopt when chance agreement is 1 (both sides put every sample in the same class), where
  // kappa is 0 / 0; never NaN.
  std::optional<double> kappa;
  std::size_t ours_events = 0, reference_events = 0;
  std::size_t reference_overlapped = 0;  // reference events sharing a sample with one of ours
  std::size_t ours_overlapped = 0;       // our events sharing a sample with a reference event
};

// ours[i], reference[i]: the event id of sample i, 0 = in no such event; the samples of one
// event share its id (ids need not be contiguous or ordered). Throws std::invalid_argument
// when the lengths differ.
EventAgreement compare_events(std::span<const std::uint32_t> ours, std::span<const std::uint32_t> reference);

}  // namespace gazelod::gaze
