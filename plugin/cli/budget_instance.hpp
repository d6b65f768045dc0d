// Reads frame-budget knapsack instances (docs/budget.md): {"capacity": c, "subsets":
// [[{"profit": p, "cost": w}, ...], ...], "groups": [...] optional}. Every error names the
// JSON path and why ("subsets[3][1].cost: must be a finite number >= 0").
#pragma once

#include "lod/mckp.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace gazelod::cli {

// Throws UsageError (exit 2) with "<where>: <path>: <why>"; `where` names the source (file).
lod::MckpInstance parse_budget_instance(const nlohmann::json& doc, const std::string& where);
lod::MckpInstance read_budget_instance(const std::string& path);

}  // namespace gazelod::cli
