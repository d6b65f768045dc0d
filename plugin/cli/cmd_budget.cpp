// gazelod budget: solves one frame-budget knapsack instance with a named solver
// (docs/budget.md). Exit 0 with a feasible answer; 2 malformed input; 3 the instance is
// infeasible (its cheapest level of detail exceeds the capacity); 4 the solver's answer is
// infeasible although the instance is not (Funkhouser & Sequin's greedy, Mason's
// counterexample 1) -- the answer is still printed, with "feasible": false.
#include "lod/knapsack.hpp"
#include "plugin/cli/budget_instance.hpp"
#include "plugin/cli/command.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <sstream>

namespace gazelod::cli {
namespace {

struct Options {
  std::string instance;
  std::string solver;
  bool json = false;
};

std::string names_list() {
  std::string s;
  for (std::string_view n : lod::solver_names()) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

int run_budget(const Options& o, Io io) {
  const auto kind = lod::solver_from_name(o.solver);
  if (!kind) throw UsageError("--solver: unknown solver '" + o.solver + "' (one of: " + names_list() + ")");
  const lod::MckpInstance inst = read_budget_instance(o.instance);
  lod::MckpSolution sol;
  try {
    sol = lod::solve(*kind, inst);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--solver ") + o.solver + ": " + e.what());
  }
  const bool flat = *kind != lod::SolverKind::mason_incremental && *kind != lod::SolverKind::mason_hierarchical;
  if (!sol.feasible) {
    // Is the instance itself infeasible? Its cheapest level: every subset's cheapest item, or
    // for the hierarchical solvers the cheapest representation of the hierarchy.
    lod::MckpInstance flat_inst = inst;
    flat_inst.groups.clear();
    const double lowest = flat || inst.groups.empty() ? lod::lowest_cost(flat_inst)
                                                      : lod::solve_mason_hierarchical(inst).cost;
    if (lowest > inst.capacity) {
      std::ostringstream msg;
      msg << "infeasible instance: the cheapest level of detail costs " << lowest
          << " > capacity " << inst.capacity;
      throw UsageError(msg.str(), 3);
    }
  }
  if (o.json) {
    nlohmann::json j;
    j["solver"] = o.solver;
    j["profit"] = sol.profit;
    j["cost"] = sol.cost;
    j["capacity"] = inst.capacity;
    j["feasible"] = sol.feasible;
    nlohmann::json sel = nlohmann::json::array();
    for (std::uint32_t c : sol.choice) sel.push_back(c == lod::kNoItem ? nlohmann::json(nullptr) : nlohmann::json(c));
    j["selection"] = sel;
    if (!inst.groups.empty()) {
      nlohmann::json g = nlohmann::json::array();
      for (std::uint32_t c : sol.group_choice) g.push_back(c == lod::kNoItem ? nlohmann::json(nullptr) : nlohmann::json(c));
      j["groups"] = g;
    }
    if (*kind == lod::SolverKind::exact) j["optimal"] = sol.proven_optimal;
    if (sol.error_bound >= 0.0) j["error_bound"] = sol.error_bound;
    io.out << j.dump() << "\n";
  } else {
    io.out << "solver:    " << o.solver << "\nprofit:    " << sol.profit << "\ncost:      " << sol.cost
           << " of capacity " << inst.capacity << "\nfeasible:  " << (sol.feasible ? "yes" : "NO")
           << "\nselection:";
    for (std::uint32_t c : sol.choice) {
      if (c == lod::kNoItem) io.out << " -";
      else io.out << " " << c;
    }
    io.out << "\n";
    if (!inst.groups.empty()) {
      io.out << "groups:   ";
      for (std::uint32_t c : sol.group_choice) {
        if (c == lod::kNoItem) io.out << " -";
        else io.out << " " << c;
      }
      io.out << "\n";
    }
    if (*kind == lod::SolverKind::exact) io.out << "optimal:   " << (sol.proven_optimal ? "proven" : "NOT proven (node limit)") << "\n";
  }
  if (!sol.feasible) {
    std::size_t empty = 0;
    for (std::uint32_t c : sol.choice) empty += c == lod::kNoItem;
    io.err << "gazelod budget: solver " << o.solver << " returned an infeasible answer"
           << (sol.cost > inst.capacity ? " (over capacity)" : "") << " with " << empty
           << " subset(s) left empty (a known flaw of Funkhouser & Sequin's greedy, Mason 1999 "
              "counterexample 1)\n";
    return 4;
  }
  return 0;
}

const Registrar registrar{
    "budget", "Solve a frame-budget knapsack instance (Funkhouser & Sequin 1993, Mason 1999)",
    [](CLI::App& sub) -> Action {
      auto o = std::make_shared<Options>();
      sub.add_option("--instance", o->instance, "instance JSON file (see docs/budget.md)")->required();
      sub.add_option("--solver", o->solver, "solver: " + names_list())->required();
      sub.add_flag("--json", o->json, "print the answer as JSON");
      return [o](Io io) { return run_budget(*o, io); };
    }};

}  // namespace
}  // namespace gazelod::cli
