// SPDX-License-Identifier: Apache-2.0
// Fuzzes the frame-budget instance reader (a JSON file in, MckpInstance out). Invariants: an accepted
// instance has a finite capacity >= 0, finite costs >= 0 and finite profits, and consistent
// subset offsets; small accepted instances are also solved, and a solution never exceeds the
// capacity when the cheapest choice fits.
#include "fuzz/fuzz_entry.hpp"

#include "budget/knapsack.hpp"
#include "budget/mckp.hpp"
#include "budget/budget_instance.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>
#include <stdexcept>

namespace gazelod::fuzz {

int budget_instance(const std::uint8_t* data, std::size_t size) {
  // Through the file reader `gazelod budget --instance` uses (JSON errors included).
  static const std::string path = [] {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir && *dir ? dir : "/tmp") + "/gazelod_fuzz_budget_" + std::to_string(::getpid()) + ".json";
  }();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  budget::MckpInstance inst;
  try {
    inst = budget::read_budget_instance(path);
  } catch (const budget::InstanceError&) {
    std::remove(path.c_str());
    return 0;  // the documented rejection (names the file and the JSON path)
  }
  std::remove(path.c_str());
  check(std::isfinite(inst.capacity) && inst.capacity >= 0.0, "capacity not finite and >= 0");
  check(!inst.subset_offsets.empty() && inst.subset_offsets.front() == 0 &&
            inst.subset_offsets.back() == inst.items.size(),
        "subset offsets do not cover the items");
  for (std::size_t k = 0; k + 1 < inst.subset_offsets.size(); ++k)
    check(inst.subset_offsets[k] <= inst.subset_offsets[k + 1], "subset offsets decrease");
  for (const budget::MckpItem& item : inst.items) {
    check(std::isfinite(item.cost) && item.cost >= 0.0, "item cost not finite and >= 0");
    check(std::isfinite(item.profit), "item profit not finite");
  }
  // Small instances go through every solver (as `gazelod budget` would); bounded so one input
  // stays fast (the exact solver is exponential).
  if (inst.items.size() > 64) return 0;
  for (std::string_view name : budget::solver_names()) {
    const auto kind = budget::solver_from_name(name);
    check(kind.has_value(), "solver_names() lists a name solver_from_name rejects");
    if (name == "exact" && inst.items.size() > 20) continue;
    try {
      const budget::MckpSolution sol = budget::solve(*kind, inst);
      check(std::isfinite(sol.profit) && std::isfinite(sol.cost), "solution not finite");
      if (sol.feasible)
        check(sol.cost <= inst.capacity * (1.0 + 1e-9) + 1e-12, "a feasible solution exceeds the capacity");
    } catch (const std::invalid_argument&) {
      // documented: the solver cannot take this instance
    }
  }
  return 0;
}

}  // namespace gazelod::fuzz

GAZELOD_FUZZ_TARGET(budget_instance)
