// SPDX-License-Identifier: Apache-2.0
// The C ABI fuzzer's frames and the readers of their results.
#include "fuzz/capi/capi_fuzz.hpp"

namespace gazelod::fuzz::capi_fuzz {

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
  // The first frame drops samples pushed before it more than 1 s after its time (another
  // clock): which of them stay, the model does not follow; it stops checking their order.
  if (!m.have_frame && m.have_sample && m.last_sample_t > f.display_time_ns + 1'000 * kMs) m.have_sample = false;
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

}  // namespace gazelod::fuzz::capi_fuzz
