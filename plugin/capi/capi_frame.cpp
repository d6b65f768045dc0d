// SPDX-License-Identifier: Apache-2.0
// Frames and inputs through the C ABI: session state, spaces, views, gaze samples, the frame's
// decision and its publication (include/gazelod/gazelod.h).
#include "plugin/capi/capi_convert.hpp"
#include "plugin/capi/capi_errors.hpp"
#include "plugin/capi/capi_publish.hpp"
#include "xr/eye_gaze_paths.hpp"

using namespace gazelod;
using namespace gazelod::capi;

namespace {

void need_openxr(gzl_plugin p, const char* call) {
  if (!p->openxr)
    throw Refusal{GZL_ERROR_WRONG_MODE, std::string("gazelod: ") + call + " is for a plugin made by gzl_create_openxr"};
}

void check_push(plugin::PushResult r, const std::string& why) {
  switch (r) {
    case plugin::PushResult::ok:
      return;
    case plugin::PushResult::out_of_order:
      throw Refusal{GZL_ERROR_TIME_OUT_OF_ORDER, why};
    case plugin::PushResult::in_future:
      throw Refusal{GZL_ERROR_TIME_IN_FUTURE, why};
    case plugin::PushResult::invalid:
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, why};
  }
}

}  // namespace

extern "C" {

GZL_API gzl_result gzl_get_gaze_binding(gzl_plugin p, gzl_gaze_binding* b) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    if (b == nullptr) throw Refusal{GZL_ERROR_NULL_POINTER, "gazelod: binding (the output) is NULL"};
    if (b->type != GZL_TYPE_GAZE_BINDING)
      throw Refusal{GZL_ERROR_STRUCT_TYPE, "gazelod: binding->type must be GZL_TYPE_GAZE_BINDING"};
    need_openxr(p, "gzl_get_gaze_binding");
    const auto lock = lock_live(p);
    if (p->gaze_input != GZL_GAZE_INPUT_MERGE_BINDING || p->xr->action_set() == XR_NULL_HANDLE)
      throw Refusal{GZL_ERROR_WRONG_MODE,
                    "gazelod: this plugin has no binding to merge: create it with GZL_GAZE_INPUT_MERGE_BINDING on a "
                    "system with eye-gaze interaction (XR_EXT_eye_gaze_interaction enabled on the instance)"};
    b->action_set = to_handle(p->xr->action_set());
    b->action = to_handle(p->xr->gaze_action());
    b->interaction_profile = xr::kEyeGazeProfile;
    b->binding_path = xr::kGazePosePath;
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_action_sets_attached(gzl_plugin p) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    need_openxr(p, "gzl_action_sets_attached");
    const auto lock = lock_live(p);
    p->xr->action_sets_attached();
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_set_gaze_space(gzl_plugin p, uint64_t gaze_space, uint64_t gaze_action) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    need_openxr(p, "gzl_set_gaze_space");
    const auto lock = lock_live(p);
    p->xr->set_gaze_space(from_handle<XrSpace>(gaze_space), from_handle<XrAction>(gaze_action));
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_on_session_state(gzl_plugin p, int32_t state, int64_t time_ns) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    need_time(time_ns, "time_ns");
    if (state < XR_SESSION_STATE_UNKNOWN || state > XR_SESSION_STATE_EXITING)
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT,
                    "gazelod: session state " + std::to_string(state) + " is not an XrSessionState"};
    const auto lock = lock_live(p);
    p->core().session_state(state == XR_SESSION_STATE_FOCUSED, time_ns);
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_set_base_space(gzl_plugin p, uint64_t space) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    need_openxr(p, "gzl_set_base_space");
    const auto lock = lock_live(p);
    p->xr->set_base_space(from_handle<XrSpace>(space));
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_set_view_resolution(gzl_plugin p, uint32_t view, uint32_t width_px, uint32_t height_px) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    const auto lock = lock_live(p);
    if (view >= p->view_count)
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, "gazelod: view " + std::to_string(view) +
                                                    " out of range: the plugin has " + std::to_string(p->view_count) +
                                                    " views"};
    if (width_px == 0 || height_px == 0 || width_px > 65536 || height_px > 65536)
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, "gazelod: a view's resolution must be 1..65536 pixels on each side"};
    if (p->openxr) {
      p->xr->set_view_resolution(view, static_cast<int>(width_px), static_cast<int>(height_px));
    } else {
      p->data_views[view].width_px = width_px;
      p->data_views[view].height_px = height_px;
    }
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_push_gaze_sample(gzl_plugin p, const gzl_gaze_sample* s) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    need_struct(s, GZL_TYPE_GAZE_SAMPLE, "sample");
    need_time(s->time_ns, "sample->time_ns");
    if (s->flags & ~7u)
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT,
                    "gazelod: sample->flags has bits that are not gzl_gaze_sample_flag_bits"};
    const plugin::PushedSample ps = to_pushed(*s);
    std::string why;
    const auto lock = lock_live(p);
    check_push(p->openxr ? p->xr->push_gaze(ps, why) : p->data->pushed.push(ps, why), why);
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_begin_frame_openxr(gzl_plugin p, int64_t t) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    need_openxr(p, "gzl_begin_frame_openxr");
    need_time(t, "predicted_display_time");
    const auto lock = lock_live(p);
    if (p->frames > 0 && t <= p->pub.info.display_time_ns)
      throw Refusal{GZL_ERROR_TIME_OUT_OF_ORDER,
                    "gazelod: predicted_display_time " + std::to_string(t) +
                        " is not after the last frame's; pass xrWaitFrame's predictedDisplayTime"};
    const FrameDecisions& d = p->xr->begin_frame(static_cast<XrTime>(t));
    publish(p, d, t);
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_begin_frame_data(gzl_plugin p, const gzl_frame_input* in) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    need_struct(in, GZL_TYPE_FRAME_INPUT, "input");
    need_time(in->display_time_ns, "input->display_time_ns");
    if (p->openxr)
      throw Refusal{GZL_ERROR_WRONG_MODE,
                    "gazelod: gzl_begin_frame_data is for a plugin made by gzl_create_data; "
                    "OpenXR mode takes gzl_begin_frame_openxr"};
    bool angular = false, linear = false;
    const plugin::HeadMotion given = to_head(in->head, angular, linear);
    const std::uint32_t n = check_views(in->view_count, in->views, "input->views", true);
    const auto lock = lock_live(p);
    DataFront& f = *p->data;
    if (f.have_frame && in->display_time_ns <= f.last_t_ns)
      throw Refusal{GZL_ERROR_TIME_OUT_OF_ORDER,
                    "gazelod: input->display_time_ns " + std::to_string(in->display_time_ns) +
                        " is not after the last frame's (" + std::to_string(f.last_t_ns) + ")"};
    if (n > 0) {
      p->view_count = n;
      std::copy(in->views, in->views + n, p->data_views.begin());
    }
    plugin::FrameInput frame;
    frame.t_ns = in->display_time_ns;
    frame.head = given.valid ? f.head.from_pose(frame.t_ns, given, angular, linear) : given;
    frame.view_count = p->view_count;
    for (std::uint32_t i = 0; i < p->view_count; ++i) frame.views[i] = to_view_input(p->data_views[i]);
    if (frame.head.valid) f.heads.push(frame.t_ns, frame.head.orientation);
    f.pushed.frame_time(frame.t_ns);
    f.have_frame = true;
    f.last_t_ns = frame.t_ns;
    publish(p, f.core.decide(frame), frame.t_ns);
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_end_frame(gzl_plugin p, double measured_frame_ms) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    if (!std::isfinite(measured_frame_ms) || measured_frame_ms < 0.0 || measured_frame_ms > 60'000.0)
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, "gazelod: measured_frame_ms must be finite, in [0, 60000]"};
    const auto lock = lock_live(p);
    p->core().end_frame(measured_frame_ms);
    return GZL_SUCCESS;
  });
}

}  // extern "C"
