// What accuracy costs in the foveal-cone tests (lod/cone.hpp): time per object of the
// sphere-cone, box-cone and projected-circle tests, and how many objects of a random scene
// each misclassifies against a reference computed independently in long double:
//   spheres: the closed-form distance from the centre to the (solid) cone, <= radius;
//   boxes:   dense samples of the box surface (a box meets an infinite cone iff its surface
//            does, or the apex is inside); boxes whose sampled minimum angle lies within the
//            sampling resolution of the half-angle are left out as undecidable.
// Counters: false_neg = touching objects the test excludes (must be 0 for the sphere and box
// tests), false_pos = over-included ones, compared = objects with a decided reference,
// touching = how many of those the reference says touch the cone.
// The scene is built to put many objects near the cone's surface, where errors happen.
#include "lod/cone.hpp"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <ctime>
#include <map>
#include <numbers>
#include <random>
#include <vector>

namespace gazelod::lod {
namespace {

using ld = long double;
constexpr ld kPi = std::numbers::pi_v<long double>;

struct ConeScene {
  Cone cone;
  glm::dvec3 view_forward, view_up{0.0, 1.0, 0.0};
  std::vector<glm::dvec3> center, box_lo, box_hi;
  std::vector<double> radius;
};

// Half-angle in degrees (tracker error 1.5 deg on top); gaze 12 deg right of the view axis.
ConeScene make_scene(double half_angle_deg, std::size_t n) {
  ConeScene s;
  const glm::dvec3 eye{0.0, 1.6, 0.0};
  const double yaw = 12.0 * std::numbers::pi / 180.0;
  s.view_forward = {0.0, 0.0, -1.0};
  s.cone = make_foveal_cone(eye, {std::sin(yaw), 0.0, -std::cos(yaw)}, half_angle_deg, 1.5);
  // Orthonormal frame around the gaze axis.
  const glm::dvec3 a = s.cone.axis;
  const glm::dvec3 u = glm::normalize(glm::cross(a, glm::dvec3{0.0, 1.0, 0.0}));
  const glm::dvec3 v = glm::cross(u, a);
  std::mt19937_64 rng(static_cast<std::uint64_t>(half_angle_deg * 1000) + n);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const double theta = s.cone.half_angle_rad;
  for (std::size_t i = 0; i < n; ++i) {
    // Direction at angle phi in [0, theta + 20 deg] from the axis, distance 0.5 .. 200 m.
    const double phi = uni(rng) * (theta + 20.0 * std::numbers::pi / 180.0);
    const double psi = uni(rng) * 2.0 * std::numbers::pi;
    const double dist = 0.5 * std::pow(400.0, uni(rng));
    const glm::dvec3 dir = std::cos(phi) * a + std::sin(phi) * (std::cos(psi) * u + std::sin(psi) * v);
    const glm::dvec3 c = eye + dist * dir;
    const double r = 0.02 * std::pow(250.0, uni(rng));  // 2 cm .. 5 m
    const glm::dvec3 half{r * (0.3 + uni(rng)), r * (0.3 + uni(rng)), r * (0.3 + uni(rng))};
    s.center.push_back(c);
    s.radius.push_back(r);
    s.box_lo.push_back(c - half);
    s.box_hi.push_back(c + half);
  }
  return s;
}

struct Lv {
  ld x, y, z;
};
Lv sub(const glm::dvec3& p, const glm::dvec3& q) {
  return {ld(p.x) - ld(q.x), ld(p.y) - ld(q.y), ld(p.z) - ld(q.z)};
}
ld dot(const Lv& a, const Lv& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
ld angle_to_axis(const Lv& p, const Lv& axis) {  // atan2(|a x p|, a . p), axis unit
  const Lv c{axis.y * p.z - axis.z * p.y, axis.z * p.x - axis.x * p.z, axis.x * p.y - axis.y * p.x};
  return std::atan2(std::sqrt(dot(c, c)), dot(axis, p));
}

// Distance from a point to the solid cone (apex 0, unit axis, half-angle theta < pi/2):
// 0 inside; |p| sin(phi - theta) while phi - theta < pi/2; else |p| (the apex is nearest).
bool sphere_reference(const ConeScene& s, std::size_t i) {
  const Lv p = sub(s.center[i], s.cone.apex_m);
  const Lv a{s.cone.axis.x, s.cone.axis.y, s.cone.axis.z};
  const ld len = std::sqrt(dot(p, p)), theta = s.cone.half_angle_rad;
  const ld phi = angle_to_axis(p, a);
  const ld dist = phi <= theta ? 0.0L : (phi - theta < kPi / 2 ? len * std::sin(phi - theta) : len);
  return dist <= ld(s.radius[i]);
}

// 1 touches, 0 does not, -1 undecided (within the sampling resolution).
int box_reference(const ConeScene& s, std::size_t i) {
  constexpr int kGrid = 40;
  const glm::dvec3 lo = s.box_lo[i], hi = s.box_hi[i], apex = s.cone.apex_m;
  if (apex.x >= lo.x && apex.x <= hi.x && apex.y >= lo.y && apex.y <= hi.y && apex.z >= lo.z &&
      apex.z <= hi.z)
    return 1;
  const Lv a{s.cone.axis.x, s.cone.axis.y, s.cone.axis.z};
  ld best = kPi;
  for (int face = 0; face < 6; ++face) {
    const int ax = face / 2;  // fixed coordinate
    const int u_ax = (ax + 1) % 3, v_ax = (ax + 2) % 3;
    for (int iu = 0; iu <= kGrid; ++iu)
      for (int iv = 0; iv <= kGrid; ++iv) {
        glm::dvec3 q;
        q[ax] = (face % 2) ? hi[ax] : lo[ax];
        q[u_ax] = lo[u_ax] + (hi[u_ax] - lo[u_ax]) * iu / kGrid;
        q[v_ax] = lo[v_ax] + (hi[v_ax] - lo[v_ax]) * iv / kGrid;
        best = std::min(best, angle_to_axis(sub(q, apex), a));
      }
  }
  // Resolution: a sample cell's diagonal seen from the box's nearest possible distance.
  const Lv c = sub(0.5 * (lo + hi), apex);
  const glm::dvec3 ext = hi - lo;
  const ld diag = std::sqrt(ld(ext.x * ext.x + ext.y * ext.y + ext.z * ext.z));
  const ld near = std::max(std::sqrt(dot(c, c)) - diag / 2, 1e-9L);
  const ld tol = 2.0L * diag / kGrid / near;
  const ld theta = s.cone.half_angle_rad;
  if (best <= theta) return 1;
  if (best > theta + tol) return 0;
  return -1;
}

struct Errors {
  std::size_t compared = 0, touching = 0, false_neg = 0, false_pos = 0;
};

constexpr std::size_t kObjects = 20000;

// Scene and references per half-angle, built once (Google Benchmark calls each benchmark
// function several times while it picks the iteration count).
struct Prepared {
  ConeScene scene;
  std::vector<signed char> sphere_ref, box_ref;  // 1 / 0, box also -1 (undecided)
};
const Prepared& prepared(int half_angle_deg) {
  static std::map<int, Prepared> cache;
  auto it = cache.find(half_angle_deg);
  if (it != cache.end()) return it->second;
  Prepared p{make_scene(half_angle_deg, kObjects), {}, {}};
  p.sphere_ref.resize(kObjects);
  p.box_ref.assign(kObjects, -1);
  for (std::size_t i = 0; i < kObjects; ++i) p.sphere_ref[i] = sphere_reference(p.scene, i) ? 1 : 0;
  for (std::size_t i = 0; i < kObjects; i += 4)  // every 4th: the sampled reference is slow
    p.box_ref[i] = static_cast<signed char>(box_reference(p.scene, i));
  return cache.emplace(half_angle_deg, std::move(p)).first->second;
}

Errors count_errors(const std::vector<signed char>& ref, const std::vector<char>& hit) {
  Errors e;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if (ref[i] < 0) continue;
    ++e.compared;
    e.touching += ref[i] == 1;
    e.false_neg += ref[i] == 1 && !hit[i];
    e.false_pos += ref[i] == 0 && hit[i];
  }
  return e;
}

void report(benchmark::State& state, std::size_t n, double cpu_ns, const Errors& e) {
  state.counters["ns_per_object"] = cpu_ns / (static_cast<double>(state.iterations()) * static_cast<double>(n));
  state.counters["compared"] = static_cast<double>(e.compared);
  state.counters["touching"] = static_cast<double>(e.touching);
  state.counters["false_neg"] = static_cast<double>(e.false_neg);
  state.counters["false_pos"] = static_cast<double>(e.false_pos);
}

double thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

void BM_SphereCone(benchmark::State& state) {
  const Prepared& p = prepared(static_cast<int>(state.range(0)));
  const ConeScene& s = p.scene;
  std::vector<char> hit(kObjects);
  const double t0 = thread_cpu_ns();
  for (auto _ : state) {
    for (std::size_t i = 0; i < kObjects; ++i) hit[i] = sphere_touches_cone(s.cone, s.center[i], s.radius[i]);
    benchmark::ClobberMemory();
  }
  report(state, kObjects, thread_cpu_ns() - t0, count_errors(p.sphere_ref, hit));
}

void BM_BoxCone(benchmark::State& state) {
  const Prepared& p = prepared(static_cast<int>(state.range(0)));
  const ConeScene& s = p.scene;
  std::vector<char> hit(kObjects);
  const double t0 = thread_cpu_ns();
  for (auto _ : state) {
    for (std::size_t i = 0; i < kObjects; ++i) hit[i] = box_touches_cone(s.cone, s.box_lo[i], s.box_hi[i]);
    benchmark::ClobberMemory();
  }
  report(state, kObjects, thread_cpu_ns() - t0, count_errors(p.box_ref, hit));
}

void BM_ProjectedCircle(benchmark::State& state) {
  const Prepared& p = prepared(static_cast<int>(state.range(0)));
  const ConeScene& s = p.scene;
  std::vector<char> hit(kObjects);
  const double t0 = thread_cpu_ns();
  for (auto _ : state) {
    for (std::size_t i = 0; i < kObjects; ++i)
      hit[i] = projected_circle_touches(s.cone, s.view_forward, s.view_up, s.center[i], s.radius[i]);
    benchmark::ClobberMemory();
  }
  report(state, kObjects, thread_cpu_ns() - t0, count_errors(p.sphere_ref, hit));
}

// Half-angles (deg, before the 1.5 deg tracker error): foveal, parafoveal, wide, very wide.
BENCHMARK(BM_SphereCone)->Arg(2)->Arg(10)->Arg(30)->Arg(60)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BoxCone)->Arg(2)->Arg(10)->Arg(30)->Arg(60)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ProjectedCircle)->Arg(2)->Arg(10)->Arg(30)->Arg(60)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace gazelod::lod
