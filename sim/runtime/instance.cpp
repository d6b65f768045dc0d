// SPDX-License-Identifier: Apache-2.0
// Instance commands: extension list, xrCreateInstance (loads the scenario), properties and the
// result / structure-type names (from openxr_reflection.h).
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/runtime_state.hpp"
#include "sim/runtime/scenario_source.hpp"

#include <openxr/openxr_reflection.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string_view>

namespace gazelod::xrrt {
namespace {

struct Extension {
  const char* name;
  std::uint32_t version;
};
const Extension kExtensions[] = {
    {XR_KHR_VULKAN_ENABLE_EXTENSION_NAME, XR_KHR_vulkan_enable_SPEC_VERSION},
    {XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME, XR_KHR_vulkan_enable2_SPEC_VERSION},
    {XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME, XR_KHR_convert_timespec_time_SPEC_VERSION},
    {XR_MND_HEADLESS_EXTENSION_NAME, XR_MND_headless_SPEC_VERSION},
    {XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME, XR_EXT_eye_gaze_interaction_SPEC_VERSION},
    {XR_EXT_CONFORMANCE_AUTOMATION_EXTENSION_NAME, XR_EXT_conformance_automation_SPEC_VERSION},
    {XR_GAZELOD_SIMULATOR_STATE_EXTENSION_NAME, XR_GAZELOD_simulator_state_SPEC_VERSION},
    {XR_KHR_LOCATE_SPACES_EXTENSION_NAME, XR_KHR_locate_spaces_SPEC_VERSION},
};

// GAZELOD_SIM_EYE_GAZE_EXTENSION=0 hides XR_EXT_eye_gaze_interaction, as on the many runtimes
// that lack it (how the eye-gaze API layer is tested). Only "0" hides it here: a bad value
// fails xrCreateInstance with its message (load_runtime_scenario), since the loader ignores
// a failing enumeration.
bool offered(std::string_view name) {
  if (name != XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME) return true;
  const char* v = std::getenv("GAZELOD_SIM_EYE_GAZE_EXTENSION");
  return v == nullptr || std::strcmp(v, "0") != 0;
}

void copy_name(char* dst, std::size_t cap, std::string_view src) {
  const std::size_t n = std::min(cap - 1, src.size());
  std::memcpy(dst, src.data(), n);
  dst[n] = '\0';
}

}  // namespace

XrResult EnumerateApiLayerProperties(uint32_t capacity, uint32_t* count, XrApiLayerProperties* /*props*/) {
  // The runtime has no API layers of its own (the loader lists the installed ones).
  if (count == nullptr) return XR_ERROR_VALIDATION_FAILURE;
  (void)capacity;
  *count = 0;
  return XR_SUCCESS;
}

XrResult EnumerateInstanceExtensionProperties(const char* layerName, uint32_t capacity, uint32_t* count,
                                              XrExtensionProperties* props) {
  return guarded([&] {
    if (layerName != nullptr) return XR_ERROR_API_LAYER_NOT_PRESENT;
    if (count == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const Extension* listed[std::size(kExtensions)];
    std::uint32_t n = 0;
    for (const Extension& e : kExtensions)
      if (offered(e.name)) listed[n++] = &e;
    *count = n;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < n) return XR_ERROR_SIZE_INSUFFICIENT;
    if (props == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (props[i].type != XR_TYPE_EXTENSION_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
      copy_name(props[i].extensionName, XR_MAX_EXTENSION_NAME_SIZE, listed[i]->name);
      props[i].extensionVersion = listed[i]->version;
    }
    return XR_SUCCESS;
  });
}

XrResult CreateInstance(const XrInstanceCreateInfo* info, XrInstance* instance) {
  return guarded([&] {
    if (info == nullptr || instance == nullptr || info->type != XR_TYPE_INSTANCE_CREATE_INFO)
      return XR_ERROR_VALIDATION_FAILURE;
    const XrVersion api = info->applicationInfo.apiVersion;
    if (XR_VERSION_MAJOR(api) != 1 || XR_VERSION_MINOR(api) != 0) return XR_ERROR_API_VERSION_UNSUPPORTED;
    if (info->applicationInfo.applicationName[0] == '\0') return XR_ERROR_NAME_INVALID;
    auto inst = std::make_unique<Instance>();
    for (std::uint32_t i = 0; i < info->enabledExtensionCount; ++i) {
      const char* name_c = info->enabledExtensionNames ? info->enabledExtensionNames[i] : nullptr;
      if (name_c == nullptr) return XR_ERROR_VALIDATION_FAILURE;
      const std::string_view name(name_c);
      if (!offered(name)) return XR_ERROR_EXTENSION_NOT_PRESENT;
      if (name == XR_KHR_VULKAN_ENABLE_EXTENSION_NAME)
        inst->ext_vulkan = true;
      else if (name == XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME)
        inst->ext_vulkan2 = true;
      else if (name == XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME)
        inst->ext_timespec = true;
      else if (name == XR_MND_HEADLESS_EXTENSION_NAME)
        inst->ext_headless = true;
      else if (name == XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME)
        inst->ext_eye_gaze = true;
      else if (name == XR_EXT_CONFORMANCE_AUTOMATION_EXTENSION_NAME)
        inst->ext_automation = true;
      else if (name == XR_GAZELOD_SIMULATOR_STATE_EXTENSION_NAME)
        inst->ext_simulator_state = true;
      else if (name == XR_KHR_LOCATE_SPACES_EXTENSION_NAME)
        inst->ext_locate_spaces = true;
      else if (name == XR_EXT_DEBUG_UTILS_EXTENSION_NAME)
        continue;  // implemented by the loader
      else
        return XR_ERROR_EXTENSION_NOT_PRESENT;
    }
    inst->app_name = info->applicationInfo.applicationName;
    try {
      sim::Scenario scenario = load_runtime_scenario();
      inst->faults = load_runtime_faults();
      inst->clock.start(scenario.runtime.paced, scenario.display.refresh_hz);
      inst->simulator = std::make_unique<sim::Simulator>(std::move(scenario));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "gazelod_xr_runtime: cannot load the scenario: %s\n", e.what());
      return XR_ERROR_INITIALIZATION_FAILED;
    }
    std::lock_guard lock(runtime_mutex());
    Runtime& rt = runtime();
    inst->id = rt.next_id++;
    *instance = to_handle<XrInstance>(inst->id);
    rt.instances.live.emplace(inst->id, std::move(inst));
    return XR_SUCCESS;
  });
}

XrResult DestroyInstance(XrInstance instance) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (find_instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    destroy_instance(handle_id(instance));
    return XR_SUCCESS;
  });
}

XrResult GetInstanceProperties(XrInstance instance, XrInstanceProperties* props) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (find_instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (props == nullptr || props->type != XR_TYPE_INSTANCE_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
    props->runtimeVersion = XR_MAKE_VERSION(0, 1, 0);
    copy_name(props->runtimeName, XR_MAX_RUNTIME_NAME_SIZE, "gazelod simulated runtime");
    return XR_SUCCESS;
  });
}

XrResult ResultToString(XrInstance instance, XrResult value, char buffer[XR_MAX_RESULT_STRING_SIZE]) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (find_instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (buffer == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    switch (value) {
#define XRRT_RESULT_CASE(name, val)                      \
  case name:                                             \
    copy_name(buffer, XR_MAX_RESULT_STRING_SIZE, #name); \
    return XR_SUCCESS;
      XR_LIST_ENUM_XrResult(XRRT_RESULT_CASE)
#undef XRRT_RESULT_CASE
          default : break;
    }
    // Unknown values, as the specification words them.
    std::snprintf(buffer, XR_MAX_RESULT_STRING_SIZE, value >= 0 ? "XR_UNKNOWN_SUCCESS_%d" : "XR_UNKNOWN_FAILURE_%d",
                  static_cast<int>(value));
    return XR_SUCCESS;
  });
}

XrResult StructureTypeToString(XrInstance instance, XrStructureType value, char buffer[XR_MAX_STRUCTURE_NAME_SIZE]) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (find_instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (buffer == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    switch (value) {
#define XRRT_TYPE_CASE(name, val)                         \
  case name:                                              \
    copy_name(buffer, XR_MAX_STRUCTURE_NAME_SIZE, #name); \
    return XR_SUCCESS;
      XR_LIST_ENUM_XrStructureType(XRRT_TYPE_CASE)
#undef XRRT_TYPE_CASE
          default : break;
    }
    std::snprintf(buffer, XR_MAX_STRUCTURE_NAME_SIZE, "XR_UNKNOWN_STRUCTURE_TYPE_%d", static_cast<int>(value));
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::xrrt
