// SPDX-License-Identifier: Apache-2.0
// The cluster hierarchy build (cluster_build.hpp): the options and the input checked, then one
// Builder (cluster_builder.hpp) makes the hierarchy.
#include "bake/cluster/cluster_build.hpp"

#include "bake/bake_error.hpp"
#include "bake/cluster/cluster_builder.hpp"

#include <cmath>
#include <sstream>

namespace gazelod::bake {

using cluster_build::Builder;
using cluster_build::kNone;

std::string validate_cluster_options(const ClusterBuildOptions& o) {
  std::ostringstream m;
  if (o.max_vertices < 3 || o.max_vertices > 255)
    m << "max vertices per cluster must be in [3, 255], got " << o.max_vertices;
  else if (o.max_triangles < 4 || o.max_triangles > 512 || o.max_triangles % 4 != 0)
    m << "max triangles per cluster must be a multiple of 4 in [4, 512], got " << o.max_triangles;
  else if (o.group_size < 2 || o.group_size > 64)
    m << "clusters per group must be in [2, 64], got " << o.group_size;
  else if (!(o.simplify_ratio > 0.0 && o.simplify_ratio < 1.0))
    m << "simplify ratio must be in (0, 1), got " << o.simplify_ratio;
  else if (!(o.stuck_ratio >= o.simplify_ratio && o.stuck_ratio < 1.0))
    m << "stuck ratio must be in [simplify ratio, 1), got " << o.stuck_ratio;
  else if (o.fold_retries > kMaxFoldRetries)
    m << "fold retries must be in [0, " << kMaxFoldRetries << "], got " << o.fold_retries;
  return m.str();
}

ClusterBuildResult build_cluster_hierarchy(std::span<const float> pos, std::span<const std::uint32_t> indices,
                                           const ClusterBuildOptions& o) {
  if (std::string e = validate_cluster_options(o); !e.empty()) throw BakeError(o.label + ": " + e);
  if (pos.size() % 3 != 0)
    throw BakeError(o.label + ": " + std::to_string(pos.size()) + " position floats is not a whole number of vertices");
  if (indices.size() % 3 != 0)
    throw BakeError(o.label + ": " + std::to_string(indices.size()) + " indices is not a whole number of triangles");
  const std::size_t vcount = pos.size() / 3;
  if (vcount > kNone) throw BakeError(o.label + ": more than 2^32 - 1 vertices");
  // All levels together hold about twice the source; first_index is 32-bit.
  if (indices.size() > (std::size_t{1} << 30))
    throw BakeError(o.label + ": " + std::to_string(indices.size() / 3) +
                    " triangles; a cluster hierarchy takes at most 2^30 indices (357913941 triangles)");
  for (std::size_t v = 0; v < vcount; ++v)
    if (!std::isfinite(pos[3 * v]) || !std::isfinite(pos[3 * v + 1]) || !std::isfinite(pos[3 * v + 2])) {
      std::ostringstream m;
      m << o.label << ": vertex " << v << " position (" << pos[3 * v] << ", " << pos[3 * v + 1] << ", "
        << pos[3 * v + 2] << ") is not finite";
      throw BakeError(m.str());
    }
  if (!o.locked_vertices.empty() && o.locked_vertices.size() != vcount)
    throw BakeError(o.label + ": " + std::to_string(o.locked_vertices.size()) + " locked-vertex flags for " +
                    std::to_string(vcount) + " vertices");
  for (std::size_t i = 0; i < indices.size(); ++i)
    if (indices[i] >= vcount)
      throw BakeError(o.label + ": index " + std::to_string(i) + " is " + std::to_string(indices[i]) +
                      ", but there are only " + std::to_string(vcount) + " vertices");
  return Builder(pos, o).run(indices);
}

}  // namespace gazelod::bake
