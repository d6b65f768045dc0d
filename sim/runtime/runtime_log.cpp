// SPDX-License-Identifier: Apache-2.0
// Optional runtime log (see runtime_log.hpp).
#include "sim/runtime/runtime_log.hpp"

#include "sim/runtime/scenario_source.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>

namespace gazelod::xrrt {

bool runtime_log_enabled() {
  // A bad value fails xrCreateInstance (load_runtime_scenario); here it only means "off".
  static const bool enabled = [] {
    try {
      return env_flag("GAZELOD_SIM_LOG", false);
    } catch (const std::exception&) {
      return false;
    }
  }();
  return enabled;
}

void runtime_log(const char* format, ...) {
  if (!runtime_log_enabled()) return;
  char line[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  std::fprintf(stderr, "gazelod_xr_runtime: %s\n", line);
}

}  // namespace gazelod::xrrt
