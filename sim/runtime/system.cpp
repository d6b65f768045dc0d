// SPDX-License-Identifier: Apache-2.0
// The one system (an HMD showing the scenario's display): xrGetSystem, its properties with
// XrSystemEyeGazeInteractionPropertiesEXT, the view configuration (per-eye pixels and FOV of
// the scenario display) and the environment blend modes (opaque only).
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/runtime_state.hpp"
#include "sim/runtime/system_info.hpp"

#include <algorithm>
#include <cstring>

namespace gazelod::xrrt {

XrViewConfigurationType primary_view_configuration(const Instance& inst) {
  return inst.simulator->scenario().display.view_count == 1 ? XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO
                                                            : XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
}

std::uint32_t view_count(const Instance& inst) {
  return inst.simulator->scenario().display.view_count == 1 ? 1u : 2u;
}

XrResult check_system(const Instance* inst, XrSystemId systemId) {
  if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
  if (systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
  return XR_SUCCESS;
}

XrResult GetSystem(XrInstance instance, const XrSystemGetInfo* getInfo, XrSystemId* systemId) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (getInfo == nullptr || systemId == nullptr || getInfo->type != XR_TYPE_SYSTEM_GET_INFO)
      return XR_ERROR_VALIDATION_FAILURE;
    // Every form factor but an HMD, known or not, is unsupported here (the conformance suite
    // asks with XR_FORM_FACTOR_MAX_ENUM and expects this code, not a validation failure).
    if (getInfo->formFactor != XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY) return XR_ERROR_FORM_FACTOR_UNSUPPORTED;
    inst->system_queried = true;
    *systemId = kSystemId;
    return XR_SUCCESS;
  });
}

XrResult GetSystemProperties(XrInstance instance, XrSystemId systemId, XrSystemProperties* properties) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (XrResult r = check_system(inst, systemId); r != XR_SUCCESS) return r;
    if (properties == nullptr || properties->type != XR_TYPE_SYSTEM_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
    const sim::Scenario& sc = inst->simulator->scenario();
    properties->systemId = kSystemId;
    properties->vendorId = 0;
    std::string name =
        "gazelod simulated HMD (" + (sc.display.label.empty() ? sc.display.name : sc.display.label) + ")";
    name.resize(std::min<std::size_t>(name.size(), XR_MAX_SYSTEM_NAME_SIZE - 1));
    std::memcpy(properties->systemName, name.c_str(), name.size() + 1);
    properties->graphicsProperties.maxSwapchainImageWidth = kMaxImageSize;
    properties->graphicsProperties.maxSwapchainImageHeight = kMaxImageSize;
    properties->graphicsProperties.maxLayerCount = kMaxLayerCount;
    properties->trackingProperties.orientationTracking = XR_TRUE;
    properties->trackingProperties.positionTracking = XR_TRUE;
    for (auto* next = static_cast<XrBaseOutStructure*>(properties->next); next != nullptr; next = next->next) {
      if (next->type == XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT && inst->ext_eye_gaze) {
        reinterpret_cast<XrSystemEyeGazeInteractionPropertiesEXT*>(next)->supportsEyeGazeInteraction =
            sc.runtime.eye_gaze_supported ? XR_TRUE : XR_FALSE;
      }
    }
    return XR_SUCCESS;
  });
}

XrResult EnumerateViewConfigurations(XrInstance instance, XrSystemId systemId, uint32_t capacity, uint32_t* count,
                                     XrViewConfigurationType* types) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (XrResult r = check_system(inst, systemId); r != XR_SUCCESS) return r;
    return two_call(capacity, count, types, std::vector<XrViewConfigurationType>{primary_view_configuration(*inst)});
  });
}

XrResult GetViewConfigurationProperties(XrInstance instance, XrSystemId systemId, XrViewConfigurationType type,
                                        XrViewConfigurationProperties* props) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (XrResult r = check_system(inst, systemId); r != XR_SUCCESS) return r;
    if (props == nullptr || props->type != XR_TYPE_VIEW_CONFIGURATION_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
    if (type != primary_view_configuration(*inst)) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    props->viewConfigurationType = type;
    props->fovMutable = XR_FALSE;
    return XR_SUCCESS;
  });
}

XrResult EnumerateViewConfigurationViews(XrInstance instance, XrSystemId systemId, XrViewConfigurationType type,
                                         uint32_t capacity, uint32_t* count, XrViewConfigurationView* views) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (XrResult r = check_system(inst, systemId); r != XR_SUCCESS) return r;
    if (type != primary_view_configuration(*inst)) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (count == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const std::uint32_t n = view_count(*inst);
    *count = n;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < n) return XR_ERROR_SIZE_INSUFFICIENT;
    if (views == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const lod::DisplaySpec& d = inst->simulator->scenario().display;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (views[i].type != XR_TYPE_VIEW_CONFIGURATION_VIEW) return XR_ERROR_VALIDATION_FAILURE;
      const lod::ViewSpec& v = d.views[i];
      views[i].recommendedImageRectWidth = static_cast<std::uint32_t>(std::clamp(v.width_px, 1, int(kMaxImageSize)));
      views[i].recommendedImageRectHeight = static_cast<std::uint32_t>(std::clamp(v.height_px, 1, int(kMaxImageSize)));
      views[i].maxImageRectWidth = kMaxImageSize;
      views[i].maxImageRectHeight = kMaxImageSize;
      views[i].recommendedSwapchainSampleCount = 1;
      views[i].maxSwapchainSampleCount = 1;
    }
    return XR_SUCCESS;
  });
}

XrResult EnumerateEnvironmentBlendModes(XrInstance instance, XrSystemId systemId, XrViewConfigurationType type,
                                        uint32_t capacity, uint32_t* count, XrEnvironmentBlendMode* modes) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (XrResult r = check_system(inst, systemId); r != XR_SUCCESS) return r;
    if (type != primary_view_configuration(*inst)) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    return two_call(capacity, count, modes, std::vector<XrEnvironmentBlendMode>{XR_ENVIRONMENT_BLEND_MODE_OPAQUE});
  });
}

}  // namespace gazelod::xrrt
