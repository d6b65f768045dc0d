// SPDX-License-Identifier: Apache-2.0
// The plugin's cluster meshes over the simulated runtime (default scenario: head sweeps,
// saccades, tracker noise): a 20 m wall built by bake's cluster hierarchy is cut per frame
// with the conditioned gaze and the switch policy, and every frame's cut, before and after the
// policy, covers the wall without a crack or an overlap. The cut follows the gaze:
// it is coarser than full detail, finer than the hierarchy's top, and finer near the gaze.
// (Cracks are checked on the triangles: every edge of the drawn cut is shared, except along
// the mesh's own rim, which the bake simplifies too; overlaps on the group links. Edges on more than two triangles are
// not a test: meshopt_simplify can leave a non-manifold edge inside a group even in a uniform cut.)
#include "run_test_util.hpp"

#include "apps/xr_host/xr_app.hpp"
#include "bake/cluster/cluster_build.hpp"
#include "plugin/lod_plugin.hpp"
#include "tests/bake/test_meshes.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <set>

namespace gazelod::test {
namespace {

// A cut's undirected edges on exactly one drawn triangle, sorted. Simplification keeps the
// source's vertex indices and locks group borders, so where two drawn clusters meet their
// edges share indices; an edge left single is a crack, or on the mesh's own rim.
std::vector<std::uint64_t> single_edges(const bake::ClusterBuildResult& r, std::span<const std::uint8_t> drawn) {
  std::vector<std::uint64_t> keys;
  for (std::size_t c = 0; c < drawn.size(); ++c) {
    if (!drawn[c]) continue;
    const std::uint32_t* t = r.indices.data() + r.hierarchy.first_index[c];
    for (std::uint32_t k = 0; k < r.hierarchy.index_count[c]; k += 3)
      for (int e = 0; e < 3; ++e) {
        const std::uint64_t a = t[k + e], b = t[k + (e + 1) % 3];
        keys.push_back(std::min(a, b) << 32 | std::max(a, b));
      }
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::uint64_t> single;
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i;
    while (j < keys.size() && keys[j] == keys[i]) ++j;
    if (j - i == 1) single.push_back(keys[i]);
    i = j;
  }
  return single;
}

// An overlap shows in the group links: a group whose record is visible has its members drawn
// (or finer ones), one whose record is invisible its outputs (or coarser ones), never both.
// Returns a group with a drawn member and a drawn output, or -1.
int group_drawn_both_ways(const bake::ClusterBuildResult& r, std::span<const std::uint8_t> drawn) {
  std::vector<std::uint8_t> member(r.groups + 1, 0), output(r.groups + 1, 0);
  for (std::size_t c = 0; c < drawn.size(); ++c) {
    if (!drawn[c]) continue;
    if (r.parent_group[c] >= 0) member[std::size_t(r.parent_group[c])] = 1;
    if (r.source_group[c] >= 0) output[std::size_t(r.source_group[c])] = 1;
  }
  for (std::size_t g = 0; g < member.size(); ++g)
    if (member[g] && output[g]) return int(g);
  return -1;
}

TEST(PluginClusters, EveryFramesCutIsConsistentAndFollowsTheGaze) {
  use_simulated_runtime("");
  const bake::testing::TestMesh wall = bake::testing::grid(160, 20.0, 0.3);  // 51,200 triangles in the XY plane
  bake::ClusterBuildOptions options;
  options.threads = 1;
  const bake::ClusterBuildResult built = bake::build_cluster_hierarchy(wall.positions, wall.indices, options);
  ASSERT_GT(built.levels, 3u);
  // The source mesh's own border: the only edges any consistent cut may leave single.
  std::vector<std::uint8_t> leaves(built.hierarchy.size(), 0);
  for (std::size_t c = 0; c < leaves.size(); ++c) leaves[c] = built.source_group[c] < 0;
  const std::vector<std::uint64_t> border = single_edges(built, leaves);
  ASSERT_FALSE(border.empty());
  // The wall's own rim meets nothing, so the bake simplifies it along itself: a cut may leave
  // single any edge between two rim vertices, and no other (that would be a crack).
  std::set<std::uint32_t> rim;
  for (std::uint64_t e : border) rim.insert({static_cast<std::uint32_t>(e >> 32), static_cast<std::uint32_t>(e)});
  const auto inside = [&](const std::vector<std::uint64_t>& single) {
    return std::count_if(single.begin(), single.end(), [&](std::uint64_t e) {
      return !rim.contains(static_cast<std::uint32_t>(e >> 32)) || !rim.contains(static_cast<std::uint32_t>(e));
    });
  };

  xr_host::XrApp app(true);
  PluginConfig cfg;
  auto plugin =
      LodPlugin::create(xrGetInstanceProcAddr, app.instance(), app.system(), app.session(), app.local_space(), cfg);
  ClusterMeshDesc desc;
  desc.hierarchy = built.hierarchy;
  desc.index_count = built.indices.size();
  desc.pose.translation_m = {-10.0, -8.4, -6.0};  // facing the viewer, 6 m ahead, centred at eye height
  EXPECT_EQ(plugin->add_cluster_mesh(desc), 0u);
  EXPECT_EQ(plugin->cluster_mesh_count(), 1u);
  // A bad hierarchy is refused with the reason, and nothing is registered.
  ClusterMeshDesc bad = desc;
  bad.hierarchy.self_error_m[0] = std::nanf("");
  EXPECT_THROW(plugin->add_cluster_mesh(bad), std::invalid_argument);
  EXPECT_EQ(plugin->cluster_mesh_count(), 1u);

  const auto triangles = [&](std::span<const std::uint8_t> drawn) {
    std::size_t t = 0;
    for (std::size_t c = 0; c < drawn.size(); ++c) t += drawn[c] ? built.hierarchy.index_count[c] / 3 : 0;
    return t;
  };
  std::size_t top_triangles = 0;
  for (std::size_t c = 0; c < built.hierarchy.size(); ++c)
    if (built.parent_group[c] < 0) top_triangles += built.hierarchy.index_count[c] / 3;

  int frames = 0, coarser_than_full = 0, finer_than_top = 0, gaze_finer = 0, gaze_frames = 0;
  while (frames < 150 && app.poll_events([&](XrSessionState s, XrTime t) { plugin->on_session_state(s, t); })) {
    if (!app.session_running()) continue;
    const XrFrameState fs = app.wait_frame();
    app.begin_frame();
    const FrameDecisions& d = plugin->begin_frame(fs.predictedDisplayTime);
    const FrameDiagnostics& diag = plugin->diagnostics();
    ASSERT_EQ(d.cluster_drawn.size(), built.hierarchy.size());
    ASSERT_EQ(d.cluster_first.size(), 1u);
    if (frames % 3 == 0)  // no crack: the cut's border runs along the mesh's rim; no overlap
      for (const auto cut : {d.cluster_drawn, diag.cluster_drawn_perceptual}) {
        ASSERT_EQ(inside(single_edges(built, cut)), 0) << "frame " << frames << ": a crack";
        ASSERT_EQ(group_drawn_both_ways(built, cut), -1) << "frame " << frames << ": an overlap";
      }
    const std::size_t drawn = triangles(d.cluster_drawn);
    coarser_than_full += drawn < built.source_triangles;
    finer_than_top += drawn > top_triangles;
    // Near the gaze the cut is finer than far from it: compare the drawn clusters' self error
    // at the wall point under the gaze with the one 8 m away.
    const glm::dvec3 eye = diag.eye_position_world, g = diag.gaze_direction_world;
    if (d.gaze_valid && std::abs(g.z) > 1e-3) {
      const double s = (-6.0 - eye.z) / g.z;
      const glm::dvec3 hit = eye + s * g;
      if (s > 0 && std::abs(hit.x) < 6.0 && std::abs(hit.y - 1.6) < 6.0) {
        const auto error_near = [&](const glm::dvec3& p) {
          float best = -1.0f, best_d = 1e9f;
          for (std::size_t c = 0; c < d.cluster_drawn.size(); ++c) {
            if (!d.cluster_drawn[c]) continue;
            const float dx = built.hierarchy.self_center_x_m[c] - 10.0f - float(p.x);
            const float dy = built.hierarchy.self_center_y_m[c] - 8.4f - float(p.y);
            const float dist = std::hypot(dx, dy);
            if (dist < best_d) best_d = dist, best = built.hierarchy.self_error_m[c];
          }
          return best;
        };
        const glm::dvec3 far = hit + glm::dvec3(hit.x < 0 ? 8.0 : -8.0, 0.0, 0.0);
        ++gaze_frames;
        gaze_finer += error_near(hit) <= error_near(far);
      }
    }
    app.end_frame(fs.predictedDisplayTime, {});
    plugin->end_frame(1.0);
    ++frames;
  }
  ASSERT_EQ(frames, 150);
  EXPECT_GT(coarser_than_full, 100) << "the cut drops detail the user cannot see";
  EXPECT_GT(finer_than_top, 100) << "and keeps detail the user can";
  ASSERT_GT(gaze_frames, 30);
  EXPECT_GE(gaze_finer, gaze_frames * 9 / 10) << "the cut is finest where the gaze is";

  // The wall moves: 5 km away its cut coarsens to the top (once the switch policy lets it,
  // within its longest deferral); back at 6 m it refines at once (refining never waits).
  EXPECT_THROW(plugin->set_cluster_mesh_motion(1, desc.pose, glm::dvec3(0.0)), std::out_of_range);
  lod::InstanceTransform nan_pose = desc.pose;
  nan_pose.translation_m.x = std::nan("");
  EXPECT_THROW(plugin->set_cluster_mesh_motion(0, nan_pose, glm::dvec3(0.0)), std::invalid_argument);
  const auto run_frames = [&](int n) {
    std::size_t drawn = 0;
    for (int k = 0; k < n && app.poll_events([&](XrSessionState s, XrTime t) { plugin->on_session_state(s, t); });) {
      if (!app.session_running()) continue;
      const XrFrameState fs = app.wait_frame();
      app.begin_frame();
      const FrameDecisions& d = plugin->begin_frame(fs.predictedDisplayTime);
      drawn = triangles(d.cluster_drawn);
      EXPECT_EQ(group_drawn_both_ways(built, d.cluster_drawn), -1) << "an overlap after a move";
      app.end_frame(fs.predictedDisplayTime, {});
      plugin->end_frame(1.0);
      ++k;
    }
    return drawn;
  };
  const std::size_t near_triangles = run_frames(1);
  lod::InstanceTransform far = desc.pose;
  far.translation_m.z = -5000.0;
  plugin->set_cluster_mesh_motion(0, far, glm::dvec3(0.0));
  const std::size_t far_triangles = run_frames(200);
  EXPECT_EQ(far_triangles, top_triangles) << "5 km away the wall is drawn at the hierarchy's top";
  EXPECT_LT(far_triangles, near_triangles);
  plugin->set_cluster_mesh_motion(0, desc.pose, glm::dvec3(0.0));
  EXPECT_GT(run_frames(1), far_triangles) << "back at 6 m the cut refines in the next frame";
}

}  // namespace
}  // namespace gazelod::test
