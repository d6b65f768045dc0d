// SPDX-License-Identifier: Apache-2.0
// `gazelod compare`'s output: a terminal table, the JSON document (a contract other checks
// rely on: {"hmds": [{"hmd", "xi_cpd", "runs": {SET: {"triangles", "average_lod"}}, "audit"}]},
// "audit" as in each run's summary.json, run/audit.hpp) and
// an SVG bar chart of triangles per criteria set and HMD.
#pragma once

#include "apps/gazelod/compare/runs.hpp"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <ostream>
#include <vector>

namespace gazelod::cli {

// Runs hold "triangles" (mean per frame, per eye), "triangles_total" and "average_lod".
nlohmann::json compare_json(const std::vector<HmdComparison>& results);
void print_compare_table(const std::vector<HmdComparison>& results, std::ostream& out, bool breakdown = false);
// Writes compare.svg into `dir`; throws std::runtime_error naming the file on failure.
void write_compare_chart(const std::vector<HmdComparison>& results, const std::filesystem::path& dir);

}  // namespace gazelod::cli
