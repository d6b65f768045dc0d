// SPDX-License-Identifier: Apache-2.0
// Fuzzes the C ABI (include/gazelod/gazelod.h) as an application drives it: the input bytes are
// a little program of calls on a data-mode plugin (create with views and a configuration from
// the bytes, objects, gaze samples, frames, the readers, shutdown, destroy), with NULL handles,
// NULL pointers, wrong struct types, NaN / infinite / huge numbers and times out of order. A
// model of the plugin (which handles are live, what the last published frame saw) follows
// the calls. Invariants:
//   - every call returns one of gzl_result's named values, never GZL_ERROR_INTERNAL;
//   - a failure leaves a fresh message "gazelod: ..." on the plugin (gzl_get_last_error), and
//     a call with a NULL plugin fails with GZL_ERROR_NULL_HANDLE (and leaves a message on the
//     thread, all but gzl_get_gaze_status, which sets none);
//   - handles are never reused; a removed or never-issued handle is GZL_ERROR_OBJECT_INVALID,
//     a live one is accepted; a failed create / add writes NULL / GZL_NULL_OBJECT;
//   - gzl_get_levels gives each object a level of its chain (0 when added after the last
//     frame, GZL_LEVEL_DISABLED when disabled at it) and writes nothing past a bad handle;
//   - a published frame's info is consistent (index, time, object count, triangle sums) and
//     its numbers finite; the foveal cone is finite, its half-angle in [0, 180];
//   - after gzl_shutdown every call but the readers and gzl_destroy is GZL_ERROR_SHUT_DOWN;
//   - gzl_get_last_error with a small buffer NUL-terminates and writes within it;
//   - no crash, no leak, no undefined behaviour (ASan + UBSan under libFuzzer).
// Work per input is bounded: at most 256 calls, 64 handles per plugin, 4 plugins.
// GAZELOD_FUZZ_TRACE=1 in the environment prints the program an input runs (each call, each
// refusal with its message), to read a reproducer: GAZELOD_FUZZ_TRACE=1 ./fuzz_capi crash-...
#include "fuzz/capi/capi_fuzz.hpp"

namespace gazelod::fuzz {

using namespace capi_fuzz;

int capi(const std::uint8_t* data, std::size_t size) {
  // GAZELOD_FUZZ_TRACE=1: one line per call of the program on stderr (reading a reproducer).
  static const bool trace = std::getenv("GAZELOD_FUZZ_TRACE") != nullptr;
  g_trace = trace;
  Bytes in(data, size);
  Model m;
  int creates = 0;
  for (std::size_t op = 0; op < kMaxOps && !in.empty(); ++op) {
    if (trace && op > 0)
      std::fprintf(stderr, "  -> plugin %s, %zu handles (%zu live), %llu frames%s\n", m.p ? "live" : "NULL",
                   m.objs.size(), m.live_count(), static_cast<unsigned long long>(m.frames),
                   m.shut_down ? ", shut down" : "");
    const std::uint8_t k = in.u8();
    if (trace) std::fprintf(stderr, "op %zu: %s\n", op, op_name(k, m.p != nullptr));
    if (m.p == nullptr || k % 32 == 0) {
      // No plugin yet (or a new one): create, or a call with a NULL plugin.
      if (k % 4 == 3) {
        op_null_handle(in);
      } else if (creates < kMaxCreates) {
        ++creates;
        op_create(in, m);
      } else if (m.p == nullptr) {
        break;
      }
      continue;
    }
    switch (k % 16) {
      case 0:
      case 1:
      case 2:
        op_add(in, m);
        break;
      case 3:
        op_remove(in, m);
        break;
      case 4:
        op_enable(in, m);
        break;
      case 5:
        op_motion(in, m);
        break;
      case 6:
      case 7:
        op_push(in, m);
        break;
      case 8:
      case 9:
      case 10:
        op_frame(in, m);
        break;
      case 11:
        op_levels(in, m);
        break;
      case 12:
        op_readers(in, m);
        break;
      case 13:
        op_last_error(in, m);
        break;
      case 14:
        op_misc(in, m);
        break;
      default:
        if (k % 64 == 15) {  // destroy: the next call makes a new plugin or uses a NULL one
          destroy(m);
        } else {
          op_null_handle(in);
        }
        break;
    }
  }
  destroy(m);
  return 0;
}

}  // namespace gazelod::fuzz

GAZELOD_FUZZ_TARGET(capi)
