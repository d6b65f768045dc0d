// SPDX-License-Identifier: Apache-2.0
// Validation and the owning builder for ObjectSet (see object_set.hpp).
#include "lod/object_set.hpp"

#include <cmath>
#include <new>
#include <sstream>
#include <stdexcept>

namespace gazelod::lod {

double level_weight(const LodLevel& level) {
  if (!(level.detail > 0.0)) return 0.0;
  return level.detail_kind == DetailKind::removed_cycles_per_diameter ? level.detail : 1.0 / level.detail;
}

float level_weight_f(const LodLevel& level) {
  const double w = level_weight(level);
  const float f = static_cast<float>(w);
  return static_cast<double>(f) > w ? std::nextafter(f, 0.0f) : f;
}

std::optional<ChainProblem> find_chain_problem(std::span<const LodLevel> levels) {
  std::ostringstream m;
  if (levels.empty() || levels.size() > kMaxChainLevels) {
    m << "a chain needs 1 to " << kMaxChainLevels << " levels, got " << levels.size();
    return ChainProblem{levels.size(), m.str()};
  }
  for (std::size_t k = 1; k < levels.size(); ++k) {
    const LodLevel& l = levels[k];
    if (l.detail_kind != levels[0].detail_kind) {
      m << "detail kind differs from level 0 (one kind per chain)";
      return ChainProblem{k, m.str()};
    }
    if (!std::isfinite(l.detail) || !(l.detail > 0.0)) {
      m << "detail must be finite and > 0, got " << l.detail;
      return ChainProblem{k, m.str()};
    }
    if (const double w = level_weight(l); !(w >= kMinLevelWeight && w <= kMaxLevelWeight)) {
      m << "detail " << l.detail << " gives a weight of " << w << ", outside [" << kMinLevelWeight << ", "
        << kMaxLevelWeight << "]";
      return ChainProblem{k, m.str()};
    }
    // A coarser level that costs more is a mislabelled chain (reports would show it as more
    // than full detail, and the frame budget would coarsen into it to save time).
    if (l.triangles > levels[k - 1].triangles) {
      m << "has more triangles (" << l.triangles << ") than level " << k - 1 << " (" << levels[k - 1].triangles
        << "): triangle counts must not increase along the chain";
      return ChainProblem{k, m.str()};
    }
    if (k >= 2 && level_weight(l) > level_weight(levels[k - 1])) {
      m << "must remove no finer detail than level " << k - 1
        << (l.detail_kind == DetailKind::removed_cycles_per_diameter
                ? " (removed cycles per diameter must not increase)"
                : " (geometric error must not decrease)");
      return ChainProblem{k, m.str()};
    }
  }
  return std::nullopt;
}

std::string validate_chain(std::span<const LodLevel> levels) {
  const std::optional<ChainProblem> p = find_chain_problem(levels);
  if (!p) return {};
  if (p->level >= levels.size()) return p->message;  // the count
  return "level " + std::to_string(p->level) + ": " + p->message;
}

std::string validate_objects(const ObjectSet& o) {
  std::ostringstream m;
  const std::size_t n = o.size();
  const bool moving = !o.vel_x_m_s.empty() || !o.vel_y_m_s.empty() || !o.vel_z_m_s.empty();
  if (o.center_x_m.size() != n || o.center_y_m.size() != n || o.center_z_m.size() != n || o.detail_kind.size() != n ||
      o.lod_first.size() != n || o.lod_count.size() != n ||
      (moving && (o.vel_x_m_s.size() != n || o.vel_y_m_s.size() != n || o.vel_z_m_s.size() != n))) {
    m << "object arrays differ in length (radius_m has " << n << ")";
    return m.str();
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(o.center_x_m[i]) || !std::isfinite(o.center_y_m[i]) || !std::isfinite(o.center_z_m[i])) {
      m << "object " << i << ": centre is not finite";
      return m.str();
    }
    if (!std::isfinite(o.radius_m[i]) || o.radius_m[i] < 0.0) {
      m << "object " << i << ": radius_m must be finite and >= 0, got " << o.radius_m[i];
      return m.str();
    }
    if (moving &&
        (!std::isfinite(o.vel_x_m_s[i]) || !std::isfinite(o.vel_y_m_s[i]) || !std::isfinite(o.vel_z_m_s[i]))) {
      m << "object " << i << ": velocity is not finite";
      return m.str();
    }
    const std::size_t first = o.lod_first[i], count = o.lod_count[i];
    if (count == 0 || first + count > o.level_weight.size()) {
      m << "object " << i << ": levels [" << first << ", " << first + count << ") out of range of level_weight ("
        << o.level_weight.size() << ")";
      return m.str();
    }
    for (std::size_t k = 1; k < count; ++k) {
      const double w = o.level_weight[first + k];
      if (!std::isfinite(w) || !(w > 0.0) || (k >= 2 && w > o.level_weight[first + k - 1])) {
        m << "object " << i << " level " << k << ": weight must be finite, > 0 and not above "
          << "the finer level's, got " << w;
        return m.str();
      }
    }
  }
  return {};
}

std::uint32_t ObjectStore::add(const glm::dvec3& c, double radius_m, const glm::dvec3& v,
                               std::span<const LodLevel> levels) {
  if (std::string e = validate_chain(levels); !e.empty()) throw std::invalid_argument(e);
  if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
    throw std::invalid_argument("centre is not finite");
  if (!std::isfinite(radius_m) || radius_m < 0.0) throw std::invalid_argument("radius_m must be finite and >= 0");
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    throw std::invalid_argument("velocity is not finite");
  const auto id = static_cast<std::uint32_t>(radius_.size());
  cx_.push_back(c.x), cy_.push_back(c.y), cz_.push_back(c.z);
  vx_.push_back(v.x), vy_.push_back(v.y), vz_.push_back(v.z);
  radius_.push_back(radius_m);
  kind_.push_back(levels[0].detail_kind);
  first_.push_back(static_cast<std::uint32_t>(weight_.size()));
  count_.push_back(static_cast<std::uint8_t>(levels.size()));
  for (const LodLevel& l : levels) weight_.push_back(level_weight_f(l));
  return id;
}

void ObjectStore::set_motion(std::uint32_t id, const glm::dvec3& c, const glm::dvec3& v) {
  if (id >= radius_.size()) throw std::out_of_range("object id out of range");
  cx_[id] = c.x, cy_[id] = c.y, cz_[id] = c.z;
  vx_[id] = v.x, vy_[id] = v.y, vz_[id] = v.z;
}

void ObjectStore::remove(std::uint32_t id) {
  if (id >= radius_.size()) throw std::out_of_range("object id out of range");
  // The object's levels stay in weight_ as a hole: erasing them shifted every later chain, a
  // pass over all objects per removal (125 us at 100k objects, with the plugin's lock held).
  // Once holes are half of weight_ they are packed out in one pass: amortised constant.
  dead_levels_ += count_[id];
  const std::size_t last = radius_.size() - 1;
  auto move_last = [&](auto& v) {
    v[id] = v[last];
    v.pop_back();
  };
  move_last(cx_), move_last(cy_), move_last(cz_), move_last(vx_), move_last(vy_), move_last(vz_);
  move_last(radius_), move_last(kind_), move_last(first_), move_last(count_);
  if (2 * dead_levels_ > weight_.size()) pack_levels();
}

void ObjectStore::pack_levels() noexcept {
  try {
    std::vector<float> packed;
    packed.reserve(weight_.size() - dead_levels_);
    std::vector<std::uint32_t> first(first_.size());
    for (std::size_t i = 0; i < first_.size(); ++i) {
      first[i] = static_cast<std::uint32_t>(packed.size());
      packed.insert(packed.end(), weight_.begin() + first_[i], weight_.begin() + first_[i] + count_[i]);
    }
    weight_.swap(packed);
    first_.swap(first);
    dead_levels_ = 0;
  } catch (const std::bad_alloc&) {
    // No room to pack now: the holes stay (the store is whole either way), tried again later.
  }
}

void ObjectStore::reserve(std::size_t objects, std::size_t levels) {
  for (auto* a : {&cx_, &cy_, &cz_, &radius_, &vx_, &vy_, &vz_}) a->reserve(objects);
  kind_.reserve(objects), first_.reserve(objects), count_.reserve(objects);
  weight_.reserve(levels);
}

ObjectSet ObjectStore::view() const {
  return ObjectSet{cx_, cy_, cz_, radius_, vx_, vy_, vz_, kind_, first_, count_, weight_};
}

}  // namespace gazelod::lod
