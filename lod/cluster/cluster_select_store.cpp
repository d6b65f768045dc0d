// SPDX-License-Identifier: Apache-2.0
// Instance transforms and the cluster store (see cluster_select_store.hpp).
#include "lod/cluster/cluster_select_store.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <sstream>
#include <stdexcept>

namespace gazelod::lod {
namespace {

bool finite3(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

float round_up(double x) {  // +inf stays +inf
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// Where transformed records go: ten arrays, written from index `first` on.
struct RecordArrays {
  float *sx, *sy, *sz, *sr, *se, *px, *py, *pz, *pr, *pe;
};

// world = t + scale R local for both centres; radii and errors times scale, rounded up.
void transform_records(const ClusterHierarchy& h, const InstanceTransform& xf, const RecordArrays& out) {
  const glm::dmat3 rot = glm::mat3_cast(glm::normalize(xf.rotation));
  const double s = xf.scale;
  const auto centre = [&](float x, float y, float z) { return xf.translation_m + s * (rot * glm::dvec3{x, y, z}); };
  for (std::size_t i = 0; i < h.size(); ++i) {
    const glm::dvec3 sc = centre(h.self_center_x_m[i], h.self_center_y_m[i], h.self_center_z_m[i]);
    const glm::dvec3 pc = centre(h.parent_center_x_m[i], h.parent_center_y_m[i], h.parent_center_z_m[i]);
    out.sx[i] = static_cast<float>(sc.x), out.sy[i] = static_cast<float>(sc.y), out.sz[i] = static_cast<float>(sc.z);
    out.px[i] = static_cast<float>(pc.x), out.py[i] = static_cast<float>(pc.y), out.pz[i] = static_cast<float>(pc.z);
    out.sr[i] = round_up(s * h.self_radius_m[i]);
    out.pr[i] = round_up(s * h.parent_radius_m[i]);
    out.se[i] = round_up(s * h.self_error_m[i]);
    out.pe[i] = round_up(s * h.parent_error_m[i]);  // kNoParentError stays +inf
  }
}

// A one-mesh, static ClusterSet over a hierarchy's records.
struct OneMesh {
  explicit OneMesh(const ClusterHierarchy& h)
      : first{0},
        count{static_cast<std::uint32_t>(h.size())},
        finest{finest_cluster_error_m(h.self_error_m, h.parent_error_m)} {
    set = ClusterSet{h.self_center_x_m,
                     h.self_center_y_m,
                     h.self_center_z_m,
                     h.self_radius_m,
                     h.self_error_m,
                     h.parent_center_x_m,
                     h.parent_center_y_m,
                     h.parent_center_z_m,
                     h.parent_radius_m,
                     h.parent_error_m,
                     {&first, 1},
                     {&count, 1},
                     {},
                     {},
                     {},
                     {&finest, 1}};
  }
  OneMesh(const OneMesh&) = delete;  // set points into this object
  OneMesh& operator=(const OneMesh&) = delete;
  std::uint32_t first, count;
  double finest;
  ClusterSet set;
};

}  // namespace

std::string validate_instance_transform(const InstanceTransform& xf) {
  const glm::dquat& q = xf.rotation;
  if (!(std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z)) ||
      !(glm::length(q) > 0.0))
    return "rotation must be finite and non-zero";
  if (!finite3(xf.translation_m)) return "translation_m is not finite";
  if (!(std::isfinite(xf.scale) && xf.scale > 0.0)) {
    std::ostringstream m;
    m << "scale must be finite and > 0, got " << xf.scale;
    return m.str();
  }
  return {};
}

std::string validate_cluster_hierarchy(const ClusterHierarchy& h, std::size_t index_buffer_size) {
  const std::size_t n = h.size();
  if (n > std::numeric_limits<std::uint32_t>::max()) return "more clusters than a uint32 counts";
  if (h.first_index.size() != n || h.index_count.size() != n || h.depth.size() != n)
    return "first_index, index_count and depth must have one entry per cluster (" + std::to_string(n) + ")";
  if (std::string e = validate_clusters(OneMesh(h).set); !e.empty()) return e;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t first = h.first_index[i], count = h.index_count[i];
    if (count % 3 == 0 && first + count <= index_buffer_size) continue;
    std::ostringstream m;  // built on failure only
    if (count % 3 != 0)
      m << "cluster " << i << ": index_count " << count << " is not a multiple of 3";
    else
      m << "cluster " << i << ": indices [" << first << ", " << first + count << ") out of range of the index buffer ("
        << index_buffer_size << ")";
    return m.str();
  }
  return {};
}

std::string transform_hierarchy(const ClusterHierarchy& local, const InstanceTransform& xf, ClusterHierarchy& world) {
  if (std::string e = validate_instance_transform(xf); !e.empty()) return e;
  const std::size_t n = local.size();
  for (auto* v : {&world.self_center_x_m, &world.self_center_y_m, &world.self_center_z_m, &world.self_radius_m,
                  &world.self_error_m, &world.parent_center_x_m, &world.parent_center_y_m, &world.parent_center_z_m,
                  &world.parent_radius_m, &world.parent_error_m})
    v->resize(n);
  world.first_index = local.first_index;
  world.index_count = local.index_count;
  world.depth = local.depth;
  transform_records(local, xf,
                    {world.self_center_x_m.data(), world.self_center_y_m.data(), world.self_center_z_m.data(),
                     world.self_radius_m.data(), world.self_error_m.data(), world.parent_center_x_m.data(),
                     world.parent_center_y_m.data(), world.parent_center_z_m.data(), world.parent_radius_m.data(),
                     world.parent_error_m.data()});
  return {};
}

void ClusterStore::write_records(std::size_t mesh, const ClusterHierarchy& local, const InstanceTransform& xf) {
  const std::size_t f = first_[mesh];
  transform_records(local, xf,
                    {self_x_.data() + f, self_y_.data() + f, self_z_.data() + f, self_radius_.data() + f,
                     self_error_.data() + f, parent_x_.data() + f, parent_y_.data() + f, parent_z_.data() + f,
                     parent_radius_.data() + f, parent_error_.data() + f});
  // The distinct records: copies of the clusters' world records they stand for.
  for (std::size_t r = rec_first_[mesh]; r < rec_first_[mesh] + rec_count_[mesh]; ++r) {
    const std::size_t i = rec_source_[r] / 2;
    const bool parent = rec_source_[r] % 2 == 1;
    rec_x_[r] = parent ? parent_x_[i] : self_x_[i];
    rec_y_[r] = parent ? parent_y_[i] : self_y_[i];
    rec_z_[r] = parent ? parent_z_[i] : self_z_[i];
    rec_radius_[r] = parent ? parent_radius_[i] : self_radius_[i];
    rec_error_[r] = parent ? parent_error_[i] : self_error_[i];
  }
}

void ClusterStore::index_records(const ClusterHierarchy& h) {
  // A record's five fields' bits, in the mesh's own space: equal there, equal after any
  // transform (transform_records is a function of the fields alone).
  using Key = std::array<std::uint32_t, 5>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t x = 0x9e3779b97f4a7c15ull;
      for (std::uint32_t v : k) x = (x ^ v) * 0x100000001b3ull, x ^= x >> 29;
      return static_cast<std::size_t>(x);
    }
  };
  const auto bits = [](float v) {
    std::uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
  };
  std::unordered_map<Key, std::uint32_t, KeyHash> seen;
  seen.reserve(h.size());
  const std::size_t first_cluster = first_.back();
  const auto first_record = static_cast<std::uint32_t>(rec_error_.size());
  rec_first_.push_back(first_record);
  for (std::size_t i = 0; i < h.size(); ++i)
    for (int which = 0; which < 2; ++which) {  // self, then parent
      const Key key = which == 0
                          ? Key{bits(h.self_center_x_m[i]), bits(h.self_center_y_m[i]), bits(h.self_center_z_m[i]),
                                bits(h.self_radius_m[i]), bits(h.self_error_m[i])}
                          : Key{bits(h.parent_center_x_m[i]), bits(h.parent_center_y_m[i]),
                                bits(h.parent_center_z_m[i]), bits(h.parent_radius_m[i]), bits(h.parent_error_m[i])};
      const auto [it, added] = seen.emplace(key, static_cast<std::uint32_t>(rec_source_.size()));
      if (added) rec_source_.push_back(2 * (first_cluster + i) + static_cast<std::uint64_t>(which));
      (which == 0 ? self_rec_ : parent_rec_).push_back(it->second);
    }
  rec_count_.push_back(static_cast<std::uint32_t>(rec_source_.size() - first_record));
  for (auto* v : {&rec_x_, &rec_y_, &rec_z_, &rec_radius_, &rec_error_}) v->resize(rec_source_.size());
}

std::uint32_t ClusterStore::add_mesh(const ClusterHierarchy& local, const InstanceTransform& pose,
                                     const glm::dvec3& velocity_m_s, std::size_t index_buffer_size) {
  if (std::string e = validate_cluster_hierarchy(local, index_buffer_size); !e.empty()) throw std::invalid_argument(e);
  if (std::string e = validate_instance_transform(pose); !e.empty()) throw std::invalid_argument(e);
  if (!finite3(velocity_m_s)) throw std::invalid_argument("velocity is not finite");
  if (size() + local.size() > std::numeric_limits<std::uint32_t>::max() ||
      record_count() + 2 * local.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("more clusters than a uint32 counts");
  ClusterHierarchy world;  // checked before the store grows, so a refusal leaves it unchanged
  if (std::string e = transform_hierarchy(local, pose, world); !e.empty()) throw std::invalid_argument(e);
  if (std::string e = validate_clusters(OneMesh(world).set); !e.empty())
    throw std::invalid_argument("in world space: " + e);

  const std::size_t f = size();
  for (auto* v : {&self_x_, &self_y_, &self_z_, &self_radius_, &self_error_, &parent_x_, &parent_y_, &parent_z_,
                  &parent_radius_, &parent_error_})
    v->resize(f + local.size());
  const auto id = static_cast<std::uint32_t>(count_.size());
  first_.push_back(static_cast<std::uint32_t>(f));
  count_.push_back(static_cast<std::uint32_t>(local.size()));
  index_records(local);
  write_records(id, local, pose);
  vel_x_.push_back(velocity_m_s.x), vel_y_.push_back(velocity_m_s.y), vel_z_.push_back(velocity_m_s.z);
  finest_.push_back(finest_cluster_error_m(world.self_error_m, world.parent_error_m));
  return id;
}

void ClusterStore::set_pose(std::uint32_t mesh, const ClusterHierarchy& local, const InstanceTransform& pose,
                            const glm::dvec3& velocity_m_s) {
  if (mesh >= count_.size()) throw std::out_of_range("mesh id out of range");
  if (local.size() != count_[mesh])
    throw std::invalid_argument("the hierarchy has " + std::to_string(local.size()) + " clusters, mesh " +
                                std::to_string(mesh) + " was registered with " + std::to_string(count_[mesh]));
  if (std::string e = validate_instance_transform(pose); !e.empty()) throw std::invalid_argument(e);
  if (!finite3(velocity_m_s)) throw std::invalid_argument("velocity is not finite");
  write_records(mesh, local, pose);
  vel_x_[mesh] = velocity_m_s.x, vel_y_[mesh] = velocity_m_s.y, vel_z_[mesh] = velocity_m_s.z;
  // The scale may have changed: the finest error with it (linear in this mesh's clusters).
  const std::size_t f = first_[mesh], n = count_[mesh];
  finest_[mesh] = finest_cluster_error_m({self_error_.data() + f, n}, {parent_error_.data() + f, n});
}

void ClusterStore::reserve(std::size_t meshes, std::size_t clusters) {
  for (auto* v : {&self_x_, &self_y_, &self_z_, &self_radius_, &self_error_, &parent_x_, &parent_y_, &parent_z_,
                  &parent_radius_, &parent_error_})
    v->reserve(clusters);
  first_.reserve(meshes), count_.reserve(meshes);
  for (auto* v : {&vel_x_, &vel_y_, &vel_z_, &finest_}) v->reserve(meshes);
  self_rec_.reserve(clusters), parent_rec_.reserve(clusters);
  rec_first_.reserve(meshes), rec_count_.reserve(meshes);
}

ClusterSet ClusterStore::view() const {
  return ClusterSet{self_x_,   self_y_,        self_z_,       self_radius_, self_error_, parent_x_,   parent_y_,
                    parent_z_, parent_radius_, parent_error_, first_,       count_,      vel_x_,      vel_y_,
                    vel_z_,    finest_,        rec_x_,        rec_y_,       rec_z_,      rec_radius_, rec_error_,
                    self_rec_, parent_rec_,    rec_first_,    rec_count_};
}

}  // namespace gazelod::lod
