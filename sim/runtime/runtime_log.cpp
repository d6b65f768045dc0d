// Optional runtime log (see runtime_log.hpp).
#include "sim/runtime/runtime_log.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace gazelod::xrrt {

bool runtime_log_enabled() {
  static const bool enabled = [] {
    const char* v = std::getenv("GAZELOD_SIM_LOG");
    return v != nullptr && std::strcmp(v, "1") == 0;
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
