// SPDX-License-Identifier: Apache-2.0
// The stand-in LOD meshes: triangle counts near the requested ones, closed, outward-facing.
#include "render/sphere_mesh.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace gazelod::render {
namespace {

TEST(SphereMesh, TriangleCountApproximatesTheLevel) {
  for (std::uint32_t target : {20u, 30u, 50u, 100u, 1000u, 5000u, 20000u, 100000u}) {
    const SphereResolution r = sphere_resolution(target);
    const MeshData m = make_sphere(r);
    EXPECT_EQ(m.triangle_count(), r.triangles()) << target;
    const double rel = std::abs(static_cast<double>(r.triangles()) - target) / target;
    EXPECT_LE(rel, target >= 1000 ? 0.02 : 0.10) << target << " -> " << r.triangles();
  }
}

TEST(SphereMesh, TinyAndHugeRequestsAreClamped) {
  EXPECT_EQ(sphere_resolution(0).triangles(), 6u);  // 2 stacks x 3 slices: a double pyramid
  EXPECT_EQ(sphere_resolution(1).triangles(), 6u);
  const SphereResolution huge = sphere_resolution(4'000'000'000u);
  EXPECT_LE(huge.triangles(), kMaxSphereTriangles);
  EXPECT_GE(huge.triangles(), kMaxSphereTriangles * 0.9);
}

TEST(SphereMesh, ClosedOutwardFacingUnitSphere) {
  for (std::uint32_t target : {6u, 80u, 2000u}) {
    const MeshData m = make_sphere(sphere_resolution(target));
    for (const glm::vec3& p : m.positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-6f);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
      const std::uint32_t a = m.indices[3 * t], b = m.indices[3 * t + 1], c = m.indices[3 * t + 2];
      ASSERT_LT(std::max({a, b, c}), m.positions.size());
      const glm::vec3 n = glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
      const glm::vec3 centroid = (m.positions[a] + m.positions[b] + m.positions[c]) / 3.0f;
      EXPECT_GT(glm::dot(n, centroid), 0.0f) << "triangle " << t << " faces inwards";
      ++directed[{a, b}];
      ++directed[{b, c}];
      ++directed[{c, a}];
    }
    // Closed and consistently oriented: each directed edge once, its reverse exactly once.
    for (const auto& [edge, count] : directed) {
      EXPECT_EQ(count, 1);
      EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
    }
    // Euler characteristic of a sphere: V - E + F = 2.
    const long v = static_cast<long>(m.positions.size());
    const long e = static_cast<long>(directed.size() / 2);
    const long f = static_cast<long>(m.triangle_count());
    EXPECT_EQ(v - e + f, 2) << target;
  }
}

}  // namespace
}  // namespace gazelod::render
