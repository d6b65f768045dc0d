// SPDX-License-Identifier: Apache-2.0
// Data mode's frames through the C ABI: the fovea follows the pushed gaze, no allocation per
// frame, engine-style levels equal their geometric equivalent, the foveal cone in a view's
// image coordinates, and an application thread beside a render thread (run under TSan in CI).
#include "tests/capi/capi_test_util.hpp"
#include "tests/counting_new.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace gazelod::test {
namespace {

constexpr int64_t kFrameNs = 11'111'111;  // 90 Hz

// Fixates yaw_deg for `frames` frames (a sample per frame), returns the last frame's time.
int64_t fixate(gzl_plugin p, int64_t t, double yaw_deg, int frames) {
  for (int f = 0; f < frames; ++f) {
    t += kFrameNs;
    gzl_gaze_sample s = gaze_at(t - 5'000'000, yaw_deg);
    EXPECT_EQ(gzl_push_gaze_sample(p, &s), GZL_SUCCESS) << last_error(p);
    gzl_frame_input in = still_head(t);
    EXPECT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS) << last_error(p);
  }
  return t;
}

TEST(CApiFrames, FoveaFollowsPushedGaze) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  gzl_object left = 0, right = 0;
  gzl_object_desc d = object_at(20, 0, 2.0);
  ASSERT_EQ(gzl_add_object(p, &d, &left), GZL_SUCCESS);
  d = object_at(-20, 0, 2.0);
  ASSERT_EQ(gzl_add_object(p, &d, &right), GZL_SUCCESS);
  const gzl_object both[2] = {left, right};
  uint8_t lv[2];
  int64_t t = fixate(p, 0, 20, 90);
  ASSERT_EQ(gzl_get_levels(p, 2, both, lv), GZL_SUCCESS);
  EXPECT_LT(lv[0], lv[1]) << "looking left: the left object is finer";
  gzl_frame_info info{};
  info.type = GZL_TYPE_FRAME_INFO;
  ASSERT_EQ(gzl_get_frame_info(p, &info), GZL_SUCCESS);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_PUSHED);
  EXPECT_EQ(info.frame_index, 90u);
  EXPECT_LT(info.triangles_drawn, info.triangles_full);
  t = fixate(p, t, -20, 90);
  ASSERT_EQ(gzl_get_levels(p, 2, both, lv), GZL_SUCCESS);
  EXPECT_GT(lv[0], lv[1]) << "looking right: the right object is finer";
  // Without samples for longer than their maximum age, gaze falls back to head-fixed and says why.
  for (int f = 0; f < 30; ++f) {
    t += kFrameNs;
    gzl_frame_input in = still_head(t);
    ASSERT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS);
  }
  ASSERT_EQ(gzl_get_frame_info(p, &info), GZL_SUCCESS);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
  char why[512];
  ASSERT_EQ(gzl_get_gaze_status(p, why, sizeof why, nullptr), GZL_SUCCESS);
  EXPECT_NE(std::string(why).find("no sample pushed in the last"), std::string::npos) << why;
  gzl_destroy(p);
}

TEST(CApiFrames, NoAllocationPerFrame) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  std::vector<gzl_object> objects;
  for (int i = 0; i < 1000; ++i) {
    gzl_object o = 0;
    gzl_object_desc d = object_at(-40 + (i % 40) * 2.0, -20 + (i / 40) * 1.6, 2.0 + (i % 7));
    ASSERT_EQ(gzl_add_object(p, &d, &o), GZL_SUCCESS);
    objects.push_back(o);
  }
  std::vector<uint8_t> levels(objects.size());
  int64_t t = fixate(p, 0, 0, 30);  // warm-up: first frames size what they need
  const long before = g_allocations.load();
  for (int f = 0; f < 100; ++f) {
    t += kFrameNs;
    gzl_gaze_sample s = gaze_at(t - 5'000'000, (f / 20) * 3.0);
    ASSERT_EQ(gzl_push_gaze_sample(p, &s), GZL_SUCCESS);
    gzl_frame_input in = still_head(t);
    in.head.angular_velocity_rad_s = {0, 0.5, 0};
    ASSERT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS);
    ASSERT_EQ(gzl_get_levels(p, static_cast<uint32_t>(objects.size()), objects.data(), levels.data()), GZL_SUCCESS);
    ASSERT_EQ(gzl_end_frame(p, 5.0), GZL_SUCCESS);
  }
  EXPECT_EQ(g_allocations.load() - before, 0) << "allocations in 100 frames of 1000 objects";
  gzl_destroy(p);
}

TEST(CApiFrames, EngineStyleLevelsMatchTheirGeometricErrors) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  // H = 1800 px, r = 0.1 m: a share s is an error of 2r / (s H); p pixels at full height p 2r / H.
  const double shares[3] = {0.5, 0.2, 0.05}, pixels[3] = {0.5, 2.0, 8.0};
  std::vector<gzl_object> geo, share, px;
  for (int i = 0; i < 24; ++i) {
    const double yaw = -30 + i * 2.5, dist = 1.0 + (i % 6);
    gzl_level g[4] = {{0, 400}}, s[4] = {{0, 400}}, q[4] = {{0, 400}};
    for (int k = 0; k < 3; ++k) {
      s[k + 1] = {shares[k], 100u >> k};
      g[k + 1] = {0.2 / (shares[k] * 1800.0), 100u >> k};
      q[k + 1] = {pixels[k], 100u >> k};
    }
    gzl_object_desc d = object_at(yaw, 0, dist);
    gzl_object o = 0;
    d.levels = g;
    ASSERT_EQ(gzl_add_object(p, &d, &o), GZL_SUCCESS);
    geo.push_back(o);
    d.metric = GZL_LEVEL_SCREEN_HEIGHT_SHARE;
    d.levels = s;
    ASSERT_EQ(gzl_add_object(p, &d, &o), GZL_SUCCESS) << last_error(p);
    share.push_back(o);
    d.metric = GZL_LEVEL_PIXELS_AT_FULL_HEIGHT;
    d.levels = q;
    ASSERT_EQ(gzl_add_object(p, &d, &o), GZL_SUCCESS) << last_error(p);
    px.push_back(o);
  }
  fixate(p, 0, 0, 60);
  std::vector<uint8_t> lg(geo.size()), ls(geo.size()), lp(geo.size());
  ASSERT_EQ(gzl_get_levels(p, 24, geo.data(), lg.data()), GZL_SUCCESS);
  ASSERT_EQ(gzl_get_levels(p, 24, share.data(), ls.data()), GZL_SUCCESS);
  ASSERT_EQ(gzl_get_levels(p, 24, px.data(), lp.data()), GZL_SUCCESS);
  EXPECT_EQ(lg, ls);
  int coarse = 0;
  for (uint8_t l : lg) coarse += l > 0;
  EXPECT_GT(coarse, 0) << "the field has objects drawn coarser than full detail";
  // 0.5 px at full height = 0.2 / 1800 * 0.5 m: equal to the share of 0.5's error divided by... the
  // same chain written both ways must give the same levels as its own geometric form.
  gzl_object bad = 0;
  gzl_level over[2] = {{0, 10}, {1.5, 5}};
  gzl_object_desc d = object_at(0, 0, 2);
  d.metric = GZL_LEVEL_SCREEN_HEIGHT_SHARE;
  d.level_count = 2;
  d.levels = over;
  EXPECT_EQ(gzl_add_object(p, &d, &bad), GZL_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last_error(p).find("(0, 1]"), std::string::npos) << last_error(p);
  gzl_destroy(p);
}

TEST(CApiFrames, FovealConeInTheViewsImage) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  fixate(p, 0, 0, 30);
  gzl_foveal_cone c{};
  c.type = GZL_TYPE_FOVEAL_CONE;
  ASSERT_EQ(gzl_get_foveal_cone(p, 0, &c), GZL_SUCCESS);
  EXPECT_NEAR(c.center_u, 0.5, 1e-3);
  EXPECT_NEAR(c.center_v, 0.5, 1e-3);
  EXPECT_TRUE(c.in_view);
  EXPECT_DOUBLE_EQ(c.half_angle_deg, c.fovea_deg + c.uncertainty_deg);
  // Across a 90 deg view, the half-angle's extent at the centre is tan(a) / 2.
  EXPECT_NEAR(c.radius_u, std::tan(c.half_angle_deg * M_PI / 180) / 2, 1e-3);
  fixate(p, 30 * kFrameNs, -20, 60);  // to the right
  ASSERT_EQ(gzl_get_foveal_cone(p, 1, &c), GZL_SUCCESS);
  EXPECT_NEAR(c.center_u, 0.5 + std::tan(20 * M_PI / 180) / 2, 0.02) << "u from tan(20 deg)";
  EXPECT_NEAR(c.center_v, 0.5, 1e-3);
  EXPECT_EQ(gzl_get_foveal_cone(p, 2, &c), GZL_ERROR_INVALID_ARGUMENT);
  gzl_destroy(p);
}

// gzl_config.disabled_criteria: each criterion switched off may no longer coarsen a level. A
// row fixated at its middle: without eccentricity the side objects are drawn like the middle
// one; without size (and eccentricity) nothing is coarsened for a still head; bits other than
// the three criteria are refused by name.
TEST(CApiFrames, DisabledCriteriaNoLongerCoarsen) {
  auto row_levels = [](uint32_t disabled) {
    gzl_config c{};
    c.type = GZL_TYPE_CONFIG;
    c.disabled_criteria = disabled;
    gzl_plugin p = make_data_plugin(&c);
    EXPECT_NE(p, nullptr) << last_error(nullptr);
    std::vector<gzl_object> row(3);
    for (int i = 0; i < 3; ++i) {
      gzl_object_desc d = object_at(-30.0 + 30.0 * i, 0, 2.0);
      EXPECT_EQ(gzl_add_object(p, &d, &row[i]), GZL_SUCCESS);
    }
    fixate(p, 0, 0, 90);
    std::vector<uint8_t> l(3);
    EXPECT_EQ(gzl_get_levels(p, 3, row.data(), l.data()), GZL_SUCCESS);
    gzl_destroy(p);
    return l;
  };
  const std::vector<uint8_t> all = row_levels(0);
  EXPECT_LT(all[1], all[0]);
  EXPECT_LT(all[1], all[2]);
  const std::vector<uint8_t> no_ecc = row_levels(GZL_CRITERION_ECCENTRICITY);
  EXPECT_EQ(no_ecc, std::vector<uint8_t>(3, all[1])) << "the sides drawn like the fixated object";
  EXPECT_EQ(row_levels(GZL_CRITERION_SIZE | GZL_CRITERION_ECCENTRICITY), std::vector<uint8_t>(3, 0))
      << "a still head and still objects: only size and eccentricity could coarsen";
  gzl_config bad{};
  bad.type = GZL_TYPE_CONFIG;
  bad.disabled_criteria = 8;
  EXPECT_EQ(make_data_plugin(&bad), nullptr);
  EXPECT_NE(last_error(nullptr).find("config->disabled_criteria"), std::string::npos) << last_error(nullptr);
}

// One view (a desktop or mono configuration) and quad views (XR_VARJO_quad_views: a primary pair
// and a denser inset pair): the display's limit is the densest view's, every view has its cone.
TEST(CApiFrames, MonoAndQuadViews) {
  auto view = [](double half_fov_deg, uint32_t px) {
    gzl_view v{};
    const double a = half_fov_deg * M_PI / 180;
    v.fov = {-a, a, a, -a};
    v.width_px = v.height_px = px;
    return v;
  };
  const gzl_view quad[4] = {view(50, 1000), view(50, 1000), view(20, 1000), view(20, 1000)};
  for (uint32_t count : {1u, 4u}) {
    gzl_data_create_info info{};
    info.type = GZL_TYPE_DATA_CREATE_INFO;
    info.view_count = count;
    info.views = quad;
    gzl_plugin p = nullptr;
    ASSERT_EQ(gzl_create_data(&info, &p), GZL_SUCCESS) << last_error(nullptr);
    fixate(p, 0, 0, 10);
    gzl_frame_info fi{};
    fi.type = GZL_TYPE_FRAME_INFO;
    ASSERT_EQ(gzl_get_frame_info(p, &fi), GZL_SUCCESS);
    // xi = pixels / (2 * FOV in degrees): 1000 / 200 = 5 for the primary, 1000 / 80 = 12.5 for the inset.
    EXPECT_NEAR(fi.xi_cpd, count == 1 ? 5.0 : 12.5, 0.2) << count << " views";
    for (uint32_t v = 0; v < count; ++v) {
      gzl_foveal_cone c{};
      c.type = GZL_TYPE_FOVEAL_CONE;
      ASSERT_EQ(gzl_get_foveal_cone(p, v, &c), GZL_SUCCESS);
      EXPECT_NEAR(c.center_u, 0.5, 1e-3);
    }
    gzl_destroy(p);
  }
  gzl_data_create_info info{};
  info.type = GZL_TYPE_DATA_CREATE_INFO;
  info.view_count = 3;
  info.views = quad;
  gzl_plugin p = nullptr;
  EXPECT_EQ(gzl_create_data(&info, &p), GZL_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last_error(nullptr).find("1, 2 or 4 views"), std::string::npos) << last_error(nullptr);
}

// The render thread decides frames while an application thread registers, removes and disables
// objects, reports session states and reads the published frame.
TEST(CApiThreads, ApplicationThreadBesideRenderThread) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  std::vector<gzl_object> base;
  for (int i = 0; i < 50; ++i) {
    gzl_object o = 0;
    gzl_object_desc d = object_at(-25 + i, 0, 3);
    ASSERT_EQ(gzl_add_object(p, &d, &o), GZL_SUCCESS);
    base.push_back(o);
  }
  std::atomic<bool> done{false};
  std::atomic<int> failures{0};
  std::thread render([&] {
    int64_t t = 0;
    for (int f = 0; f < 300; ++f) {
      t += kFrameNs;
      gzl_gaze_sample s = gaze_at(t - 4'000'000, (f % 60) - 30.0);
      gzl_frame_input in = still_head(t);
      if (gzl_push_gaze_sample(p, &s) != GZL_SUCCESS || gzl_begin_frame_data(p, &in) != GZL_SUCCESS ||
          gzl_end_frame(p, 4.0) != GZL_SUCCESS)
        ++failures;
    }
    done = true;
  });
  std::thread app([&] {
    std::vector<uint8_t> levels(base.size());
    int round = 0;
    while (!done) {
      gzl_object o = 0;
      gzl_object_desc d = object_at(round % 40 - 20.0, 5, 2);
      if (gzl_add_object(p, &d, &o) != GZL_SUCCESS) ++failures;
      if (gzl_set_object_enabled(p, base[round % base.size()], round % 2) != GZL_SUCCESS) ++failures;
      if (gzl_remove_object(p, o) != GZL_SUCCESS) ++failures;
      if (gzl_on_session_state(p, 5 /* FOCUSED */, round) != GZL_SUCCESS) ++failures;
      if (gzl_get_levels(p, static_cast<uint32_t>(base.size()), base.data(), levels.data()) != GZL_SUCCESS) ++failures;
      gzl_frame_info info{};
      info.type = GZL_TYPE_FRAME_INFO;
      if (gzl_get_frame_info(p, &info) != GZL_SUCCESS) ++failures;
      ++round;
    }
  });
  render.join();
  app.join();
  EXPECT_EQ(failures.load(), 0) << last_error(p);
  gzl_destroy(p);
}

// gzl_shutdown on one thread while another registers: the flag is read under the lock a change
// takes (ThreadSanitizer in CI saw it read without), so once a call has been refused no later
// one succeeds, and no registration runs after gzl_shutdown has returned.
TEST(CApiThreads, ShutdownBesideRegistration) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  std::atomic<bool> shut{false};
  std::atomic<int> wrong{0};
  std::thread app([&] {
    bool refused = false;
    for (int i = 0; !refused; ++i) {  // until gzl_shutdown (below) refuses one
      gzl_object o = 0;
      gzl_object_desc d = object_at(i % 40 - 20.0, 0, 2);
      const bool was_shut = shut.load();  // gzl_shutdown had returned before this call began
      const gzl_result r = gzl_add_object(p, &d, &o);
      if (r == GZL_ERROR_SHUT_DOWN)
        refused = true;
      else if (r != GZL_SUCCESS || was_shut)
        ++wrong;
    }
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_EQ(gzl_shutdown(p), GZL_SUCCESS);
  shut = true;
  app.join();
  EXPECT_EQ(wrong.load(), 0);
  gzl_destroy(p);
}

}  // namespace
}  // namespace gazelod::test
