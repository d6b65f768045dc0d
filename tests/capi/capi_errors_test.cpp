// SPDX-License-Identifier: Apache-2.0
// Bad input through the C ABI: every refusal is a result code and a "gazelod:" message that
// names the field, never a crash; the plugin stays usable after it.
#include "tests/capi/capi_test_util.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace gazelod::test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void expect_error(gzl_plugin p, gzl_result got, gzl_result want, const char* mentions) {
  EXPECT_EQ(got, want) << gzl_result_to_string(got);
  const std::string m = last_error(p);
  EXPECT_EQ(m.rfind("gazelod:", 0), 0u) << m;
  EXPECT_NE(m.find(mentions), std::string::npos) << m;
}

TEST(CApi, VersionsAndResultNames) {
  EXPECT_EQ(GZL_VERSION_MAJOR(gzl_version()), GZL_VERSION_MAJOR(GZL_HEADER_VERSION));
  EXPECT_STREQ(gzl_result_to_string(GZL_ERROR_TIME_OUT_OF_ORDER), "GZL_ERROR_TIME_OUT_OF_ORDER");
  EXPECT_STREQ(gzl_result_to_string(static_cast<gzl_result>(-999)), "GZL_RESULT_UNKNOWN");
}

TEST(CApi, NullHandlesAndPointers) {
  gzl_object o = 0;
  gzl_object_desc d = object_at(0, 0, 3);
  EXPECT_EQ(gzl_add_object(nullptr, &d, &o), GZL_ERROR_NULL_HANDLE);
  EXPECT_EQ(gzl_begin_frame_data(nullptr, nullptr), GZL_ERROR_NULL_HANDLE);
  EXPECT_EQ(gzl_create_data(nullptr, nullptr), GZL_ERROR_NULL_POINTER);
  gzl_plugin p = nullptr;
  expect_error(nullptr, gzl_create_data(nullptr, &p), GZL_ERROR_NULL_POINTER, "info");
  EXPECT_EQ(p, nullptr);
  gzl_destroy(nullptr);  // accepted

  p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  expect_error(p, gzl_add_object(p, nullptr, &o), GZL_ERROR_NULL_POINTER, "desc");
  expect_error(p, gzl_add_object(p, &d, nullptr), GZL_ERROR_NULL_POINTER, "object");
  d.levels = nullptr;
  expect_error(p, gzl_add_object(p, &d, &o), GZL_ERROR_NULL_POINTER, "desc->levels");
  expect_error(p, gzl_set_object_motion(p, 1, nullptr, nullptr), GZL_ERROR_NULL_POINTER, "center_m");
  uint8_t level = 0;
  expect_error(p, gzl_get_levels(p, 1, nullptr, &level), GZL_ERROR_NULL_POINTER, "objects");
  gzl_destroy(p);
}

TEST(CApi, WrongStructTypesAndModes) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  gzl_object o = 0;
  gzl_object_desc d = object_at(0, 0, 3);
  d.type = GZL_TYPE_GAZE_SAMPLE;
  expect_error(p, gzl_add_object(p, &d, &o), GZL_ERROR_STRUCT_TYPE, "desc->type");
  gzl_frame_info info{};
  expect_error(p, gzl_get_frame_info(p, &info), GZL_ERROR_STRUCT_TYPE, "GZL_TYPE_FRAME_INFO");
  expect_error(p, gzl_begin_frame_openxr(p, 1), GZL_ERROR_WRONG_MODE, "gzl_create_openxr");
  expect_error(p, gzl_set_base_space(p, 1), GZL_ERROR_WRONG_MODE, "gzl_create_openxr");
  gzl_config c{};
  c.type = GZL_TYPE_DATA_CREATE_INFO;
  gzl_plugin q = make_data_plugin(&c);
  EXPECT_EQ(q, nullptr);
  EXPECT_NE(last_error(nullptr).find("config->type"), std::string::npos) << last_error(nullptr);
  c.type = GZL_TYPE_CONFIG;
  c.gaze_accuracy_deg = kNaN;
  EXPECT_EQ(make_data_plugin(&c), nullptr);
  EXPECT_NE(last_error(nullptr).find("gaze_accuracy_deg"), std::string::npos) << last_error(nullptr);
  // A value too small to print with %f (a unit slip) is named as given, not as "0.000000",
  // which read as if 0, the default, were refused.
  c.gaze_accuracy_deg = 1e-310;
  EXPECT_EQ(make_data_plugin(&c), nullptr);
  EXPECT_NE(last_error(nullptr).find("config->gaze_accuracy_deg = 1e-310 is outside [0.01, 45]"), std::string::npos)
      << last_error(nullptr);
  gzl_openxr_create_info xi{};
  xi.type = GZL_TYPE_OPENXR_CREATE_INFO;
  expect_error(nullptr, gzl_create_openxr(&xi, &q), GZL_ERROR_NULL_POINTER, "get_instance_proc_addr");
  gzl_destroy(p);
}

TEST(CApi, NonFiniteInputsAreRefusedByField) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  gzl_object o = 0;
  gzl_object_desc d = object_at(0, 0, 3);
  d.center_m.y = kNaN;
  expect_error(p, gzl_add_object(p, &d, &o), GZL_ERROR_INVALID_ARGUMENT, "desc->center_m");
  d = object_at(0, 0, 3);
  const gzl_level rising[2] = {{0, 100}, {-1, 10}};
  d.levels = rising;
  d.level_count = 2;
  expect_error(p, gzl_add_object(p, &d, &o), GZL_ERROR_INVALID_ARGUMENT, "desc->levels[1].value");
  d = object_at(0, 0, 3);
  ASSERT_EQ(gzl_add_object(p, &d, &o), GZL_SUCCESS);

  gzl_frame_input in = still_head(1'000'000);
  in.head.orientation = {kNaN, 0, 0, 1};
  expect_error(p, gzl_begin_frame_data(p, &in), GZL_ERROR_INVALID_ARGUMENT, "input->head.orientation");
  // Finite but past the square's range: normalised, not refused as "not finite".
  in = still_head(500'000);
  in.head.orientation = {0, 0, 0, 1e200};
  EXPECT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS) << last_error(p);
  EXPECT_EQ(gzl_end_frame(p, 5.0), GZL_SUCCESS) << last_error(p);
  in = still_head(600'000);
  in.head.orientation = {0, 0, 0, 1e-7};  // below 1e-6: no orientation at all
  expect_error(p, gzl_begin_frame_data(p, &in), GZL_ERROR_INVALID_ARGUMENT, "input->head.orientation");
  in = still_head(1'000'000);
  in.head.angular_velocity_rad_s.z = std::numeric_limits<double>::infinity();
  expect_error(p, gzl_begin_frame_data(p, &in), GZL_ERROR_INVALID_ARGUMENT, "angular_velocity");
  gzl_gaze_sample s = gaze_at(0, 0);
  s.direction = {kNaN, 0, -1};
  expect_error(p, gzl_push_gaze_sample(p, &s), GZL_ERROR_INVALID_ARGUMENT, "direction");
  gzl_vec3 c{0, 0, -3}, v{kNaN, 0, 0};
  expect_error(p, gzl_set_object_motion(p, o, &c, &v), GZL_ERROR_INVALID_ARGUMENT, "velocity_m_s");
  // Still usable: a good frame goes through.
  in = still_head(1'000'000);
  EXPECT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS) << last_error(p);
  gzl_destroy(p);
}

TEST(CApi, GazeSamplesOutOfOrderOrFromTheFuture) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  gzl_gaze_sample s = gaze_at(100'000'000, 0);
  ASSERT_EQ(gzl_push_gaze_sample(p, &s), GZL_SUCCESS);
  s.time_ns = 90'000'000;
  expect_error(p, gzl_push_gaze_sample(p, &s), GZL_ERROR_TIME_OUT_OF_ORDER, "older than the previous");
  gzl_frame_input in = still_head(110'000'000);
  ASSERT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS);
  s.time_ns = 110'000'000 + 5'000'000'000LL;
  expect_error(p, gzl_push_gaze_sample(p, &s), GZL_ERROR_TIME_IN_FUTURE, "after the last frame");
  in = still_head(100'000'000);
  expect_error(p, gzl_begin_frame_data(p, &in), GZL_ERROR_TIME_OUT_OF_ORDER, "not after the last frame");
  gzl_destroy(p);
}

TEST(CApi, RemovedAndForeignHandles) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  gzl_object a = 0, b = 0, c = 0;
  gzl_object_desc d = object_at(0, 0, 3);
  ASSERT_EQ(gzl_add_object(p, &d, &a), GZL_SUCCESS);
  ASSERT_EQ(gzl_add_object(p, &d, &b), GZL_SUCCESS);
  d = object_at(30, 0, 3);
  ASSERT_EQ(gzl_add_object(p, &d, &c), GZL_SUCCESS);
  EXPECT_TRUE(a != b && b != c && a != c);
  ASSERT_EQ(gzl_remove_object(p, a), GZL_SUCCESS);
  expect_error(p, gzl_remove_object(p, a), GZL_ERROR_OBJECT_INVALID, "removed");
  expect_error(p, gzl_set_object_enabled(p, a, 0), GZL_ERROR_OBJECT_INVALID, "removed");
  expect_error(p, gzl_set_object_enabled(p, 77, 0), GZL_ERROR_OBJECT_INVALID, "never issued");
  uint8_t level = 0;
  expect_error(p, gzl_get_levels(p, 1, &a, &level), GZL_ERROR_OBJECT_INVALID, "removed");
  // The object moved into the freed slot keeps its own handle and data: c stays peripheral.
  ASSERT_EQ(gzl_set_object_enabled(p, b, 0), GZL_SUCCESS);
  gzl_gaze_sample s = gaze_at(0, 0);
  ASSERT_EQ(gzl_push_gaze_sample(p, &s), GZL_SUCCESS);
  gzl_frame_input in = still_head(1'000'000);
  ASSERT_EQ(gzl_begin_frame_data(p, &in), GZL_SUCCESS);
  const gzl_object both[2] = {b, c};
  uint8_t levels[2] = {0, 0};
  ASSERT_EQ(gzl_get_levels(p, 2, both, levels), GZL_SUCCESS);
  EXPECT_EQ(levels[0], GZL_LEVEL_DISABLED);
  EXPECT_GT(levels[1], 0) << "the object 30 deg out is drawn coarser than full detail";
  // A new object gets a new handle, never a reused one.
  gzl_object e = 0;
  ASSERT_EQ(gzl_add_object(p, &d, &e), GZL_SUCCESS);
  EXPECT_GT(e, c);
  gzl_destroy(p);
}

TEST(CApi, AfterShutdownOnlyDestroy) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(gzl_shutdown(p), GZL_SUCCESS);
  EXPECT_EQ(gzl_shutdown(p), GZL_SUCCESS);
  gzl_frame_input in = still_head(1);
  expect_error(p, gzl_begin_frame_data(p, &in), GZL_ERROR_SHUT_DOWN, "gzl_destroy");
  gzl_destroy(p);
}

TEST(CApi, ErrorMessagesTruncateSafely) {
  gzl_plugin p = make_data_plugin();
  ASSERT_NE(p, nullptr);
  gzl_object o = 0;
  EXPECT_NE(gzl_add_object(p, nullptr, &o), GZL_SUCCESS);
  char small[8];
  size_t length = 0;
  ASSERT_EQ(gzl_get_last_error(p, small, sizeof small, &length), GZL_SUCCESS);
  EXPECT_STREQ(small, "gazelod");
  EXPECT_GT(length, sizeof small);
  gzl_destroy(p);
}

}  // namespace
}  // namespace gazelod::test
