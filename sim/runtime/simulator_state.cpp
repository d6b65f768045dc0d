// SPDX-License-Identifier: Apache-2.0
// XR_GAZELOD_simulator_state: the side channel that reports the simulation's progress and the
// last frame's composition layers (see simulator_state_ext.h).
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/runtime_state.hpp"

namespace gazelod::xrrt {

XrResult GetSimulatorStateGAZELOD(XrSession session, XrSimulatorStateGAZELOD* state) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (state == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const Instance& inst = *instance_of(*s);
    state->frameCount = s->wait_frame_calls;
    state->scenarioTimeBase = kTimeBaseNs;
    state->lastPredictedDisplayTime = s->last_predicted_time;
    state->scenarioDuration = inst.simulator->duration_ns();
    state->scenarioEnded = s->scenario_ended ? XR_TRUE : XR_FALSE;
    state->paced = inst.clock.paced() ? XR_TRUE : XR_FALSE;
    return XR_SUCCESS;
  });
}

XrResult EnumerateSubmittedLayersGAZELOD(XrSession session, uint32_t capacity, uint32_t* count,
                                         XrSubmittedLayerGAZELOD* layers) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    const Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    return two_call(capacity, count, layers, s->last_layers);
  });
}

}  // namespace gazelod::xrrt
