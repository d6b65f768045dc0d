// SPDX-License-Identifier: Apache-2.0
#include "budget/knapsack.hpp"

#include <array>
#include <stdexcept>

namespace gazelod::budget {
namespace {

constexpr std::array<std::string_view, 7> kNames = {
    "exact",      "funkhouser",        "funkhouser-incremental", "mason-greedy",
    "mason-full", "mason-incremental", "mason-hierarchical"};

}  // namespace

std::span<const std::string_view> solver_names() {
  return kNames;
}

std::optional<SolverKind> solver_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return static_cast<SolverKind>(i);
  return std::nullopt;
}

std::string_view solver_name(SolverKind kind) {
  return kNames[static_cast<std::size_t>(kind)];
}

bool is_incremental(SolverKind kind) {
  return kind == SolverKind::funkhouser_incremental || kind == SolverKind::mason_incremental;
}

MckpSolution solve(SolverKind kind, const MckpInstance& instance, const SolveLimits& limits) {
  switch (kind) {
    case SolverKind::exact:
      return solve_exact(instance);
    case SolverKind::funkhouser:
      return solve_funkhouser(instance);
    case SolverKind::funkhouser_incremental:
      return solve_funkhouser_incremental(instance, limits);
    case SolverKind::mason_greedy:
      return solve_mason_greedy(instance);
    case SolverKind::mason_full:
      return solve_mason_full(instance);
    case SolverKind::mason_incremental:
      return solve_mason_incremental(instance, limits);
    case SolverKind::mason_hierarchical:
      return solve_mason_hierarchical(instance);
  }
  throw std::invalid_argument("unknown solver");
}

}  // namespace gazelod::budget
