// SPDX-License-Identifier: Apache-2.0
// The one check for OpenXR results in gazelod: a failed call throws XrCallError naming the
// call and the result's registry name (XR_ERROR_RUNTIME_FAILURE), which needs no instance.
#pragma once

#include <openxr/openxr.h>

#include <stdexcept>
#include <string>

namespace gazelod {

struct XrCallError : std::runtime_error {
  // result: the failing call's result (XR_ERROR_RUNTIME_FAILURE where no OpenXR call failed).
  explicit XrCallError(const std::string& message, XrResult result_ = XR_ERROR_RUNTIME_FAILURE)
      : std::runtime_error(message), result(result_) {}
  XrResult result;
};

// "XR_ERROR_RUNTIME_FAILURE", or "XrResult -123" for a value the registry does not name.
std::string xr_result_name(XrResult result);

// Throws XrCallError("<context><call> failed: <name>") when `result` is a failure.
void xr_check(XrResult result, const char* call, const char* context = "");

}  // namespace gazelod
