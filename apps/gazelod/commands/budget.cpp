// SPDX-License-Identifier: Apache-2.0
// gazelod budget: solves one frame-budget knapsack instance with a named solver
// (docs/budget.md). Exit 0 with a feasible answer; 2 malformed input; 3 the instance is
// infeasible (its cheapest level of detail exceeds the capacity); 4 the solver's answer is
// infeasible although the instance is not (Funkhouser & Sequin's greedy, Mason's
// counterexample 1) -- the answer is still printed, with "feasible": false.
// Deterministic: the same instance file and options print the same output on every run. The
// incremental solvers stop at --max-moves if given; a wall-clock limit (--time-limit-ms) applies
// only when asked for, and then the answer depends on timing.
#include "auxiliary/time.hpp"
#include "budget/knapsack.hpp"
#include "budget/budget_instance.hpp"
#include "apps/gazelod/commands/command.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <chrono>
#include <cctype>
#include <cstdint>
#include <memory>
#include <sstream>

namespace gazelod::cli {
namespace {

struct Options {
  std::string instance;
  std::string solver;
  bool json = false;
  std::string max_moves;                       // parsed when given
  std::string time_limit_ms;                   // parsed when given
  const CLI::Option* max_moves_opt = nullptr;  // given: count() > 0
  const CLI::Option* time_limit_opt = nullptr;
};

// A move count: decimal digits only (CLI11 would wrap "-1" around to 2^64 - 1).
std::uint64_t parse_moves(const std::string& text) {
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || !std::isdigit(static_cast<unsigned char>(text.front())) || ec != std::errc{} ||
      end != text.data() + text.size())
    throw UsageError("--max-moves: '" + text + "' is not a whole number of moves >= 0");
  return v;
}

std::string names_list() {
  std::string s;
  for (std::string_view n : budget::solver_names()) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

int solve_and_print(const Options& o, Io io) {
  const auto kind = budget::solver_from_name(o.solver);
  if (!kind) throw UsageError("--solver: unknown solver '" + o.solver + "' (one of: " + names_list() + ")");
  budget::MckpInstance inst;
  try {
    inst = budget::read_budget_instance(o.instance);
  } catch (const budget::InstanceError& e) {
    throw UsageError(e.what());
  }
  budget::SolveLimits limits;
  const bool incremental = budget::is_incremental(*kind);
  const bool max_moves_given = o.max_moves_opt->count() > 0;
  const bool time_limit_given = o.time_limit_opt->count() > 0;
  if ((max_moves_given || time_limit_given) && !incremental)
    throw UsageError(std::string(max_moves_given ? "--max-moves" : "--time-limit-ms") +
                     ": applies to the incremental solvers only (funkhouser-incremental, "
                     "mason-incremental), not " +
                     o.solver);
  if (max_moves_given) limits.max_moves = parse_moves(o.max_moves);
  if (time_limit_given) {  // explicit only: the answer then depends on timing
    const double ms = parse_number("--time-limit-ms", o.time_limit_ms);
    if (!(ms >= 0.0 && ms <= 1e9)) throw UsageError("--time-limit-ms: must be in [0, 1e9] ms, got " + o.time_limit_ms);
    limits.wall_clock_limit = std::chrono::nanoseconds(aux::ns_from_ms(ms));
  }
  budget::MckpSolution sol;
  try {
    sol = budget::solve(*kind, inst, limits);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--solver ") + o.solver + ": " + e.what());
  }
  // The reader keeps every reachable sum finite; an answer that is not is a solver's fault.
  if (!std::isfinite(sol.profit) || !std::isfinite(sol.cost))
    throw UsageError("--solver " + o.solver + ": the answer's profit or cost is not finite (overflow)", 1);
  const bool flat = *kind != budget::SolverKind::mason_incremental && *kind != budget::SolverKind::mason_hierarchical;
  if (!sol.feasible) {
    // Is the instance itself infeasible? Its cheapest level: every subset's cheapest item, or
    // for the hierarchical solvers the cheapest representation of the hierarchy.
    budget::MckpInstance flat_inst = inst;
    flat_inst.groups.clear();
    const double lowest =
        flat || inst.groups.empty() ? budget::lowest_cost(flat_inst) : budget::solve_mason_hierarchical(inst).cost;
    if (lowest > inst.capacity) {
      std::ostringstream msg;
      msg << "infeasible instance: the cheapest level of detail costs " << lowest << " > capacity " << inst.capacity;
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
    for (std::uint32_t c : sol.choice)
      sel.push_back(c == budget::kNoItem ? nlohmann::json(nullptr) : nlohmann::json(c));
    j["selection"] = sel;
    if (!inst.groups.empty()) {
      nlohmann::json g = nlohmann::json::array();
      for (std::uint32_t c : sol.group_choice)
        g.push_back(c == budget::kNoItem ? nlohmann::json(nullptr) : nlohmann::json(c));
      j["groups"] = g;
    }
    if (*kind == budget::SolverKind::exact) j["optimal"] = sol.proven_optimal;
    if (sol.error_bound >= 0.0) j["error_bound"] = sol.error_bound;
    if (incremental) {
      j["moves"] = sol.iterations;
      j["truncated"] = sol.truncated;
    }
    io.out << aux::json_text(j) << "\n";
  } else {
    io.out << "solver:    " << o.solver << "\nprofit:    " << sol.profit << "\ncost:      " << sol.cost
           << " of capacity " << inst.capacity << "\nfeasible:  " << (sol.feasible ? "yes" : "NO") << "\nselection:";
    for (std::uint32_t c : sol.choice) {
      if (c == budget::kNoItem)
        io.out << " -";
      else
        io.out << " " << c;
    }
    io.out << "\n";
    if (!inst.groups.empty()) {
      io.out << "groups:   ";
      for (std::uint32_t c : sol.group_choice) {
        if (c == budget::kNoItem)
          io.out << " -";
        else
          io.out << " " << c;
      }
      io.out << "\n";
    }
    if (*kind == budget::SolverKind::exact)
      io.out << "optimal:   " << (sol.proven_optimal ? "proven" : "NOT proven (node limit)") << "\n";
    if (incremental)
      io.out << "moves:     " << sol.iterations << (sol.truncated ? " (truncated: stopped at its limit)" : "") << "\n";
  }
  if (!sol.feasible) {
    std::size_t empty = 0;
    for (std::uint32_t c : sol.choice) empty += c == budget::kNoItem;
    io.err << "gazelod budget: solver " << o.solver << " returned an infeasible answer"
           << (sol.cost > inst.capacity ? " (over capacity)" : "") << " with " << empty
           << " subset(s) left empty (a known flaw of Funkhouser & Sequin's greedy, Mason 1999 "
              "counterexample 1)\n";
    return 4;
  }
  return 0;
}

// With --json every error is also one JSON object on stdout, {"error": message, "exit_code":
// n, "kind": ...}, so a script reading stdout sees why there is no answer; stderr keeps the
// usual "gazelod budget: ..." line.
int run_budget(const Options& o, Io io) {
  auto report = [&](const std::string& message, int code) {
    if (!o.json) return;
    const char* kind = code == 2 ? "bad_input" : code == 3 ? "infeasible_instance" : "error";
    io.out << aux::json_text(nlohmann::json{{"error", message}, {"exit_code", code}, {"kind", kind}}) << "\n";
  };
  try {
    return solve_and_print(o, io);
  } catch (const UsageError& e) {
    report(e.what(), e.exit_code);
    throw;
  } catch (const std::exception& e) {
    report(std::string("error: ") + e.what(), 1);
    throw;
  }
}

const Registrar registrar{
    "budget", "Solve a frame-budget knapsack instance (Funkhouser & Sequin 1993, Mason 1999)",
    [](CLI::App& sub) -> Action {
      auto o = std::make_shared<Options>();
      sub.add_option("--instance", o->instance, "instance JSON file (see docs/budget.md)")->required();
      sub.add_option("--solver", o->solver, "solver: " + names_list())->required();
      sub.add_flag("--json", o->json, "print the answer as JSON");
      o->max_moves_opt =
          sub.add_option("--max-moves", o->max_moves,
                         "incremental solvers: stop after N moves (increments + decrements; deterministic). "
                         "Default: run to convergence");
      o->time_limit_opt = sub.add_option("--time-limit-ms", o->time_limit_ms,
                                         "incremental solvers: also stop after this much wall time (off by default; "
                                         "makes the answer depend on timing)");
      return [o](Io io) { return run_budget(*o, io); };
    }};

}  // namespace
}  // namespace gazelod::cli
