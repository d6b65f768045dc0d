// SPDX-License-Identifier: Apache-2.0
// xrWaitFrame (paced to the display rate, or unpaced for offline runs), xrBeginFrame and
// xrEndFrame with the layer checks of OpenXR 1.0 chapter 10 ("Rendering") and 12.
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/events.hpp"
#include "sim/runtime/pose_math.hpp"
#include "sim/runtime/system_info.hpp"

#include <algorithm>
#include <thread>

namespace gazelod::xrrt {
namespace {

XrResult check_sub_image(const Session& s, const XrSwapchainSubImage& sub) {
  const Swapchain* sc = find_swapchain(sub.swapchain);
  if (sc == nullptr || sc->session_id != s.id) return XR_ERROR_HANDLE_INVALID;
  if (!sc->released_once) return XR_ERROR_LAYER_INVALID;
  if (sub.imageArrayIndex >= sc->info.arraySize) return XR_ERROR_VALIDATION_FAILURE;
  const XrRect2Di& r = sub.imageRect;
  if (r.offset.x < 0 || r.offset.y < 0 || r.extent.width <= 0 || r.extent.height <= 0 ||
      std::int64_t(r.offset.x) + r.extent.width > std::int64_t(sc->info.width) ||
      std::int64_t(r.offset.y) + r.extent.height > std::int64_t(sc->info.height))
    return XR_ERROR_SWAPCHAIN_RECT_INVALID;
  return XR_SUCCESS;
}

XrResult check_space(const Session& s, XrSpace space) {
  const Space* sp = find_space(space);
  return (sp == nullptr || sp->session_id != s.id) ? XR_ERROR_HANDLE_INVALID : XR_SUCCESS;
}

XrResult check_layer(const Instance& inst, const Session& s, const XrCompositionLayerBaseHeader* layer) {
  if (layer == nullptr) return XR_ERROR_LAYER_INVALID;
  if (XrResult r = check_space(s, layer->space); r != XR_SUCCESS) return r;
  if (layer->type == XR_TYPE_COMPOSITION_LAYER_PROJECTION) {
    const auto* p = reinterpret_cast<const XrCompositionLayerProjection*>(layer);
    if (p->viewCount != view_count(inst) || p->views == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    for (std::uint32_t i = 0; i < p->viewCount; ++i) {
      const XrCompositionLayerProjectionView& v = p->views[i];
      if (v.type != XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW) return XR_ERROR_VALIDATION_FAILURE;
      if (!is_unit_orientation(v.pose)) return XR_ERROR_POSE_INVALID;
      if (XrResult r = check_sub_image(s, v.subImage); r != XR_SUCCESS) return r;
    }
    return XR_SUCCESS;
  }
  if (layer->type == XR_TYPE_COMPOSITION_LAYER_QUAD) {
    const auto* q = reinterpret_cast<const XrCompositionLayerQuad*>(layer);
    if (q->eyeVisibility > XR_EYE_VISIBILITY_RIGHT) return XR_ERROR_VALIDATION_FAILURE;
    if (!is_unit_orientation(q->pose)) return XR_ERROR_POSE_INVALID;
    return check_sub_image(s, q->subImage);
  }
  return XR_ERROR_LAYER_INVALID;
}

// What XR_GAZELOD_simulator_state reports of a submitted layer: its type, space and pose(s).
// Headless sessions' layers are not checked, so only what is there is read.
XrSubmittedLayerGAZELOD record_layer(const XrCompositionLayerBaseHeader& layer) {
  XrSubmittedLayerGAZELOD out{};
  out.layerType = layer.type;
  out.space = layer.space;
  auto one = [&](const XrPosef& pose) {
    out.poseCount = 1;
    out.poses[0] = pose;
  };
  switch (layer.type) {
    case XR_TYPE_COMPOSITION_LAYER_QUAD:
      one(reinterpret_cast<const XrCompositionLayerQuad&>(layer).pose);
      break;
    case XR_TYPE_COMPOSITION_LAYER_CYLINDER_KHR:
      one(reinterpret_cast<const XrCompositionLayerCylinderKHR&>(layer).pose);
      break;
    case XR_TYPE_COMPOSITION_LAYER_EQUIRECT_KHR:
      one(reinterpret_cast<const XrCompositionLayerEquirectKHR&>(layer).pose);
      break;
    case XR_TYPE_COMPOSITION_LAYER_EQUIRECT2_KHR:
      one(reinterpret_cast<const XrCompositionLayerEquirect2KHR&>(layer).pose);
      break;
    case XR_TYPE_COMPOSITION_LAYER_CUBE_KHR:
      one(XrPosef{reinterpret_cast<const XrCompositionLayerCubeKHR&>(layer).orientation, {0.0f, 0.0f, 0.0f}});
      break;
    case XR_TYPE_COMPOSITION_LAYER_PROJECTION: {
      const auto& p = reinterpret_cast<const XrCompositionLayerProjection&>(layer);
      if (p.views == nullptr) break;
      out.poseCount = std::min<std::uint32_t>(p.viewCount, XR_GAZELOD_SUBMITTED_LAYER_MAX_POSES);
      for (std::uint32_t i = 0; i < out.poseCount; ++i) out.poses[i] = p.views[i].pose;
      break;
    }
    default:
      break;
  }
  return out;
}

}  // namespace

XrResult WaitFrame(XrSession session, const XrFrameWaitInfo* waitInfo, XrFrameState* frameState) {
  return guarded([&] {
    std::int64_t sleep_until_mono_ns = 0;
    std::int64_t vsync = 0;
    {
      std::lock_guard lock(runtime_mutex());
      Session* s = find_session(session);
      if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
      if ((waitInfo != nullptr && waitInfo->type != XR_TYPE_FRAME_WAIT_INFO) || frameState == nullptr ||
          frameState->type != XR_TYPE_FRAME_STATE)
        return XR_ERROR_VALIDATION_FAILURE;
      if (!s->running) return XR_ERROR_SESSION_NOT_RUNNING;
      if (s->lost) return XR_ERROR_SESSION_LOST;
      const SimClock& clock = instance_of(*s)->clock;
      const std::int64_t period = clock.period_ns();
      vsync = s->last_vsync_index + 1;
      if (clock.paced()) {
        // Wake at the next display refresh; a late application skips the ones it missed.
        vsync = std::max(vsync, (clock.now() - kTimeBaseNs) / period + 1);
        sleep_until_mono_ns = clock.to_monotonic_ns(kTimeBaseNs + vsync * period);
      }
      s->last_vsync_index = vsync;
    }
    if (sleep_until_mono_ns != 0) {
      const std::int64_t wait_ns = sleep_until_mono_ns - SimClock::monotonic_ns();
      if (wait_ns > 0) std::this_thread::sleep_for(std::chrono::nanoseconds(wait_ns));
    }
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;  // destroyed by another thread meanwhile
    Instance& inst = *instance_of(*s);
    const std::int64_t period = inst.clock.period_ns();
    const XrTime predicted = kTimeBaseNs + (vsync + 1) * period;  // shown one refresh later
    inst.clock.note_frame(predicted);
    s->last_predicted_time = predicted;
    ++s->waited_frames;
    ++s->wait_frame_calls;
    // The frame loop is now synchronised with the (simulated) compositor.
    if (s->state == XR_SESSION_STATE_READY) raise_to_focused(inst, *s, predicted);
    check_scenario_end(inst, *s, predicted);
    frameState->predictedDisplayTime = predicted;
    frameState->predictedDisplayPeriod = period;
    frameState->shouldRender =
        (s->state == XR_SESSION_STATE_VISIBLE || s->state == XR_SESSION_STATE_FOCUSED) ? XR_TRUE : XR_FALSE;
    return XR_SUCCESS;
  });
}

XrResult BeginFrame(XrSession session, const XrFrameBeginInfo* info) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info != nullptr && info->type != XR_TYPE_FRAME_BEGIN_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (!s->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (s->lost) return XR_ERROR_SESSION_LOST;
    if (s->waited_frames == 0) return XR_ERROR_CALL_ORDER_INVALID;
    --s->waited_frames;
    if (s->frame_begun) return XR_FRAME_DISCARDED;  // the previous begun frame is dropped
    s->frame_begun = true;
    return XR_SUCCESS;
  });
}

XrResult EndFrame(XrSession session, const XrFrameEndInfo* info) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || info->type != XR_TYPE_FRAME_END_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (!s->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (s->lost) return XR_ERROR_SESSION_LOST;
    if (!s->frame_begun) return XR_ERROR_CALL_ORDER_INVALID;
    if (info->displayTime <= 0) return XR_ERROR_TIME_INVALID;
    if (info->environmentBlendMode != XR_ENVIRONMENT_BLEND_MODE_OPAQUE) {
      const bool known = info->environmentBlendMode == XR_ENVIRONMENT_BLEND_MODE_ADDITIVE ||
                         info->environmentBlendMode == XR_ENVIRONMENT_BLEND_MODE_ALPHA_BLEND;
      return known ? XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED : XR_ERROR_VALIDATION_FAILURE;
    }
    if (info->layerCount > kMaxLayerCount) return XR_ERROR_LAYER_LIMIT_EXCEEDED;
    if (info->layerCount > 0 && info->layers == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const Instance& inst = *instance_of(*s);
    // A headless session (XR_MND_headless) shows nothing: it accepts and ignores layers, as the
    // conformance suite expects of it (its headless frames submit layers without swapchains or
    // views).
    if (!s->headless)
      for (std::uint32_t i = 0; i < info->layerCount; ++i)
        if (XrResult r = check_layer(inst, *s, info->layers[i]); r != XR_SUCCESS) return r;
    s->frame_begun = false;
    ++s->frames_submitted;
    s->layers_submitted += info->layerCount;
    s->last_layers.clear();
    for (std::uint32_t i = 0; i < info->layerCount; ++i)
      if (info->layers[i] != nullptr) s->last_layers.push_back(record_layer(*info->layers[i]));
    if (inst.faults.lose_session_at_frame != 0 && s->frames_submitted == inst.faults.lose_session_at_frame) {
      // Injected fault: this frame was shown; the session is lost from here on.
      s->lost = true;
      if (!inst.faults.lose_session_silently)
        change_state(*instance_of(*s), *s, XR_SESSION_STATE_LOSS_PENDING, info->displayTime);
    }
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::xrrt
