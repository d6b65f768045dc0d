// SPDX-License-Identifier: Apache-2.0
// Event queue, session state transitions and xrPollEvent (see events.hpp).
#include "sim/runtime/events.hpp"
#include "sim/runtime/entry_points.hpp"

#include <algorithm>
#include <cstring>

namespace gazelod::xrrt {
namespace {

constexpr std::size_t kMaxQueuedEvents = 256;

template <class E>
void push(Instance& inst, const E& event) {
  static_assert(sizeof(E) <= sizeof(XrEventDataBuffer));
  XrEventDataBuffer buffer{};
  std::memcpy(&buffer, &event, sizeof(E));
  if (inst.events.size() >= kMaxQueuedEvents) {
    // The specification's way out of a full queue: drop the oldest and report the loss.
    inst.events.pop_front();
    XrEventDataEventsLost lost{XR_TYPE_EVENT_DATA_EVENTS_LOST, nullptr, 1};
    XrEventDataBuffer lost_buffer{};
    std::memcpy(&lost_buffer, &lost, sizeof(lost));
    inst.events.push_front(lost_buffer);
  }
  inst.events.push_back(buffer);
}

template <class E>
E read_event(const XrEventDataBuffer& buffer) {
  E event;
  std::memcpy(&event, &buffer, sizeof(E));
  return event;
}

int rank(XrSessionState s) {
  switch (s) {
    case XR_SESSION_STATE_SYNCHRONIZED:
      return 1;
    case XR_SESSION_STATE_VISIBLE:
      return 2;
    case XR_SESSION_STATE_FOCUSED:
      return 3;
    default:
      return 0;
  }
}

}  // namespace

void change_state(Instance& inst, Session& session, XrSessionState state, XrTime time) {
  // Event times never go backwards, although some come from predicted display times and
  // others from the clock.
  time = std::max(time, session.last_event_time);
  session.last_event_time = time;
  session.state = state;
  XrEventDataSessionStateChanged e{XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED, nullptr, to_handle<XrSession>(session.id),
                                   state, time};
  push(inst, e);
}

void raise_to_focused(Instance& inst, Session& session, XrTime time) {
  if (!session.running || session.exit_requested) return;
  static const XrSessionState kUp[] = {XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_VISIBLE,
                                       XR_SESSION_STATE_FOCUSED};
  for (XrSessionState s : kUp)
    if (rank(session.state) < rank(s)) change_state(inst, session, s, time);
}

void lower_to_stopping(Instance& inst, Session& session, XrTime time) {
  if (session.state == XR_SESSION_STATE_FOCUSED) change_state(inst, session, XR_SESSION_STATE_VISIBLE, time);
  if (session.state == XR_SESSION_STATE_VISIBLE) change_state(inst, session, XR_SESSION_STATE_SYNCHRONIZED, time);
  // STOPPING follows only SYNCHRONIZED (section 9.3's diagram): a running session asked to
  // stop before its first xrWaitFrame passes through SYNCHRONIZED first.
  if (session.state == XR_SESSION_STATE_READY) change_state(inst, session, XR_SESSION_STATE_SYNCHRONIZED, time);
  if (session.state == XR_SESSION_STATE_SYNCHRONIZED) change_state(inst, session, XR_SESSION_STATE_STOPPING, time);
}

void check_scenario_end(Instance& inst, Session& session, XrTime time) {
  if (!session.running || session.exit_requested) return;
  if (SimClock::scenario_ns(time) < inst.simulator->duration_ns()) return;
  session.exit_requested = true;
  session.scenario_ended = true;
  lower_to_stopping(inst, session, time);
}

void discard_session_events(Instance& inst, std::uint64_t session_id) {
  const XrSession doomed = to_handle<XrSession>(session_id);
  std::erase_if(inst.events, [&](const XrEventDataBuffer& buffer) {
    XrSession named = XR_NULL_HANDLE;
    switch (buffer.type) {  // every event type this runtime queues that holds a session
      case XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED:
        named = read_event<XrEventDataSessionStateChanged>(buffer).session;
        break;
      case XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED:
        named = read_event<XrEventDataInteractionProfileChanged>(buffer).session;
        break;
      default:
        return false;
    }
    return named == doomed;
  });
}

void queue_profile_changed(Instance& inst, const Session& session) {
  XrEventDataInteractionProfileChanged e{XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED, nullptr,
                                         to_handle<XrSession>(session.id)};
  push(inst, e);
}

XrResult PollEvent(XrInstance instance, XrEventDataBuffer* eventData) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (eventData == nullptr || eventData->type != XR_TYPE_EVENT_DATA_BUFFER) return XR_ERROR_VALIDATION_FAILURE;
    if (inst->clock.paced()) {
      // Paced, the scenario ends on the wall clock even if the application renders no frame.
      const XrTime now = inst->clock.now();
      for (auto& [id, s] : runtime().sessions.live)
        if (s->instance_id == inst->id) check_scenario_end(*inst, *s, now);
    }
    if (inst->events.empty()) return XR_EVENT_UNAVAILABLE;
    *eventData = inst->events.front();
    inst->events.pop_front();
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::xrrt
