// SPDX-License-Identifier: Apache-2.0
// Instance and system: at xrCreateApiLayerInstance the layer decides (decision.hpp) whether to
// emulate XR_EXT_eye_gaze_interaction; emulating, it takes the extension off the create info
// it passes down (adding XR_KHR_convert_timespec_time for the HID source's clock when the
// runtime has it), opens the gaze source, and later answers supportsEyeGazeInteraction and
// delivers the interaction-profile events it owes.
#include "layer/decision.hpp"
#include "layer/entry_points.hpp"
#include "layer/layer_state.hpp"

#include "gaze/trace_error.hpp"
#include "xr/eye_gaze_paths.hpp"

#include <algorithm>
#include <cstring>
#include <string_view>
#include <vector>

namespace gazelod::layer {
namespace {

bool has_name(const XrInstanceCreateInfo* info, std::string_view name) {
  for (uint32_t i = 0; i < info->enabledExtensionCount; ++i)
    if (info->enabledExtensionNames[i] != nullptr && name == info->enabledExtensionNames[i]) return true;
  return false;
}

// The extensions of what lies below (the runtime, through any layers under this one).
std::vector<std::string> next_extensions(PFN_xrGetInstanceProcAddr next_gipa) {
  PFN_xrVoidFunction fn = nullptr;
  if (XR_FAILED(next_gipa(XR_NULL_HANDLE, "xrEnumerateInstanceExtensionProperties", &fn)) || fn == nullptr) return {};
  auto enumerate = reinterpret_cast<PFN_xrEnumerateInstanceExtensionProperties>(fn);
  uint32_t n = 0;
  if (XR_FAILED(enumerate(nullptr, 0, &n, nullptr))) return {};
  std::vector<XrExtensionProperties> props(n, {XR_TYPE_EXTENSION_PROPERTIES});
  if (XR_FAILED(enumerate(nullptr, n, &n, props.data()))) return {};
  std::vector<std::string> names;
  for (uint32_t i = 0; i < n && i < props.size(); ++i) names.emplace_back(props[i].extensionName);
  return names;
}

std::int64_t runtime_now_ns(PFN_xrConvertTimespecTimeToTimeKHR convert, XrInstance instance) {
  timespec ts{};
  if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0) return 0;
  XrTime t = 0;
  if (XR_FAILED(convert(instance, &ts, &t))) return 0;
  return static_cast<std::int64_t>(t);
}

// Opens the configured source; "" or why not (one line).
std::string open_source(const LayerConfig& config, EmulatedInstance& e, std::string& described, std::string& note) {
  try {
    if (!config.trace_path.empty()) {
      auto feed = open_trace_feed(config);
      described = feed->describe();
      e.feed = std::move(feed);
      return "";
    }
    if (e.next.ConvertTimespecTimeToTimeKHR == nullptr)
      return "the HID eye tracker needs XR_KHR_convert_timespec_time (the runtime's clock), which the runtime does not "
             "offer";
    HidFeedOptions o;
    const auto convert = e.next.ConvertTimespecTimeToTimeKHR;
    const XrInstance handle = e.handle;
    o.now_ns = [convert, handle] { return runtime_now_ns(convert, handle); };
    o.log = [](const std::string& line) { log_line(line); };
    e.feed = open_hid_feed(config, std::move(o), note);
    described = e.feed->describe();
    return "";
  } catch (const gaze::TraceError& err) {
    return std::string(kTraceEnv) + ": " + err.what();
  } catch (const std::exception& err) {
    return std::string(kTraceEnv) + ": " + err.what();
  }
}

XrPath to_path(const EmulatedInstance& e, const char* s) {
  XrPath p = XR_NULL_PATH;
  if (XR_FAILED(e.next.StringToPath(e.handle, s, &p))) return XR_NULL_PATH;
  return p;
}

}  // namespace

XrResult CreateApiLayerInstance(const XrInstanceCreateInfo* info, const xr::XrApiLayerCreateInfo* layer_info,
                                XrInstance* instance) {
  return guarded(XR_ERROR_INITIALIZATION_FAILED, [&]() -> XrResult {
    if (info == nullptr || instance == nullptr || layer_info == nullptr ||
        layer_info->structType != xr::XR_LOADER_INTERFACE_STRUCT_API_LAYER_CREATE_INFO ||
        layer_info->structVersion < xr::kApiLayerCreateInfoStructVersion ||
        layer_info->structSize < sizeof(xr::XrApiLayerCreateInfo) || layer_info->nextInfo == nullptr)
      return XR_ERROR_INITIALIZATION_FAILED;
    const xr::XrApiLayerNextInfo* next_info = layer_info->nextInfo;
    if (next_info->structType != xr::XR_LOADER_INTERFACE_STRUCT_API_LAYER_NEXT_INFO ||
        next_info->structVersion < xr::kApiLayerNextInfoStructVersion ||
        next_info->structSize < sizeof(xr::XrApiLayerNextInfo) || next_info->nextGetInstanceProcAddr == nullptr ||
        next_info->nextCreateApiLayerInstance == nullptr || std::strcmp(next_info->layerName, kLayerName) != 0)
      return XR_ERROR_INITIALIZATION_FAILED;
    if (info->enabledExtensionCount > 0 && info->enabledExtensionNames == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const PFN_xrGetInstanceProcAddr next_gipa = next_info->nextGetInstanceProcAddr;
    xr::XrApiLayerCreateInfo chained = *layer_info;
    chained.nextInfo = next_info->next;

    DecisionInputs in;
    in.application_enables_extension = has_name(info, XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME);
    LayerConfig config;
    std::vector<std::string> below;
    if (in.application_enables_extension) {
      ConfigResult cr = load_config_from_env();
      config = cr.config;
      in.config_error = cr.error;
      in.override_runtime = cr.error.empty() && config.override_runtime;
      below = next_extensions(next_gipa);
      in.runtime_has_extension =
          std::find(below.begin(), below.end(), XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME) != below.end();
    }
    const bool emulate = needs_source(in);
    {
      std::lock_guard lock(layer_state().mutex);
      if (emulate && layer_state().emulated) {
        log_line("a second instance while one emulates eye gaze: XR_ERROR_LIMIT_REACHED (one at a time)");
        return XR_ERROR_LIMIT_REACHED;
      }
    }
    if (!in.config_error.empty()) log_line(in.config_error);
    if (!emulate) {
      const XrResult r = next_info->nextCreateApiLayerInstance(info, &chained, instance);
      if (XR_SUCCEEDED(r)) {
        std::lock_guard lock(layer_state().mutex);
        layer_state().passed_through[*instance] = next_gipa;
        layer_state().last_next_gipa = next_gipa;
      }
      return r;
    }

    // Emulating: the extension stays above; the HID source's clock goes down with it.
    const bool want_timespec =
        in.config_error.empty() && config.trace_path.empty() &&
        std::find(below.begin(), below.end(), XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME) != below.end();
    std::vector<const char*> names;
    for (uint32_t i = 0; i < info->enabledExtensionCount; ++i) {
      const char* n = info->enabledExtensionNames[i];
      if (n != nullptr && std::string_view(n) == XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME) continue;
      names.push_back(n);
    }
    if (want_timespec && !has_name(info, XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME))
      names.push_back(XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME);
    XrInstanceCreateInfo down = *info;
    down.enabledExtensionCount = static_cast<uint32_t>(names.size());
    down.enabledExtensionNames = names.empty() ? nullptr : names.data();
    const XrResult r = next_info->nextCreateApiLayerInstance(&down, &chained, instance);
    if (XR_FAILED(r)) return r;

    auto e = std::make_unique<EmulatedInstance>();
    e->handle = *instance;
    const std::string missing = load_next_dispatch(next_gipa, *instance, want_timespec, e->next);
    if (!missing.empty()) {
      log_line("the layer below does not give " + missing + "; cannot emulate eye gaze");
      PFN_xrVoidFunction fn = nullptr;
      if (XR_SUCCEEDED(next_gipa(*instance, "xrDestroyInstance", &fn)) && fn != nullptr)
        reinterpret_cast<PFN_xrDestroyInstance>(fn)(*instance);
      *instance = XR_NULL_HANDLE;
      return XR_ERROR_INITIALIZATION_FAILED;
    }
    e->paths = {to_path(*e, xr::kEyesUserPath), to_path(*e, xr::kGazePosePath), to_path(*e, xr::kEyeGazeProfile)};
    e->tracker_in_head = Pose{config.tracker_orientation, config.tracker_position_m};
    std::string note;
    if (in.config_error.empty()) in.source_error = open_source(config, *e, in.source, note);
    if (!in.source_error.empty()) log_line(in.source_error);
    if (!note.empty()) log_line(note);
    const Decision d = decide(in);
    e->gaze_available = d.gaze_available;
    if (!d.gaze_available) e->feed.reset();
    std::lock_guard lock(layer_state().mutex);
    layer_state().emulated = std::move(e);
    layer_state().last_next_gipa = next_gipa;
    return XR_SUCCESS;
  });
}

XrResult EnumerateInstanceExtensionProperties(const char* layerName, uint32_t capacity, uint32_t* count,
                                              XrExtensionProperties* props) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    if (count == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    std::vector<XrExtensionProperties> list;
    const bool ours = layerName != nullptr && std::strcmp(layerName, kLayerName) == 0;
    bool add_eye_gaze = true;
    if (!ours) {
      // The chain's list, with eye gaze added when what lies below lacks it; another layer's
      // own list as it is.
      add_eye_gaze = layerName == nullptr;
      PFN_xrGetInstanceProcAddr next = nullptr;
      {
        std::lock_guard lock(layer_state().mutex);
        next = layer_state().last_next_gipa;
      }
      if (layerName != nullptr && next == nullptr) return XR_ERROR_API_LAYER_NOT_PRESENT;
      if (next != nullptr) {
        PFN_xrVoidFunction fn = nullptr;
        if (XR_FAILED(next(XR_NULL_HANDLE, "xrEnumerateInstanceExtensionProperties", &fn)) || fn == nullptr)
          return XR_ERROR_RUNTIME_FAILURE;
        auto below = reinterpret_cast<PFN_xrEnumerateInstanceExtensionProperties>(fn);
        uint32_t n = 0;
        XrResult r = below(layerName, 0, &n, nullptr);
        if (XR_FAILED(r)) return r;
        list.assign(n, {XR_TYPE_EXTENSION_PROPERTIES});
        r = below(layerName, n, &n, list.data());
        if (XR_FAILED(r)) return r;
        list.resize(n);
      }
    }
    if (add_eye_gaze && std::none_of(list.begin(), list.end(), [](const XrExtensionProperties& p) {
          return std::strcmp(p.extensionName, XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME) == 0;
        })) {
      XrExtensionProperties eye{XR_TYPE_EXTENSION_PROPERTIES};
      std::strncpy(eye.extensionName, XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME, XR_MAX_EXTENSION_NAME_SIZE - 1);
      eye.extensionVersion = XR_EXT_eye_gaze_interaction_SPEC_VERSION;
      list.push_back(eye);
    }
    *count = static_cast<uint32_t>(list.size());
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < list.size()) return XR_ERROR_SIZE_INSUFFICIENT;
    if (props == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (props[i].type != XR_TYPE_EXTENSION_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
      std::memcpy(props[i].extensionName, list[i].extensionName, sizeof props[i].extensionName);
      props[i].extensionVersion = list[i].extensionVersion;
    }
    return XR_SUCCESS;
  });
}

XrResult DestroyInstance(XrInstance instance) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrGetInstanceProcAddr next = nullptr;
    std::unique_ptr<EmulatedInstance> gone;
    {
      LayerState& st = layer_state();
      std::lock_guard lock(st.mutex);
      if (st.emulated && st.emulated->handle == instance) {
        gone = std::move(st.emulated);
        next = gone->next.GetInstanceProcAddr;
      } else if (auto it = st.passed_through.find(instance); it != st.passed_through.end()) {
        next = it->second;
        st.passed_through.erase(it);
      }
    }
    if (next == nullptr) return XR_ERROR_HANDLE_INVALID;
    // The source's reader thread calls the runtime's clock: it stops before the instance goes.
    if (gone) gone->feed.reset();
    PFN_xrVoidFunction fn = nullptr;
    const XrResult r = next(instance, "xrDestroyInstance", &fn);
    if (XR_FAILED(r) || fn == nullptr) return XR_FAILED(r) ? r : XR_ERROR_RUNTIME_FAILURE;
    return reinterpret_cast<PFN_xrDestroyInstance>(fn)(instance);
  });
}

XrResult GetSystemProperties(XrInstance instance, XrSystemId systemId, XrSystemProperties* properties) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrGetSystemProperties next = nullptr;
    bool supported = false;
    {
      std::lock_guard lock(layer_state().mutex);
      const auto& e = layer_state().emulated;
      if (!e || e->handle != instance) return XR_ERROR_HANDLE_INVALID;
      next = e->next.GetSystemProperties;
      supported = e->gaze_available;
    }
    if (properties == nullptr) return next(instance, systemId, properties);
    // Take the eye-gaze structure out of the chain the runtime sees (it does not know it), then
    // put it back and fill it.
    XrBaseOutStructure* prev = reinterpret_cast<XrBaseOutStructure*>(properties);
    XrSystemEyeGazeInteractionPropertiesEXT* eye = nullptr;
    while (prev->next != nullptr) {
      if (prev->next->type == XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT) {
        eye = reinterpret_cast<XrSystemEyeGazeInteractionPropertiesEXT*>(prev->next);
        prev->next = eye->next ? static_cast<XrBaseOutStructure*>(eye->next) : nullptr;
        break;
      }
      prev = prev->next;
    }
    const XrResult r = next(instance, systemId, properties);
    if (eye != nullptr) {
      eye->next = prev->next;
      prev->next = reinterpret_cast<XrBaseOutStructure*>(eye);
      if (XR_SUCCEEDED(r)) eye->supportsEyeGazeInteraction = supported ? XR_TRUE : XR_FALSE;
    }
    return r;
  });
}

XrResult PollEvent(XrInstance instance, XrEventDataBuffer* eventData) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrPollEvent next = nullptr;
    {
      std::lock_guard lock(layer_state().mutex);
      auto& e = layer_state().emulated;
      if (!e || e->handle != instance) return XR_ERROR_HANDLE_INVALID;
      next = e->next.PollEvent;
      if (eventData != nullptr && eventData->type == XR_TYPE_EVENT_DATA_BUFFER && !e->profile_events.empty()) {
        // Owed since an xrSyncActions made the eye-gaze profile current.
        const XrSession s = e->profile_events.front();
        e->profile_events.pop_front();
        auto* changed = reinterpret_cast<XrEventDataInteractionProfileChanged*>(eventData);
        changed->type = XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED;
        changed->next = nullptr;
        changed->session = s;
        return XR_SUCCESS;
      }
    }
    return next(instance, eventData);
  });
}

}  // namespace gazelod::layer
