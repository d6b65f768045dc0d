// SPDX-License-Identifier: Apache-2.0
// gazelod eval family --against FILE: this run beside an earlier one of the same seeds (that
// run's family.json). A tuning step is judged by which seeds enter or leave each target, not only
// by how the medians move: a change that brings five seeds within the triangle target and pushes
// one past the degradation target is a trade, and the report should say so without a script.
//
//   FamilyBaseline base = read_family_baseline("before/family.json");  // before any seed runs
//   check_same_run(base, first, count, duration_s);
//   ... run_family(...) -> members ...
//   std::string md = against_markdown(members, base);  nlohmann::json j = against_json(members, base);
//
// Errors (UsageError, exit 2) name the file and the JSON path, or the line and column of a
// syntax error: "--against: a.json: members[3].audit.triangles_in_view.drawn_over_oracle:
// expected a number >= 0, got string".
#pragma once

#include "apps/gazelod/eval/family.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::cli {

// A family.json larger than this is refused before it is parsed (10 000 seeds with their
// breakdowns are ~60 MB).
inline constexpr std::uint64_t kMaxBaselineBytes = 256ull << 20;

// One seed's three target figures from the earlier run.
struct BaselineRow {
  std::uint64_t seed = 0;
  double degraded_share = 0.0;  // of fixation object-frames, 0..1
  double triangle_ratio = 0.0;  // drawn / oracle
  double switches_per_object_s = 0.0;
};

struct FamilyBaseline {
  std::string source;                         // the file, as given
  std::vector<std::string> settings_changed;  // that run's --set and what-ifs
  double duration_s = 0.0;                    // seconds per scenario
  std::vector<BaselineRow> rows;              // in seed order
};

// Reads an earlier `gazelod eval family` report. Throws UsageError for a missing or unreadable
// file, one over kMaxBaselineBytes, bad JSON, a missing or mistyped figure, a seed twice.
FamilyBaseline read_family_baseline(const std::string& path);

// Throws UsageError unless the baseline ran scenarios of duration_s and holds exactly seeds
// [first, first + count): figures of other seeds, or of the same seeds run for another time,
// would compare other scenarios. So would other eyes: `recording` is this run's
// "recording=PATH" entry of settings_changed ("" for the family's own eyes), and the
// baseline's must be the same. (What-ifs such as --ideal, --criteria or --set may differ:
// comparing them is the point.)
void check_same_run(const FamilyBaseline& base, std::uint64_t first, int count, double duration_s,
                    const std::string& recording = "");

// The comparison section of family.md (members: the seeds of the baseline, in order, else
// UsageError): per target, how many seeds are within before and now, and
// which entered or left it; each figure's median, 90th percentile and worst before and now; the
// seeds whose standing changed, with their figures.
std::string against_markdown(const std::vector<FamilyMember>& members, const FamilyBaseline& base);
// The same for family.json ("against").
nlohmann::json against_json(const std::vector<FamilyMember>& members, const FamilyBaseline& base);

}  // namespace gazelod::cli
