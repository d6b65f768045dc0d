// SPDX-License-Identifier: Apache-2.0
// Where separately baked primitives meet (bake/cluster/shared_positions.hpp) and what the cluster bake
// does there: the meeting positions stay at every level, so neighbouring meshes drawn at
// different levels still meet, while each mesh's free rim is simplified.
#include "bake/baked_scene.hpp"
#include "bake/cluster/cluster_bake.hpp"
#include "bake/generated_scene.hpp"
#include "bake/cluster/shared_positions.hpp"
#include "bake/terrain_mesh.hpp"
#include "tests/bake/cluster_invariants.hpp"
#include "tests/bake/test_meshes.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <numeric>

namespace gazelod::bake {
namespace {

// Two unit squares (two triangles each, 4 vertices) side by side along x.
const std::vector<float> kLeft{0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1};
const std::vector<float> kRight{1, 0, 0, 2, 0, 0, 2, 0, 1, 1, 0, 1};
const std::vector<std::uint32_t> kSquare{0, 3, 2, 0, 2, 1};

TEST(SharedPositions, MeetingVerticesOfTwoPrimitivesAreFlagged) {
  const std::vector<PlacedPrimitive> p{{kLeft, kSquare, {glm::dmat4(1.0)}}, {kRight, kSquare, {glm::dmat4(1.0)}}};
  const auto s = shared_positions(p);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0], (std::vector<std::uint8_t>{0, 1, 1, 0}));  // x = 1 on the left
  EXPECT_EQ(s[1], (std::vector<std::uint8_t>{1, 0, 0, 1}));  // x = 1 on the right
}

TEST(SharedPositions, InstancesMeetThroughTheirTransforms) {
  // One square placed twice, the second shifted by +1 in x (and -0 for +0 in z): they meet at
  // x = 1. A duplicate position inside one instance (an attribute seam) is not a meeting.
  std::vector<float> seam = kLeft;
  seam.insert(seam.end(), {0.0f, 0.0f, -0.0f});  // vertex 4 = vertex 0, within one instance
  const glm::dmat4 shifted = glm::translate(glm::dmat4(1.0), glm::dvec3(1.0, 0.0, 0.0));
  const std::vector<PlacedPrimitive> p{{seam, kSquare, {glm::dmat4(1.0), shifted}}};
  const auto s = shared_positions(p);
  ASSERT_EQ(s.size(), 1u);
  // Instance 1's vertices 0 and 3 (x = 1 after the shift) meet instance 0's vertices 1 and 2.
  // Vertex 4 has vertex 0's position, so it is on the same border and meets the same way.
  EXPECT_EQ(s[0], (std::vector<std::uint8_t>{1, 1, 1, 1, 1}));
  const std::vector<PlacedPrimitive> alone{{seam, kSquare, {glm::dmat4(1.0)}}};
  EXPECT_EQ(shared_positions(alone)[0], (std::vector<std::uint8_t>(5, 0)));
  const std::vector<PlacedPrimitive> apart{
      {kLeft, kSquare, {glm::translate(glm::dmat4(1.0), glm::dvec3(5.0, 0.0, 0.0))}},
      {kRight, kSquare, {glm::dmat4(1.0)}}};
  for (const auto& flags : shared_positions(apart)) EXPECT_EQ(std::accumulate(flags.begin(), flags.end(), 0), 0);
}

TEST(SharedPositions, CoincidingInteriorsAreNotBorders) {
  // A 2 x 2 grid of quads (vertex 4 in the middle) placed twice at the same spot: the rim meets
  // the other copy's rim, the middle vertex is interior and stays free.
  const testing::TestMesh m = testing::grid(2, 2.0, 0.0);
  const std::vector<PlacedPrimitive> twice{{m.positions, m.indices, {glm::dmat4(1.0), glm::dmat4(1.0)}}};
  const auto s = shared_positions(twice);
  EXPECT_EQ(s[0], (std::vector<std::uint8_t>{1, 1, 1, 1, 0, 1, 1, 1, 1}));
}

// A 2 x 2 tiled terrain through the file bake: each tile's seams with its neighbours stay vertex
// for vertex at every cut, its outer rim (meeting nothing) is simplified.
TEST(SharedPositions, TiledTerrainKeepsTileSeamsAndSimplifiesTheRim) {
  TerrainOptions terrain;
  terrain.triangles = 20'000;
  terrain.size_m = 100.0;
  terrain.tiles = 2;
  const std::vector<GeneratedMesh> meshes = terrain_meshes(terrain);
  ASSERT_EQ(meshes.size(), 4u);
  const std::string dir = testing::temp_dir("cluster_shared_tiles");
  write_generated_glb(meshes, dir + "/tiles.glb");
  const ClusterBakeReport report = bake_clusters_file(dir + "/tiles.glb", dir + "/clusters.glb", {});
  const std::uint32_t per_side = terrain_quads_per_side(terrain) / 2 + 1;
  // Each tile meets two neighbours along one row and one column: 2 * per_side - 1 vertices.
  EXPECT_EQ(report.shared_vertices, 4u * (2 * per_side - 1));
  EXPECT_NE(format_cluster_summary(report).find("where primitives meet"), std::string::npos);

  const BakedScene scene = load_baked(dir + "/clusters.glb");
  ASSERT_EQ(scene.cluster_meshes.size(), 4u);
  for (std::size_t t = 0; t < 4; ++t) {
    SCOPED_TRACE("tile " + std::to_string(t));
    const BakedClusterPrimitive& prim = scene.cluster_meshes[t].primitives.at(0);
    const GeneratedMesh& source = meshes[static_cast<std::size_t>(scene.cluster_meshes[t].mesh)];
    // The seam: x or z at 0, the tiles' common lines.
    std::vector<std::uint8_t> seam(prim.vertex_count, 0);
    for (std::size_t v = 0; v < seam.size(); ++v)
      seam[v] = source.positions[3 * v] == 0.0f || source.positions[3 * v + 2] == 0.0f;
    ClusterBuildResult r;
    r.hierarchy = prim.hierarchy;
    r.indices = prim.indices;
    const testing::OpenEdges rim = testing::open_edges(source.positions, source.indices);
    const testing::OpenEdges top = testing::open_edges(source.positions, testing::cut(r, FLT_MAX));
    std::size_t seam_edges = 0, top_seam_edges = 0, top_rim_edges = 0;
    for (const auto& [e, count] : rim)
      if (seam[e.first] && seam[e.second]) {
        ++seam_edges;
        EXPECT_EQ(top.count(e), 1u) << "seam edge " << e.first << "-" << e.second << " kept";
      }
    for (const auto& [e, count] : top) (seam[e.first] && seam[e.second] ? top_seam_edges : top_rim_edges) += 1;
    EXPECT_EQ(seam_edges, 2u * (per_side - 1));
    EXPECT_EQ(top_seam_edges, seam_edges) << "nothing else runs along the seam";
    EXPECT_LT(top_rim_edges, seam_edges / 4) << "the outer rim is simplified";
  }
}

}  // namespace
}  // namespace gazelod::bake
