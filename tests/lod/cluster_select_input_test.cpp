// SPDX-License-Identifier: Apache-2.0
// Per-cluster selection at its seams (eye inside a sphere, gaze at a centre, errors 0 and +inf,
// radius 0, the eye at a centre), with data validation refused and unvalidated bad data
// harmless, and the instance transform / store.
#include "lod/cluster/cluster_select.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "tests/lod/cluster_test_hierarchy.hpp"
#include "tests/lod/reference_cluster_select.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

namespace gazelod::lod {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInfF = std::numeric_limits<float>::infinity();

struct Rec {
  glm::dvec3 c;
  double r, e;
};

// Clusters given as (self, parent) record pairs, one static mesh, as plain vectors (so a test
// can put bad values in that a store would refuse).
struct Raw {
  void add(const Rec& self, const Rec& parent) {
    sx.push_back(float(self.c.x)), sy.push_back(float(self.c.y)), sz.push_back(float(self.c.z));
    sr.push_back(float(self.r)), se.push_back(float(self.e));
    px.push_back(float(parent.c.x)), py.push_back(float(parent.c.y)), pz.push_back(float(parent.c.z));
    pr.push_back(float(parent.r)), pe.push_back(float(parent.e));
    count[0] = static_cast<std::uint32_t>(se.size());
    finest[0] = finest_cluster_error_m(se, pe);
  }
  ClusterSet view() const { return {sx, sy, sz, sr, se, px, py, pz, pr, pe, first, count, {}, {}, {}, finest}; }
  std::vector<float> sx, sy, sz, sr, se, px, py, pz, pr, pe;
  std::vector<std::uint32_t> first{0}, count{0};
  std::vector<double> finest{0.0};
};

struct Result {
  std::vector<std::uint8_t> drawn, why, bits;
};
Result run(const Viewer& vw, const ClusterSet& cs) {
  Result r{std::vector<std::uint8_t>(cs.size(), 9), std::vector<std::uint8_t>(cs.size(), 9),
           std::vector<std::uint8_t>(cs.size(), 9)};
  EXPECT_EQ(select_clusters(vw, cs, {r.drawn, r.why, {}, {}, {}, r.bits}), "");
  return r;
}

// A leaf (error 0) under a big record (error e): drawn when the big record is visible.
Raw leaf_under(const glm::dvec3& c, double e, double big_r = 2.0) {
  Raw raw;
  raw.add({c, 0.05, 0.0}, {c, big_r, e});
  raw.add({c, big_r, e}, {c, big_r, kInfF});
  return raw;
}

TEST(ClusterSelectSeams, EyeInsideASphereKeepsItsDetail) {
  Viewer vw;  // at the origin, still, looking down -z
  vw.xi_cpd = 8.0;
  for (bool others : {false, true}) {
    vw.use_eccentricity = vw.use_velocity = others;
    const Raw raw = leaf_under({0.3, 0.0, -0.5}, 0.004);  // the eye is inside the big sphere
    const Result r = run(vw, raw.view());
    EXPECT_EQ(r.drawn[0], 1);
    EXPECT_EQ(r.drawn[1], 0);
    EXPECT_EQ(r.bits[0], 1);  // self (error 0) invisible, parent not
    EXPECT_EQ(static_cast<Criterion>(r.why[0]), Criterion::none);
  }
}

TEST(ClusterSelectSeams, GazeExactlyAtTheCentreAndAway) {
  // An error that only eccentricity lets go: kept while gazed at, dropped 40 deg away.
  const glm::dvec3 c{0.0, 0.0, -10.0};
  const Raw raw = leaf_under(c, 0.01, 0.5);
  Viewer vw;
  vw.xi_cpd = 20.0;
  vw.gaze_direction = c;
  Result r = run(vw, raw.view());
  EXPECT_EQ(r.drawn[0], 1);
  EXPECT_EQ(test::reference_record(vw, raw.view(), 0, true).ecc_deg, 0.0);
  vw.gaze_direction = {std::sin(0.7), 0.0, -std::cos(0.7)};
  r = run(vw, raw.view());
  EXPECT_EQ(r.drawn[1], 1);
  EXPECT_EQ(static_cast<Criterion>(r.why[1]), Criterion::eccentricity);
}

TEST(ClusterSelectSeams, ErrorZeroAlwaysGoesErrorInfiniteNever) {
  Raw raw;
  raw.add({{0, 0, 0}, 1.0, 0.0}, {{0, 0, 0}, 1.0, kInfF});        // the eye at the centre
  raw.add({{0, 0, -1e4}, 0.0, 0.0}, {{0, 0, -1e4}, 0.0, kInfF});  // far, radius 0
  Viewer vw;
  vw.xi_cpd = 60.0;
  vw.head_angular_velocity_rad_s = {0.0, 50.0, 0.0};  // G = 0 everywhere: A = 0
  for (bool fast : {false, true}) {
    vw.use_velocity = fast;
    const Result r = run(vw, raw.view());
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_EQ(r.bits[i], 1) << i;  // self (0) invisible, parent (+inf) never
      EXPECT_EQ(r.drawn[i], 1) << i;
    }
  }
}

TEST(ClusterSelectSeams, RadiusZeroAndEyeAtTheCentreGiveNoNaN) {
  Raw raw;
  raw.add({{0, 0, 0}, 0.0, 0.0}, {{0, 0, 0}, 0.0, 1e-3});  // point at the eye
  raw.add({{0, 0, 0}, 0.0, 1e-3}, {{0, 0, 0}, 0.0, kInfF});
  raw.add({{0, 0, -3}, 0.0, 0.0}, {{0, 0, -3}, 0.0, 1e-5});  // a point straight ahead
  raw.add({{0, 0, -3}, 0.0, 1e-5}, {{0, 0, -3}, 0.0, kInfF});
  Viewer vw;
  vw.gaze_direction = {0.0, 0.0, -1.0};
  const Result r = run(vw, raw.view());
  EXPECT_EQ(r.drawn[0], 1);  // at the eye: seen from the floor distance, 1 mm stays visible
  EXPECT_EQ(r.drawn[1], 0);
  EXPECT_EQ(r.drawn[2], 0);  // 10 um at 3 m, in the fovea: invisible (f = 2618 cycles/deg)
  EXPECT_EQ(r.drawn[3], 1);
  EXPECT_EQ(static_cast<Criterion>(r.why[3]), Criterion::size);
}

TEST(ClusterSelectSeams, UnvalidatedBadDataIsNotDrawnAndHarmsNothingElse) {
  const test::TestTree t = test::make_tree({4, true, 1}, 2);
  ClusterStore store;
  store.add_mesh(t.h, {}, {}, 3 * t.h.size());
  Viewer vw;
  vw.eye_position_m = {2.0, 1.0, 2.0};
  const ClusterSet clean = store.view();
  const Result ref = run(vw, clean);
  for (float bad : {kNaN, kInfF, -1.0f}) {
    for (int field = 0; field < 10; ++field) {
      std::vector<std::vector<float>> f{{clean.self_center_x_m.begin(), clean.self_center_x_m.end()},
                                        {clean.self_center_y_m.begin(), clean.self_center_y_m.end()},
                                        {clean.self_center_z_m.begin(), clean.self_center_z_m.end()},
                                        {clean.self_radius_m.begin(), clean.self_radius_m.end()},
                                        {clean.self_error_m.begin(), clean.self_error_m.end()},
                                        {clean.parent_center_x_m.begin(), clean.parent_center_x_m.end()},
                                        {clean.parent_center_y_m.begin(), clean.parent_center_y_m.end()},
                                        {clean.parent_center_z_m.begin(), clean.parent_center_z_m.end()},
                                        {clean.parent_radius_m.begin(), clean.parent_radius_m.end()},
                                        {clean.parent_error_m.begin(), clean.parent_error_m.end()}};
      const std::size_t victim = 7;
      f[field][victim] = bad;
      ClusterSet cs = clean;
      cs.self_center_x_m = f[0], cs.self_center_y_m = f[1], cs.self_center_z_m = f[2], cs.self_radius_m = f[3];
      cs.self_error_m = f[4], cs.parent_center_x_m = f[5], cs.parent_center_y_m = f[6], cs.parent_center_z_m = f[7];
      cs.parent_radius_m = f[8], cs.parent_error_m = f[9];
      // -1 as a coordinate and +inf as an error are numbers to the kernel (a moved sphere, an
      // error never invisible); validation refuses all but a parent error of +inf.
      const bool number = (bad == -1.0f && field % 5 < 3) || (bad == kInfF && field % 5 == 4);
      if (!(bad == kInfF && field == 9)) {
        EXPECT_NE(validate_clusters(cs), "") << field << " " << bad;
      }
      const Result r = run(vw, cs);
      const bool refused = !number;
      for (std::size_t i = 0; i < cs.size(); ++i) {
        ASSERT_LE(r.drawn[i], 1);
        ASSERT_LE(r.why[i], static_cast<std::uint8_t>(Criterion::invalid_input));
        if (i != victim) {
          ASSERT_EQ(r.bits[i], ref.bits[i]) << field;
        }
      }
      if (refused) {
        EXPECT_EQ(r.drawn[victim], 0) << field << " " << bad;
        EXPECT_EQ(static_cast<Criterion>(r.why[victim]), Criterion::invalid_input) << field << " " << bad;
      }
    }
  }
}

TEST(ClusterSelectValidation, NamesTheFirstBadClusterAndField) {
  const auto msg = [](const std::function<void(Raw&)>& spoil) {
    Raw raw = leaf_under({0, 0, -5}, 0.01);
    raw.add({{0, 0, -5}, 0.05, 0.0}, {{0, 0, -5}, 2.0, 0.01});
    spoil(raw);
    return validate_clusters(raw.view());
  };
  EXPECT_EQ(msg([](Raw&) {}), "");
  EXPECT_EQ(msg([](Raw& r) { r.sy[2] = kNaN; }), "cluster 2: self centre is not finite");
  EXPECT_EQ(msg([](Raw& r) { r.sr[1] = -1.0f; }), "cluster 1: self_radius_m must be finite and >= 0, got -1");
  EXPECT_EQ(msg([](Raw& r) { r.se[0] = kNaN; }), "cluster 0: self_error_m must be finite and >= 0, got nan");
  EXPECT_EQ(msg([](Raw& r) { r.pz[2] = kInfF; }), "cluster 2: parent centre is not finite");
  EXPECT_EQ(msg([](Raw& r) { r.pe[0] = -0.5f; }), "cluster 0: parent_error_m must be >= 0 or +inf, got -0.5");
  EXPECT_NE(msg([](Raw& r) { r.se[2] = 0.02f; }).find("cluster 2: self_error_m 0.02 exceeds parent_error_m 0.01"),
            std::string::npos);
  EXPECT_NE(msg([](Raw& r) { r.pr[0] = 0.01f; }).find("cluster 0: parent sphere (radius 0.01) does not contain"),
            std::string::npos);
  EXPECT_NE(msg([](Raw& r) { r.finest[0] = 0.5; }).find("mesh 0: mesh_finest_error_m must be > 0"), std::string::npos);
  EXPECT_NE(msg([](Raw& r) { r.count[0] = 2; }).find("meshes cover 2 clusters, the arrays hold 3"), std::string::npos);
  EXPECT_NE(msg([](Raw& r) { r.pe.pop_back(); }).find("differ in length"), std::string::npos);
  // A top record's bounds are free (its error is never invisible).
  EXPECT_EQ(msg([](Raw& r) { r.pr[1] = 0.0f; }), "");
}

TEST(ClusterSelectValidation, SelectRefusesBadViewerAndShortOutputs) {
  const Raw raw = leaf_under({0, 0, -5}, 0.01);
  std::vector<std::uint8_t> a(2, 7), b(2, 7), c(1, 7);
  Viewer vw;
  vw.xi_cpd = -1.0;
  EXPECT_NE(select_clusters(vw, raw.view(), {a, b, {}, {}, {}, {}}).find("viewer: xi_cpd"), std::string::npos);
  vw = Viewer{};
  EXPECT_NE(select_clusters(vw, raw.view(), {a, c, {}, {}, {}, {}}), "");
  EXPECT_NE(select_clusters(vw, raw.view(), {a, b, a, {}, {}, {}}), "");  // per-criterion: all or none
  EXPECT_NE(select_clusters(vw, raw.view(), {a, b, {}, {}, {}, c}), "");
  Raw gap = raw;
  gap.first[0] = 1;
  EXPECT_NE(select_clusters(vw, gap.view(), {a, b, {}, {}, {}, {}}).find("back to back"), std::string::npos);
  EXPECT_EQ(a, std::vector<std::uint8_t>(2, 7));  // untouched
}

TEST(ClusterStore, TransformAndMovingMeshes) {
  const test::TestTree t = test::make_tree({4, true, 2}, 5);
  InstanceTransform xf;
  xf.rotation = glm::angleAxis(0.7, glm::normalize(glm::dvec3{1, 2, 3}));
  xf.translation_m = {10.0, -2.0, 5.0};
  xf.scale = 2.5;
  ClusterHierarchy world;
  ASSERT_EQ(transform_hierarchy(t.h, xf, world), "");
  const glm::dvec3 c0 = xf.translation_m +
                        xf.scale * (glm::mat3_cast(xf.rotation) *
                                    glm::dvec3{t.h.self_center_x_m[3], t.h.self_center_y_m[3], t.h.self_center_z_m[3]});
  EXPECT_NEAR(world.self_center_y_m[3], c0.y, 1e-5);
  EXPECT_GE(world.parent_radius_m[3], 2.5f * t.h.parent_radius_m[3]);  // rounded up
  const std::size_t top = t.h.size() - 1;
  EXPECT_GT(t.h.self_error_m[top], 0.0f);
  EXPECT_GE(world.self_error_m[top], 2.5f * t.h.self_error_m[top]);
  ClusterStore moved, placed;
  moved.add_mesh(t.h, {}, {}, 3 * t.h.size());
  moved.set_pose(0, t.h, xf, {1.0, 0.0, 0.0});
  placed.add_mesh(t.h, xf, {1.0, 0.0, 0.0}, 3 * t.h.size());
  const ClusterSet a = moved.view(), b = placed.view();
  EXPECT_EQ(validate_clusters(a), "");
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a.parent_center_z_m[i], b.parent_center_z_m[i]);
  EXPECT_EQ(a.mesh_finest_error_m[0], b.mesh_finest_error_m[0]);
  EXPECT_EQ(a.mesh_vel_x_m_s[0], 1.0);
  // Refusals leave the store unchanged.
  InstanceTransform bad = xf;
  bad.scale = 0.0;
  EXPECT_THROW(placed.add_mesh(t.h, bad, {}, 3 * t.h.size()), std::invalid_argument);
  EXPECT_THROW(placed.add_mesh(t.h, xf, {}, 3 * t.h.size() - 1), std::invalid_argument);
  EXPECT_THROW(placed.set_pose(1, t.h, xf, {}), std::out_of_range);
  EXPECT_EQ(placed.mesh_count(), 1u);
  EXPECT_EQ(placed.size(), t.h.size());
}

TEST(ClusterStore, DistinctRecordsFollowMovesAndBadTablesAreNamed) {
  const test::TestTree t = test::make_tree({4, true, 2}, 5);
  ClusterStore store;
  store.add_mesh(t.h, {}, {}, 3 * t.h.size());
  store.add_mesh(t.h, {}, {}, 3 * t.h.size());
  InstanceTransform xf;
  xf.rotation = glm::angleAxis(0.7, glm::normalize(glm::dvec3{1, 2, 3}));
  xf.translation_m = {10.0, -2.0, 5.0};
  xf.scale = 2.5;
  store.set_pose(1, t.h, xf, {0.5, 0.0, 0.0});
  const ClusterSet cs = store.view();
  // Equal records per mesh (the two meshes' are apart: their velocities and size caps differ).
  EXPECT_EQ(cs.mesh_record_count[0], cs.mesh_record_count[1]);
  EXPECT_LT(cs.mesh_record_count[0], 2 * t.h.size());
  EXPECT_EQ(validate_clusters(cs), "") << "the moved mesh's records were re-transformed with it";
  // A table that no longer matches its clusters, or points outside its mesh, is named.
  std::vector<float> err(cs.record_error_m.begin(), cs.record_error_m.end());
  std::vector<std::uint32_t> parent(cs.parent_record.begin(), cs.parent_record.end());
  ClusterSet spoiled = cs;
  err[cs.parent_record[2]] += 1.0f;
  spoiled.record_error_m = err;
  EXPECT_NE(validate_clusters(spoiled).find("differs from the cluster's own"), std::string::npos)
      << validate_clusters(spoiled);
  spoiled = cs;
  parent[0] = cs.mesh_first_record[1];
  spoiled.parent_record = parent;
  EXPECT_NE(validate_clusters(spoiled).find("cluster 0: parent_record " + std::to_string(parent[0]) +
                                            " is outside its mesh's records"),
            std::string::npos)
      << validate_clusters(spoiled);
  // Per frame the same index only stays in bounds: no crash, bytes in range.
  std::vector<std::uint8_t> d(cs.size()), w(cs.size()), a(cs.size()), b(cs.size()), c(cs.size());
  std::vector<std::uint32_t> flags(cs.record_count());
  ClusterDecisions out{d, w, a, b, c, {}, flags};
  EXPECT_EQ(select_clusters(Viewer{}, spoiled, out), "");
  for (std::uint8_t v : w) ASSERT_LE(v, static_cast<std::uint8_t>(Criterion::invalid_input));
  // Scratch shorter than the records is refused, not ignored.
  ClusterDecisions short_scratch = out;
  short_scratch.record_flags = std::span(flags).first(flags.size() - 1);
  EXPECT_NE(select_clusters(Viewer{}, cs, short_scratch).find("decisions: record_flags has"), std::string::npos);
  // Lengths: a table missing a mesh's range is refused per frame.
  spoiled = cs;
  spoiled.mesh_record_count = spoiled.mesh_record_count.first(1);
  EXPECT_NE(select_clusters(Viewer{}, spoiled, out).find("mesh record arrays differ in length"), std::string::npos);
}

TEST(ClusterStore, HierarchyValidationChecksTriangleRanges) {
  test::TestTree t = test::make_tree({2, false, 1}, 1);
  const std::size_t n = t.h.size();
  EXPECT_EQ(validate_cluster_hierarchy(t.h, 3 * n), "");
  EXPECT_NE(validate_cluster_hierarchy(t.h, 3 * n - 1).find("out of range of the index buffer"), std::string::npos);
  t.h.index_count[1] = 4;
  EXPECT_EQ(validate_cluster_hierarchy(t.h, 3 * n), "cluster 1: index_count 4 is not a multiple of 3");
  t.h.depth.pop_back();
  EXPECT_NE(validate_cluster_hierarchy(t.h, 3 * n).find("one entry per cluster"), std::string::npos);
}

}  // namespace
}  // namespace gazelod::lod
