// SPDX-License-Identifier: Apache-2.0
// Sessions and frames: the layer records each session of the instance it emulates for, drops
// its gaze spaces and owed events when it goes, and gives the gaze feed every predicted display
// time (a trace is replayed from the session's first one).
#include "layer/entry_points.hpp"
#include "layer/layer_state.hpp"

#include <algorithm>

namespace gazelod::layer {

XrResult CreateSession(XrInstance instance, const XrSessionCreateInfo* createInfo, XrSession* session) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrCreateSession next = nullptr;
    {
      std::lock_guard lock(layer_state().mutex);
      const auto& e = layer_state().emulated;
      if (!e || e->handle != instance) return XR_ERROR_HANDLE_INVALID;
      next = e->next.CreateSession;
    }
    const XrResult r = next(instance, createInfo, session);
    if (XR_SUCCEEDED(r)) {
      std::lock_guard lock(layer_state().mutex);
      if (auto& e = layer_state().emulated) e->sessions[*session] = SessionRecord{};
    }
    return r;
  });
}

XrResult DestroySession(XrSession session) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrDestroySession next = nullptr;
    {
      std::lock_guard lock(layer_state().mutex);
      auto& e = layer_state().emulated;
      if (!e) return XR_ERROR_HANDLE_INVALID;
      next = e->next.DestroySession;
      // The runtime destroys the session's spaces (the gaze spaces' VIEW spaces among them).
      if (e->sessions.erase(session) != 0) {
        std::erase_if(e->gaze_spaces, [&](const auto& kv) { return kv.second.session == session; });
        std::erase(e->profile_events, session);
      }
    }
    return next(session);
  });
}

XrResult WaitFrame(XrSession session, const XrFrameWaitInfo* frameWaitInfo, XrFrameState* frameState) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrWaitFrame next = nullptr;
    {
      std::lock_guard lock(layer_state().mutex);
      const auto& e = layer_state().emulated;
      if (!e) return XR_ERROR_HANDLE_INVALID;
      next = e->next.WaitFrame;
    }
    // Not under the lock: a paced runtime blocks here, and other threads may locate meanwhile.
    const XrResult r = next(session, frameWaitInfo, frameState);
    if (XR_SUCCEEDED(r) && frameState != nullptr) {
      std::lock_guard lock(layer_state().mutex);
      auto& e = layer_state().emulated;
      if (!e) return r;
      auto it = e->sessions.find(session);
      if (it == e->sessions.end()) return r;
      SessionRecord& s = it->second;
      const auto t = static_cast<std::int64_t>(frameState->predictedDisplayTime);
      if (e->feed) e->feed->on_frame(t, !s.frames_started);
      s.frames_started = true;
      s.last_display_time_ns = t;
    }
    return r;
  });
}

}  // namespace gazelod::layer
