// SPDX-License-Identifier: Apache-2.0
// Object handles through the C ABI (plugin/capi/capi_handles.hpp): a streaming world's adds and
// removes keep the handle tables as long as the most objects live at once, a handle value is
// never issued twice (not even once a row's generations are spent), and a handle from another
// plugin or a removed object is refused rather than taken for another object. Also the pushed
// gaze's first-frame clock check and its stale status.
#include "plugin/capi/capi_plugin.hpp"
#include "tests/capi/capi_test_util.hpp"
#include "tests/counting_new.hpp"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace gazelod::test {
namespace {

constexpr int64_t kFrameNs = 11'111'111;

// The handle tables' lengths (white box: the C ABI does not show them).
std::size_t rows(gzl_plugin p) {
  return p->pub.level_by_row.size();
}

TEST(CApiHandles, ChurnKeepsTablesAtTheLiveCountAndNeverRepeatsAHandle) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  std::vector<gzl_object> live;
  std::set<gzl_object> issued;
  gzl_object_desc d = object_at(10, 0, 3.0);
  for (int i = 0; i < 100; ++i) {
    gzl_object h = 0;
    ASSERT_EQ(gzl_add_object(p, &d, &h), GZL_SUCCESS);
    ASSERT_TRUE(issued.insert(h).second);
    live.push_back(h);
  }
  gzl_frame_input in = still_head(kFrameNs);
  ASSERT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS);
  for (int i = 0; i < 20000; ++i) {
    const std::size_t k = static_cast<std::size_t>(i * 37) % live.size();
    const gzl_object gone = live[k];
    ASSERT_EQ(gzl_remove_object(p, gone), GZL_SUCCESS);
    ASSERT_EQ(gzl_remove_object(p, gone), GZL_ERROR_OBJECT_INVALID);
    EXPECT_NE(last_error(p).find("was removed"), std::string::npos) << last_error(p);
    ASSERT_EQ(gzl_add_object(p, &d, &live[k]), GZL_SUCCESS);
    ASSERT_TRUE(issued.insert(live[k]).second) << "handle " << live[k] << " issued twice";
    uint8_t level = 0;
    ASSERT_EQ(gzl_get_levels(p, 1, &gone, &level), GZL_ERROR_OBJECT_INVALID) << "a reused row's old handle";
  }
  EXPECT_EQ(rows(p), 100u);
  EXPECT_EQ(p->pub.level_triangles.size(), 400u);  // blocks reused: every object has 4 levels
  in = still_head(2 * kFrameNs);
  ASSERT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS);
  gzl_frame_info info{GZL_TYPE_FRAME_INFO, nullptr};
  ASSERT_EQ(gzl_get_frame_info(p, &info), GZL_SUCCESS);
  EXPECT_EQ(info.object_count, 100u);
  EXPECT_EQ(info.triangles_full, 100u * 4000u);  // the live objects, each once
  std::vector<uint8_t> levels(live.size());
  EXPECT_EQ(gzl_get_levels(p, 100, live.data(), levels.data()), GZL_SUCCESS) << last_error(p);
  gzl_destroy(p);
}

// A row's 16-bit generation runs out after 65536 objects: the row is retired, so its next
// handle cannot repeat the first one.
TEST(CApiHandles, ASpentRowIsRetiredNotReused) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  gzl_object_desc d = object_at(0, 0, 3.0);
  std::set<gzl_object> issued;
  for (int i = 0; i < 65536 + 2; ++i) {
    gzl_object h = 0;
    ASSERT_EQ(gzl_add_object(p, &d, &h), GZL_SUCCESS);
    ASSERT_TRUE(issued.insert(h).second) << "handle " << h << " issued twice, at add " << i;
    ASSERT_EQ(gzl_remove_object(p, h), GZL_SUCCESS);
  }
  EXPECT_EQ(rows(p), 2u);
  gzl_destroy(p);
}

TEST(CApiHandles, AnotherPluginsHandleIsRefused) {
  gzl_plugin a = make_data_plugin(), b = make_data_plugin();
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  gzl_object_desc d = object_at(0, 0, 3.0);
  gzl_object ha = 0, hb = 0;
  ASSERT_EQ(gzl_add_object(a, &d, &ha), GZL_SUCCESS);
  ASSERT_EQ(gzl_add_object(b, &d, &hb), GZL_SUCCESS);
  EXPECT_NE(ha, hb);
  EXPECT_EQ(gzl_remove_object(a, hb), GZL_ERROR_OBJECT_INVALID);
  EXPECT_NE(last_error(a).find("was never issued by this plugin"), std::string::npos) << last_error(a);
  EXPECT_EQ(gzl_set_object_enabled(a, hb, 0), GZL_ERROR_OBJECT_INVALID);
  uint8_t level = 0;
  EXPECT_EQ(gzl_get_levels(a, 1, &hb, &level), GZL_ERROR_OBJECT_INVALID);
  EXPECT_EQ(gzl_remove_object(a, ha), GZL_SUCCESS);  // a's own object was untouched
  // A handle with a generation the row has not reached yet was never issued either.
  EXPECT_EQ(gzl_remove_object(b, hb + (gzl_object{1} << 32)), GZL_ERROR_OBJECT_INVALID);
  EXPECT_NE(last_error(b).find("was never issued"), std::string::npos) << last_error(b);
  gzl_destroy(a);
  gzl_destroy(b);
}

// A sample pushed before the first frame cannot be checked against a frame's clock; one that
// the first frame shows to be on another clock is dropped, not kept to make every later sample
// "out of order" for the plugin's whole life.
TEST(CApiPushedGaze, ASampleOnAnotherClockBeforeTheFirstFrameIsDroppedAndSaid) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  gzl_object h = 0;
  gzl_object_desc d = object_at(0, 0, 3.0);
  ASSERT_EQ(gzl_add_object(p, &d, &h), GZL_SUCCESS);
  gzl_gaze_sample wrong = gaze_at(int64_t{1} << 61, 0);
  ASSERT_EQ(gzl_push_gaze_sample(p, &wrong), GZL_SUCCESS);  // no frame yet to check it against
  int64_t t = 1'000'000'000;
  gzl_frame_input in = still_head(t);
  ASSERT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS);
  char why[512];
  ASSERT_EQ(gzl_get_gaze_status(p, why, sizeof why, nullptr), GZL_SUCCESS);
  EXPECT_NE(std::string(why).find("1 sample(s) pushed before the first frame"), std::string::npos) << why;
  for (int f = 0; f < 5; ++f) {
    t += kFrameNs;
    gzl_gaze_sample s = gaze_at(t - 5'000'000, 0);
    ASSERT_EQ(gzl_push_gaze_sample(p, &s), GZL_SUCCESS) << last_error(p);
    in = still_head(t);
    ASSERT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS);
  }
  gzl_frame_info info{GZL_TYPE_FRAME_INFO, nullptr};
  ASSERT_EQ(gzl_get_frame_info(p, &info), GZL_SUCCESS);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_PUSHED);
  gzl_destroy(p);
}

// Frames after the pushed samples stop: head-fixed, said once, and no allocation per frame.
TEST(CApiPushedGaze, StaleGazeFramesDoNotAllocate) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  gzl_object h = 0;
  gzl_object_desc d = object_at(0, 0, 3.0);
  ASSERT_EQ(gzl_add_object(p, &d, &h), GZL_SUCCESS);
  int64_t t = 0;
  for (int f = 0; f < 60; ++f) {  // 30 frames with samples, 30 after them (the change said)
    t += kFrameNs;
    if (f < 30) {
      gzl_gaze_sample s = gaze_at(t - 5'000'000, 0);
      ASSERT_EQ(gzl_push_gaze_sample(p, &s), GZL_SUCCESS);
    }
    gzl_frame_input in = still_head(t);
    ASSERT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS);
  }
  const long before = g_allocations.load();
  for (int f = 0; f < 100; ++f) {
    t += kFrameNs;
    gzl_frame_input in = still_head(t);
    ASSERT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS);
  }
  EXPECT_EQ(g_allocations.load() - before, 0) << "allocations in 100 frames without gaze samples";
  gzl_frame_info info{GZL_TYPE_FRAME_INFO, nullptr};
  ASSERT_EQ(gzl_get_frame_info(p, &info), GZL_SUCCESS);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
  gzl_destroy(p);
}

}  // namespace
}  // namespace gazelod::test
