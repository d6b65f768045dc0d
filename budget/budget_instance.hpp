// SPDX-License-Identifier: Apache-2.0
// Reads frame-budget knapsack instances (docs/budget.md): {"capacity": c, "subsets":
// [[{"profit": p, "cost": w}, ...], ...], "groups": [...] optional}. Every error names the
// JSON path and why ("subsets[3][1].cost: must be a finite number >= 0"). Profits and costs
// are finite and >= 0, and the largest total any answer can reach must not overflow a double.
#pragma once

#include "budget/mckp.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

namespace gazelod::budget {

// A malformed or unreadable instance: "<where>: <path>: <why>"; `where` names the source (file).
struct InstanceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Both throw InstanceError.
MckpInstance parse_budget_instance(const nlohmann::json& doc, const std::string& where);
MckpInstance read_budget_instance(const std::string& path);

}  // namespace gazelod::budget
