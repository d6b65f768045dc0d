// SPDX-License-Identifier: Apache-2.0
// Shared hierarchies and their instances (see cluster_instances.hpp).
#include "lod/cluster/cluster_instances.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace gazelod::lod {
namespace {

// Calls f(data, bytes) for every array of h, in a fixed order.
template <typename F>
void for_each_array(const ClusterHierarchy& h, F&& f) {
  for (const auto* v :
       {&h.self_center_x_m, &h.self_center_y_m, &h.self_center_z_m, &h.self_radius_m, &h.self_error_m,
        &h.parent_center_x_m, &h.parent_center_y_m, &h.parent_center_z_m, &h.parent_radius_m, &h.parent_error_m})
    f(static_cast<const void*>(v->data()), v->size() * sizeof(float));
  for (const auto* v : {&h.first_index, &h.index_count}) f(static_cast<const void*>(v->data()), v->size() * 4);
  f(static_cast<const void*>(h.depth.data()), h.depth.size());
}

std::uint64_t hash_of(const ClusterHierarchy& h, std::size_t index_buffer_size) {
  std::uint64_t x = 0xcbf29ce484222325ull ^ index_buffer_size;
  for_each_array(h, [&](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    x = (x ^ bytes) * 0x100000001b3ull;
    std::size_t i = 0;
    for (; i + 8 <= bytes; i += 8) {  // a word at a time: registration hashes every instance's copy
      std::uint64_t w;
      std::memcpy(&w, p + i, 8);
      x = (x ^ w) * 0x100000001b3ull;
      x ^= x >> 29;
    }
    for (; i < bytes; ++i) x = (x ^ p[i]) * 0x100000001b3ull;
  });
  return x;
}

bool bitwise_equal(const ClusterHierarchy& a, const ClusterHierarchy& b) {
  std::vector<std::pair<const void*, std::size_t>> left;
  for_each_array(a, [&](const void* d, std::size_t n) { left.emplace_back(d, n); });
  std::size_t k = 0;
  bool equal = true;
  for_each_array(b, [&](const void* d, std::size_t n) {
    equal = equal && left[k].second == n && (n == 0 || std::memcmp(left[k].first, d, n) == 0);
    ++k;
  });
  return equal;
}

void check_motion(const InstanceTransform& pose, const glm::dvec3& velocity_m_s) {
  if (std::string e = validate_instance_transform(pose); !e.empty()) throw std::invalid_argument(e);
  if (!(std::isfinite(velocity_m_s.x) && std::isfinite(velocity_m_s.y) && std::isfinite(velocity_m_s.z)))
    throw std::invalid_argument("velocity is not finite");
}

// Layout generations, unique across every store of the process.
std::uint64_t next_generation() {
  static std::atomic<std::uint64_t> next{1};
  return next.fetch_add(1, std::memory_order_relaxed);
}

InstanceTransform normalised(InstanceTransform pose) {
  pose.rotation = glm::normalize(pose.rotation);
  return pose;
}

}  // namespace

ClusterInstances::ClusterInstances(std::size_t task_clusters)
    : task_clusters_(task_clusters), generation_(next_generation()) {}

std::uint32_t ClusterInstances::add_hierarchy(const ClusterHierarchy& local, std::size_t index_buffer_size) {
  const std::uint64_t hash = hash_of(local, index_buffer_size);
  for (std::size_t h = 0; h < hierarchies_.size(); ++h)
    if (hierarchies_[h]->hash == hash && hierarchies_[h]->index_buffer_size == index_buffer_size &&
        bitwise_equal(hierarchies_[h]->local, local))
      return static_cast<std::uint32_t>(h);
  if (std::string e = validate_cluster_hierarchy(local, index_buffer_size); !e.empty()) throw std::invalid_argument(e);
  auto stored = std::make_unique<Stored>();
  stored->local = local;
  stored->index_buffer_size = index_buffer_size;
  stored->hash = hash;
  stored->bvh = build_cluster_bvh(stored->local, task_clusters_);
  hierarchies_.push_back(std::move(stored));
  return static_cast<std::uint32_t>(hierarchies_.size() - 1);
}

std::uint32_t ClusterInstances::add_instance(std::uint32_t hierarchy, const InstanceTransform& pose,
                                             const glm::dvec3& velocity_m_s) {
  if (hierarchy >= hierarchies_.size())
    throw std::out_of_range("cluster hierarchy " + std::to_string(hierarchy) + " is not registered");
  check_motion(pose, velocity_m_s);
  const std::size_t n = hierarchies_[hierarchy]->local.size();
  if (clusters_ + n > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("more clusters than a uint32 counts");
  instances_.push_back({hierarchy, static_cast<std::uint32_t>(clusters_), normalised(pose), velocity_m_s});
  clusters_ += n;
  generation_ = next_generation();
  return static_cast<std::uint32_t>(instances_.size() - 1);
}

void ClusterInstances::set_pose(std::uint32_t instance, const InstanceTransform& pose, const glm::dvec3& velocity_m_s) {
  if (instance >= instances_.size())
    throw std::out_of_range("cluster instance " + std::to_string(instance) + " is not registered");
  check_motion(pose, velocity_m_s);
  instances_[instance].pose = normalised(pose);
  instances_[instance].velocity_m_s = velocity_m_s;
}

std::size_t ClusterInstances::memory_bytes() const {
  std::size_t bytes = instances_.capacity() * sizeof(ClusterInstance) + hierarchies_.capacity() * sizeof(void*);
  for (const auto& s : hierarchies_) {
    bytes += sizeof(Stored) + s->bvh.memory_bytes();
    const ClusterHierarchy& h = s->local;
    for (const auto* v :
         {&h.self_center_x_m, &h.self_center_y_m, &h.self_center_z_m, &h.self_radius_m, &h.self_error_m,
          &h.parent_center_x_m, &h.parent_center_y_m, &h.parent_center_z_m, &h.parent_radius_m, &h.parent_error_m})
      bytes += v->capacity() * sizeof(float);
    bytes += (h.first_index.capacity() + h.index_count.capacity()) * sizeof(std::uint32_t) + h.depth.capacity();
  }
  return bytes;
}

}  // namespace gazelod::lod
