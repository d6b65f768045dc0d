// SPDX-License-Identifier: Apache-2.0
// gazelod layer check: what the OpenXR API layer XR_APILAYER_GAZELOD_eye_gaze (layer/,
// docs/layer.md) would do in this environment: whether the loader finds it, the runtime the
// loader finds and whether it offers XR_EXT_eye_gaze_interaction, the configuration
// (GAZELOD_LAYER_TRACE, GAZELOD_LAYER_CONFIG), whether the configured source is there, and the
// decision, made by the layer's own code (layer/decision.hpp) for an application that enables
// XR_EXT_eye_gaze_interaction. Exit 0 when the layer would pass through or serve gaze, 1 when
// gaze would be unavailable or no runtime is found.
#include "auxiliary/time.hpp"
#include "layer/decision.hpp"
#include "layer/gaze_feed.hpp"
#include "layer/layer_config.hpp"
#include "layer/xr_headers.hpp"
#include "apps/gazelod/commands/command.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace gazelod::cli {
namespace {

// Sets (or unsets) a variable for the check's loader calls, restoring it afterwards.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      ::setenv(name, value->c_str(), 1);
    else
      ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

std::string result_name(XrResult r) {
  switch (r) {
    case XR_ERROR_RUNTIME_UNAVAILABLE:
      return "XR_ERROR_RUNTIME_UNAVAILABLE";
    case XR_ERROR_RUNTIME_FAILURE:
      return "XR_ERROR_RUNTIME_FAILURE";
    case XR_ERROR_INITIALIZATION_FAILED:
      return "XR_ERROR_INITIALIZATION_FAILED";
    case XR_ERROR_API_LAYER_NOT_PRESENT:
      return "XR_ERROR_API_LAYER_NOT_PRESENT";
    case XR_ERROR_EXTENSION_NOT_PRESENT:
      return "XR_ERROR_EXTENSION_NOT_PRESENT";
    case XR_ERROR_FILE_ACCESS_ERROR:
      return "XR_ERROR_FILE_ACCESS_ERROR";
    case XR_ERROR_FILE_CONTENTS_INVALID:
      return "XR_ERROR_FILE_CONTENTS_INVALID";
    default:
      return "XrResult " + std::to_string(static_cast<int>(r));
  }
}

// XR_ENABLE_API_LAYERS without this layer (the runtime's own list is wanted).
std::optional<std::string> env_layers_without_ours(bool& named) {
  named = false;
  const char* v = std::getenv("XR_ENABLE_API_LAYERS");
  if (v == nullptr) return std::nullopt;
  std::string kept, item;
  std::istringstream in(v);
  while (std::getline(in, item, ':')) {
    if (item == layer::kLayerName) {
      named = true;
      continue;
    }
    if (!item.empty()) kept += (kept.empty() ? "" : ":") + item;
  }
  if (kept.empty()) return std::nullopt;
  return kept;
}

struct RuntimeFacts {
  std::string error;  // "" = found
  std::string name;
  bool eye_gaze = false, timespec = false;
};

RuntimeFacts probe_runtime() {
  RuntimeFacts f;
  bool named = false;
  const ScopedEnv layers("XR_ENABLE_API_LAYERS", env_layers_without_ours(named));
  const ScopedEnv disable(layer::kLayerDisableEnv, std::string("1"));  // an implicit install
  uint32_t n = 0;
  XrResult r = xrEnumerateInstanceExtensionProperties(nullptr, 0, &n, nullptr);
  std::vector<XrExtensionProperties> props(n, {XR_TYPE_EXTENSION_PROPERTIES});
  if (XR_SUCCEEDED(r)) r = xrEnumerateInstanceExtensionProperties(nullptr, n, &n, props.data());
  if (XR_FAILED(r)) {
    f.error = "xrEnumerateInstanceExtensionProperties: " + result_name(r);
    return f;
  }
  for (uint32_t i = 0; i < n && i < props.size(); ++i) {
    const std::string name = props[i].extensionName;
    f.eye_gaze = f.eye_gaze || name == XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME;
    f.timespec = f.timespec || name == XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME;
  }
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strncpy(info.applicationInfo.applicationName, "gazelod layer check", XR_MAX_APPLICATION_NAME_SIZE - 1);
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  XrInstance instance = XR_NULL_HANDLE;
  r = xrCreateInstance(&info, &instance);
  if (XR_FAILED(r)) {
    f.error = "xrCreateInstance: " + result_name(r);
    return f;
  }
  XrInstanceProperties ip{XR_TYPE_INSTANCE_PROPERTIES};
  if (XR_SUCCEEDED(xrGetInstanceProperties(instance, &ip))) {
    std::ostringstream s;
    s << ip.runtimeName << " " << XR_VERSION_MAJOR(ip.runtimeVersion) << "." << XR_VERSION_MINOR(ip.runtimeVersion)
      << "." << XR_VERSION_PATCH(ip.runtimeVersion);
    f.name = s.str();
  }
  xrDestroyInstance(instance);
  return f;
}

std::string layer_line() {
  uint32_t n = 0;
  std::vector<XrApiLayerProperties> props;
  if (XR_SUCCEEDED(xrEnumerateApiLayerProperties(0, &n, nullptr))) {
    props.assign(n, {XR_TYPE_API_LAYER_PROPERTIES});
    if (XR_FAILED(xrEnumerateApiLayerProperties(n, &n, props.data()))) props.clear();
  }
  const bool found = std::any_of(props.begin(), props.end(), [](const XrApiLayerProperties& p) {
    return std::strcmp(p.layerName, layer::kLayerName) == 0;
  });
  bool named = false;
  env_layers_without_ours(named);
  std::string s = std::string(layer::kLayerName) + ": ";
  if (!found) return s + "not found by the loader (XR_API_LAYER_PATH, or install it: docs/layer.md)";
  s += "found by the loader, ";
  if (named) return s + "enabled (XR_ENABLE_API_LAYERS)";
  if (std::getenv(layer::kLayerEnableEnv) != nullptr && std::getenv(layer::kLayerDisableEnv) == nullptr)
    return s + "enabled if installed as an implicit layer (" + layer::kLayerEnableEnv + " is set)";
  return s + "not enabled here (XR_ENABLE_API_LAYERS does not name it)";
}

int run_check(Io io) {
  io.out << "layer      " << layer_line() << "\n";
  const RuntimeFacts rt = probe_runtime();
  if (!rt.error.empty()) {
    io.out << "runtime    none found through the loader (" << rt.error
           << "; set XR_RUNTIME_JSON or an active_runtime.json)\n";
    io.out << "decision   none: the layer needs a runtime below it\n";
    return 1;
  }
  io.out << "runtime    " << rt.name << " (through the loader)\n";
  io.out << "extension  " << XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME << ": "
         << (rt.eye_gaze ? "offered by the runtime" : "not offered by the runtime") << "\n";

  const layer::ConfigResult cr = layer::load_config_from_env();
  layer::DecisionInputs in;
  in.runtime_has_extension = rt.eye_gaze;
  in.config_error = cr.error;
  in.override_runtime = cr.error.empty() && cr.config.override_runtime;
  if (!cr.error.empty())
    io.out << "config     error: " << cr.error << "\n";
  else if (cr.config.config_path.empty())
    io.out << "config     " << layer::kConfigEnv << " unset: defaults\n";
  else
    io.out << "config     " << cr.config.config_path << ": ok (override " << (cr.config.override_runtime ? "on" : "off")
           << ", freshness " << aux::whole_ms_from_ns(cr.config.effective_freshness_ns()) << " ms)\n";

  const layer::LayerConfig& c = cr.config;
  if (!layer::needs_source(in) || !cr.error.empty()) {
    io.out << "source     not opened (" << (cr.error.empty() ? "the layer would pass through" : "configuration error")
           << ")\n";
  } else if (!c.trace_path.empty()) {
    try {
      in.source = layer::open_trace_feed(c)->describe();
      io.out << "source     " << in.source << "\n";
    } catch (const std::exception& e) {
      in.source_error = std::string(layer::kTraceEnv) + ": " + e.what();
      io.out << "source     error: " << in.source_error << "\n";
    }
  } else if (!rt.timespec) {
    in.source_error = "the HID eye tracker needs XR_KHR_convert_timespec_time, which the runtime does not offer";
    io.out << "source     error: " << in.source_error << "\n";
  } else {
    in.source = "HID eye tracker (usage page 0x12)";
    const std::string found = layer::describe_hid_trackers(c);
    io.out << "source     HID: "
           << (found.empty() ? "no eye tracker (usage page 0x12) found now; gaze inactive until one is plugged in"
                             : found)
           << "\n";
  }
  const layer::Decision d = layer::decide(in);
  io.out << "decision   " << d.why << "\n";
  if (!cr.error.empty()) return 2;  // a configuration the user must fix, whatever the layer then does
  return d.mode == layer::LayerMode::pass_through || d.gaze_available ? 0 : 1;
}

const Registrar reg("layer", "The OpenXR eye-gaze API layer: check what it would do here (docs/layer.md)",
                    [](CLI::App& sub) -> Action {
                      sub.require_subcommand(1);
                      sub.add_subcommand("check", "print what XR_APILAYER_GAZELOD_eye_gaze would do on this machine");
                      return [](Io io) { return run_check(io); };
                    });

}  // namespace
}  // namespace gazelod::cli
