// SPDX-License-Identifier: Apache-2.0
// The peer: OpenSceneGraph's osg::LOD in PIXEL_SIZE_ON_SCREEN mode against gazelod's
// select_lods over the same objects, in the same process. OSG's selection happens in the cull
// traversal (osgUtil::CullVisitor, as osgViewer runs it each frame); each object is an
// osg::LOD with four children whose pixel-size ranges encode Reddy 1998's size rule
// (peer_scene.hpp). Counters: ns_per_object (CPU time / objects), triangles (what the chosen
// levels would draw, per frame). Variants:
//   Osg_NoCulling     cull traversal with culling off: LOD selection for every object
//   Osg_FrustumCull   OSG's default culling (view frustum + small features) as well
//   Gazelod_Size      select_lods with only the size criterion (the same rule as OSG's ranges)
//   Gazelod_All       select_lods with size, eccentricity, velocity (observer at 4.36 m/s)
// The ratio Osg_NoCulling / Gazelod_All is the one to quote.
#include "bench/peer/peer_scene.hpp"
#include "lod/select.hpp"

#include <benchmark/benchmark.h>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Group>
#include <osg/LOD>
#include <osg/Viewport>
#include <osgUtil/CullVisitor>
#include <osgUtil/RenderStage>
#include <osgUtil/StateGraph>

#include <ctime>
#include <limits>
#include <vector>

namespace gazelod::peer {
namespace {

double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Counts the triangles of the drawables the cull traversal keeps; never culls itself.
struct CountTriangles : osg::DrawableCullCallback {
  CountTriangles(std::uint64_t* counter, std::uint32_t triangles) : counter_(counter), triangles_(triangles) {}
  bool cull(osg::NodeVisitor*, osg::Drawable*, osg::RenderInfo*) const override {
    *counter_ += triangles_;
    return false;
  }
  std::uint64_t* counter_;
  std::uint32_t triangles_;
};

osg::ref_ptr<osg::Group> build_osg(const std::vector<PeerObject>& objects, std::uint64_t* counter) {
  osg::ref_ptr<osg::Group> root = new osg::Group;
  std::vector<osg::ref_ptr<CountTriangles>> callbacks;
  for (std::uint32_t t : kTriangles) callbacks.push_back(new CountTriangles(counter, t));
  const float inf = std::numeric_limits<float>::max();
  for (const PeerObject& o : objects) {
    osg::ref_ptr<osg::LOD> lod = new osg::LOD;
    lod->setRangeMode(osg::LOD::PIXEL_SIZE_ON_SCREEN);
    lod->setCenterMode(osg::LOD::USER_DEFINED_CENTER);
    const osg::Vec3 c(static_cast<float>(o.x), static_cast<float>(o.y), static_cast<float>(o.z));
    lod->setCenter(c);
    lod->setRadius(static_cast<float>(o.radius));
    const float r = static_cast<float>(o.radius);
    for (std::size_t k = 0; k < kTriangles.size(); ++k) {
      // Geometry without vertex data: its bound is the object's, set up front; the cull
      // traversal only needs bounds, and the callback counts what it would draw.
      osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
      g->setInitialBound(osg::BoundingBox(c - osg::Vec3(r, r, r), c + osg::Vec3(r, r, r)));
      g->setCullCallback(callbacks[k].get());
      osg::ref_ptr<osg::Geode> geode = new osg::Geode;
      geode->addDrawable(g.get());
      const float hi = k == 0 ? inf : static_cast<float>(level_max_pixels(k));
      const float lo = k + 1 < kTriangles.size() ? static_cast<float>(level_max_pixels(k + 1)) : 0.0f;
      lod->addChild(geode.get(), lo, hi);
    }
    root->addChild(lod.get());
  }
  return root;
}

void osg_cull(benchmark::State& state, bool culling) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto objects = peer_objects(n);
  std::uint64_t counter = 0;
  osg::ref_ptr<osg::Group> root = build_osg(objects, &counter);
  osg::ref_ptr<osgUtil::CullVisitor> cv = new osgUtil::CullVisitor;
  osg::ref_ptr<osgUtil::StateGraph> graph = new osgUtil::StateGraph;
  osg::ref_ptr<osgUtil::RenderStage> stage = new osgUtil::RenderStage;
  osg::ref_ptr<osg::Viewport> viewport = new osg::Viewport(0, 0, kWidthPx, kHeightPx);
  stage->setViewport(viewport.get());
  cv->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
  if (!culling) cv->setCullingMode(osg::CullSettings::NO_CULLING);
  osg::ref_ptr<osg::RefMatrix> projection =
      new osg::RefMatrix(osg::Matrix::perspective(kFovVDeg, static_cast<double>(kWidthPx) / kHeightPx, 0.1, 1000.0));
  osg::ref_ptr<osg::RefMatrix> view = new osg::RefMatrix(osg::Matrix::identity());  // eye at 0, looking -Z
  std::uint64_t triangles = 0;
  const double cpu0 = thread_cpu_s();
  for (auto _ : state) {
    counter = 0;
    cv->reset();
    graph->clean();
    stage->reset();
    cv->setStateGraph(graph.get());
    cv->setRenderStage(stage.get());
    cv->pushViewport(viewport.get());
    cv->pushProjectionMatrix(projection.get());
    cv->pushModelViewMatrix(view.get(), osg::Transform::ABSOLUTE_RF);
    root->accept(*cv);
    cv->popModelViewMatrix();
    cv->popProjectionMatrix();
    cv->popViewport();
    triangles = counter;
    benchmark::DoNotOptimize(triangles);
  }
  const double cpu = thread_cpu_s() - cpu0;
  state.counters["ns_per_object"] = 1e9 * cpu / (static_cast<double>(state.iterations()) * static_cast<double>(n));
  state.counters["triangles"] = static_cast<double>(triangles);
}

void gazelod_select(benchmark::State& state, bool all) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto objects = peer_objects(n);
  std::vector<lod::LodLevel> chain;
  for (std::size_t k = 0; k < kTriangles.size(); ++k)
    chain.push_back({kTriangles[k], 0, lod::DetailKind::removed_cycles_per_diameter, k == 0 ? 0.0 : removed_cycles(k)});
  lod::ObjectStore store;
  for (const PeerObject& o : objects) store.add({o.x, o.y, o.z}, o.radius, {0.0, 0.0, 0.0}, chain);
  lod::Viewer viewer;
  viewer.eye_velocity_m_s = {0.0, 0.0, all ? -4.36 : 0.0};
  // xi = max(1280 / (2 * 43.6), 1024 / (2 * 33.4)) = 15.33 c/deg (Reddy 1998 equation 4).
  viewer.xi_cpd = std::max(kWidthPx / (2.0 * kFovHDeg), kHeightPx / (2.0 * kFovVDeg));
  viewer.use_eccentricity = all;
  viewer.use_velocity = all;
  std::vector<std::uint8_t> lod(n), limited(n), s(n), e(n), v(n);
  const lod::Decisions out{lod, limited, s, e, v, {}, {}, {}};
  const lod::ObjectSet set = store.view();
  std::uint64_t triangles = 0;
  const double cpu0 = thread_cpu_s();
  for (auto _ : state) {
    const std::string err = lod::select_lods(viewer, set, out);
    if (!err.empty()) {
      state.SkipWithError(err.c_str());
      return;
    }
    benchmark::DoNotOptimize(lod.data());
  }
  const double cpu = thread_cpu_s() - cpu0;
  for (std::uint8_t l : lod) triangles += kTriangles[l];
  state.counters["ns_per_object"] = 1e9 * cpu / (static_cast<double>(state.iterations()) * static_cast<double>(n));
  state.counters["triangles"] = static_cast<double>(triangles);
}

void Osg_NoCulling(benchmark::State& s) {
  osg_cull(s, false);
}
void Osg_FrustumCull(benchmark::State& s) {
  osg_cull(s, true);
}
void Gazelod_Size(benchmark::State& s) {
  gazelod_select(s, false);
}
void Gazelod_All(benchmark::State& s) {
  gazelod_select(s, true);
}

BENCHMARK(Osg_NoCulling)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK(Osg_FrustumCull)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK(Gazelod_Size)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK(Gazelod_All)->Arg(100)->Arg(1000)->Arg(10000);

}  // namespace
}  // namespace gazelod::peer

BENCHMARK_MAIN();
