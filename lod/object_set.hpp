// Per-object data for the selection in structure-of-arrays form (one span per field), and
// ObjectStore, an owning builder that validates LOD chains once at registration so the
// per-frame loop does not have to. Chains are flattened: object i's levels are
// level_weight[lod_first[i] .. lod_first[i] + lod_count[i]).
#pragma once

#include "lod/lod_chain.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gazelod::lod {

struct ObjectSet {
  std::span<const double> center_x_m, center_y_m, center_z_m;  // bounding-sphere centre, world
  std::span<const double> radius_m;                            // bounding-sphere radius, >= 0
  // World velocity; all three empty means every object is static.
  std::span<const double> vel_x_m_s, vel_y_m_s, vel_z_m_s;
  std::span<const DetailKind> detail_kind;  // per object (one kind per chain)
  std::span<const std::uint32_t> lod_first;  // per object, index into level_weight
  std::span<const std::uint8_t> lod_count;   // per object, levels in the chain (1..255)
  // Per level: removed cycles per object diameter, or 1 / geometric error (1/m); level 0's
  // entry is ignored (full detail is always allowed). Non-increasing along a chain.
  std::span<const double> level_weight;

  std::size_t size() const { return radius_m.size(); }
};

// The weight a level contributes (see ObjectSet::level_weight); 0 for a zero detail.
double level_weight(const LodLevel& level);

// "" when the set is consistent (span sizes, finite non-negative numbers, chains in range
// and ordered), else a message naming the first bad object and field.
std::string validate_objects(const ObjectSet& objects);

// "" for a valid chain: 1..255 levels, one kind, detail finite and > 0 from level 1 on,
// removed cycles non-increasing / geometric error non-decreasing towards coarser levels.
std::string validate_chain(std::span<const LodLevel> levels);

// Owns the arrays behind an ObjectSet. add() throws std::invalid_argument with the reason.
class ObjectStore {
 public:
  std::uint32_t add(const glm::dvec3& center_m, double radius_m, const glm::dvec3& velocity_m_s,
                    std::span<const LodLevel> levels);
  void set_motion(std::uint32_t id, const glm::dvec3& center_m, const glm::dvec3& velocity_m_s);
  void reserve(std::size_t objects, std::size_t levels);
  std::size_t size() const { return radius_.size(); }
  ObjectSet view() const;

 private:
  std::vector<double> cx_, cy_, cz_, radius_, vx_, vy_, vz_, weight_;
  std::vector<DetailKind> kind_;
  std::vector<std::uint32_t> first_;
  std::vector<std::uint8_t> count_;
};

}  // namespace gazelod::lod
