// SPDX-License-Identifier: Apache-2.0
// xrStringToPath / xrPathToString (OpenXR 1.0 section 6.1); the grammar is in path_table.cpp.
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/path_table.hpp"
#include "sim/runtime/runtime_state.hpp"

namespace gazelod::xrrt {

XrResult StringToPath(XrInstance instance, const char* pathString, XrPath* path) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (pathString == nullptr || path == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (!is_well_formed_path(pathString)) return XR_ERROR_PATH_FORMAT_INVALID;
    *path = inst->paths.intern(pathString);
    return XR_SUCCESS;
  });
}

XrResult PathToString(XrInstance instance, XrPath path, uint32_t bufferCapacityInput, uint32_t* bufferCountOutput,
                      char* buffer) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
    const std::string* s = inst->paths.find(path);
    if (s == nullptr) return XR_ERROR_PATH_INVALID;
    return two_call_string(bufferCapacityInput, bufferCountOutput, buffer, *s);
  });
}

}  // namespace gazelod::xrrt
