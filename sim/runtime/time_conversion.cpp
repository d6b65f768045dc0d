// SPDX-License-Identifier: Apache-2.0
// XR_KHR_convert_timespec_time: CLOCK_MONOTONIC <-> XrTime on the simulated clock.
#include "auxiliary/time.hpp"
#include "sim/runtime/entry_points.hpp"

#include "sim/runtime/runtime_state.hpp"

namespace gazelod::xrrt {

XrResult ConvertTimespecTimeToTimeKHR(XrInstance instance, const struct timespec* timespecTime, XrTime* time) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (timespecTime == nullptr || time == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const XrTime t = inst->clock.from_monotonic_ns(aux::ns_from_timespec(*timespecTime));
    if (t <= 0) return XR_ERROR_TIME_INVALID;  // before the simulated clock's range
    *time = t;
    return XR_SUCCESS;
  });
}

XrResult ConvertTimeToTimespecTimeKHR(XrInstance instance, XrTime time, struct timespec* timespecTime) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (timespecTime == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (time <= 0) return XR_ERROR_TIME_INVALID;
    const std::int64_t mono = inst->clock.to_monotonic_ns(time);
    if (mono < 0) return XR_ERROR_TIME_INVALID;
    *timespecTime = aux::timespec_from_ns(mono);
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::xrrt
