// SPDX-License-Identifier: Apache-2.0
// What an application registers with the plugin: objects with LOD chains, and meshes drawn as
// a cut of their cluster hierarchy. Plain data.
#pragma once

#include "lod/cluster/cluster_hierarchy.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "lod/lod_chain.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace gazelod {

struct ObjectDesc {
  glm::dvec3 center_m{0.0};  // in the base space
  double radius_m = 0.5;     // bounding sphere
  glm::dvec3 velocity_m_s{0.0};
  std::vector<lod::LodLevel> lods;  // level 0 = full detail
  double importance = 1.0;
};

// A mesh drawn as a cut of its cluster hierarchy (gazelod bake --clusters; lod/cluster/cluster_select.hpp):
// each cluster is drawn where its own simplification error is invisible and its parent's is
// not, with Reddy's rule per cluster, so detail follows the fovea across one mesh.
struct ClusterMeshDesc {
  lod::ClusterHierarchy hierarchy;  // the mesh's own space
  std::size_t index_count = 0;      // size of the mesh's index buffer (the clusters' ranges lie in it)
  lod::InstanceTransform pose;      // mesh space -> base space (rotation, translation, uniform scale)
  glm::dvec3 velocity_m_s{0.0};     // in the base space
};

}  // namespace gazelod
