// SPDX-License-Identifier: Apache-2.0
// Per-object data for the selection in structure-of-arrays form (one span per field), and
// ObjectStore, an owning builder that validates LOD chains once at registration so the
// per-frame loop does not have to. Chains are flattened: object i's levels are
// level_weight[lod_first[i] .. lod_first[i] + lod_count[i]).
#pragma once

#include "lod/lod_chain.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gazelod::lod {

struct ObjectSet {
  std::span<const double> center_x_m, center_y_m, center_z_m;  // bounding-sphere centre, world
  std::span<const double> radius_m;                            // bounding-sphere radius, >= 0
  // World velocity; all three empty means every object is static.
  std::span<const double> vel_x_m_s, vel_y_m_s, vel_z_m_s;
  std::span<const DetailKind> detail_kind;   // per object (one kind per chain)
  std::span<const std::uint32_t> lod_first;  // per object, index into level_weight
  std::span<const std::uint8_t> lod_count;   // per object, levels in the chain (1..255)
  // Per level: removed cycles per object diameter, or 1 / geometric error (1/m); level 0's
  // entry is ignored (full detail is always allowed). Non-increasing along a chain. Float:
  // half the memory traffic of the selection's largest array; ObjectStore rounds towards
  // zero (level_weight_f), so a stored weight never allows a coarser level than the exact one.
  std::span<const float> level_weight;

  std::size_t size() const { return radius_m.size(); }
};

// The weight a level contributes (see ObjectSet::level_weight); 0 for a zero detail.
double level_weight(const LodLevel& level);
// The same, as stored: rounded towards zero to float.
float level_weight_f(const LodLevel& level);

// Weights a chain may have (validate_chain): well inside float's normal range.
inline constexpr double kMinLevelWeight = 1e-30, kMaxLevelWeight = 1e30;

// "" when the set is consistent (span sizes, finite non-negative numbers, chains in range
// and ordered), else a message naming the first bad object and field.
[[nodiscard]] std::string validate_objects(const ObjectSet& objects);

// Levels a chain may have (ObjectSet::lod_count is a uint8).
inline constexpr std::size_t kMaxChainLevels = 255;

// "" for a valid chain: 1..255 levels, one kind, detail finite and > 0 from level 1 on with a
// weight in [kMinLevelWeight, kMaxLevelWeight], removed cycles non-increasing / geometric
// error non-decreasing towards coarser levels.
[[nodiscard]] std::string validate_chain(std::span<const LodLevel> levels);

// The same check, for readers that name the bad level themselves (a scenario's JSON path):
// nullopt for a valid chain, else the level at fault (levels.size() when the count is wrong)
// and the message without validate_chain's "level k: " prefix.
struct ChainProblem {
  std::size_t level = 0;
  std::string message;
};
[[nodiscard]] std::optional<ChainProblem> find_chain_problem(std::span<const LodLevel> levels);

// Owns the arrays behind an ObjectSet. add() throws std::invalid_argument with the reason.
class ObjectStore {
 public:
  std::uint32_t add(const glm::dvec3& center_m, double radius_m, const glm::dvec3& velocity_m_s,
                    std::span<const LodLevel> levels);
  void set_motion(std::uint32_t id, const glm::dvec3& center_m, const glm::dvec3& velocity_m_s);
  // Removes object `id`: the last object moves into its place (ids stay dense). Its levels are
  // left as a hole, packed out when holes are half the levels: amortised constant time. Throws
  // std::out_of_range.
  void remove(std::uint32_t id);
  void reserve(std::size_t objects, std::size_t levels);
  std::size_t size() const { return radius_.size(); }
  ObjectSet view() const;

 private:
  std::vector<double> cx_, cy_, cz_, radius_, vx_, vy_, vz_;
  std::vector<float> weight_;
  std::vector<DetailKind> kind_;
  std::vector<std::uint32_t> first_;
  std::vector<std::uint8_t> count_;
  std::size_t dead_levels_ = 0;  // entries of weight_ that no object's chain covers
  void pack_levels() noexcept;
};

}  // namespace gazelod::lod
