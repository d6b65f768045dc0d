// SPDX-License-Identifier: Apache-2.0
// Sends this process a signal once a command running on another thread has put its handler in
// place (run/signals.hpp): sent before, the default action would end the test. Returns false,
// sending nothing, when no handler came within `wait`.
#pragma once

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <thread>

namespace gazelod::test {

inline bool interrupt_when_handled(int signal = SIGINT, std::chrono::milliseconds settle = std::chrono::milliseconds(0),
                                   std::chrono::milliseconds wait = std::chrono::seconds(5)) {
  const auto end = std::chrono::steady_clock::now() + wait;
  for (;;) {
    struct sigaction now {};
    ::sigaction(signal, nullptr, &now);
    if (now.sa_handler != SIG_DFL) break;
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  std::this_thread::sleep_for(settle);  // let the command reach the part under test
  ::kill(::getpid(), signal);
  return true;
}

}  // namespace gazelod::test
