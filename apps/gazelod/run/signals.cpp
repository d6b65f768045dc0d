// SPDX-License-Identifier: Apache-2.0
// Stop-on-signal for `gazelod run` (run/signals.hpp). The handler only stores the signal
// number (async-signal-safe); the frame loop reads it between frames.
#include "apps/gazelod/run/signals.hpp"

#include <csignal>

namespace gazelod::cli {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;
struct sigaction g_previous_int, g_previous_term;
// Stoppers alive: `gazelod eval family` holds one around its seeds' runs, each run its own.
// Only the outermost installs and restores the handlers; an inner one leaves a signal it did
// not act on to the outer one (raising it again would read as the second signal).
int g_depth = 0;

extern "C" void on_stop_signal(int signal) {
  if (g_stop_signal != 0) {  // the second: leave now, as the signal's default would have
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  g_stop_signal = signal;
}

}  // namespace

StopOnSignal::StopOnSignal() {
  if (g_depth++ > 0) return;
  g_stop_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &g_previous_int);
  sigaction(SIGTERM, &sa, &g_previous_term);
}

StopOnSignal::~StopOnSignal() {
  if (--g_depth > 0) return;  // the outer stopper sees the signal, acted on or not
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
  if (g_stop_signal != 0 && !acted_) std::raise(g_stop_signal);  // to whoever handles it now
}

int StopOnSignal::requested() const {
  return g_stop_signal;
}

const char* StopOnSignal::name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
  }
  return "a signal";
}

}  // namespace gazelod::cli
