// SPDX-License-Identifier: Apache-2.0
// The event queue and the session state machine of OpenXR 1.0 section 9.3 ("Session
// Lifecycle"): IDLE -> READY -> SYNCHRONIZED -> VISIBLE -> FOCUSED, and back down through
// STOPPING to IDLE and EXITING when the application or the scenario's end asks to stop.
#pragma once

#include "sim/runtime/runtime_state.hpp"

namespace gazelod::xrrt {

// Sets the session's state and queues XrEventDataSessionStateChanged.
void change_state(Instance& inst, Session& session, XrSessionState state, XrTime time);
// Walks a running session from its state up to FOCUSED, one event per step.
void raise_to_focused(Instance& inst, Session& session, XrTime time);
// Walks a running session down to STOPPING (the application must then call xrEndSession).
void lower_to_stopping(Instance& inst, Session& session, XrTime time);
// Starts the stop once the scenario's time (predicted or current) reaches its duration.
void check_scenario_end(Instance& inst, Session& session, XrTime time);
// Drops queued events that name a session being destroyed (OpenXR 1.0 section 2.9: the
// runtime discards queued events holding a destroyed handle).
void discard_session_events(Instance& inst, std::uint64_t session_id);
// Queues XrEventDataInteractionProfileChanged.
void queue_profile_changed(Instance& inst, const Session& session);

}  // namespace gazelod::xrrt
