// SPDX-License-Identifier: Apache-2.0
// The hierarchy invariants of cluster_invariants.hpp.
#include "tests/bake/cluster_invariants.hpp"

#include "bake/cluster/cluster_bake.hpp"
#include "bake/cluster/cluster_sphere.hpp"
#include "bake/mesh_extract.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

namespace gazelod::bake::testing {
namespace {

// vertex -> first vertex with the same position.
std::vector<std::uint32_t> weld(std::span<const float> p) {
  std::map<std::array<float, 3>, std::uint32_t> first;
  std::vector<std::uint32_t> w(p.size() / 3);
  for (std::size_t v = 0; v < w.size(); ++v)
    w[v] = first.try_emplace({p[3 * v] + 0.0f, p[3 * v + 1] + 0.0f, p[3 * v + 2] + 0.0f}, static_cast<std::uint32_t>(v))
               .first->second;
  return w;
}

// Triangles as (welded) corner triples rotated to start at the smallest, orientation kept.
std::multiset<std::array<std::uint32_t, 3>> canonical(std::span<const std::uint32_t> tris) {
  std::multiset<std::array<std::uint32_t, 3>> s;
  for (std::size_t t = 0; t + 2 < tris.size(); t += 3) {
    std::array<std::uint32_t, 3> a{tris[t], tris[t + 1], tris[t + 2]};
    std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
    s.insert(a);
  }
  return s;
}

Sphere self_sphere(const lod::ClusterHierarchy& h, std::size_t c) {
  return {h.self_center_x_m[c], h.self_center_y_m[c], h.self_center_z_m[c], h.self_radius_m[c]};
}
Sphere parent_sphere(const lod::ClusterHierarchy& h, std::size_t c) {
  return {h.parent_center_x_m[c], h.parent_center_y_m[c], h.parent_center_z_m[c], h.parent_radius_m[c]};
}
bool same(const Sphere& a, const Sphere& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z && a.radius_m == b.radius_m;
}

}  // namespace

std::vector<std::vector<std::vector<std::uint8_t>>> meeting_vertices_of(const tinygltf::Model& m) {
  std::vector<std::vector<PrimitiveGeometry>> geometry(m.meshes.size());
  for (const tinygltf::Node& n : m.nodes)
    if (n.mesh >= 0 && geometry[static_cast<std::size_t>(n.mesh)].empty())
      for (std::size_t p = 0; p < m.meshes[static_cast<std::size_t>(n.mesh)].primitives.size(); ++p)
        geometry[static_cast<std::size_t>(n.mesh)].push_back(extract_primitive(m, n.mesh, static_cast<int>(p)));
  return meeting_vertices(m, geometry);
}

OpenEdges open_edges(std::span<const float> positions, std::span<const std::uint32_t> tris) {
  const std::vector<std::uint32_t> w = weld(positions);
  OpenEdges e;
  for (std::size_t t = 0; t + 2 < tris.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = w[tris[t + k]], b = w[tris[t + (k + 1) % 3]];
      if (a == b) continue;
      int& n = e[std::minmax(a, b)];
      n += a < b ? 1 : -1;
      if (n == 0) e.erase(std::minmax(a, b));
    }
  return e;
}

std::vector<std::uint32_t> triangles_of(const ClusterBuildResult& r, std::span<const std::uint32_t> clusters) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t c : clusters)
    out.insert(out.end(), r.indices.begin() + r.hierarchy.first_index[c],
               r.indices.begin() + r.hierarchy.first_index[c] + r.hierarchy.index_count[c]);
  return out;
}

std::vector<std::uint32_t> cut(const ClusterBuildResult& r, float t) {
  std::vector<std::uint32_t> drawn;
  for (std::uint32_t c = 0; c < r.hierarchy.size(); ++c)
    if (r.hierarchy.self_error_m[c] <= t && t < r.hierarchy.parent_error_m[c]) drawn.push_back(c);
  return triangles_of(r, drawn);
}

void expect_hierarchy_invariants(const ClusterBuildResult& r, std::span<const float> pos,
                                 std::span<const std::uint32_t> source, const ClusterBuildOptions& o) {
  const lod::ClusterHierarchy& h = r.hierarchy;
  const std::size_t n = h.size();
  ASSERT_EQ(r.parent_group.size(), n);
  ASSERT_EQ(r.source_group.size(), n);
  for (const auto* v :
       {&h.self_center_x_m, &h.self_center_y_m, &h.self_center_z_m, &h.self_radius_m, &h.parent_center_x_m,
        &h.parent_center_y_m, &h.parent_center_z_m, &h.parent_radius_m, &h.parent_error_m})
    ASSERT_EQ(v->size(), n);
  ASSERT_EQ(h.first_index.size(), n);
  ASSERT_EQ(h.index_count.size(), n);
  ASSERT_EQ(h.depth.size(), n);

  // The source without its degenerate triangles (two corners at one position).
  const std::vector<std::uint32_t> w = weld(pos);
  std::vector<std::uint32_t> kept;
  for (std::size_t t = 0; t + 2 < source.size(); t += 3) {
    const std::uint32_t a = w[source[t]], b = w[source[t + 1]], c = w[source[t + 2]];
    if (a != b && b != c && c != a) kept.insert(kept.end(), {source[t], source[t + 1], source[t + 2]});
  }
  EXPECT_EQ(r.source_triangles, kept.size() / 3);
  EXPECT_EQ(r.degenerate_triangles, (source.size() - kept.size()) / 3);

  std::vector<std::uint32_t> leaves;
  std::map<std::int32_t, std::vector<std::uint32_t>> children, products;
  std::size_t covered = 0;
  for (std::uint32_t c = 0; c < n; ++c) {
    SCOPED_TRACE("cluster " + std::to_string(c));
    EXPECT_EQ(h.index_count[c] % 3, 0u);
    EXPECT_GT(h.index_count[c], 0u);
    EXPECT_LE(h.index_count[c], 3 * o.max_triangles);
    EXPECT_EQ(h.first_index[c], covered) << "clusters are contiguous, in order";
    covered += h.index_count[c];
    std::set<std::uint32_t> verts(r.indices.begin() + h.first_index[c],
                                  r.indices.begin() + h.first_index[c] + h.index_count[c]);
    EXPECT_LE(verts.size(), o.max_vertices);
    EXPECT_GE(h.self_error_m[c], 0.0f);
    EXPECT_LE(h.self_error_m[c], h.parent_error_m[c]) << "monotone";
    EXPECT_TRUE(sphere_contains(parent_sphere(h, c), self_sphere(h, c)));
    for (std::uint32_t v : verts)
      EXPECT_TRUE(sphere_contains(self_sphere(h, c), {pos[3 * v], pos[3 * v + 1], pos[3 * v + 2], 0.0f}));
    if (r.source_group[c] < 0) {
      leaves.push_back(c);
      EXPECT_EQ(h.self_error_m[c], 0.0f);
      EXPECT_EQ(h.depth[c], 0);
    } else {
      products[r.source_group[c]].push_back(c);
    }
    if (r.parent_group[c] >= 0) {
      children[r.parent_group[c]].push_back(c);
      // Readers derive the groups from record equality: a group never repeats a member's record.
      EXPECT_FALSE(same(parent_sphere(h, c), self_sphere(h, c)) && h.parent_error_m[c] == h.self_error_m[c])
          << "the parent record repeats the self record";
    } else {
      EXPECT_EQ(h.parent_error_m[c], lod::kNoParentError);
    }
  }
  EXPECT_EQ(covered, r.indices.size());
  EXPECT_EQ(children.size(), r.groups);
  EXPECT_EQ(products.size(), r.groups);
  EXPECT_EQ(canonical(triangles_of(r, leaves)), canonical(kept)) << "leaves = the source, once";

  const OpenEdges source_border = open_edges(pos, kept);
  // The free outline: welded vertices of the source's open border that the caller does not
  // lock. An open edge at one of them may be simplified along the outline (from a locked corner
  // to the next free vertex left, say); an open edge between two others (between groups, at
  // locked positions) must stay as it is, so a crack shows there.
  std::set<std::uint32_t> free_outline;
  if (!o.lock_open_borders) {
    for (const auto& [e, count] : source_border) free_outline.insert({e.first, e.second});
    for (std::size_t v = 0; v < o.locked_vertices.size(); ++v)
      if (o.locked_vertices[v]) free_outline.erase(w[v]);
  }
  const auto fixed = [&](const OpenEdges& edges) {
    OpenEdges out;
    for (const auto& [e, count] : edges)
      if (!free_outline.contains(e.first) && !free_outline.contains(e.second)) out.emplace(e, count);
    return out;
  };
  const auto at_free_outline = [&](const OpenEdges& edges) {
    return std::all_of(edges.begin(), edges.end(), [&](const auto& kv) {
      return free_outline.contains(kv.first.first) || free_outline.contains(kv.first.second);
    });
  };
  const OpenEdges source_fixed = fixed(source_border);
  std::set<float> errors;
  for (const auto& [g, members] : children) {
    SCOPED_TRACE("group " + std::to_string(g));
    const std::uint32_t m0 = members[0];
    for (std::uint32_t m : members) {
      EXPECT_EQ(h.parent_error_m[m], h.parent_error_m[m0]);
      EXPECT_TRUE(same(parent_sphere(h, m), parent_sphere(h, m0)));
    }
    for (std::uint32_t p : products[g]) {
      EXPECT_EQ(h.self_error_m[p], h.parent_error_m[m0]);
      EXPECT_TRUE(same(self_sphere(h, p), parent_sphere(h, m0)));
      EXPECT_EQ(h.depth[p], h.depth[m0] + 1);
    }
    const OpenEdges before = open_edges(pos, triangles_of(r, members));
    const OpenEdges after = open_edges(pos, triangles_of(r, products[g]));
    EXPECT_TRUE(fixed(before) == fixed(after))
        << "the group's border with other groups is locked: " << fixed(before).size()
        << " such open edges before its simplification, " << fixed(after).size() << " after";
    OpenEdges moved;  // what simplification changed: only along the free outline
    for (const auto& [e, count] : after)
      if (auto it = before.find(e); it == before.end() || it->second != count) moved.emplace(e, count);
    EXPECT_TRUE(at_free_outline(moved)) << "a new open edge away from the mesh's free outline";
    errors.insert(h.parent_error_m[m0]);
  }
  // Cuts: all leaves, at most 24 group errors spread over their range, all top.
  std::vector<float> thresholds{0.0f};
  const std::vector<float> sorted(errors.begin(), errors.end());
  for (std::size_t k = 0; k < std::min<std::size_t>(24, sorted.size()); ++k)
    thresholds.push_back(sorted[k * sorted.size() / std::min<std::size_t>(24, sorted.size())]);
  thresholds.push_back(std::numeric_limits<float>::max());
  std::size_t previous = SIZE_MAX;
  for (float t : thresholds) {
    SCOPED_TRACE("cut at " + std::to_string(t));
    const std::vector<std::uint32_t> drawn = cut(r, t);
    const OpenEdges border = open_edges(pos, drawn);
    EXPECT_TRUE(fixed(border) == source_fixed)
        << "no crack, no overlap: " << fixed(border).size() << " open edges off the free outline, the source has "
        << source_fixed.size();
    EXPECT_LE(drawn.size(), previous);
    previous = drawn.size();
  }
}

}  // namespace gazelod::bake::testing
