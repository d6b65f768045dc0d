// SPDX-License-Identifier: Apache-2.0
// Per-cluster selection: the cut's consistency under random viewers on synthetic hierarchies,
// the float kernel against the exact rule in double (never coarser, equal where robust),
// equality with select_lods on a one-cluster-per-level chain, and monotonicity.
#include "lod/cluster/cluster_select.hpp"
#include "lod/cluster/cluster_select_kernel.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "tests/lod/cluster_test_hierarchy.hpp"
#include "tests/lod/reference_cluster_select.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace gazelod::lod {
namespace {

using test::TestTree;
using test::TreeSpec;

struct Out {
  explicit Out(std::size_t n) : drawn(n), why(n), s(n), e(n), v(n), bits(n) {}
  ClusterDecisions all() { return {drawn, why, s, e, v, bits}; }
  ClusterDecisions combined_only() { return {drawn, why, {}, {}, {}, bits}; }
  std::vector<std::uint8_t> drawn, why, s, e, v, bits;
};

// A viewer near a random mesh's random cluster (often inside its sphere), gazing anywhere or at
// a cluster's centre, moving, turning and pursuing at random; sometimes with criteria off.
Viewer random_viewer(std::mt19937_64& rng, const ClusterSet& cs) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto pick = [&]() {
    const std::size_t m = static_cast<std::size_t>(u(rng) * double(cs.mesh_count())) % cs.mesh_count();
    return cs.mesh_first_cluster[m] +
           static_cast<std::size_t>(u(rng) * cs.mesh_cluster_count[m]) % cs.mesh_cluster_count[m];
  };
  const auto centre = [&](std::size_t i) {
    return glm::dvec3{cs.self_center_x_m[i], cs.self_center_y_m[i], cs.self_center_z_m[i]};
  };
  const auto uv = [&]() { return glm::dvec3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5}; };
  Viewer vw;
  const double away = u(rng);  // inside a sphere, near, or farther
  vw.eye_position_m = centre(pick()) + (away < 0.2 ? 0.01 : away < 0.7 ? 3.0 : 20.0) * uv();
  vw.gaze_direction = u(rng) < 0.4 ? centre(pick()) - vw.eye_position_m : uv();
  if (!(glm::length(vw.gaze_direction) > 0.0)) vw.gaze_direction = {0, 0, -1};
  vw.eye_velocity_m_s = 2.0 * uv();
  const double turn = u(rng);  // mostly slow; now and then a fast head turn (G down to 0)
  vw.head_angular_velocity_rad_s = (turn < 0.7 ? 0.3 : turn < 0.9 ? 1.5 : 6.0) * uv();
  vw.gaze_angular_velocity_in_head_rad_s = 0.5 * uv();
  vw.xi_cpd = 4.0 + 60.0 * u(rng);
  vw.scale = 0.3 + 0.7 * u(rng);
  vw.tracker_error_deg = 3.0 * u(rng);
  if (u(rng) < 0.3) {
    vw.use_size = u(rng) < 0.5, vw.use_eccentricity = u(rng) < 0.5, vw.use_velocity = u(rng) < 0.5;
  }
  return vw;
}

struct Scene {
  std::vector<TestTree> trees;
  ClusterStore store;
};

// Trees as meshes, side by side along x, every other one moving.
Scene make_scene(const std::vector<TreeSpec>& specs, std::uint64_t seed) {
  Scene sc;
  double x = 0.0;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    sc.trees.push_back(test::make_tree(specs[k], seed + k));
    const TestTree& t = sc.trees.back();
    InstanceTransform xf;
    xf.translation_m = {x, 0.0, 0.0};
    xf.rotation = glm::angleAxis(0.3 * double(k), glm::dvec3{0, 1, 0});
    const glm::dvec3 vel = k % 2 ? glm::dvec3{0.8, 0.0, -0.5} : glm::dvec3{0.0};
    sc.store.add_mesh(t.h, xf, vel, 3 * t.h.size());
    x += specs[k].spacing_m * double(1 << specs[k].levels) + 1.0;
  }
  return sc;
}

// The cut of mesh k, as its own span.
std::span<const std::uint8_t> mesh_cut(const Scene& sc, std::size_t k, const std::vector<std::uint8_t>& v) {
  return std::span<const std::uint8_t>(v).subspan(sc.store.first_cluster(static_cast<std::uint32_t>(k)),
                                                  sc.trees[k].h.size());
}

TEST(ClusterSelect, CutIsConsistentUnderRandomViewers) {
  const Scene sc = make_scene({{8, false, 1}, {5, true, 2}, {4, true, 1, 0.3, 0.002, 0.3}}, 11);
  const ClusterSet cs = sc.store.view();
  ASSERT_EQ(validate_clusters(cs), "");
  std::mt19937_64 rng(5);
  std::size_t mixed = 0;  // cuts with both source clusters and coarser ones
  for (int trial = 0; trial < 300; ++trial) {
    const Viewer vw = random_viewer(rng, cs);
    Out out(cs.size()), fast(cs.size());
    ASSERT_EQ(select_clusters(vw, cs, out.all()), "");
    // Without per-criterion outputs (the size screen, self records implied by invisible
    // parents): the same cut and reasons.
    ASSERT_EQ(select_clusters(vw, cs, fast.combined_only()), "");
    ASSERT_EQ(fast.drawn, out.drawn) << "trial " << trial;
    ASSERT_EQ(fast.why, out.why) << "trial " << trial;
    for (std::size_t i = 0; i < cs.size(); ++i)
      if ((out.bits[i] & 2) == 0) {
        ASSERT_EQ(fast.bits[i], out.bits[i]) << "trial " << trial;
      }
    for (std::size_t k = 0; k < sc.trees.size(); ++k) {
      ASSERT_EQ(test::check_cut(sc.trees[k], mesh_cut(sc, k, out.drawn)), "") << "trial " << trial << " mesh " << k;
      for (const auto* cut : {&out.s, &out.e, &out.v})
        ASSERT_EQ(test::check_cut(sc.trees[k], mesh_cut(sc, k, *cut)), "") << "trial " << trial;
      const std::vector<int> lv = test::cut_levels(sc.trees[k], mesh_cut(sc, k, out.drawn));
      const int top = *std::max_element(lv.begin(), lv.end()), bottom = *std::min_element(lv.begin(), lv.end());
      mixed += top > bottom;  // the cut is not one level across the mesh
    }
  }
  EXPECT_GT(mixed, 450u);  // of 900: most cuts are not one level across the mesh
}

TEST(ClusterSelect, DistinctRecordsGiveTheSameDecisions) {
  // Selection over the store's distinct records (each evaluated once, then combined per
  // cluster) against the same selection evaluated per cluster: every output equal.
  const Scene sc = make_scene({{8, false, 1}, {5, true, 2}, {4, true, 1, 0.3, 0.002, 0.3}}, 11);
  const ClusterSet cs = sc.store.view();
  ASSERT_EQ(validate_clusters(cs), "");
  ASSERT_TRUE(cs.has_records());
  // A group's record is shared by its members and the clusters it produced: far fewer
  // distinct records than the two per cluster.
  EXPECT_LT(cs.record_count(), cs.size() * 3 / 2) << cs.record_count() << " records, " << cs.size() << " clusters";
  ClusterSet per_cluster = cs;
  per_cluster.record_center_x_m = {}, per_cluster.record_center_y_m = {}, per_cluster.record_center_z_m = {};
  per_cluster.record_radius_m = {}, per_cluster.record_error_m = {};
  per_cluster.self_record = {}, per_cluster.parent_record = {};
  per_cluster.mesh_first_record = {}, per_cluster.mesh_record_count = {};
  ASSERT_FALSE(per_cluster.has_records());
  std::mt19937_64 rng(17);
  std::vector<std::uint32_t> flags(cs.record_count());
  std::size_t drawn = 0;
  // Both paths with and without the per-criterion cuts (the frame's path: the size screen, self
  // records under an invisible parent set by the nesting).
  const auto run = [&](const Viewer& vw, bool per_criterion, Out& by_record, Out& own) {
    ClusterDecisions with = per_criterion ? by_record.all() : by_record.combined_only();
    with.record_flags = flags;
    ASSERT_EQ(select_clusters(vw, cs, with), "");
    ASSERT_EQ(select_clusters(vw, per_cluster, per_criterion ? own.all() : own.combined_only()), "");
    ASSERT_EQ(by_record.drawn, own.drawn);
    ASSERT_EQ(by_record.why, own.why);
    ASSERT_EQ(by_record.bits, own.bits);
    if (per_criterion) {
      ASSERT_EQ(by_record.s, own.s);
      ASSERT_EQ(by_record.e, own.e);
      ASSERT_EQ(by_record.v, own.v);
    }
  };
  for (int trial = 0; trial < 300; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const Viewer vw = random_viewer(rng, cs);
    Out a(cs.size()), b(cs.size()), c(cs.size()), d(cs.size());
    run(vw, true, a, b);
    run(vw, false, c, d);
    ASSERT_EQ(c.drawn, a.drawn);
    drawn += static_cast<std::size_t>(std::count(a.drawn.begin(), a.drawn.end(), 1));
  }
  EXPECT_GT(drawn, 300u);
}

TEST(ClusterSelect, ShuffledClustersGiveTheSameDecisions) {
  // Where a record sits (which block, gathered or not, which vector lane) must not change its
  // decision.
  const TestTree t = test::make_tree({6, true, 2}, 3);
  std::vector<std::size_t> perm(t.h.size());
  for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = i;
  std::shuffle(perm.begin(), perm.end(), std::mt19937_64(9));
  ClusterHierarchy shuffled = t.h;
  for (std::size_t i = 0; i < perm.size(); ++i) {
    const std::size_t j = perm[i];
    shuffled.self_center_x_m[i] = t.h.self_center_x_m[j], shuffled.self_center_y_m[i] = t.h.self_center_y_m[j];
    shuffled.self_center_z_m[i] = t.h.self_center_z_m[j], shuffled.self_radius_m[i] = t.h.self_radius_m[j];
    shuffled.self_error_m[i] = t.h.self_error_m[j], shuffled.parent_error_m[i] = t.h.parent_error_m[j];
    shuffled.parent_center_x_m[i] = t.h.parent_center_x_m[j], shuffled.parent_center_y_m[i] = t.h.parent_center_y_m[j];
    shuffled.parent_center_z_m[i] = t.h.parent_center_z_m[j], shuffled.parent_radius_m[i] = t.h.parent_radius_m[j];
  }
  ClusterStore a, b;
  a.add_mesh(t.h, {}, {}, 3 * t.h.size());
  b.add_mesh(shuffled, {}, {}, 3 * t.h.size());
  std::mt19937_64 rng(2);
  for (int trial = 0; trial < 100; ++trial) {
    const Viewer vw = random_viewer(rng, a.view());
    Out oa(t.h.size()), ob(t.h.size());
    ASSERT_EQ(select_clusters(vw, a.view(), oa.combined_only()), "");
    ASSERT_EQ(select_clusters(vw, b.view(), ob.combined_only()), "");
    for (std::size_t i = 0; i < perm.size(); ++i) {
      ASSERT_EQ(ob.bits[i], oa.bits[perm[i]]) << trial;
      ASSERT_EQ(ob.why[i], oa.why[perm[i]]) << trial;
    }
  }
}

// Every record of every cluster through the kernel (full evaluation, every criterion) and the
// screen, against the exact rule.
void expect_kernel_matches_reference(const Viewer& vw, const ClusterSet& cs, std::size_t& compared, std::size_t& robust,
                                     std::size_t& by_ecc_or_vel) {
  const detail::ClusterFrame f = detail::make_cluster_frame(vw);
  for (std::size_t k = 0; k < cs.mesh_count(); ++k) {
    const detail::ClusterMeshFrame m = detail::make_cluster_mesh_frame(vw, cs, k);
    for (bool parent : {false, true}) {
      const detail::RecordInput in =
          parent ? detail::RecordInput{cs.parent_center_x_m.data(), cs.parent_center_y_m.data(),
                                       cs.parent_center_z_m.data(), cs.parent_radius_m.data(), cs.parent_error_m.data()}
                 : detail::RecordInput{cs.self_center_x_m.data(), cs.self_center_y_m.data(), cs.self_center_z_m.data(),
                                       cs.self_radius_m.data(), cs.self_error_m.data()};
      const std::size_t end = std::size_t{cs.mesh_first_cluster[k]} + cs.mesh_cluster_count[k];
      for (std::size_t base = cs.mesh_first_cluster[k]; base < end; base += detail::kClusterBlock) {
        const std::size_t n = std::min(detail::kClusterBlock, end - base);
        detail::RecordBlock full, screened, trivial;
        detail::evaluate_records(f, m, in, base, n, true, detail::RecordScreen::none, nullptr, full);
        detail::evaluate_records(f, m, in, base, n, true, detail::RecordScreen::by_size, nullptr, screened);
        detail::evaluate_records(f, m, in, base, n, true, detail::RecordScreen::trivial, nullptr, trivial);
        for (std::size_t j = 0; j < n; ++j) {
          const test::RecordRef ref = test::reference_record(vw, cs, base + j, parent);
          const bool kc = full.combined[j] > 0.5f, ks = full.size[j] > 0.5f, ke = full.eccentricity[j] > 0.5f,
                     kv = full.velocity[j] > 0.5f;
          const auto where = [&]() {
            return "record " + std::to_string(base + j) + (parent ? " (parent)" : " (self)") + ": E " +
                   std::to_string(ref.ecc_deg) + " / " + std::to_string(full.ecc_deg[j]) + ", v " +
                   std::to_string(ref.vel_dps) + " / " + std::to_string(full.vel_dps[j]) + ", d " +
                   std::to_string(ref.near_m) + " / " + std::to_string(full.near_m[j]) + " (exact / kernel)";
          };
          ASSERT_EQ(screened.combined[j], full.combined[j]) << where();
          ASSERT_EQ(screened.size[j], full.size[j]) << where();
          // The trivial screen (the per-criterion path's) leaves every output as it was.
          ASSERT_EQ(trivial.combined[j], full.combined[j]) << where();
          ASSERT_EQ(trivial.size[j], full.size[j]) << where();
          ASSERT_EQ(trivial.eccentricity[j], full.eccentricity[j]) << where();
          ASSERT_EQ(trivial.velocity[j], full.velocity[j]) << where();
          ASSERT_EQ(trivial.positive[j], full.positive[j]) << where();
          ASSERT_EQ(trivial.invalid[j], full.invalid[j]) << where();
          // Never coarser: invisible to the kernel only where invisible to the exact rule.
          ASSERT_TRUE(!kc || ref.combined) << where();
          ASSERT_TRUE(!ks || ref.size) << where();
          ASSERT_TRUE(!ke || ref.eccentricity) << where();
          ASSERT_TRUE(!kv || ref.velocity) << where();
          ++compared;
          if (!ref.robust) continue;
          ++robust;
          ASSERT_EQ(kc, ref.combined) << where();
          ASSERT_EQ(ks, ref.size) << where();
          ASSERT_EQ(ke, ref.eccentricity) << where();
          ASSERT_EQ(kv, ref.velocity) << where();
          by_ecc_or_vel += ref.combined && !ref.size && std::isfinite(cs.self_error_m[base + j]);
        }
      }
    }
  }
}

TEST(ClusterSelect, KernelMatchesExactReference) {
  const Scene sc = make_scene({{8, false, 1}, {5, true, 2}}, 21);
  const ClusterSet cs = sc.store.view();
  std::mt19937_64 rng(8);
  std::size_t compared = 0, robust = 0, by_ecc_or_vel = 0;
  for (int trial = 0; trial < 120 && !HasFatalFailure(); ++trial)
    expect_kernel_matches_reference(random_viewer(rng, cs), cs, compared, robust, by_ecc_or_vel);
  EXPECT_GT(robust, compared * 99 / 100);
  EXPECT_GT(by_ecc_or_vel, 1000u);  // eccentricity and velocity decide a good share
}

// Records built to sit on the kernel's hard cases: far from the origin, from a micrometre to
// 10 km away, radii from 0 to enclosing the eye, the eye just outside a surface, the gaze
// tangent to a sphere, pursuit cancelling the motion, errors from 0 through 1e-9 m to +inf.
TEST(ClusterSelect, KernelNeverCoarserOnAdversarialRecords) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto dir = [&]() {
    glm::dvec3 v{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5};
    return glm::length(v) > 1e-3 ? glm::normalize(v) : glm::dvec3{1, 0, 0};
  };
  std::size_t compared = 0, robust = 0, by_ecc_or_vel = 0;
  for (int trial = 0; trial < 60; ++trial) {
    Viewer vw;
    vw.eye_position_m = (trial % 3 ? 1e4 : 1.0) * dir();
    vw.gaze_direction = dir();
    vw.eye_velocity_m_s = 2.0 * dir();
    vw.head_angular_velocity_rad_s = std::pow(10.0, 2 * u(rng) - 1.5) * dir();
    vw.xi_cpd = 2.0 + 58.0 * u(rng), vw.scale = 0.2 + 0.8 * u(rng), vw.tracker_error_deg = 2.0 * u(rng);
    const glm::dvec3 mesh_vel = 3.0 * dir();
    std::vector<float> f[10];
    for (int i = 0; i < 512; ++i) {
      const double d = std::pow(10.0, 10 * u(rng) - 6);
      glm::dvec3 toward = dir();
      double r = i % 7 == 0 ? 0.0 : d * std::pow(10.0, 6.3 * u(rng) - 6);
      if (i % 5 == 1) r = d / (1.0 + std::pow(10.0, 5 * u(rng) - 7));  // eye just outside
      if (i % 5 == 2) {                                                // the gaze grazing the sphere
        r = d * 0.3 * u(rng);
        const double a = std::asin(r / d) + (u(rng) - 0.5) * 1e-5;
        const glm::dvec3 side = glm::normalize(glm::cross(vw.gaze_direction, dir()));
        toward = std::cos(a) * glm::normalize(vw.gaze_direction) + std::sin(a) * side;
      }
      const glm::dvec3 c = vw.eye_position_m + d * toward;
      const double e = i % 11 == 0 ? 0.0 : i % 13 == 0 ? double(kNoParentError) : std::pow(10.0, 10 * u(rng) - 9);
      const double vals[5] = {c.x, c.y, c.z, r, e};
      for (int k = 0; k < 5; ++k)
        f[k].push_back(static_cast<float>(vals[k])), f[5 + k].push_back(static_cast<float>(vals[k]));
    }
    if (trial % 2) {  // pursuit of record 3: the gaze turns with it
      const glm::dvec3 r3 = glm::dvec3{f[0][3], f[1][3], f[2][3]} - vw.eye_position_m;
      vw.gaze_angular_velocity_in_head_rad_s =
          glm::cross(r3, mesh_vel - vw.eye_velocity_m_s) / glm::dot(r3, r3) - vw.head_angular_velocity_rad_s;
    }
    const std::vector<std::uint32_t> first{0}, count{512};
    const std::vector<double> vx{mesh_vel.x}, vy{mesh_vel.y}, vz{mesh_vel.z}, finest{1e-9};
    const ClusterSet cs{f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8], f[9], first, count, vx, vy, vz, finest};
    expect_kernel_matches_reference(vw, cs, compared, robust, by_ecc_or_vel);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(robust, compared * 7 / 10);  // adversarial: many sit at a tie on purpose
}

// One mesh whose hierarchy is a chain: cluster k with self error e_k (e_0 = 0) and parent error
// e_{k+1} (the last: none), every record one sphere; select_lods on the same sphere with the
// geometric-error chain e_1..e_K must pick level k exactly where cluster k is drawn. Radius 0,
// and (every other trial) a sphere of up to 8 m that the eye may be inside, with velocity off:
// both rules see the error from the sphere's nearest point, but only the cluster rule bounds
// the velocity over the sphere.
TEST(ClusterSelect, ChainSelectsTheLevelOfSelectLods) {
  const std::vector<double> err{0.0, 0.001, 0.003, 0.008, 0.02, 0.06, 0.2};
  const std::size_t n = err.size();
  const auto chain_of_radius = [&](float radius_m) {
    ClusterHierarchy chain;
    for (std::size_t k = 0; k < n; ++k) {
      for (auto* v : {&chain.self_center_x_m, &chain.self_center_y_m, &chain.self_center_z_m, &chain.parent_center_x_m,
                      &chain.parent_center_y_m, &chain.parent_center_z_m})
        v->push_back(0.0f);
      chain.self_radius_m.push_back(radius_m), chain.parent_radius_m.push_back(radius_m);
      chain.self_error_m.push_back(static_cast<float>(err[k]));
      chain.parent_error_m.push_back(k + 1 < n ? static_cast<float>(err[k + 1]) : kNoParentError);
      chain.first_index.push_back(0), chain.index_count.push_back(0),
          chain.depth.push_back(static_cast<std::uint8_t>(k));
    }
    return chain;
  };
  std::vector<LodLevel> levels;
  for (std::size_t k = 0; k < n; ++k) levels.push_back({100, 0, DetailKind::geometric_error_m, err[k]});
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::size_t compared = 0, coarser = 0, compared_sized = 0, inside = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const glm::dvec3 at{30.0 * u(rng), 3.0 * u(rng), 30.0 * u(rng)}, vel{2 * u(rng), 0.2 * u(rng), 2 * u(rng)};
    const bool sized = trial % 2 == 1;
    const float radius_m = sized ? static_cast<float>(8.0 * std::abs(u(rng))) : 0.0f;
    ClusterStore cs;
    InstanceTransform xf;
    xf.translation_m = at;
    cs.add_mesh(chain_of_radius(radius_m), xf, vel, 0);
    ObjectStore os;
    os.add(at, radius_m, vel, levels);
    Viewer vw = random_viewer(rng, cs.view());
    if (sized) vw.use_velocity = false;
    vw.eye_position_m = glm::dvec3{4.0 * u(rng), 1.6, 4.0 * u(rng)};
    if (trial % 3 == 0) vw.gaze_direction = at - vw.eye_position_m + 0.05 * glm::dvec3{u(rng), u(rng), u(rng)};
    std::vector<std::uint8_t> lod(1), why(1), ls(1), le(1), lv(1);
    ASSERT_EQ(select_lods(vw, os.view(), {lod, why, ls, le, lv, {}, {}, {}}), "");
    Out out(n);
    ASSERT_EQ(select_clusters(vw, cs.view(), out.all()), "");
    bool robust = true;
    for (std::size_t k = 0; k < n; ++k)
      for (bool parent : {false, true}) robust &= test::reference_record(vw, cs.view(), k, parent).robust;
    const auto drawn_level = [&](const std::vector<std::uint8_t>& cut) {
      EXPECT_EQ(std::count(cut.begin(), cut.end(), 1), 1);
      return static_cast<std::uint8_t>(std::find(cut.begin(), cut.end(), 1) - cut.begin());
    };
    const std::uint8_t k = drawn_level(out.drawn);
    // Both keep detail under rounding: never more than one level apart, and only at a tie.
    ASSERT_LE(std::abs(int(k) - int(lod[0])), robust ? 0 : 1) << trial;
    if (!robust) continue;
    ++compared, coarser += k > 0;
    compared_sized += sized;
    inside += sized && glm::length(vw.eye_position_m - at) <= radius_m;
    ASSERT_EQ(out.why[k], why[0]) << trial;
    ASSERT_EQ(drawn_level(out.s), ls[0]) << trial;
    ASSERT_EQ(drawn_level(out.e), le[0]) << trial;
    ASSERT_EQ(drawn_level(out.v), lv[0]) << trial;
  }
  EXPECT_GT(compared, 2500u);  // trials with every record clear of a threshold
  EXPECT_GT(coarser, 1000u);
  EXPECT_GT(compared_sized, 1200u);
  EXPECT_GT(inside, 20u);  // the eye inside the sphere: level 0 by both rules
}

// Per leaf of each tree, the level of the node drawn over it.
std::vector<std::vector<int>> levels_of(const Scene& sc, const std::vector<std::uint8_t>& cut) {
  std::vector<std::vector<int>> out;
  for (std::size_t k = 0; k < sc.trees.size(); ++k) out.push_back(test::cut_levels(sc.trees[k], mesh_cut(sc, k, cut)));
  return out;
}

TEST(ClusterSelect, GazingAtAClusterNeverCoarsensIt) {
  const Scene sc = make_scene({{7, false, 1}, {5, true, 2}}, 31);
  const ClusterSet cs = sc.store.view();
  std::mt19937_64 rng(6);
  std::size_t refined = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Viewer vw = random_viewer(rng, cs);
    const std::size_t m = trial % 2, node_cluster = sc.store.first_cluster(static_cast<std::uint32_t>(m)) +
                                                    rng() % sc.trees[m].h.size();
    Out before(cs.size()), after(cs.size());
    ASSERT_EQ(select_clusters(vw, cs, before.combined_only()), "");
    vw.gaze_direction = glm::dvec3{cs.self_center_x_m[node_cluster], cs.self_center_y_m[node_cluster],
                                   cs.self_center_z_m[node_cluster]} -
                        vw.eye_position_m;
    if (!(glm::length(vw.gaze_direction) > 0.0)) continue;
    ASSERT_EQ(select_clusters(vw, cs, after.combined_only()), "");
    // The cluster's node and every leaf under it: a node above it drawn after only where that
    // node (or one above) was drawn before.
    const TestTree& t = sc.trees[m];
    const int node = t.cluster_node[node_cluster - sc.store.first_cluster(static_cast<std::uint32_t>(m))];
    const std::vector<int> lb = levels_of(sc, before.drawn)[m], la = levels_of(sc, after.drawn)[m];
    int node_level = 0;
    for (std::size_t li = 0; li < t.leaves.size(); ++li) {
      int lvl = 0;
      bool under = false;
      for (int n = t.leaves[li]; n >= 0; n = t.node_parent[n], ++lvl)
        if (n == node) under = true, node_level = lvl;
      if (!under) continue;
      if (la[li] > node_level) {
        ASSERT_GE(lb[li], la[li]) << trial;
      }
      refined += la[li] < lb[li];
    }
  }
  EXPECT_GT(refined, 0u);
}

TEST(ClusterSelect, SwitchingCriteriaOffNeverCoarsensAndCombinedIsAtLeastEachAlone) {
  const Scene sc = make_scene({{7, false, 1}, {5, true, 2}}, 41);
  const ClusterSet cs = sc.store.view();
  std::mt19937_64 rng(7);
  std::size_t by[5] = {};
  for (int trial = 0; trial < 150; ++trial) {
    Viewer on = random_viewer(rng, cs);
    on.use_size = on.use_eccentricity = on.use_velocity = true;
    Out all(cs.size());
    ASSERT_EQ(select_clusters(on, cs, all.all()), "");
    const auto lc = levels_of(sc, all.drawn), ls = levels_of(sc, all.s), le = levels_of(sc, all.e),
               lv = levels_of(sc, all.v);
    for (std::size_t m = 0; m < lc.size(); ++m)
      for (std::size_t li = 0; li < lc[m].size(); ++li)
        ASSERT_GE(lc[m][li], std::max({ls[m][li], le[m][li], lv[m][li]})) << trial;
    for (std::size_t i = 0; i < cs.size(); ++i) {
      if (!all.drawn[i]) continue;
      const auto why = static_cast<Criterion>(all.why[i]);
      ++by[all.why[i] < 5 ? all.why[i] : 0];
      if (why == Criterion::none) {
        EXPECT_EQ(cs.self_error_m[i], 0.0f) << i;
      }
      if (why == Criterion::size) {
        EXPECT_EQ(all.s[i], 1) << i;
      }
      if (why == Criterion::eccentricity) {
        EXPECT_EQ(all.e[i], 1) << i;
      }
      if (why == Criterion::velocity) {
        EXPECT_EQ(all.v[i], 1) << i;
      }
    }
    for (int mask = 0; mask < 7; ++mask) {
      Viewer off = on;
      off.use_size = mask & 1, off.use_eccentricity = mask & 2, off.use_velocity = mask & 4;
      Out o(cs.size());
      ASSERT_EQ(select_clusters(off, cs, o.combined_only()), "");
      const auto lo = levels_of(sc, o.drawn);
      for (std::size_t m = 0; m < lc.size(); ++m)
        for (std::size_t li = 0; li < lc[m].size(); ++li) ASSERT_LE(lo[m][li], lc[m][li]) << trial << " mask " << mask;
    }
  }
  for (int c = 1; c < 5; ++c) EXPECT_GT(by[c], 0u) << to_string(static_cast<Criterion>(c));
}

}  // namespace
}  // namespace gazelod::lod
