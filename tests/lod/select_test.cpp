// SPDX-License-Identifier: Apache-2.0
// Per-object selection: agreement with an exact scalar reference on random scenes, the
// criteria switches, hard inputs, and monotonicity of the chosen level.
#include "lod/acuity.hpp"
#include "tests/lod/reference_criteria.hpp"
#include "lod/select.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

namespace gazelod::lod {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Reddy's prototype chain shape: four levels; removed cycles per diameter fall with level.
std::vector<LodLevel> cycles_chain() {
  return {{3928, 0, DetailKind::removed_cycles_per_diameter, 0.0},
          {834, 0, DetailKind::removed_cycles_per_diameter, 400.0},
          {254, 0, DetailKind::removed_cycles_per_diameter, 120.0},
          {76, 0, DetailKind::removed_cycles_per_diameter, 30.0}};
}
std::vector<LodLevel> error_chain() {
  return {{1000, 0, DetailKind::geometric_error_m, 0.0},
          {300, 0, DetailKind::geometric_error_m, 0.002},
          {80, 0, DetailKind::geometric_error_m, 0.01},
          {20, 0, DetailKind::geometric_error_m, 0.05}};
}

struct Out {
  explicit Out(std::size_t n) : lod(n), why(n), s(n), e(n), v(n), ecc(n), vel(n), ang(n) {}
  Decisions d() { return {lod, why, s, e, v, ecc, vel, ang}; }
  std::vector<std::uint8_t> lod, why, s, e, v;
  std::vector<float> ecc, vel, ang;
};

struct Ref {
  unsigned lc = 0, ls = 0, le = 0, lv = 0;
  double margin = 1.0;  // smallest relative distance of any comparison from its threshold
};

// The selection rule written with the exact scalar functions (reference_criteria.hpp, acuity.hpp).
Ref reference(const Viewer& vw, const glm::dvec3& c, double r, const glm::dvec3& vel,
              const std::vector<LodLevel>& chain) {
  const double d = glm::length(c - vw.eye_position_m);
  // The detail's size is seen from the sphere's nearest point (lod/lod_chain.hpp).
  const double d_near = std::max(d - r, kNearestPointFloorM);
  double e =
      std::max(0.0, nearest_point_eccentricity_deg(vw.eye_position_m, vw.gaze_direction, c, r) - vw.tracker_error_deg);
  double v = retinal_velocity_dps(vw.eye_position_m, vw.eye_velocity_m_s,
                                  vw.head_angular_velocity_rad_s + vw.gaze_angular_velocity_in_head_rad_s, c, vel);
  if (!vw.use_eccentricity) e = 0;
  if (!vw.use_velocity) v = 0;
  const double s = vw.scale, xi = vw.xi_cpd;
  const double a0 = acuity_cpd(0, 0, xi, s);
  std::vector<double> w, f;
  for (const LodLevel& l : chain) w.push_back(level_weight(l));
  const bool cyc = chain[0].detail_kind == DetailKind::removed_cycles_per_diameter;
  const double q = (cyc ? d_near / r : d_near) * M_PI / 360.0;
  const double cap = w.size() > 1 ? a0 / w[1] * (1.0 - 1e-15) : q;
  const double q_off = std::min(q, cap);
  Ref ref;
  auto count = [&](double qq, double a, unsigned& out) {
    for (std::size_t k = 1; k < w.size(); ++k) {
      out += w[k] * qq > a;
      // Both sides computed identically in select.cpp (the size-off cap against the static
      // limit): no rounding difference to allow for.
      if (qq == cap && a == a0) continue;
      ref.margin = std::min(ref.margin, std::abs(w[k] * qq - a) / std::max(a, 1e-300));
    }
  };
  count(q, a0, ref.ls);
  count(q_off, acuity_cpd(0, e, xi, s), ref.le);
  count(q_off, acuity_cpd(v, 0, xi, s), ref.lv);
  count(vw.use_size ? q : q_off, acuity_cpd(v, e, xi, s), ref.lc);
  if (!vw.use_size) ref.ls = 0;
  if (!vw.use_eccentricity) ref.le = 0;
  if (!vw.use_velocity) ref.lv = 0;
  return ref;
}

struct Scene {
  ObjectStore store;
  std::vector<glm::dvec3> c, v;
  std::vector<double> r;
  std::vector<std::vector<LodLevel>> chains;
};

// Random objects; chain_for(i) gives object i's chain (default: cycles and error alternating).
Scene random_scene(std::size_t n, std::uint64_t seed,
                   const std::function<std::vector<LodLevel>(std::size_t)>& chain_for = {}) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Scene s;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 c{u(rng) * 50, u(rng) * 20, u(rng) * 50};
    const double r = std::pow(10.0, 1.5 * u(rng) - 0.5);
    const glm::dvec3 v{u(rng) * 5, u(rng) * 5, u(rng) * 5};
    auto chain = chain_for ? chain_for(i) : (i % 2) ? cycles_chain() : error_chain();
    s.store.add(c, r, v, chain);
    s.c.push_back(c), s.v.push_back(v), s.r.push_back(r), s.chains.push_back(chain);
  }
  return s;
}

Viewer moving_viewer() {
  Viewer vw;
  vw.eye_position_m = {0.3, 1.6, -0.2};
  vw.eye_velocity_m_s = {0.5, 0.0, -1.0};
  vw.gaze_direction = glm::normalize(glm::dvec3{0.2, -0.1, -1.0});
  vw.head_angular_velocity_rad_s = {0.1, 1.2, 0.0};
  vw.gaze_angular_velocity_in_head_rad_s = {0.0, -0.3, 0.05};
  vw.xi_cpd = 10.0;
  vw.tracker_error_deg = 1.5;
  vw.scale = 0.8;
  return vw;
}

void expect_matches_reference(const Viewer& vw, const Scene& sc) {
  Out out(sc.r.size());
  ASSERT_EQ(select_lods(vw, sc.store.view(), out.d()), "");
  std::size_t compared = 0, reduced = 0;
  for (std::size_t i = 0; i < sc.r.size(); ++i) {
    const Ref ref = reference(vw, sc.c[i], sc.r[i], sc.v[i], sc.chains[i]);
    // Near a threshold the kernel's float comparison (and float weights) may keep a finer
    // level than the exact rule, never a coarser one; its atan and log are good to 1e-10,
    // so below a margin of 1e-9 nothing is asserted.
    if (ref.margin >= 1e-9) {
      ASSERT_LE(out.lod[i], ref.lc) << i;
      ASSERT_LE(out.s[i], ref.ls) << i;
      ASSERT_LE(out.e[i], ref.le) << i;
      ASSERT_LE(out.v[i], ref.lv) << i;
    }
    // Float weights and comparisons round apart from the exact rule within ~2e-7.
    if (ref.margin < 1e-6) continue;
    ++compared;
    reduced += ref.lc > 0;
    ASSERT_EQ(out.lod[i], ref.lc) << i;
    ASSERT_EQ(out.s[i], ref.ls) << i;
    ASSERT_EQ(out.e[i], ref.le) << i;
    ASSERT_EQ(out.v[i], ref.lv) << i;
  }
  EXPECT_GT(compared, sc.r.size() * 99 / 100);
  if (vw.use_size || vw.use_eccentricity || vw.use_velocity) {
    EXPECT_GT(reduced, 0u);
  }
}

TEST(Select, MatchesExactReferenceOnRandomScenes) {
  const Scene sc = random_scene(20000, 1);
  Viewer vw = moving_viewer();
  expect_matches_reference(vw, sc);
  vw.scale = 1.0, vw.tracker_error_deg = 0.0, vw.xi_cpd = 25.0;
  expect_matches_reference(vw, sc);
}

TEST(Select, MatchesReferenceWithCriteriaSwitchedOff) {
  const Scene sc = random_scene(5000, 2);
  for (int mask = 0; mask < 8; ++mask) {
    Viewer vw = moving_viewer();
    vw.use_size = mask & 1, vw.use_eccentricity = mask & 2, vw.use_velocity = mask & 4;
    expect_matches_reference(vw, sc);
  }
}

TEST(Select, SwitchingOffNeverLowersDetailAndCombinedIsAtLeastEachAlone) {
  const Scene sc = random_scene(5000, 3);
  Viewer all = moving_viewer();
  Out on(sc.r.size());
  ASSERT_EQ(select_lods(all, sc.store.view(), on.d()), "");
  for (int mask = 0; mask < 7; ++mask) {
    Viewer vw = all;
    vw.use_size = mask & 1, vw.use_eccentricity = mask & 2, vw.use_velocity = mask & 4;
    Out off(sc.r.size());
    ASSERT_EQ(select_lods(vw, sc.store.view(), off.d()), "");
    for (std::size_t i = 0; i < sc.r.size(); ++i) ASSERT_LE(off.lod[i], on.lod[i]);
  }
  std::size_t by_size = 0;
  for (std::size_t i = 0; i < sc.r.size(); ++i) {
    ASSERT_GE(on.lod[i], std::max({on.s[i], on.e[i], on.v[i]}));
    ASSERT_LT(on.lod[i], sc.chains[i].size());
    const auto why = static_cast<Criterion>(on.why[i]);
    if (on.lod[i] == 0) {
      EXPECT_EQ(why, Criterion::none);
    }
    if (why == Criterion::size) {
      EXPECT_EQ(on.s[i], on.lod[i]);
      ++by_size;
    }
    if (why == Criterion::eccentricity) {
      EXPECT_EQ(on.e[i], on.lod[i]);
    }
    if (why == Criterion::velocity) {
      EXPECT_EQ(on.v[i], on.lod[i]);
    }
    if (why == Criterion::combined) {
      EXPECT_GT(on.lod[i], std::max({on.s[i], on.e[i], on.v[i]}));
    }
  }
  EXPECT_GT(by_size, 0u);
}

TEST(Select, AllOffKeepsFullDetailExceptDisplayLimit) {
  // With every criterion off only the display's xi can drop levels; with xi >= 60 nothing.
  const Scene sc = random_scene(2000, 4);
  Viewer vw = moving_viewer();
  vw.use_size = vw.use_eccentricity = vw.use_velocity = false;
  vw.xi_cpd = 60.0, vw.scale = 1.0;
  Out out(sc.r.size());
  ASSERT_EQ(select_lods(vw, sc.store.view(), out.d()), "");
  for (std::size_t i = 0; i < sc.r.size(); ++i) EXPECT_EQ(out.lod[i], 0) << i;
}

// One object, one viewer: the chosen level and the limiting criterion.
struct One {
  std::uint8_t lod, why;
  float ecc, vel;
};
One select_one(const Viewer& vw, const glm::dvec3& c, double r, const glm::dvec3& v,
               const std::vector<LodLevel>& chain = cycles_chain()) {
  ObjectStore st;
  st.add({0, 0, -1}, 1, {}, chain);  // placeholder, then overwrite motion (bypasses add checks)
  st.set_motion(0, c, v);
  ObjectSet os = st.view();
  std::vector<double> radius{r};
  os.radius_m = radius;
  Out out(1);
  EXPECT_EQ(select_lods(vw, os, out.d()), "");
  return {out.lod[0], out.why[0], out.ecc[0], out.vel[0]};
}

TEST(SelectHardCases, GazeThroughObjectCentre) {
  Viewer vw;
  const One o = select_one(vw, {0, 0, -10}, 1.0, {});
  EXPECT_EQ(o.ecc, 0.0f);
  EXPECT_LT(o.lod, 4);
}

TEST(SelectHardCases, EyeInsideBoundingSphere) {
  Viewer vw;
  const One o = select_one(vw, {0, 0, -0.5}, 2.0, {});
  EXPECT_EQ(o.ecc, 0.0f);
  EXPECT_EQ(o.lod, 0);                                                  // fills the view: full detail
  EXPECT_EQ(select_one(vw, {0, 0, 0}, 2.0, {}, error_chain()).lod, 0);  // centre at the eye
}

TEST(SelectHardCases, ObjectBehindEye) {
  Viewer vw;
  vw.xi_cpd = 12.0;
  const One o = select_one(vw, {0, 0, 10}, 1.0, {});
  EXPECT_GT(o.ecc, 170.0f);
  EXPECT_LE(o.ecc, 180.0f);
  EXPECT_LT(o.lod, 4);
}

TEST(SelectHardCases, TinyAngle1em7RadSurvives) {
  Viewer vw;
  const double a = 1e-7;
  const One o = select_one(vw, glm::dvec3{std::sin(a), 0, -std::cos(a)} * 1000.0, 0.0, {});
  EXPECT_NEAR(o.ecc, a * 180 / M_PI, 1e-12);
}

TEST(SelectHardCases, NonFiniteObjectGetsFullDetailAndInvalid) {
  Viewer vw;
  for (double bad : {kNaN, std::numeric_limits<double>::infinity()}) {
    const One o = select_one(vw, {bad, 0, -10}, 1.0, {});
    EXPECT_EQ(o.lod, 0);
    EXPECT_EQ(static_cast<Criterion>(o.why), Criterion::invalid_input);
    EXPECT_EQ(select_one(vw, {0, 0, -10}, kNaN, {}).why, static_cast<std::uint8_t>(Criterion::invalid_input));
    EXPECT_EQ(select_one(vw, {0, 0, -10}, 1.0, {bad, 0, 0}).why, static_cast<std::uint8_t>(Criterion::invalid_input));
  }
}

TEST(SelectHardCases, HugeVelocityGivesCoarsestNeverNaN) {
  Viewer vw;
  vw.head_angular_velocity_rad_s = {0, 1e6, 0};
  const One o = select_one(vw, {0, 0, -10}, 1.0, {});
  EXPECT_EQ(o.lod, 3);
  EXPECT_FALSE(std::isnan(o.vel));
  vw.head_angular_velocity_rad_s = {0, 1e300, 0};
  EXPECT_FALSE(std::isnan(select_one(vw, {0, 0, -10}, 1.0, {}).vel));
}

TEST(SelectHardCases, ChainOutOfRangeIsInvalidNotARead) {
  ObjectStore st;
  st.add({0, 0, -10}, 1, {}, cycles_chain());
  ObjectSet os = st.view();
  std::vector<std::uint8_t> count{200};
  os.lod_count = count;
  Out out(1);
  ASSERT_EQ(select_lods(Viewer{}, os, out.d()), "");
  EXPECT_EQ(out.lod[0], 0);
  EXPECT_EQ(static_cast<Criterion>(out.why[0]), Criterion::invalid_input);
  EXPECT_NE(validate_objects(os).find("out of range"), std::string::npos);
}

TEST(SelectValidation, RefusesBadViewerAndShortOutputs) {
  const Scene sc = random_scene(10, 5);
  Out out(10);
  Viewer vw;
  vw.scale = 0.0;
  EXPECT_NE(select_lods(vw, sc.store.view(), out.d()).find("scale"), std::string::npos);
  vw = Viewer{}, vw.gaze_direction = {0, 0, 0};
  EXPECT_NE(select_lods(vw, sc.store.view(), out.d()).find("gaze_direction"), std::string::npos);
  vw = Viewer{}, vw.xi_cpd = kNaN;
  EXPECT_NE(select_lods(vw, sc.store.view(), out.d()).find("xi_cpd"), std::string::npos);
  vw = Viewer{}, vw.tracker_error_deg = -1;
  EXPECT_NE(select_lods(vw, sc.store.view(), out.d()).find("tracker_error"), std::string::npos);
  Out small(5);
  EXPECT_NE(select_lods(Viewer{}, sc.store.view(), small.d()).find("shorter"), std::string::npos);
  EXPECT_EQ(validate_objects(sc.store.view()), "");
}

TEST(SelectValidation, ChainsRefusedAtRegistration) {
  ObjectStore st;
  auto bad = cycles_chain();
  bad[2].detail = 1000.0;  // finer than level 1
  EXPECT_THROW(st.add({0, 0, -1}, 1, {}, bad), std::invalid_argument);
  bad = cycles_chain(), bad[1].detail = kNaN;
  EXPECT_THROW(st.add({0, 0, -1}, 1, {}, bad), std::invalid_argument);
  bad = cycles_chain(), bad[3].detail_kind = DetailKind::geometric_error_m;
  EXPECT_THROW(st.add({0, 0, -1}, 1, {}, bad), std::invalid_argument);
  EXPECT_THROW(st.add({0, 0, -1}, 1, {}, std::vector<LodLevel>{}), std::invalid_argument);
  EXPECT_THROW(st.add({0, 0, -1}, -1, {}, cycles_chain()), std::invalid_argument);
  EXPECT_EQ(st.size(), 0u);
  auto e = error_chain();
  e[2].detail = 0.001;  // smaller error than level 1
  EXPECT_NE(validate_chain(e).find("must not decrease"), std::string::npos);
  // Triangle counts must not grow along the chain (a coarser level that costs more); equal
  // counts (a simplifier that could not reduce) are allowed.
  auto t = cycles_chain();
  for (std::size_t k = 0; k < t.size(); ++k) t[k].triangles = static_cast<std::uint32_t>(1000 >> k);
  EXPECT_EQ(validate_chain(t), "");
  t[2].triangles = t[1].triangles;
  EXPECT_EQ(validate_chain(t), "");
  t[3].triangles = t[2].triangles + 1;
  EXPECT_EQ(validate_chain(t),
            "level 3: has more triangles (501) than level 2 (500): triangle counts must not "
            "increase along the chain");
  EXPECT_THROW(st.add({0, 0, -1}, 1, {}, t), std::invalid_argument);
}

TEST(SelectValidation, WeightsOutsideFloatRangeRefused) {
  auto e = error_chain();
  e[1].detail = 1e-31;  // weight 1e31 per metre: beyond kMaxLevelWeight
  EXPECT_NE(validate_chain(e).find("outside"), std::string::npos);
  auto c = cycles_chain();
  c[3].detail = 1e-31;
  EXPECT_NE(validate_chain(c).find("outside"), std::string::npos);
  c = cycles_chain(), c[1].detail = 1e30, c[2].detail = 1e-30, c[3].detail = 1e-30;
  EXPECT_EQ(validate_chain(c), "");  // the range's ends are allowed
}

TEST(SelectValidation, StoredWeightsRoundTowardsZero) {
  // A weight rounded up could allow a coarser level than the exact one; rounded towards
  // zero it never does.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-30, 30);
  for (int i = 0; i < 20000; ++i) {
    const LodLevel l{1, 0, i % 2 ? DetailKind::geometric_error_m : DetailKind::removed_cycles_per_diameter,
                     std::pow(10.0, u(rng))};
    const double exact = level_weight(l), stored = level_weight_f(l);
    ASSERT_LE(stored, exact) << l.detail;
    ASSERT_GT(stored, exact * (1 - 1.2e-7)) << l.detail;
  }
}

// Monotonicity of the chosen level along dense sweeps.
TEST(SelectMonotone, FartherNeverMoreDetail) {
  Viewer vw;
  vw.xi_cpd = 15.0;
  for (const auto& chain : {cycles_chain(), error_chain()}) {
    int prev = 0;
    for (double z = 0.01; z < 2000.0; z *= 1.001) {
      const int l = select_one(vw, {0.3, 0, -z}, 0.5, {}, chain).lod;
      ASSERT_GE(l, prev) << z;
      prev = l;
    }
    EXPECT_EQ(prev, 3);
  }
}

TEST(SelectMonotone, FasterHeadNeverMoreDetail) {
  Viewer vw;
  vw.xi_cpd = 15.0;
  int prev = 0;
  for (double w = 0.0; w < 10.0; w += 1e-4) {
    vw.head_angular_velocity_rad_s = {0, w, 0};
    const int l = select_one(vw, {0, 0, -30}, 0.5, {}).lod;
    ASSERT_GE(l, prev) << w;
    prev = l;
  }
  EXPECT_EQ(prev, 3);
}

TEST(SelectMonotone, FurtherFromGazeNeverMoreDetail) {
  Viewer vw;
  vw.xi_cpd = 20.0;
  int prev = 0;
  for (double a = 0.0; a < M_PI; a += 1e-4) {
    const int l = select_one(vw, glm::dvec3{std::sin(a), 0, -std::cos(a)} * 8.0, 0.3, {}).lod;
    ASSERT_GE(l, prev) << a;
    prev = l;
  }
  EXPECT_GT(prev, 0);
}

TEST(SelectMonotone, LowerScaleNeverMoreDetail) {
  Viewer vw;
  vw.xi_cpd = 15.0;
  int prev = 0;
  for (double s = 1.0; s > 1e-3; s -= 1e-4) {
    vw.scale = s;
    const int l = select_one(vw, {0, 0, -5}, 0.5, {}).lod;
    ASSERT_GE(l, prev) << s;
    prev = l;
  }
  EXPECT_EQ(prev, 3);
}

// The fast path handles blocks of back-to-back chains of one length up to 8 levels; these
// cover the other paths: chains of mixed length (filled object by object), chains longer
// than 8 levels (a scalar loop), single-level chains, a count that is not a multiple of the
// block size, and static objects (no velocity arrays).
std::vector<LodLevel> chain_of(std::size_t levels, bool cycles) {
  std::vector<LodLevel> c{
      {1000, 0, cycles ? DetailKind::removed_cycles_per_diameter : DetailKind::geometric_error_m, 0.0}};
  for (std::size_t k = 1; k < levels; ++k)
    c.push_back({100, 0, c[0].detail_kind,
                 cycles ? 600.0 / std::pow(1.6, double(k - 1)) : 0.001 * std::pow(1.7, double(k - 1))});
  return c;
}

Scene mixed_chain_scene(std::size_t n, std::uint64_t seed) {
  return random_scene(n, seed, [](std::size_t i) {
    return chain_of(1 + (i * 7) % 12, i % 3 != 0);  // 1 .. 12 levels
  });
}

TEST(SelectPaths, MixedAndLongChainsMatchReference) {
  const Scene sc = mixed_chain_scene(3001, 11);
  for (int mask = 0; mask < 8; ++mask) {
    Viewer vw = moving_viewer();
    vw.use_size = mask & 1, vw.use_eccentricity = mask & 2, vw.use_velocity = mask & 4;
    expect_matches_reference(vw, sc);
  }
  // Long chains do reach their deep levels (the scalar path is exercised, not skipped).
  Out out(sc.r.size());
  ASSERT_EQ(select_lods(moving_viewer(), sc.store.view(), out.d()), "");
  EXPECT_GT(*std::max_element(out.lod.begin(), out.lod.end()), 7);
}

TEST(SelectPaths, LayoutOfWeightsDoesNotChangeDecisions) {
  // The same objects once back to back (bulk path) and once with the chains stored in
  // reverse order (object-by-object path): identical bytes.
  const Scene sc = random_scene(1000, 12);
  const ObjectSet a = sc.store.view();
  std::vector<float> weights;
  std::vector<std::uint32_t> first(a.size());
  for (std::size_t i = a.size(); i-- > 0;) {
    first[i] = static_cast<std::uint32_t>(weights.size());
    for (std::size_t k = 0; k < a.lod_count[i]; ++k) weights.push_back(a.level_weight[a.lod_first[i] + k]);
  }
  ObjectSet b = a;
  b.level_weight = weights;
  b.lod_first = first;
  ASSERT_EQ(validate_objects(b), "");
  Out oa(a.size()), ob(a.size());
  ASSERT_EQ(select_lods(moving_viewer(), a, oa.d()), "");
  ASSERT_EQ(select_lods(moving_viewer(), b, ob.d()), "");
  EXPECT_EQ(oa.lod, ob.lod);
  EXPECT_EQ(oa.why, ob.why);
  EXPECT_EQ(oa.s, ob.s);
  EXPECT_EQ(oa.e, ob.e);
  EXPECT_EQ(oa.v, ob.v);
}

TEST(SelectPaths, StaticObjectsEqualZeroVelocity) {
  Scene sc;
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t i = 0; i < 700; ++i)
    sc.store.add({u(rng) * 40, u(rng) * 10, u(rng) * 40}, 0.5 + u(rng) * 0.4, {0, 0, 0},
                 (i % 2) ? cycles_chain() : error_chain());
  ObjectSet with = sc.store.view(), without = with;
  without.vel_x_m_s = without.vel_y_m_s = without.vel_z_m_s = {};
  Out o1(with.size()), o2(with.size());
  ASSERT_EQ(select_lods(moving_viewer(), with, o1.d()), "");
  ASSERT_EQ(select_lods(moving_viewer(), without, o2.d()), "");
  EXPECT_EQ(o1.lod, o2.lod);
  EXPECT_EQ(o1.why, o2.why);
  EXPECT_EQ(o1.vel, o2.vel);
}

TEST(SelectPaths, InvalidObjectWithLongChainStaysInvalid) {
  ObjectStore st;
  st.add({0, 0, -10}, 1, {}, chain_of(12, true));
  st.add({0, 0, -10}, 1, {}, chain_of(12, true));
  st.set_motion(1, {kNaN, 0, -10}, {});
  Out out(2);
  Viewer vw;
  vw.xi_cpd = 10;
  ASSERT_EQ(select_lods(vw, st.view(), out.d()), "");
  EXPECT_GT(out.lod[0], 0);
  EXPECT_EQ(out.lod[1], 0);
  EXPECT_EQ(static_cast<Criterion>(out.why[1]), Criterion::invalid_input);
  EXPECT_EQ(out.ecc[1], 0.0f);
}

TEST(SelectPaths, EmptyWeightArrayIsInvalidNotARead) {
  ObjectStore st;
  st.add({0, 0, -10}, 1, {}, cycles_chain());
  ObjectSet os = st.view();
  os.level_weight = {};  // every chain now out of range (ASan checks there is no read)
  Out out(1);
  ASSERT_EQ(select_lods(Viewer{}, os, out.d()), "");
  EXPECT_EQ(out.lod[0], 0);
  EXPECT_EQ(static_cast<Criterion>(out.why[0]), Criterion::invalid_input);
}

}  // namespace
}  // namespace gazelod::lod
