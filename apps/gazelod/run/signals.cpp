// SPDX-License-Identifier: Apache-2.0
// Stop-on-signal for `gazelod run` (run/signals.hpp). The handler only stores the signal
// number (async-signal-safe); the frame loop reads it between frames.
#include "apps/gazelod/run/signals.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>

namespace gazelod::cli {
namespace {

// TemporaryOnSignal's paths: written by the main thread, `held` set last with release order,
// read by the handler with acquire order. The handler may run on any thread (lavapipe's and the
// runtime's threads do not block the signals), so a lock-free atomic, not a compiler fence.
struct HeldPath {
  char path[4096];
  std::atomic<int> held{0};
};
static_assert(std::atomic<int>::is_always_lock_free, "async-signal-safe only when lock-free");
HeldPath g_temporaries[TemporaryOnSignal::kHeldTemporaries];

volatile std::sig_atomic_t g_stop_signal = 0;
struct sigaction g_previous_int, g_previous_term;
// Stoppers alive: `gazelod eval family` holds one around its seeds' runs, each run its own.
// Only the outermost installs and restores the handlers; an inner one leaves a signal it did
// not act on to the outer one (raising it again would read as the second signal).
int g_depth = 0;

extern "C" void on_stop_signal(int signal) {
  if (g_stop_signal != 0) {  // the second: leave now, as the signal's default would have
    // No temporary left behind (unlink is async-signal-safe).
    for (const HeldPath& t : g_temporaries)
      if (t.held.load(std::memory_order_acquire) != 0) ::unlink(t.path);
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

void TemporaryOnSignal::hold(const std::string& path) {
  release();
  if (path.empty() || path.size() >= sizeof(HeldPath::path)) return;
  for (int i = 0; i < kHeldTemporaries; ++i) {
    if (g_temporaries[i].held.load(std::memory_order_relaxed) != 0) continue;
    std::memcpy(g_temporaries[i].path, path.c_str(), path.size() + 1);
    g_temporaries[i].held.store(1, std::memory_order_release);  // the whole path before `held`
    slot_ = i;
    return;
  }
}

void TemporaryOnSignal::release() {
  if (slot_ < 0) return;
  g_temporaries[slot_].held.store(0, std::memory_order_release);
  slot_ = -1;
}

AtomicRunFile::AtomicRunFile(std::string path) : file_(std::move(path)) {
  temporary_.hold(file_.temp_path());
}

void write_run_file(const std::string& path, std::string_view bytes) {
  AtomicRunFile file(path);
  file.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  file.commit();
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
