// SPDX-License-Identifier: Apache-2.0
// The C ABI fuzzer's checks of results and messages, and its choices of views, times and handles.
#include "fuzz/capi/capi_fuzz.hpp"

namespace gazelod::fuzz::capi_fuzz {

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
gzl_result checked(gzl_plugin p, gzl_result r, const std::string& sentinel, bool may_repeat_sentinel) {
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
    case 1:  // the newest handle's tag and generation, a row never made
      return (m.max_handle & ~gzl_object{0xffffffff}) | 0xfffffffe;
    case 2:
      return std::numeric_limits<gzl_object>::max();
    default:
      return in.u64();
  }
}

void destroy(Model& m) {
  gzl_destroy(m.p);
  m = Model{};
}

}  // namespace gazelod::fuzz::capi_fuzz
