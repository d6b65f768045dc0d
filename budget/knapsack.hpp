// SPDX-License-Identifier: Apache-2.0
// The frame-budget knapsack solvers behind one call (Funkhouser & Sequin 1993 sec. 6;
// Mason 1999 Ch. 2-3, 6-7). Each solver is one source file, knapsack_<name>.cpp; all take an
// MckpInstance and return an MckpSolution, and break ties by one strict order (mckp.hpp).
#pragma once

#include "budget/mckp.hpp"

#include <optional>
#include <span>
#include <string_view>

namespace gazelod::budget {

enum class SolverKind : std::uint8_t {
  exact,                   // branch and bound with the LP bound; proves optimality
  funkhouser,              // F&S greedy by value p/w, as published (may be infeasible)
  funkhouser_incremental,  // F&S incremental by value, from the lowest level
  mason_greedy,            // Mason Fig. 20: simplified greedy by relative value + critical item
  mason_full,              // Mason Fig. 22: full greedy, half-optimal without convexity
  mason_incremental,       // Mason Fig. 41: incremental, here from the lowest level
  mason_hierarchical,      // Mason Fig. 39-40: HMCKP greedy over the instance's groups
};

std::span<const std::string_view> solver_names();
std::optional<SolverKind> solver_from_name(std::string_view name);
std::string_view solver_name(SolverKind kind);

// Whether the solver is one of the incremental ones (the only ones `limits` applies to).
bool is_incremental(SolverKind kind);

// One-shot solve. Flat solvers ignore `instance.groups` (every subset drawn by its own item);
// the hierarchical and incremental ones use them. `limits` truncates the incremental solvers
// (default: none, so they run to convergence); the others ignore it. Every solver's answer is a
// function of its input (and `limits.max_moves`) alone unless `limits.wall_clock_limit` is set.
// Throws std::invalid_argument when the solver cannot take the instance (e.g. too large for
// `exact`).
MckpSolution solve(SolverKind kind, const MckpInstance& instance, const SolveLimits& limits = {});

// The solvers, one per file.
MckpSolution solve_exact(const MckpInstance& instance, std::uint64_t node_limit = 50'000'000);
MckpSolution solve_funkhouser(const MckpInstance& instance);
MckpSolution solve_funkhouser_incremental(const MckpInstance& instance, const SolveLimits& limits = {});
// fill_after_critical: Fig. 20 as published keeps trying cheaper moves after the first that
// does not fit; false stops there (the state the incremental algorithm converges to).
MckpSolution solve_mason_greedy(const MckpInstance& instance, bool fill_after_critical = true);
MckpSolution solve_mason_full(const MckpInstance& instance);
MckpSolution solve_mason_incremental(const MckpInstance& instance, const SolveLimits& limits = {});
MckpSolution solve_mason_hierarchical(const MckpInstance& instance, bool fill_after_critical = true);

}  // namespace gazelod::budget
