// SPDX-License-Identifier: Apache-2.0
// gazelod: a thin C++17 wrapper over the C ABI (gazelod/gazelod.h). Header-only: it adds RAII
// and exceptions on the application's side of the boundary and nothing else, so the
// application's compiler and standard library never meet gazelod's.
//
//   gazelod::Plugin plugin = gazelod::Plugin::data(info);      // or Plugin::openxr(info)
//   gzl_object cube = plugin.add_object(desc);
//   plugin.push_gaze(sample); plugin.begin_frame(input); plugin.levels(handles, levels);
#ifndef GAZELOD_GAZELOD_HPP_
#define GAZELOD_GAZELOD_HPP_

#include "gazelod/gazelod.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace gazelod {

// A failed call: what() is gazelod's message ("gazelod: ..."), result() its code.
class Error : public std::runtime_error {
 public:
  Error(gzl_result result, const std::string& message) : std::runtime_error(message), result_(result) {}
  gzl_result result() const noexcept { return result_; }

 private:
  gzl_result result_;
};

namespace detail {
inline std::string last_error(gzl_plugin p) {
  size_t n = 0;
  gzl_get_last_error(p, nullptr, 0, &n);
  std::string s(n + 1, '\0');
  gzl_get_last_error(p, &s[0], s.size(), nullptr);
  s.resize(n);
  return s;
}
inline void check(gzl_plugin p, gzl_result r) {
  if (r != GZL_SUCCESS) throw Error(r, last_error(p));
}
}  // namespace detail

class Plugin {
 public:
  static Plugin data(const gzl_data_create_info& info) {
    gzl_plugin p = nullptr;
    detail::check(nullptr, gzl_create_data(&info, &p));
    return Plugin(p);
  }
  static Plugin openxr(const gzl_openxr_create_info& info) {
    gzl_plugin p = nullptr;
    detail::check(nullptr, gzl_create_openxr(&info, &p));
    return Plugin(p);
  }

  Plugin(Plugin&& o) noexcept : p_(std::exchange(o.p_, nullptr)) {}
  Plugin& operator=(Plugin&& o) noexcept {
    if (this != &o) {
      gzl_destroy(p_);
      p_ = std::exchange(o.p_, nullptr);
    }
    return *this;
  }
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;
  ~Plugin() { gzl_destroy(p_); }

  gzl_plugin handle() const noexcept { return p_; }

  gzl_object add_object(const gzl_object_desc& desc) {
    gzl_object o = GZL_NULL_OBJECT;
    check(gzl_add_object(p_, &desc, &o));
    return o;
  }
  void remove_object(gzl_object o) { check(gzl_remove_object(p_, o)); }
  void set_object_enabled(gzl_object o, bool enabled) { check(gzl_set_object_enabled(p_, o, enabled ? 1u : 0u)); }
  void set_object_motion(gzl_object o, const gzl_vec3& center_m, const gzl_vec3& velocity_m_s) {
    check(gzl_set_object_motion(p_, o, &center_m, &velocity_m_s));
  }

  void on_session_state(int32_t xr_session_state, int64_t time_ns) {
    check(gzl_on_session_state(p_, xr_session_state, time_ns));
  }
  void push_gaze(const gzl_gaze_sample& s) { check(gzl_push_gaze_sample(p_, &s)); }
  void begin_frame(const gzl_frame_input& in) { check(gzl_begin_frame_data(p_, &in)); }
  void begin_frame(int64_t predicted_display_time) { check(gzl_begin_frame_openxr(p_, predicted_display_time)); }
  void end_frame(double measured_frame_ms) { check(gzl_end_frame(p_, measured_frame_ms)); }

  // levels[i] for objects[i], from the last published frame.
  void levels(uint32_t count, const gzl_object* objects, uint8_t* levels) const {
    check(gzl_get_levels(p_, count, objects, levels));
  }
  gzl_frame_info frame_info() const {
    gzl_frame_info i{};
    i.type = GZL_TYPE_FRAME_INFO;
    check(gzl_get_frame_info(p_, &i));
    return i;
  }
  gzl_foveal_cone foveal_cone(uint32_t view) const {
    gzl_foveal_cone c{};
    c.type = GZL_TYPE_FOVEAL_CONE;
    check(gzl_get_foveal_cone(p_, view, &c));
    return c;
  }
  gzl_frame_record frame_record() const {
    gzl_frame_record r{};
    r.type = GZL_TYPE_FRAME_RECORD;
    check(gzl_get_frame_record(p_, &r));
    return r;
  }
  void shutdown() { check(gzl_shutdown(p_)); }

 private:
  explicit Plugin(gzl_plugin p) : p_(p) {}
  void check(gzl_result r) const { detail::check(p_, r); }
  gzl_plugin p_ = nullptr;
};

}  // namespace gazelod

#endif  // GAZELOD_GAZELOD_HPP_
