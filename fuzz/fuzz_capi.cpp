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

namespace gazelod::fuzz {
namespace {

constexpr std::size_t kMaxOps = 256;
constexpr std::size_t kMaxHandles = 64;
constexpr int kMaxCreates = 4;
constexpr std::int64_t kMs = 1'000'000;

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

// ---- results and messages -------------------------------------------------------------------

std::string last_error(gzl_plugin p) {
  std::size_t len = 0;
  check(gzl_get_last_error(p, nullptr, 0, &len) == GZL_SUCCESS, "gzl_get_last_error (length only) failed");
  std::string s(len + 1, '\0');
  std::size_t len2 = 0;
  check(gzl_get_last_error(p, s.data(), s.size(), &len2) == GZL_SUCCESS, "gzl_get_last_error failed");
  check(len2 == len, "gzl_get_last_error: length changed between two calls");
  check(s[len] == '\0' && std::strlen(s.c_str()) == len,
        "gzl_get_last_error: message not NUL-terminated at its length");
  s.resize(len);
  return s;
}

bool g_trace = false;  // GAZELOD_FUZZ_TRACE (capi() below)

void check_named(gzl_result r) {
  check(std::strcmp(gzl_result_to_string(r), "GZL_RESULT_UNKNOWN") != 0, "a call returned an unnamed gzl_result");
  check(r != GZL_ERROR_INTERNAL, "a call returned GZL_ERROR_INTERNAL (a bug in gazelod)");
  check(r != GZL_ERROR_OUT_OF_MEMORY, "a call ran out of memory on a bounded input");
}

// A message any later failure on `p` must replace: a reader's refusal, which changes nothing
// (for a NULL plugin, the calling thread's: a create with a type no other call here passes).
std::string set_sentinel(gzl_plugin p) {
  if (p == nullptr) {
    gzl_data_create_info info{static_cast<gzl_structure_type>(0x7fff0000), nullptr};
    gzl_plugin out = nullptr;
    check(gzl_create_data(&info, &out) == GZL_ERROR_STRUCT_TYPE && out == nullptr,
          "gzl_create_data accepted a wrong struct type");
    return last_error(nullptr);
  }
  const gzl_object none = GZL_NULL_OBJECT;
  std::uint8_t level = 0;
  check(gzl_get_levels(p, 1, &none, &level) == GZL_ERROR_OBJECT_INVALID, "gzl_get_levels accepted object 0");
  return last_error(p);
}

// The result of a call on live plugin `p`, with its message checked when it failed.
// `sentinel`: the message set before the call (a failure must replace it).
gzl_result checked(gzl_plugin p, gzl_result r, const std::string& sentinel, bool may_repeat_sentinel = false) {
  check_named(r);
  if (r == GZL_SUCCESS) return r;
  const std::string m = last_error(p);
  if (g_trace) std::fprintf(stderr, "  %s: %s\n", gzl_result_to_string(r), m.c_str());
  check(!m.empty(), "a failed call left no message");
  check(m.rfind("gazelod:", 0) == 0, "a failure's message does not start with \"gazelod:\"");
  check(may_repeat_sentinel || m != sentinel, "a failed call did not set its own message");
  return r;
}

// ---- views and configuration ----------------------------------------------------------------

gzl_view good_view(int eye) {
  gzl_view v{};
  v.fov = {-0.87, 0.75, 0.79, -0.8};
  if (eye == 1) v.fov = {-0.75, 0.87, 0.79, -0.8};
  v.position_in_head_m = {eye == 0 ? -0.032 : 0.032, 0.0, 0.0};
  v.width_px = 1920;
  v.height_px = 1832;
  return v;
}

// Valid views mostly; else any field from the bytes.
void make_views(Bytes& in, gzl_view* views, std::uint32_t count) {
  for (std::uint32_t i = 0; i < count; ++i) {
    views[i] = good_view(static_cast<int>(i % 2));
    if (!in.one_in(4)) continue;
    gzl_view& v = views[i];
    switch (in.pick(6)) {
      case 0:
        v.fov = {in.num(3.2), in.num(3.2), in.num(3.2), in.num(3.2)};
        break;
      case 1:
        v.width_px = in.one_in(2) ? in.u16() : in.u32();
        v.height_px = in.one_in(2) ? in.u16() : in.u32();
        break;
      case 2:
        v.orientation_in_head = {in.num(1.0), in.num(1.0), in.num(1.0), in.num(1.0)};
        break;
      case 3:
        v.position_in_head_m = {in.num(0.1), in.num(0.1), in.num(0.1)};
        break;
      case 4:
        v.fov.angle_left = v.fov.angle_right;
        break;  // zero width
      default:
        v.fov = {-1.6, 1.6, 1.6, -1.6};
        break;  // past 180 degrees
    }
  }
}

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

// A frame or sample time: near the clock mostly (frames 11 ms apart, samples 1-8 ms), else
// backwards, repeated, far in the future or at the extremes of int64.
std::int64_t pick_time(Bytes& in, Model& m, bool sample) {
  const std::uint8_t k = in.u8();
  if (k < 200) {
    const std::int64_t jitter = static_cast<std::int64_t>(in.pick(5)) - 2;
    const std::int64_t step = sample ? (1 + static_cast<std::int64_t>(in.pick(8))) * kMs : 11 * kMs + jitter * kMs / 4;
    m.clock += step;
    return m.clock;
  }
  switch (k % 8) {
    case 0:
      return m.clock;
    case 1:
      return m.clock - static_cast<std::int64_t>(in.u16()) * kMs;
    case 2:
      return m.clock + 2'000 * kMs;
    case 3:
      return std::numeric_limits<std::int64_t>::max() - static_cast<std::int64_t>(in.u8());
    case 4:
      return std::numeric_limits<std::int64_t>::min() + static_cast<std::int64_t>(in.u8());
    case 5:
      return 0;
    case 6:
      return -static_cast<std::int64_t>(in.u32());
    default:
      return static_cast<std::int64_t>(in.u64());
  }
}

// A handle to pass: a live one mostly, else removed, 0, never issued or huge.
gzl_object pick_handle(Bytes& in, const Model& m) {
  const std::uint8_t k = in.u8();
  if (!m.objs.empty() && k < 200) return m.objs[in.pick(static_cast<std::uint32_t>(m.objs.size()))].handle;
  switch (k % 4) {
    case 0:
      return GZL_NULL_OBJECT;
    case 1:
      return m.max_handle + 1;
    case 2:
      return std::numeric_limits<gzl_object>::max();
    default:
      return in.u64();
  }
}

// ---- the calls ------------------------------------------------------------------------------

void destroy(Model& m) {
  gzl_destroy(m.p);
  m = Model{};
}

const XrResult kFakeFailure = XR_ERROR_FUNCTION_UNSUPPORTED;
XRAPI_ATTR XrResult XRAPI_CALL fake_get_instance_proc_addr(XrInstance, const char*, PFN_xrVoidFunction* function) {
  if (function != nullptr) *function = nullptr;
  return kFakeFailure;
}

// gzl_create_data (or, now and then, gzl_create_openxr over a loader that has nothing).
void op_create(Bytes& in, Model& m) {
  destroy(m);
  const std::string sentinel = set_sentinel(nullptr);
  if (in.one_in(16)) {
    gzl_openxr_create_info info{in.type(GZL_TYPE_OPENXR_CREATE_INFO), nullptr};
    info.get_instance_proc_addr =
        in.one_in(4) ? nullptr : reinterpret_cast<gzl_void_function>(&fake_get_instance_proc_addr);
    info.instance = in.u8();
    info.session = in.u8();
    info.base_space = in.u8();
    info.view_configuration_type = in.one_in(2) ? in.pick(4) : in.u32();
    info.gaze_input = static_cast<gzl_gaze_input>(in.pick(6));
    info.gaze_space = in.u8();
    gzl_plugin p = reinterpret_cast<gzl_plugin>(&m);  // must be overwritten
    const gzl_result r = checked(nullptr, gzl_create_openxr(in.one_in(16) ? nullptr : &info, &p), sentinel);
    check(r != GZL_SUCCESS, "gzl_create_openxr succeeded without an OpenXR runtime");
    check(p == nullptr, "a failed gzl_create_openxr left *plugin non-NULL");
    return;
  }

  // Views: 1, 2 or 4 valid ones mostly.
  static constexpr std::uint32_t kCounts[] = {2, 2, 2, 1, 4, 0, 3, 5};
  std::uint32_t count = kCounts[in.pick(8)];
  if (in.one_in(32)) count = in.u32();
  gzl_view views[GZL_MAX_VIEWS];
  make_views(in, views, std::min<std::uint32_t>(count, GZL_MAX_VIEWS));
  gzl_config config{in.type(GZL_TYPE_CONFIG), nullptr};
  const bool use_config = in.one_in(2);
  if (use_config) {
    config.disabled_criteria = in.one_in(8) ? in.u32() : in.pick(8);
    config.disable_switch_policy = in.pick(2);
    const std::uint8_t k = in.u8();
    config.frame_budget_ms = k < 128 ? 0.0 : k < 200 ? 2.0 + k % 8 : in.num(2000.0);
    if (in.one_in(4)) config.gaze_accuracy_deg = in.num(50.0);
    if (in.one_in(4)) config.head_fixed_cone_deg = in.num(200.0);
    if (in.one_in(4)) config.gaze_silence_timeout_s = in.num(4000.0);
    if (in.one_in(4)) config.max_gaze_sample_age_s = in.num(1.5);
    static const char* const kPresets[] = {nullptr, "", "questpro", "no-such-hmd"};
    config.hmd_preset = kPresets[in.pick(4)];
  }
  gzl_data_create_info info{in.type(GZL_TYPE_DATA_CREATE_INFO), nullptr};
  info.view_count = count;
  info.views = in.one_in(32) ? nullptr : views;
  info.config = use_config ? &config : nullptr;
  if (count > GZL_MAX_VIEWS) info.views = nullptr;  // never let it read past the array

  const bool null_out = in.one_in(32), null_info = in.one_in(32);
  gzl_plugin p = reinterpret_cast<gzl_plugin>(&m);
  const gzl_result r =
      checked(nullptr, gzl_create_data(null_info ? nullptr : &info, null_out ? nullptr : &p), sentinel);
  if (null_out) {
    check(r == GZL_ERROR_NULL_POINTER, "gzl_create_data with a NULL output did not fail with GZL_ERROR_NULL_POINTER");
    return;
  }
  if (r != GZL_SUCCESS) {
    check(p == nullptr, "a failed gzl_create_data left *plugin non-NULL");
    return;
  }
  check(p != nullptr, "gzl_create_data succeeded with a NULL plugin");
  m.p = p;
  m.view_count = count;
}

void op_add(Bytes& in, Model& m) {
  if (m.objs.size() >= kMaxHandles) return;
  gzl_object_desc d{in.type(GZL_TYPE_OBJECT_DESC), nullptr};
  const bool plain = !in.one_in(4);
  d.center_m = {in.num(40.0), plain ? 1.6 : in.num(10.0), plain ? -2.0 - in.pick(40) : in.num(50.0)};
  d.radius_m = plain ? 0.05 + in.pick(20) * 0.05 : in.num(10.0);
  if (in.one_in(3)) d.velocity_m_s = {in.num(3.0), in.num(3.0), in.num(3.0)};
  d.importance = plain ? in.pick(5) * 0.25 : in.num(1.5);
  // Any value the enum can hold (C++ makes loading one outside 0..GZL_LEVEL_METRIC_MAX_ENUM UB).
  d.metric = static_cast<gzl_level_metric>(in.one_in(16) ? in.u32() & 0x7fffffffu : in.pick(4));
  std::uint32_t n = 1 + in.pick(6);
  if (in.one_in(32)) n = in.one_in(2) ? 0 : 250 + in.pick(10);
  d.level_count = n;
  std::vector<gzl_level> levels(std::min<std::uint32_t>(n, 260));
  double value = 0.0;
  std::uint32_t tris = 20'000;
  for (gzl_level& l : levels) {
    // Coarser levels: larger errors (metres, pixels), lower removed frequencies, smaller
    // screen shares.
    if (d.metric == GZL_LEVEL_SCREEN_HEIGHT_SHARE)
      value = value == 0.0 ? 0.8 : value * 0.5;
    else if (d.metric == GZL_LEVEL_REMOVED_CYCLES_PER_DIAMETER)
      value = value == 0.0 ? 256.0 : value * 0.25;
    else
      value = value == 0.0 ? 0.001 : value * 4.0;
    l.value = in.one_in(8) ? in.num(10.0) : value;
    l.triangles = in.one_in(8) ? in.u32() : tris;
    tris = std::max<std::uint32_t>(tris / 4, 12);
  }
  d.levels = in.one_in(32) ? nullptr : levels.data();
  if (levels.size() < n) d.levels = nullptr;  // never let it read past the array

  const bool null_out = in.one_in(32);
  const std::string sentinel = set_sentinel(m.p);
  gzl_object h = 12345;
  const gzl_result r =
      checked(m.p, gzl_add_object(m.p, in.one_in(32) ? nullptr : &d, null_out ? nullptr : &h), sentinel);
  if (m.shut_down)
    check(r == GZL_ERROR_SHUT_DOWN, "gzl_add_object after gzl_shutdown did not fail with GZL_ERROR_SHUT_DOWN");
  if (null_out) {
    check(r != GZL_SUCCESS, "gzl_add_object with a NULL output succeeded");
    return;
  }
  if (r != GZL_SUCCESS) {
    check(m.shut_down || h == GZL_NULL_OBJECT, "a failed gzl_add_object did not write GZL_NULL_OBJECT");
    return;
  }
  check(h != GZL_NULL_OBJECT && h > m.max_handle, "gzl_add_object reused a handle (or gave 0)");
  m.max_handle = h;
  Obj o;
  o.handle = h;
  for (const gzl_level& l : levels) o.triangles.push_back(l.triangles);
  m.objs.push_back(std::move(o));
}

// Whether a call that takes a handle should fail on it (-1 unknown, 0 accepted, 1 refused).
void check_handle_result(const Model& m, gzl_object h, gzl_result r, const char* call) {
  const Obj* o = nullptr;
  for (const Obj& x : m.objs)
    if (x.handle == h) o = &x;
  if (m.shut_down) {
    check(r == GZL_ERROR_SHUT_DOWN,
          (std::string(call) + " after gzl_shutdown did not fail with GZL_ERROR_SHUT_DOWN").c_str());
    return;
  }
  if (o == nullptr || !o->live)
    check(r == GZL_ERROR_OBJECT_INVALID,
          (std::string(call) + " with a removed or never-issued handle did not fail with GZL_ERROR_OBJECT_INVALID")
              .c_str());
  else
    check(r == GZL_SUCCESS, (std::string(call) + " refused a live handle").c_str());
}

void op_remove(Bytes& in, Model& m) {
  const gzl_object h = pick_handle(in, m);
  const std::string sentinel = set_sentinel(m.p);
  const gzl_result r = checked(m.p, gzl_remove_object(m.p, h), sentinel);
  check_handle_result(m, h, r, "gzl_remove_object");
  if (r == GZL_SUCCESS) m.find(h)->live = false;
}

void op_enable(Bytes& in, Model& m) {
  const gzl_object h = pick_handle(in, m);
  const gzl_bool32 on = in.one_in(8) ? in.u32() : in.pick(2);
  const std::string sentinel = set_sentinel(m.p);
  const gzl_result r = checked(m.p, gzl_set_object_enabled(m.p, h, on), sentinel);
  check_handle_result(m, h, r, "gzl_set_object_enabled");
  if (r == GZL_SUCCESS) m.find(h)->enabled = on != 0;
}

void op_motion(Bytes& in, Model& m) {
  const gzl_object h = pick_handle(in, m);
  const bool wild = in.one_in(4);
  const gzl_vec3 c{in.num(40.0), wild ? in.num(10.0) : 1.6, wild ? in.num(50.0) : -2.0 - in.pick(40)};
  const gzl_vec3 v =
      wild ? gzl_vec3{in.num(100.0), in.num(100.0), in.num(100.0)} : gzl_vec3{in.num(2.0), 0.0, in.num(2.0)};
  const bool null_c = in.one_in(32), null_v = in.one_in(32);
  const std::string sentinel = set_sentinel(m.p);
  const gzl_result r =
      checked(m.p, gzl_set_object_motion(m.p, h, null_c ? nullptr : &c, null_v ? nullptr : &v), sentinel);
  const bool finite = std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(v.x) &&
                      std::isfinite(v.y) && std::isfinite(v.z);
  if (!null_c && !null_v && finite) check_handle_result(m, h, r, "gzl_set_object_motion");
  if (null_c || null_v) check(r != GZL_SUCCESS, "gzl_set_object_motion accepted a NULL vector");
  if (!finite) check(r != GZL_SUCCESS, "gzl_set_object_motion accepted a non-finite vector");
}

void op_push(Bytes& in, Model& m) {
  gzl_gaze_sample s{in.type(GZL_TYPE_GAZE_SAMPLE), nullptr};
  s.time_ns = pick_time(in, m, true);
  const bool plain = !in.one_in(4);
  if (plain) {
    s.direction = {in.num(0.3), in.num(0.3), -1.0};
  } else {
    s.direction = {in.num(2.0), in.num(2.0), in.num(2.0)};
    s.origin_m = {in.num(0.1), in.num(0.1), in.num(0.1)};
  }
  if (in.one_in(16)) {
    s.flags = in.u32();
  } else {
    s.flags = in.one_in(8) ? 0u : 1u;  // a blink now and then
    s.flags |= in.pick(4) << 1;
  }
  if (s.flags & GZL_GAZE_SAMPLE_HEAD_ORIENTATION)
    s.head_orientation =
        plain ? gzl_quat{0.0, in.num(0.2), 0.0, 1.0} : gzl_quat{in.num(1.0), in.num(1.0), in.num(1.0), in.num(1.0)};
  const bool null_sample = in.one_in(64);
  const std::string sentinel = set_sentinel(m.p);
  const gzl_result r = checked(m.p, gzl_push_gaze_sample(m.p, null_sample ? nullptr : &s), sentinel);
  if (m.shut_down)
    check(r == GZL_ERROR_SHUT_DOWN, "gzl_push_gaze_sample after gzl_shutdown did not fail with GZL_ERROR_SHUT_DOWN");
  if (r != GZL_SUCCESS) return;
  check(!m.have_sample || s.time_ns >= m.last_sample_t,
        "gzl_push_gaze_sample accepted a sample older than the last one");
  m.have_sample = true;
  m.last_sample_t = s.time_ns;
}

void check_frame_info(Model& m, std::int64_t t) {
  gzl_frame_info info{GZL_TYPE_FRAME_INFO, nullptr};
  check(gzl_get_frame_info(m.p, &info) == GZL_SUCCESS, "gzl_get_frame_info failed after a frame");
  check(info.type == GZL_TYPE_FRAME_INFO && info.next == nullptr, "gzl_get_frame_info overwrote type or next");
  check(info.frame_index == m.frames, "frame_info.frame_index is not the number of frames published");
  check(info.display_time_ns == t, "frame_info.display_time_ns is not the frame's");
  check(info.object_count == m.live_count(), "frame_info.object_count is not the number of live objects");
  check(std::isfinite(info.gaze_uncertainty_deg) && info.gaze_uncertainty_deg >= 0.0,
        "frame_info.gaze_uncertainty_deg not finite and >= 0");
  check(std::isfinite(info.xi_cpd) && info.xi_cpd > 0.0, "frame_info.xi_cpd not finite and > 0");
  const gzl_vec3& g = info.gaze_direction_base;
  check(std::isfinite(g.x) && std::isfinite(g.y) && std::isfinite(g.z), "frame_info.gaze_direction_base not finite");
  const double len = std::sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
  check(std::abs(len - 1.0) < 1e-6, "frame_info.gaze_direction_base is not a unit vector");
  check(info.gaze_source <= GZL_GAZE_SOURCE_PUSHED, "frame_info.gaze_source is not a gzl_gaze_source");
  check(info.eye_motion <= GZL_EYE_LOSS, "frame_info.eye_motion is not a gzl_eye_motion");

  // Every live object's level, and the triangle sums from them.
  std::vector<gzl_object> handles;
  for (const Obj& o : m.objs)
    if (o.live) handles.push_back(o.handle);
  std::vector<std::uint8_t> levels(handles.size(), 0);
  if (!handles.empty())
    check(gzl_get_levels(m.p, static_cast<std::uint32_t>(handles.size()), handles.data(), levels.data()) == GZL_SUCCESS,
          "gzl_get_levels refused the live handles");
  std::uint64_t drawn = 0, full = 0;
  for (std::size_t i = 0; i < handles.size(); ++i) {
    const Obj& o = *m.find(handles[i]);
    if (!o.enabled) {
      check(levels[i] == GZL_LEVEL_DISABLED, "a disabled object's level is not GZL_LEVEL_DISABLED");
      continue;
    }
    check(levels[i] < o.triangles.size(), "an object's level is past its chain");
    drawn += o.triangles[levels[i]];
    full += o.triangles[0];
  }
  check(info.triangles_drawn == drawn, "frame_info.triangles_drawn is not the sum of the drawn levels' triangles");
  check(info.triangles_full == full, "frame_info.triangles_full is not the sum of the enabled objects' level 0");

  gzl_frame_record rec{GZL_TYPE_FRAME_RECORD, nullptr};
  check(gzl_get_frame_record(m.p, &rec) == GZL_SUCCESS, "gzl_get_frame_record failed after a frame");
  check(rec.display_time_ns == t, "frame_record.display_time_ns is not the frame's");
  check(rec.view_count == m.view_count, "frame_record.view_count is not the frame's");
  for (std::uint32_t v = 0; v < rec.view_count; ++v) {
    gzl_foveal_cone c{GZL_TYPE_FOVEAL_CONE, nullptr};
    check(gzl_get_foveal_cone(m.p, v, &c) == GZL_SUCCESS, "gzl_get_foveal_cone refused a view of the frame");
    const gzl_vec3& d = c.direction_in_view;
    check(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z), "foveal cone direction not finite");
    check(std::isfinite(c.half_angle_deg) && c.half_angle_deg >= 0.0 && c.half_angle_deg <= 180.0,
          "foveal cone half-angle not in [0, 180]");
    check(std::isfinite(c.center_u) && std::isfinite(c.center_v), "foveal cone centre not finite");
  }
}

void op_frame(Bytes& in, Model& m) {
  gzl_frame_input f{in.type(GZL_TYPE_FRAME_INPUT), nullptr};
  f.display_time_ns = pick_time(in, m, false);
  gzl_head_pose& h = f.head;
  const std::uint8_t k = in.u8();
  if (k < 200) {  // a plausible head: small turns, standing
    const double yaw = in.num(0.5);
    h.orientation = {0.0, std::sin(yaw / 2), 0.0, std::cos(yaw / 2)};
    h.position_m = {in.num(0.2), 1.6, in.num(0.2)};
    h.angular_velocity_rad_s = {0.0, in.num(2.0), 0.0};
    h.flags = 1u | (in.pick(4) << 1);
  } else {
    h.orientation = {in.num(1.0), in.num(1.0), in.num(1.0), in.num(1.0)};
    h.position_m = {in.num(1e3), in.num(1e3), in.num(1e3)};
    h.angular_velocity_rad_s = {in.num(50.0), in.num(50.0), in.num(50.0)};
    h.linear_velocity_m_s = {in.num(50.0), in.num(50.0), in.num(50.0)};
    h.flags = in.one_in(4) ? in.u32() : in.pick(8);
  }
  gzl_view views[GZL_MAX_VIEWS];
  std::uint32_t count = 0;
  const std::uint8_t vk = in.u8();
  if (vk >= 224) {  // new views (a resolution change, a garbage count)
    static constexpr std::uint32_t kCounts[] = {1, 2, 4, 3, 2, 2, 4, 7};
    count = kCounts[in.pick(8)];
    make_views(in, views, std::min<std::uint32_t>(count, GZL_MAX_VIEWS));
  }
  f.view_count = count;
  f.views = count > GZL_MAX_VIEWS || in.one_in(64) ? nullptr : views;
  const bool null_input = in.one_in(64);
  const std::string sentinel = set_sentinel(m.p);
  const gzl_result r = checked(m.p, gzl_begin_frame_data(m.p, null_input ? nullptr : &f), sentinel);
  if (m.shut_down)
    check(r == GZL_ERROR_SHUT_DOWN, "gzl_begin_frame_data after gzl_shutdown did not fail with GZL_ERROR_SHUT_DOWN");
  if (r != GZL_SUCCESS) return;
  check(!m.have_frame || f.display_time_ns > m.last_frame_t,
        "gzl_begin_frame_data accepted a frame not after the last one");
  m.have_frame = true;
  m.last_frame_t = f.display_time_ns;
  ++m.frames;
  if (count > 0) m.view_count = count;
  for (Obj& o : m.objs) o.seen = o.enabled ? Seen::enabled : Seen::disabled;
  check_frame_info(m, f.display_time_ns);
}

void op_levels(Bytes& in, Model& m) {
  const std::uint32_t n = in.one_in(16) ? 0 : 1 + in.pick(8);
  std::vector<gzl_object> handles(n);
  for (gzl_object& h : handles) h = pick_handle(in, m);
  constexpr std::uint8_t kUntouched = 0xA5;
  std::vector<std::uint8_t> levels(n, kUntouched);
  const bool null_objects = n > 0 && in.one_in(32), null_levels = n > 0 && in.one_in(32);
  const std::string sentinel = set_sentinel(m.p);
  const gzl_result r = checked(
      m.p, gzl_get_levels(m.p, n, null_objects ? nullptr : handles.data(), null_levels ? nullptr : levels.data()),
      sentinel, true);
  if (null_objects || null_levels) {
    check(r == GZL_ERROR_NULL_POINTER, "gzl_get_levels with NULL arrays did not fail with GZL_ERROR_NULL_POINTER");
    return;
  }
  // The first bad handle stops it; everything before it is written, nothing after.
  std::size_t bad = n;
  for (std::size_t i = 0; i < n && bad == n; ++i) {
    const Obj* o = m.find(handles[i]);
    if (o == nullptr || !o->live) bad = i;
  }
  check((r == GZL_SUCCESS) == (bad == n), "gzl_get_levels: result does not match the handles' validity");
  if (r != GZL_SUCCESS) check(r == GZL_ERROR_OBJECT_INVALID, "gzl_get_levels refused a handle with the wrong code");
  for (std::size_t i = 0; i < n; ++i) {
    if (i > bad) {
      check(levels[i] == kUntouched, "gzl_get_levels wrote past the bad handle");
      continue;
    }
    if (i == bad) continue;  // nothing written there either, but it may hold anything of ours
    const Obj& o = *m.find(handles[i]);
    switch (o.seen) {
      case Seen::added_since:
        check(levels[i] == 0, "an object added after the last frame does not read level 0");
        break;
      case Seen::disabled:
        check(levels[i] == GZL_LEVEL_DISABLED, "an object disabled at the last frame is not GZL_LEVEL_DISABLED");
        break;
      case Seen::enabled:
        check(levels[i] < o.triangles.size(), "an object's level is past its chain");
        break;
    }
  }
}

void op_readers(Bytes& in, Model& m) {
  const std::string sentinel = set_sentinel(m.p);
  switch (in.pick(4)) {
    case 0: {
      gzl_frame_info info{in.type(GZL_TYPE_FRAME_INFO), nullptr};
      const gzl_result r = checked(m.p, gzl_get_frame_info(m.p, in.one_in(32) ? nullptr : &info), sentinel);
      if (r == GZL_SUCCESS) {
        check(info.frame_index == m.frames, "frame_info.frame_index is not the number of frames published");
        if (m.frames > 0)
          check(info.display_time_ns == m.last_frame_t, "frame_info.display_time_ns is not the last frame's");
      }
      break;
    }
    case 1: {
      const std::uint32_t view = in.one_in(8) ? in.u32() : in.pick(5);
      gzl_foveal_cone cone{in.type(GZL_TYPE_FOVEAL_CONE), nullptr};
      const gzl_result r = checked(m.p, gzl_get_foveal_cone(m.p, view, in.one_in(32) ? nullptr : &cone), sentinel);
      if (r == GZL_SUCCESS) {
        check(m.frames > 0 && view < m.view_count, "gzl_get_foveal_cone accepted a view the last frame did not have");
        check(std::isfinite(cone.half_angle_deg) && cone.half_angle_deg <= 180.0,
              "foveal cone half-angle not in [0, 180]");
      }
      break;
    }
    case 2: {
      gzl_frame_record rec{in.type(GZL_TYPE_FRAME_RECORD), nullptr};
      const gzl_result r = checked(m.p, gzl_get_frame_record(m.p, in.one_in(32) ? nullptr : &rec), sentinel);
      if (r == GZL_SUCCESS && m.frames > 0)
        check(rec.display_time_ns == m.last_frame_t, "frame_record is not the last frame's");
      break;
    }
    default: {
      const std::size_t cap = in.pick(12);
      std::unique_ptr<char[]> buf(cap > 0 ? new char[cap] : nullptr);
      std::size_t len = 0;
      const bool want_len = !in.one_in(4);
      check_named(gzl_get_gaze_status(m.p, buf.get(), cap, want_len ? &len : nullptr));
      if (cap > 0) check(std::memchr(buf.get(), '\0', cap) != nullptr, "gzl_get_gaze_status did not NUL-terminate");
      break;
    }
  }
}

// gzl_get_last_error into a buffer of exactly `cap` bytes (ASan sees a write past it).
void op_last_error(Bytes& in, Model& m) {
  const gzl_plugin p = in.one_in(4) ? nullptr : m.p;
  const std::string full = last_error(p);
  const std::size_t cap = in.pick(24);
  std::unique_ptr<char[]> buf(cap > 0 ? new char[cap] : nullptr);
  if (cap > 0) std::memset(buf.get(), 'x', cap);
  std::size_t len = 12345;
  const bool want_len = !in.one_in(4);
  check(gzl_get_last_error(p, buf.get(), cap, want_len ? &len : nullptr) == GZL_SUCCESS, "gzl_get_last_error failed");
  if (want_len) check(len == full.size(), "gzl_get_last_error: *length is not the message's length");
  if (cap > 0) {
    const std::size_t n = std::min(full.size(), cap - 1);
    check(buf[n] == '\0', "gzl_get_last_error: not NUL-terminated at min(length, capacity - 1)");
    check(std::memcmp(buf.get(), full.data(), n) == 0, "gzl_get_last_error: the copy is not the message's start");
  }
}

void op_misc(Bytes& in, Model& m) {
  const std::string sentinel = set_sentinel(m.p);
  switch (in.pick(6)) {
    case 0: {
      const double ms = in.one_in(4) ? in.num(1e5) : 5.0 + in.pick(20);
      const gzl_result r = checked(m.p, gzl_end_frame(m.p, ms), sentinel);
      if (m.shut_down)
        check(r == GZL_ERROR_SHUT_DOWN, "gzl_end_frame after gzl_shutdown did not fail with GZL_ERROR_SHUT_DOWN");
      if (!std::isfinite(ms) || ms < 0.0) check(r != GZL_SUCCESS, "gzl_end_frame accepted a bad time");
      break;
    }
    case 1: {
      const std::uint32_t view = in.pick(6), w = in.one_in(4) ? in.u32() : 1 + in.u16(),
                          h = in.one_in(4) ? in.u32() : 1 + in.u16();
      const gzl_result r = checked(m.p, gzl_set_view_resolution(m.p, view, w, h), sentinel);
      if (r == GZL_SUCCESS)
        check(view < m.view_count, "gzl_set_view_resolution accepted a view the plugin does not have");
      break;
    }
    case 2: {
      const auto state = static_cast<std::int32_t>(in.one_in(4) ? in.u32() : in.pick(10));
      const gzl_result r = checked(m.p, gzl_on_session_state(m.p, state, pick_time(in, m, true)), sentinel);
      if (m.shut_down)
        check(r == GZL_ERROR_SHUT_DOWN,
              "gzl_on_session_state after gzl_shutdown did not fail with GZL_ERROR_SHUT_DOWN");
      break;
    }
    case 3: {  // OpenXR-mode calls on a data-mode plugin
      gzl_result r = GZL_SUCCESS;
      gzl_gaze_binding b{GZL_TYPE_GAZE_BINDING, nullptr};
      switch (in.pick(4)) {
        case 0:
          r = gzl_begin_frame_openxr(m.p, pick_time(in, m, false));
          break;
        case 1:
          r = gzl_set_base_space(m.p, in.u64());
          break;
        case 2:
          r = gzl_action_sets_attached(m.p);
          break;
        default:
          r = gzl_get_gaze_binding(m.p, &b);
          break;
      }
      checked(m.p, r, sentinel);
      check(r == (m.shut_down ? GZL_ERROR_SHUT_DOWN : GZL_ERROR_WRONG_MODE),
            "an OpenXR-mode call on a data-mode plugin was not refused");
      break;
    }
    case 4: {
      const gzl_result r = checked(m.p, gzl_shutdown(m.p), sentinel);
      check(r == GZL_SUCCESS, "gzl_shutdown failed");
      m.shut_down = true;
      break;
    }
    default: {
      const std::uint32_t v = gzl_version();
      check(GZL_VERSION_MAJOR(v) == GZL_VERSION_MAJOR(GZL_HEADER_VERSION), "gzl_version's major is not the header's");
      const auto any = static_cast<gzl_result>(static_cast<std::int32_t>(in.u32()));
      (void)gzl_result_to_string(any);  // any value: a name or GZL_RESULT_UNKNOWN, never a crash
      break;
    }
  }
}

// A call with a NULL plugin: GZL_ERROR_NULL_HANDLE.
void op_null_handle(Bytes& in) {
  gzl_result r = GZL_SUCCESS;
  const std::string sentinel = set_sentinel(nullptr);
  bool fresh_message = true;
  std::uint8_t level = 0;
  const gzl_object one = 1;
  gzl_frame_info info{GZL_TYPE_FRAME_INFO, nullptr};
  gzl_foveal_cone cone{GZL_TYPE_FOVEAL_CONE, nullptr};
  gzl_frame_record rec{GZL_TYPE_FRAME_RECORD, nullptr};
  gzl_gaze_sample s{GZL_TYPE_GAZE_SAMPLE, nullptr};
  s.direction = {0.0, 0.0, -1.0};
  s.flags = GZL_GAZE_SAMPLE_VALID;
  gzl_frame_input f{GZL_TYPE_FRAME_INPUT, nullptr};
  gzl_object_desc d{GZL_TYPE_OBJECT_DESC, nullptr};
  const gzl_level lv{0.0, 100};
  d.level_count = 1;
  d.levels = &lv;
  gzl_object h = 0;
  const gzl_vec3 zero{0.0, 0.0, 0.0};
  char buf[8];
  switch (in.pick(18)) {
    case 0:
      r = gzl_add_object(nullptr, &d, &h);
      break;
    case 1:
      r = gzl_remove_object(nullptr, one);
      break;
    case 2:
      r = gzl_set_object_enabled(nullptr, one, 1);
      break;
    case 3:
      r = gzl_set_object_motion(nullptr, one, &zero, &zero);
      break;
    case 4:
      r = gzl_push_gaze_sample(nullptr, &s);
      break;
    case 5:
      r = gzl_begin_frame_data(nullptr, &f);
      break;
    case 6:
      r = gzl_end_frame(nullptr, 1.0);
      break;
    case 7:
      r = gzl_get_levels(nullptr, 1, &one, &level);
      break;
    case 8:
      r = gzl_get_frame_info(nullptr, &info);
      break;
    case 9:
      r = gzl_get_foveal_cone(nullptr, 0, &cone);
      break;
    case 10:
      r = gzl_get_frame_record(nullptr, &rec);
      break;
    case 11:
      r = gzl_shutdown(nullptr);
      break;
    case 12:
      r = gzl_set_view_resolution(nullptr, 0, 100, 100);
      break;
    case 13:
      r = gzl_on_session_state(nullptr, 5, 0);
      break;
    case 14:
      r = gzl_begin_frame_openxr(nullptr, 1);
      break;
    case 15:
      r = gzl_set_base_space(nullptr, 1);
      break;
    case 16:
      r = gzl_action_sets_attached(nullptr);
      break;
    default:
      // The only entry point that does not leave a message for a NULL plugin (it is a reader
      // of the plugin's own strings); its code is still GZL_ERROR_NULL_HANDLE.
      r = gzl_get_gaze_status(nullptr, buf, sizeof buf, nullptr);
      fresh_message = false;
      break;
  }
  gzl_destroy(nullptr);
  check_named(r);
  check(r == GZL_ERROR_NULL_HANDLE, "a call with a NULL plugin did not fail with GZL_ERROR_NULL_HANDLE");
  if (fresh_message) checked(nullptr, r, sentinel);
}

// What capi() below does for op byte k (for the trace).
const char* op_name(std::uint8_t k, bool have_plugin) {
  if (!have_plugin || k % 32 == 0) return k % 4 == 3 ? "call with a NULL plugin" : "create";
  static const char* const kNames[16] = {"add_object",
                                         "add_object",
                                         "add_object",
                                         "remove_object",
                                         "set_object_enabled",
                                         "set_object_motion",
                                         "push_gaze_sample",
                                         "push_gaze_sample",
                                         "begin_frame_data",
                                         "begin_frame_data",
                                         "begin_frame_data",
                                         "get_levels",
                                         "frame info / cone / record / gaze status",
                                         "get_last_error",
                                         "misc",
                                         ""};
  if (k % 16 != 15) return kNames[k % 16];
  return k % 64 == 15 ? "destroy" : "call with a NULL plugin";
}

}  // namespace

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
