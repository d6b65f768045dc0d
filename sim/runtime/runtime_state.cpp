// SPDX-License-Identifier: Apache-2.0
// Handle registry and the cascade of destruction (destroying an instance destroys its
// sessions, action sets and actions; a session its spaces and swapchains).
#include "sim/runtime/runtime_state.hpp"
#include "sim/runtime/events.hpp"
#include "sim/runtime/vulkan_images.hpp"

#include <cstring>

namespace gazelod::xrrt {

std::mutex& runtime_mutex() {
  static std::mutex m;
  return m;
}

Runtime& runtime() {
  static Runtime r;
  return r;
}

Instance* find_instance(XrInstance h) {
  return runtime().instances.find(handle_id(h));
}
Session* find_session(XrSession h) {
  return runtime().sessions.find(handle_id(h));
}
Space* find_space(XrSpace h) {
  return runtime().spaces.find(handle_id(h));
}
ActionSet* find_action_set(XrActionSet h) {
  return runtime().action_sets.find(handle_id(h));
}
Action* find_action(XrAction h) {
  return runtime().actions.find(handle_id(h));
}
Swapchain* find_swapchain(XrSwapchain h) {
  return runtime().swapchains.find(handle_id(h));
}
Instance* instance_of(const Session& session) {
  return runtime().instances.find(session.instance_id);
}

void destroy_swapchain(std::uint64_t id) {
  Runtime& rt = runtime();
  Swapchain* sc = rt.swapchains.find(id);
  if (sc == nullptr) return;
  if (const Session* s = rt.sessions.find(sc->session_id)) destroy_vulkan_images(*s, *sc);
  rt.swapchains.live.erase(id);
}

void destroy_session(std::uint64_t id) {
  Runtime& rt = runtime();
  std::vector<std::uint64_t> doomed;
  for (const auto& [sid, sc] : rt.swapchains.live)
    if (sc->session_id == id) doomed.push_back(sid);
  for (std::uint64_t sid : doomed) destroy_swapchain(sid);
  std::erase_if(rt.spaces.live, [&](const auto& kv) { return kv.second->session_id == id; });
  if (const Session* s = rt.sessions.find(id))
    if (Instance* inst = rt.instances.find(s->instance_id)) discard_session_events(*inst, id);
  rt.sessions.live.erase(id);
}

void destroy_action_set(std::uint64_t id) {
  Runtime& rt = runtime();
  std::vector<std::uint64_t> actions;
  for (const auto& [aid, a] : rt.actions.live)
    if (a->set_id == id) actions.push_back(aid);
  // Action spaces of destroyed actions stay valid handles but locate as untracked.
  for (std::uint64_t aid : actions) rt.actions.live.erase(aid);
  rt.action_sets.live.erase(id);
}

void destroy_instance(std::uint64_t id) {
  Runtime& rt = runtime();
  std::vector<std::uint64_t> sessions, sets;
  for (const auto& [sid, s] : rt.sessions.live)
    if (s->instance_id == id) sessions.push_back(sid);
  for (const auto& [sid, s] : rt.action_sets.live)
    if (s->instance_id == id) sets.push_back(sid);
  for (std::uint64_t sid : sessions) destroy_session(sid);
  for (std::uint64_t sid : sets) destroy_action_set(sid);
  rt.instances.live.erase(id);
}

XrResult two_call_string(std::uint32_t capacity, std::uint32_t* count, char* out, const std::string& s) {
  if (count == nullptr) return XR_ERROR_VALIDATION_FAILURE;
  *count = static_cast<std::uint32_t>(s.size() + 1);  // with the terminating NUL
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < s.size() + 1) return XR_ERROR_SIZE_INSUFFICIENT;
  if (out == nullptr) return XR_ERROR_VALIDATION_FAILURE;
  std::memcpy(out, s.c_str(), s.size() + 1);
  return XR_SUCCESS;
}

}  // namespace gazelod::xrrt
