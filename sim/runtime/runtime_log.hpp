// SPDX-License-Identifier: Apache-2.0
// Optional runtime log on stderr (GAZELOD_SIM_LOG=1): session states, frame counts at the end
// of a session. Tests read it to see what the runtime itself did.
#pragma once

namespace gazelod::xrrt {

bool runtime_log_enabled();
// printf-style; prefixed with "gazelod_xr_runtime: " and ended with a newline.
void runtime_log(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace gazelod::xrrt
