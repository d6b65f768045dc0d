// SPDX-License-Identifier: Apache-2.0
// The C ABI fuzzer's other calls: configuration, status, NULL plugins.
#include "fuzz/capi/capi_fuzz.hpp"

namespace gazelod::fuzz::capi_fuzz {

void op_misc(Bytes& in, Model& m) {
  const std::string sentinel = set_sentinel(m.p);
  switch (in.pick(6)) {
    case 0: {
      const double ms = in.one_in(4) ? in.num(1e5) : 5.0 + in.pick(20);
      const gzl_result r = checked(m.p, gzl_end_frame(m.p, ms), sentinel);
      if (m.shut_down)
        check(r == GZL_ERROR_SHUT_DOWN, "gzl_end_frame after gzl_shutdown did not fail with GZL_ERROR_SHUT_DOWN");
      if (!std::isfinite(ms) || ms < 0.0) check(r != GZL_SUCCESS, "gzl_end_frame accepted a bad time");
      break;
    }
    case 1: {
      const std::uint32_t view = in.pick(6), w = in.one_in(4) ? in.u32() : 1 + in.u16(),
                          h = in.one_in(4) ? in.u32() : 1 + in.u16();
      const gzl_result r = checked(m.p, gzl_set_view_resolution(m.p, view, w, h), sentinel);
      if (r == GZL_SUCCESS)
        check(view < m.view_count, "gzl_set_view_resolution accepted a view the plugin does not have");
      break;
    }
    case 2: {
      const auto state = static_cast<std::int32_t>(in.one_in(4) ? in.u32() : in.pick(10));
      const gzl_result r = checked(m.p, gzl_on_session_state(m.p, state, pick_time(in, m, true)), sentinel);
      if (m.shut_down)
        check(r == GZL_ERROR_SHUT_DOWN,
              "gzl_on_session_state after gzl_shutdown did not fail with GZL_ERROR_SHUT_DOWN");
      break;
    }
    case 3: {  // OpenXR-mode calls on a data-mode plugin
      gzl_result r = GZL_SUCCESS;
      gzl_gaze_binding b{GZL_TYPE_GAZE_BINDING, nullptr};
      switch (in.pick(4)) {
        case 0:
          r = gzl_begin_frame_openxr(m.p, pick_time(in, m, false));
          break;
        case 1:
          r = gzl_set_base_space(m.p, in.u64());
          break;
        case 2:
          r = gzl_action_sets_attached(m.p);
          break;
        default:
          r = gzl_get_gaze_binding(m.p, &b);
          break;
      }
      checked(m.p, r, sentinel);
      check(r == (m.shut_down ? GZL_ERROR_SHUT_DOWN : GZL_ERROR_WRONG_MODE),
            "an OpenXR-mode call on a data-mode plugin was not refused");
      break;
    }
    case 4: {
      const gzl_result r = checked(m.p, gzl_shutdown(m.p), sentinel);
      check(r == GZL_SUCCESS, "gzl_shutdown failed");
      m.shut_down = true;
      break;
    }
    default: {
      const std::uint32_t v = gzl_version();
      check(GZL_VERSION_MAJOR(v) == GZL_VERSION_MAJOR(GZL_HEADER_VERSION), "gzl_version's major is not the header's");
      const auto any = static_cast<gzl_result>(static_cast<std::int32_t>(in.u32()));
      (void)gzl_result_to_string(any);  // any value: a name or GZL_RESULT_UNKNOWN, never a crash
      break;
    }
  }
}

// A call with a NULL plugin: GZL_ERROR_NULL_HANDLE.
void op_null_handle(Bytes& in) {
  gzl_result r = GZL_SUCCESS;
  const std::string sentinel = set_sentinel(nullptr);
  bool fresh_message = true;
  std::uint8_t level = 0;
  const gzl_object one = 1;
  gzl_frame_info info{GZL_TYPE_FRAME_INFO, nullptr};
  gzl_foveal_cone cone{GZL_TYPE_FOVEAL_CONE, nullptr};
  gzl_frame_record rec{GZL_TYPE_FRAME_RECORD, nullptr};
  gzl_gaze_sample s{GZL_TYPE_GAZE_SAMPLE, nullptr};
  s.direction = {0.0, 0.0, -1.0};
  s.flags = GZL_GAZE_SAMPLE_VALID;
  gzl_frame_input f{GZL_TYPE_FRAME_INPUT, nullptr};
  gzl_object_desc d{GZL_TYPE_OBJECT_DESC, nullptr};
  const gzl_level lv{0.0, 100};
  d.level_count = 1;
  d.levels = &lv;
  gzl_object h = 0;
  const gzl_vec3 zero{0.0, 0.0, 0.0};
  char buf[8];
  switch (in.pick(18)) {
    case 0:
      r = gzl_add_object(nullptr, &d, &h);
      break;
    case 1:
      r = gzl_remove_object(nullptr, one);
      break;
    case 2:
      r = gzl_set_object_enabled(nullptr, one, 1);
      break;
    case 3:
      r = gzl_set_object_motion(nullptr, one, &zero, &zero);
      break;
    case 4:
      r = gzl_push_gaze_sample(nullptr, &s);
      break;
    case 5:
      r = gzl_begin_frame_data(nullptr, &f);
      break;
    case 6:
      r = gzl_end_frame(nullptr, 1.0);
      break;
    case 7:
      r = gzl_get_levels(nullptr, 1, &one, &level);
      break;
    case 8:
      r = gzl_get_frame_info(nullptr, &info);
      break;
    case 9:
      r = gzl_get_foveal_cone(nullptr, 0, &cone);
      break;
    case 10:
      r = gzl_get_frame_record(nullptr, &rec);
      break;
    case 11:
      r = gzl_shutdown(nullptr);
      break;
    case 12:
      r = gzl_set_view_resolution(nullptr, 0, 100, 100);
      break;
    case 13:
      r = gzl_on_session_state(nullptr, 5, 0);
      break;
    case 14:
      r = gzl_begin_frame_openxr(nullptr, 1);
      break;
    case 15:
      r = gzl_set_base_space(nullptr, 1);
      break;
    case 16:
      r = gzl_action_sets_attached(nullptr);
      break;
    default:
      // The only entry point that does not leave a message for a NULL plugin (it is a reader
      // of the plugin's own strings); its code is still GZL_ERROR_NULL_HANDLE.
      r = gzl_get_gaze_status(nullptr, buf, sizeof buf, nullptr);
      fresh_message = false;
      break;
  }
  gzl_destroy(nullptr);
  check_named(r);
  check(r == GZL_ERROR_NULL_HANDLE, "a call with a NULL plugin did not fail with GZL_ERROR_NULL_HANDLE");
  if (fresh_message) checked(nullptr, r, sentinel);
}

// What capi() below does for op byte k (for the trace).
const char* op_name(std::uint8_t k, bool have_plugin) {
  if (!have_plugin || k % 32 == 0) return k % 4 == 3 ? "call with a NULL plugin" : "create";
  static const char* const kNames[16] = {"add_object",
                                         "add_object",
                                         "add_object",
                                         "remove_object",
                                         "set_object_enabled",
                                         "set_object_motion",
                                         "push_gaze_sample",
                                         "push_gaze_sample",
                                         "begin_frame_data",
                                         "begin_frame_data",
                                         "begin_frame_data",
                                         "get_levels",
                                         "frame info / cone / record / gaze status",
                                         "get_last_error",
                                         "misc",
                                         ""};
  if (k % 16 != 15) return kNames[k % 16];
  return k % 64 == 15 ? "destroy" : "call with a NULL plugin";
}

}  // namespace gazelod::fuzz::capi_fuzz
