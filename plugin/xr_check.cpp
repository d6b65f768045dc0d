// SPDX-License-Identifier: Apache-2.0
#include "plugin/xr_check.hpp"

#include <openxr/openxr_reflection.h>

namespace gazelod {

std::string xr_result_name(XrResult result) {
  switch (result) {
#define GAZELOD_XR_RESULT_CASE(name, value) \
  case name:                                \
    return #name;
    XR_LIST_ENUM_XrResult(GAZELOD_XR_RESULT_CASE)
#undef GAZELOD_XR_RESULT_CASE
        default : break;
  }
  return "XrResult " + std::to_string(static_cast<int>(result));
}

void xr_check(XrResult result, const char* call, const char* context) {
  if (XR_SUCCEEDED(result)) return;
  throw XrCallError(std::string(context) + call + " failed: " + xr_result_name(result), result);
}

}  // namespace gazelod
