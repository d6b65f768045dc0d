// SPDX-License-Identifier: Apache-2.0
// The fuzz entry points: one function per target, plain bytes in. Each returns 0 for every input
// the code under test handles correctly (accepted, or rejected with its documented error type)
// and aborts (through check()) when an invariant is broken; any other exception escapes, which
// libFuzzer reports as a crash and the corpus replay test (tests/faults/) as a failure.
// fuzz_<name>.cpp defines gazelod::fuzz::<name>; with GAZELOD_LIBFUZZER it also defines
// LLVMFuzzerTestOneInput, so the same function runs under libFuzzer and in the gcc build.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace gazelod::fuzz {

int trace_reader(const std::uint8_t* data, std::size_t size);
int scenario(const std::uint8_t* data, std::size_t size);
int hid_reports(const std::uint8_t* data, std::size_t size);
int budget_instance(const std::uint8_t* data, std::size_t size);
int gltf(const std::uint8_t* data, std::size_t size);
int capi(const std::uint8_t* data, std::size_t size);

// An invariant of the code under test; abort (a finding) when it does not hold.
inline void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "gazelod fuzz invariant broken: %s\n", what);
    std::abort();
  }
}

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace gazelod::fuzz

#ifdef GAZELOD_LIBFUZZER
#define GAZELOD_FUZZ_TARGET(fn)                                                       \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
    return gazelod::fuzz::fn(data, size);                                             \
  }
#else
#define GAZELOD_FUZZ_TARGET(fn)
#endif
