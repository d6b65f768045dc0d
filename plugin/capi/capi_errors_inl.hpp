// SPDX-License-Identifier: Apache-2.0
// guarded(): the template body of plugin/capi/capi_errors.hpp.
#pragma once

#include "plugin/xr_check.hpp"

#include <stdexcept>

namespace gazelod::capi {

template <typename Body>
gzl_result guarded(gzl_plugin p, Body&& body) noexcept {
  try {
    return body();
  } catch (const Refusal& r) {
    return fail(p, r.result, r.message);
  } catch (const XrCallError& e) {
    return fail(p, GZL_ERROR_OPENXR_CALL, prefixed(e.what()));
  } catch (const std::invalid_argument& e) {
    return fail(p, GZL_ERROR_INVALID_ARGUMENT, prefixed(e.what()));
  } catch (const std::out_of_range& e) {
    return fail(p, GZL_ERROR_INVALID_ARGUMENT, prefixed(e.what()));
  } catch (const std::bad_alloc&) {
    return fail(p, GZL_ERROR_OUT_OF_MEMORY, "gazelod: out of memory");
  } catch (const std::exception& e) {
    return fail(p, GZL_ERROR_INTERNAL, std::string("gazelod: internal error (please report): ") + e.what());
  } catch (...) {
    return fail(p, GZL_ERROR_INTERNAL, "gazelod: internal error (please report): unknown exception");
  }
}

}  // namespace gazelod::capi
