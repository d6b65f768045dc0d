// SPDX-License-Identifier: Apache-2.0
// The C ABI fuzzer's parts (fuzz/fuzz_capi.cpp runs them): the input as a stream of choices,
// the model of the plugin the calls are checked against, and the calls themselves, one
// function per kind of call (capi_objects.cpp, capi_frames.cpp, capi_misc.cpp).
#pragma once

#include "fuzz/fuzz_entry.hpp"

#include "gazelod/gazelod.h"

#include <openxr/openxr.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace gazelod::fuzz::capi_fuzz {

inline constexpr std::size_t kMaxOps = 256;
inline constexpr std::size_t kMaxHandles = 64;
inline constexpr int kMaxCreates = 4;
inline constexpr std::int64_t kMs = 1'000'000;

inline bool g_trace = false;  // GAZELOD_FUZZ_TRACE (fuzz_capi.cpp's capi())

// The input, read front to back; past its end every read is 0.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : p_(data), n_(data == nullptr ? 0 : size) {}
  bool empty() const { return i_ >= n_; }
  std::uint8_t u8() { return i_ < n_ ? p_[i_++] : 0; }
  std::uint32_t pick(std::uint32_t n) { return n == 0 ? 0 : u8() % n; }
  // Little-endian; each read is its own statement (the operands of | are unsequenced, and the
  // same bytes must mean the same program under gcc and clang).
  std::uint16_t u16() {
    const std::uint16_t lo = u8();
    return static_cast<std::uint16_t>(lo | (u8() << 8));
  }
  std::uint32_t u32() {
    const std::uint32_t lo = u16();
    return lo | (static_cast<std::uint32_t>(u16()) << 16);
  }
  std::uint64_t u64() {
    const std::uint64_t lo = u32();
    return lo | (static_cast<std::uint64_t>(u32()) << 32);
  }
  bool one_in(std::uint32_t n) { return pick(n) == 0; }

  // A double: mostly plain values around `scale`, sometimes the edge cases (NaN, inf, huge,
  // tiny, signed zero) or any bit pattern.
  double num(double scale) {
    const std::uint8_t k = u8();
    if (k < 160) return static_cast<double>(static_cast<std::int16_t>(u16())) / 32768.0 * scale;
    switch (k % 12) {
      case 0:
        return std::numeric_limits<double>::quiet_NaN();
      case 1:
        return std::numeric_limits<double>::infinity();
      case 2:
        return -std::numeric_limits<double>::infinity();
      case 3:
        return 1e308;
      case 4:
        return -1e308;
      case 5:
        return 0.0;
      case 6:
        return -0.0;
      case 7:
        return std::numeric_limits<double>::denorm_min();
      case 8:
        return 1e-12;
      case 9:
        return scale;
      case 10:
        return -scale;
      default: {
        const std::uint64_t bits = u64();
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
      }
    }
  }
  // A type field: the right one mostly.
  gzl_structure_type type(gzl_structure_type right) {
    if (!one_in(16)) return right;
    return static_cast<gzl_structure_type>(pick(12));
  }

 private:
  const std::uint8_t* p_;
  std::size_t n_, i_ = 0;
};

// ---- the model ------------------------------------------------------------------------------

enum class Seen { added_since, enabled, disabled };  // as of the last published frame

struct Obj {
  gzl_object handle = GZL_NULL_OBJECT;
  bool live = true;
  bool enabled = true;
  Seen seen = Seen::added_since;
  std::vector<std::uint32_t> triangles;  // per level
};

struct Model {
  gzl_plugin p = nullptr;
  bool shut_down = false;
  std::vector<Obj> objs;
  gzl_object max_handle = GZL_NULL_OBJECT;
  std::uint32_t view_count = 0;
  std::uint64_t frames = 0;  // published
  bool have_frame = false;
  std::int64_t last_frame_t = 0;  // of the last published frame
  bool have_sample = false;
  std::int64_t last_sample_t = 0;    // of the last accepted sample
  std::int64_t clock = 1'000 * kMs;  // where the realistic times are

  std::size_t live_count() const {
    return static_cast<std::size_t>(std::count_if(objs.begin(), objs.end(), [](const Obj& o) { return o.live; }));
  }
  Obj* find(gzl_object h) {
    for (Obj& o : objs)
      if (o.handle == h) return &o;
    return nullptr;
  }
};

// ---- results and messages (capi_model.cpp) ------------------------------------------------

std::string last_error(gzl_plugin p);
void check_named(gzl_result r);
// A message any later failure on `p` must replace: a reader's refusal, which changes nothing
// (for a NULL plugin, the calling thread's: a create with a type no other call here passes).
std::string set_sentinel(gzl_plugin p);
// The result of a call on live plugin `p`, with its message checked when it failed.
// `sentinel`: the message set before the call (a failure must replace it).
gzl_result checked(gzl_plugin p, gzl_result r, const std::string& sentinel, bool may_repeat_sentinel = false);

// ---- views, times, handles (capi_model.cpp) ------------------------------------------------

gzl_view good_view(int eye);
// Valid views mostly; else any field from the bytes.
void make_views(Bytes& in, gzl_view* views, std::uint32_t count);
// A frame or sample time: near the clock mostly (frames 11 ms apart, samples 1-8 ms), else
// backwards, repeated, far in the future or at the extremes of int64.
std::int64_t pick_time(Bytes& in, Model& m, bool sample);
// A handle to pass: a live one mostly, else removed, 0, never issued or huge.
gzl_object pick_handle(Bytes& in, const Model& m);
void destroy(Model& m);

// ---- the calls ----------------------------------------------------------------------------

void op_create(Bytes& in, Model& m);  // capi_objects.cpp
void op_add(Bytes& in, Model& m);
void op_remove(Bytes& in, Model& m);
void op_enable(Bytes& in, Model& m);
void op_motion(Bytes& in, Model& m);
void op_push(Bytes& in, Model& m);
// Whether a call that takes a handle should fail on it (-1 unknown, 0 accepted, 1 refused).
void check_handle_result(const Model& m, gzl_object h, gzl_result r, const char* call);
void op_frame(Bytes& in, Model& m);  // capi_frames.cpp
void op_levels(Bytes& in, Model& m);
void op_readers(Bytes& in, Model& m);
void op_last_error(Bytes& in, Model& m);
void op_misc(Bytes& in, Model& m);  // capi_misc.cpp
void op_null_handle(Bytes& in);
// What capi() does for op byte k (for the trace).
const char* op_name(std::uint8_t k, bool have_plugin);

}  // namespace gazelod::fuzz::capi_fuzz
