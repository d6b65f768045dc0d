// SPDX-License-Identifier: Apache-2.0
// Session creation (Vulkan binding or XR_MND_headless), begin / end / request exit, following
// the error codes of OpenXR 1.0 section 9 ("Session").
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/events.hpp"
#include "sim/runtime/runtime_log.hpp"
#include "sim/runtime/system_info.hpp"

namespace gazelod::xrrt {
namespace {

const XrGraphicsBindingVulkanKHR* find_vulkan_binding(const void* next) {
  for (auto* n = static_cast<const XrBaseInStructure*>(next); n != nullptr; n = n->next)
    if (n->type == XR_TYPE_GRAPHICS_BINDING_VULKAN_KHR) return reinterpret_cast<const XrGraphicsBindingVulkanKHR*>(n);
  return nullptr;
}

}  // namespace

XrResult CreateSession(XrInstance instance, const XrSessionCreateInfo* info, XrSession* session) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || session == nullptr || info->type != XR_TYPE_SESSION_CREATE_INFO)
      return XR_ERROR_VALIDATION_FAILURE;
    if (XrResult r = check_system(inst, info->systemId); r != XR_SUCCESS) return r;
    auto s = std::make_unique<Session>();
    if (const XrGraphicsBindingVulkanKHR* vk = find_vulkan_binding(info->next)) {
      if (!inst->ext_vulkan && !inst->ext_vulkan2) return XR_ERROR_GRAPHICS_DEVICE_INVALID;
      if (!inst->graphics_requirements_queried) return XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING;
      if (vk->instance == VK_NULL_HANDLE || vk->physicalDevice == VK_NULL_HANDLE || vk->device == VK_NULL_HANDLE)
        return XR_ERROR_GRAPHICS_DEVICE_INVALID;
      s->vk_instance = vk->instance;
      s->vk_physical_device = vk->physicalDevice;
      s->vk_device = vk->device;
      s->vk_queue_family = vk->queueFamilyIndex;
      s->vk_queue_index = vk->queueIndex;
    } else if (inst->ext_headless) {
      s->headless = true;
    } else {
      return XR_ERROR_GRAPHICS_DEVICE_INVALID;
    }
    Runtime& rt = runtime();
    for (const auto& [id, other] : rt.sessions.live)
      if (other->instance_id == inst->id) return XR_ERROR_LIMIT_REACHED;  // one session per instance
    s->id = rt.next_id++;
    s->instance_id = inst->id;
    s->view_config = primary_view_configuration(*inst);
    Session& ref = *s;
    rt.sessions.live.emplace(s->id, std::move(s));
    const XrTime now = inst->clock.now();
    change_state(*inst, ref, XR_SESSION_STATE_IDLE, now);
    change_state(*inst, ref, XR_SESSION_STATE_READY, now);
    runtime_log("session created (%s)", ref.headless ? "headless" : "Vulkan");
    *session = to_handle<XrSession>(ref.id);
    return XR_SUCCESS;
  });
}

XrResult DestroySession(XrSession session) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    runtime_log("session destroyed: %llu frames submitted, %llu layers",
                static_cast<unsigned long long>(s->frames_submitted),
                static_cast<unsigned long long>(s->layers_submitted));
    destroy_session(s->id);
    return XR_SUCCESS;
  });
}

XrResult BeginSession(XrSession session, const XrSessionBeginInfo* info) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || info->type != XR_TYPE_SESSION_BEGIN_INFO) return XR_ERROR_VALIDATION_FAILURE;
    Instance& inst = *instance_of(*s);
    if (info->primaryViewConfigurationType != s->view_config) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (s->running) return XR_ERROR_SESSION_RUNNING;
    if (s->state != XR_SESSION_STATE_READY) return XR_ERROR_SESSION_NOT_READY;
    s->running = true;
    s->exit_requested = false;
    runtime_log("session begun");
    // Headless sessions have no compositor to synchronise with: they are focused at once.
    if (s->headless) raise_to_focused(inst, *s, inst.clock.now());
    return XR_SUCCESS;
  });
}

XrResult EndSession(XrSession session) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!s->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (s->state != XR_SESSION_STATE_STOPPING) return XR_ERROR_SESSION_NOT_STOPPING;
    Instance& inst = *instance_of(*s);
    s->running = false;
    s->waited_frames = 0;
    s->frame_begun = false;
    const XrTime now = inst.clock.now();
    change_state(inst, *s, XR_SESSION_STATE_IDLE, now);
    // The only reasons to stop are the application's request and the scenario's end; both
    // mean the session will not become ready again.
    change_state(inst, *s, XR_SESSION_STATE_EXITING, now);
    runtime_log("session ended after %llu frames", static_cast<unsigned long long>(s->frames_submitted));
    return XR_SUCCESS;
  });
}

XrResult RequestExitSession(XrSession session) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!s->running) return XR_ERROR_SESSION_NOT_RUNNING;
    Instance& inst = *instance_of(*s);
    if (!s->exit_requested) {
      s->exit_requested = true;
      lower_to_stopping(inst, *s, inst.clock.now());
    }
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::xrrt
