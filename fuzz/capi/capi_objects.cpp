// SPDX-License-Identifier: Apache-2.0
// The C ABI fuzzer's calls that create a plugin and add, remove, enable, move objects and push gaze.
#include "fuzz/capi/capi_fuzz.hpp"

#include <algorithm>

namespace gazelod::fuzz::capi_fuzz {

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
  check(h != GZL_NULL_OBJECT && m.find(h) == nullptr, "gzl_add_object reused a handle (or gave 0)");
  m.max_handle = std::max(m.max_handle, h);
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

}  // namespace gazelod::fuzz::capi_fuzz
