// SPDX-License-Identifier: Apache-2.0
// gzl_create_data, gzl_create_openxr, errors, versions and teardown (include/gazelod/gazelod.h).
#include "plugin/capi/capi_convert.hpp"
#include "plugin/capi/capi_errors.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>

using namespace gazelod;
using namespace gazelod::capi;

namespace gazelod::capi {

std::string& thread_error() {
  thread_local std::string message;
  return message;
}

std::string prefixed(const std::string& m) {
  return m.rfind("gazelod:", 0) == 0 ? m : "gazelod: " + m;
}

void set_error(gzl_plugin p, const std::string& message) {
  if (p == nullptr) {
    thread_error() = message;
    return;
  }
  std::lock_guard lock(p->err_mu);
  p->last_error = message;
}

gzl_result fail(gzl_plugin p, gzl_result r, const std::string& message) {
  try {
    set_error(p, message);
  } catch (...) {
    // No memory for the message: the code still says what happened.
  }
  return r;
}

void need_plugin(gzl_plugin p) {
  if (p == nullptr) throw Refusal{GZL_ERROR_NULL_HANDLE, "gazelod: the gzl_plugin is NULL (create one first)"};
}

void need_live(gzl_plugin p) {
  need_plugin(p);
  if (p->shut_down.load())
    throw Refusal{GZL_ERROR_SHUT_DOWN,
                  "gazelod: the plugin was shut down (gzl_shutdown); only its readers and gzl_destroy remain"};
}

std::unique_lock<std::mutex> lock_live(gzl_plugin p) {
  need_plugin(p);
  std::unique_lock<std::mutex> lock(p->mu);
  need_live(p);  // again: a gzl_shutdown on another thread may have run since the caller's check
  return lock;
}

std::uint16_t next_plugin_tag() {
  static std::atomic<std::uint16_t> counter{0};
  std::uint16_t tag = 0;
  while (tag == 0) tag = ++counter;  // 0 is skipped when the counter wraps
  return tag;
}

}  // namespace gazelod::capi

namespace {

// Creation is a refusal-or-plugin; the new plugin's first published frame is empty.
gzl_result finish_create(std::unique_ptr<gzl_plugin_T> p, gzl_plugin* out) {
  gzl_plugin raw = p.get();
  // Reported once per change of source, inside a frame: the only allocation then.
  p->core().on_source_changed([raw](GazeSourceKind, const std::string& why) {
    std::lock_guard lock(raw->err_mu);
    raw->gaze_status = why;
  });
  p->pub.info.type = GZL_TYPE_FRAME_INFO;
  p->pub.record.type = GZL_TYPE_FRAME_RECORD;
  *out = p.release();
  return GZL_SUCCESS;
}

}  // namespace

extern "C" {

GZL_API uint32_t gzl_version(void) {
  return GZL_HEADER_VERSION;
}

GZL_API const char* gzl_result_to_string(gzl_result r) {
  switch (r) {
#define GZL_CASE(name) \
  case name:           \
    return #name;
    GZL_CASE(GZL_SUCCESS)
    GZL_CASE(GZL_ERROR_NULL_HANDLE)
    GZL_CASE(GZL_ERROR_NULL_POINTER)
    GZL_CASE(GZL_ERROR_STRUCT_TYPE)
    GZL_CASE(GZL_ERROR_INVALID_ARGUMENT)
    GZL_CASE(GZL_ERROR_TIME_OUT_OF_ORDER)
    GZL_CASE(GZL_ERROR_TIME_IN_FUTURE)
    GZL_CASE(GZL_ERROR_OBJECT_INVALID)
    GZL_CASE(GZL_ERROR_WRONG_MODE)
    GZL_CASE(GZL_ERROR_OPENXR_CALL)
    GZL_CASE(GZL_ERROR_OPENXR_FUNCTION)
    GZL_CASE(GZL_ERROR_CAPACITY)
    GZL_CASE(GZL_ERROR_SHUT_DOWN)
    GZL_CASE(GZL_ERROR_OUT_OF_MEMORY)
    GZL_CASE(GZL_ERROR_INTERNAL)
#undef GZL_CASE
    default:
      break;
  }
  return "GZL_RESULT_UNKNOWN";
}

namespace {
gzl_result copy_out(const std::string& copy, char* buffer, size_t capacity, size_t* length) {
  if (length != nullptr) *length = copy.size();
  if (buffer != nullptr && capacity > 0) {
    const std::size_t n = std::min(copy.size(), capacity - 1);
    std::memcpy(buffer, copy.data(), n);
    buffer[n] = '\0';
  }
  return GZL_SUCCESS;
}
}  // namespace

GZL_API gzl_result gzl_get_gaze_status(gzl_plugin p, char* buffer, size_t capacity, size_t* length) {
  if (p == nullptr) return fail(nullptr, GZL_ERROR_NULL_HANDLE, "gazelod: the gzl_plugin is NULL (create one first)");
  try {
    std::string copy;
    {
      std::lock_guard lock(p->err_mu);
      copy = p->gaze_status;
    }
    return copy_out(copy, buffer, capacity, length);
  } catch (...) {
    return GZL_ERROR_OUT_OF_MEMORY;
  }
}

GZL_API gzl_result gzl_get_last_error(gzl_plugin p, char* buffer, size_t capacity, size_t* length) {
  try {
    std::string copy;
    if (p == nullptr) {
      copy = thread_error();
    } else {
      std::lock_guard lock(p->err_mu);
      copy = p->last_error;
    }
    return copy_out(copy, buffer, capacity, length);
  } catch (...) {
    return GZL_ERROR_OUT_OF_MEMORY;
  }
}

GZL_API gzl_result gzl_create_data(const gzl_data_create_info* info, gzl_plugin* plugin) {
  return guarded(nullptr, [&]() -> gzl_result {
    if (plugin == nullptr) throw Refusal{GZL_ERROR_NULL_POINTER, "gazelod: plugin (the output) is NULL"};
    *plugin = nullptr;
    need_struct(info, GZL_TYPE_DATA_CREATE_INFO, "info");
    auto p = std::make_unique<gzl_plugin_T>();
    p->config = to_plugin_config(info->config);
    p->view_count = check_views(info->view_count, info->views, "info->views", false);
    std::copy(info->views, info->views + p->view_count, p->data_views.begin());
    p->data = std::make_unique<DataFront>(p->config);
    return finish_create(std::move(p), plugin);
  });
}

GZL_API gzl_result gzl_create_openxr(const gzl_openxr_create_info* info, gzl_plugin* plugin) {
  return guarded(nullptr, [&]() -> gzl_result {
    if (plugin == nullptr) throw Refusal{GZL_ERROR_NULL_POINTER, "gazelod: plugin (the output) is NULL"};
    *plugin = nullptr;
    need_struct(info, GZL_TYPE_OPENXR_CREATE_INFO, "info");
    if (info->get_instance_proc_addr == nullptr)
      throw Refusal{
          GZL_ERROR_NULL_POINTER,
          "gazelod: info->get_instance_proc_addr is NULL; pass (gzl_void_function)xrGetInstanceProcAddr, or the "
          "pointer your engine hands its plugins"};
    if (info->instance == 0 || info->session == 0 || info->base_space == 0)
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, "gazelod: info->instance, session and base_space must be live handles"};
    auto p = std::make_unique<gzl_plugin_T>();
    p->openxr = true;
    p->config = to_plugin_config(info->config);
    OpenXrOptions options = to_openxr_options(*info);
    const auto gipa = reinterpret_cast<PFN_xrGetInstanceProcAddr>(info->get_instance_proc_addr);
    try {
      p->xr = LodPlugin::create(gipa, from_handle<XrInstance>(info->instance), static_cast<XrSystemId>(info->system_id),
                                from_handle<XrSession>(info->session), from_handle<XrSpace>(info->base_space),
                                p->config, options);
    } catch (const XrCallError& e) {
      // A function the application's loader does not give is a different fault from a call
      // that failed.
      const bool lookup = std::string(e.what()).find("xrGetInstanceProcAddr") != std::string::npos;
      throw Refusal{lookup ? GZL_ERROR_OPENXR_FUNCTION : GZL_ERROR_OPENXR_CALL, prefixed(e.what())};
    }
    p->view_count = p->xr->view_count();
    p->gaze_input = info->gaze_input;
    return finish_create(std::move(p), plugin);
  });
}

GZL_API gzl_result gzl_shutdown(gzl_plugin p) {
  return guarded(p, [&]() -> gzl_result {
    need_plugin(p);
    std::lock_guard lock(p->mu);
    if (p->xr) p->xr->shutdown();
    p->shut_down = true;
    return GZL_SUCCESS;
  });
}

GZL_API void gzl_destroy(gzl_plugin p) {
  if (p == nullptr) return;
  (void)gzl_shutdown(p);
  delete p;
}

}  // extern "C"
