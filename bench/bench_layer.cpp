// SPDX-License-Identifier: Apache-2.0
// The eye-gaze API layer's added cost (layer/), on the unpaced headless simulated runtime
// without eye gaze, through the Khronos loader, each case against its baseline in the same
// process:
//  - per xrLocateSpace: the layer's gaze space in LOCAL against a plain VIEW space in LOCAL
//    without the layer (and that VIEW locate with the layer loaded: its pass-down cost);
//  - per frame: xrWaitFrame + xrBeginFrame + xrEndFrame + xrSyncActions with the layer serving
//    the gaze action against the same loop without the layer.
// The layer replays a 1200 s trace written at start (GAZELOD_LAYER_TRACE). One instance at a
// time (the loader's rule), so each benchmark makes its own. Prints the ratios at the end.
#include "gaze/trace_reader.hpp"
#include "gaze/trace_writer.hpp"

#include <openxr/openxr.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace {

std::string trace_path() {
  return std::string(GAZELOD_BINARY_DIR) + "/bench/bench_layer_trace.csv";
}

void write_trace() {
  std::ofstream out(trace_path());
  gazelod::gaze::TraceWriterOptions o;
  o.write_head = false;
  gazelod::gaze::TraceWriter w(out, o);
  for (int i = 0; i < 72'000; ++i) {  // 1200 s at 60 Hz: longer than any frame loop below
    gazelod::gaze::TraceRecord r;
    const double t = i / 60.0;
    r.gaze.t_ns = static_cast<std::int64_t>(std::llround(t * 1e9));
    r.gaze.direction = gazelod::gaze::direction_from_yaw_pitch_deg(10.0 * std::sin(0.7 * t), 3.0 * std::cos(0.3 * t));
    r.gaze.valid = true;
    r.gaze.confidence = 1.0f;
    w.write(r);
  }
}

struct Client {
  XrInstance instance = XR_NULL_HANDLE;
  XrSession session = XR_NULL_HANDLE;
  XrActionSet set = XR_NULL_HANDLE;
  XrAction gaze = XR_NULL_HANDLE;
  XrSpace gaze_space = XR_NULL_HANDLE, view = XR_NULL_HANDLE, local = XR_NULL_HANDLE;
  XrTime last = 0;
  bool ok = false;

  explicit Client(bool layer) {
    setenv("XR_RUNTIME_JSON", GAZELOD_XR_RUNTIME_JSON, 1);
    setenv("GAZELOD_SIM_PACED", "0", 1);
    setenv("GAZELOD_SIM_DURATION_S", "1000000", 1);
    setenv("GAZELOD_SIM_EYE_GAZE_EXTENSION", "0", 1);
    if (layer) {
      setenv("XR_API_LAYER_PATH", GAZELOD_LAYER_MANIFEST_DIR, 1);
      setenv("XR_ENABLE_API_LAYERS", "XR_APILAYER_GAZELOD_eye_gaze", 1);
      setenv("GAZELOD_LAYER_TRACE", trace_path().c_str(), 1);
    } else {
      unsetenv("XR_ENABLE_API_LAYERS");
    }
    // Without the layer the runtime has no eye gaze: the same action set, nothing bound.
    const char* ext[] = {XR_MND_HEADLESS_EXTENSION_NAME, XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME};
    XrInstanceCreateInfo ci{XR_TYPE_INSTANCE_CREATE_INFO};
    std::strcpy(ci.applicationInfo.applicationName, "bench_layer");
    ci.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    ci.enabledExtensionCount = layer ? 2 : 1;
    ci.enabledExtensionNames = ext;
    if (xrCreateInstance(&ci, &instance) != XR_SUCCESS) return;
    XrSystemGetInfo sgi{XR_TYPE_SYSTEM_GET_INFO};
    sgi.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    XrSystemId system = XR_NULL_SYSTEM_ID;
    if (xrGetSystem(instance, &sgi, &system) != XR_SUCCESS) return;
    XrSessionCreateInfo sci{XR_TYPE_SESSION_CREATE_INFO};
    sci.systemId = system;
    if (xrCreateSession(instance, &sci, &session) != XR_SUCCESS) return;
    XrActionSetCreateInfo asi{XR_TYPE_ACTION_SET_CREATE_INFO};
    std::strcpy(asi.actionSetName, "gaze");
    std::strcpy(asi.localizedActionSetName, "Gaze");
    if (xrCreateActionSet(instance, &asi, &set) != XR_SUCCESS) return;
    XrActionCreateInfo aci{XR_TYPE_ACTION_CREATE_INFO};
    aci.actionType = XR_ACTION_TYPE_POSE_INPUT;
    std::strcpy(aci.actionName, "gaze");
    std::strcpy(aci.localizedActionName, "Gaze");
    if (xrCreateAction(set, &aci, &gaze) != XR_SUCCESS) return;
    if (layer) {
      XrPath profile = XR_NULL_PATH, binding = XR_NULL_PATH;
      xrStringToPath(instance, "/interaction_profiles/ext/eye_gaze_interaction", &profile);
      xrStringToPath(instance, "/user/eyes_ext/input/gaze_ext/pose", &binding);
      const XrActionSuggestedBinding b{gaze, binding};
      XrInteractionProfileSuggestedBinding sb{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
      sb.interactionProfile = profile;
      sb.countSuggestedBindings = 1;
      sb.suggestedBindings = &b;
      if (xrSuggestInteractionProfileBindings(instance, &sb) != XR_SUCCESS) return;
    }
    XrSessionActionSetsAttachInfo at{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    at.countActionSets = 1;
    at.actionSets = &set;
    if (xrAttachSessionActionSets(session, &at) != XR_SUCCESS) return;
    XrActionSpaceCreateInfo as{XR_TYPE_ACTION_SPACE_CREATE_INFO};
    as.action = gaze;
    as.poseInActionSpace.orientation.w = 1.0f;
    if (xrCreateActionSpace(session, &as, &gaze_space) != XR_SUCCESS) return;
    XrReferenceSpaceCreateInfo rs{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    rs.poseInReferenceSpace.orientation.w = 1.0f;
    rs.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
    xrCreateReferenceSpace(session, &rs, &view);
    rs.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    xrCreateReferenceSpace(session, &rs, &local);
    XrSessionBeginInfo bi{XR_TYPE_SESSION_BEGIN_INFO};
    bi.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    if (xrBeginSession(session, &bi) != XR_SUCCESS) return;
    drain();
    frame();
    ok = sync() == XR_SUCCESS;
  }
  ~Client() {
    if (session != XR_NULL_HANDLE) xrDestroySession(session);
    if (instance != XR_NULL_HANDLE) xrDestroyInstance(instance);
  }
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;
  void drain() {
    XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER};
    while (xrPollEvent(instance, &e) == XR_SUCCESS) e = {XR_TYPE_EVENT_DATA_BUFFER};
  }
  XrTime frame() {
    XrFrameState fs{XR_TYPE_FRAME_STATE};
    xrWaitFrame(session, nullptr, &fs);
    xrBeginFrame(session, nullptr);
    XrFrameEndInfo fe{XR_TYPE_FRAME_END_INFO};
    fe.displayTime = fs.predictedDisplayTime;
    fe.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    xrEndFrame(session, &fe);
    return last = fs.predictedDisplayTime;
  }
  XrResult sync() {
    const XrActiveActionSet active{set, XR_NULL_PATH};
    XrActionsSyncInfo info{XR_TYPE_ACTIONS_SYNC_INFO};
    info.countActiveActionSets = 1;
    info.activeActionSets = &active;
    return xrSyncActions(session, &info);
  }
};

// One located space per iteration, at the latest frame's time.
void locate(benchmark::State& state, bool layer, bool gaze_space) {
  Client c(layer);
  if (!c.ok) return state.SkipWithError("client set-up failed (runtime or layer missing?)");
  const XrSpace space = gaze_space ? c.gaze_space : c.view;
  std::int64_t tracked = 0;
  for (auto _ : state) {
    XrEyeGazeSampleTimeEXT st{XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT};
    XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION, gaze_space ? &st : nullptr};
    xrLocateSpace(space, c.local, c.last, &loc);
    tracked += (loc.locationFlags & XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT) != 0;
    benchmark::DoNotOptimize(loc.pose);
  }
  if (tracked != static_cast<std::int64_t>(state.iterations())) state.SkipWithError("a locate was not tracked");
  state.SetItemsProcessed(state.iterations());
}

void BM_LocateView_NoLayer(benchmark::State& s) {
  locate(s, false, false);
}
void BM_LocateView_Layer(benchmark::State& s) {
  locate(s, true, false);
}
void BM_LocateGaze_Layer(benchmark::State& s) {
  locate(s, true, true);
}

// wait + begin + end + sync per iteration.
void frames(benchmark::State& state, bool layer) {
  Client c(layer);
  if (!c.ok) return state.SkipWithError("client set-up failed (runtime or layer missing?)");
  for (auto _ : state) {
    c.frame();
    benchmark::DoNotOptimize(c.sync());
  }
  // After the loop (not timed): is the layer's gaze action active, i.e. was it doing its work?
  XrActionStateGetInfo gi{XR_TYPE_ACTION_STATE_GET_INFO};
  gi.action = c.gaze;
  XrActionStatePose st{XR_TYPE_ACTION_STATE_POSE};
  xrGetActionStatePose(c.session, &gi, &st);
  if (layer && !st.isActive) state.SkipWithError("the gaze action went inactive (trace too short?)");
  c.drain();
  state.SetItemsProcessed(state.iterations());
}

void BM_Frame_NoLayer(benchmark::State& s) {
  frames(s, false);
}
void BM_Frame_Layer(benchmark::State& s) {
  frames(s, true);
}

BENCHMARK(BM_LocateView_NoLayer);
BENCHMARK(BM_LocateView_Layer);
BENCHMARK(BM_LocateGaze_Layer);
// Fixed counts keep the simulated time (11 ms a frame) inside the trace.
BENCHMARK(BM_Frame_NoLayer)->Iterations(50'000);
BENCHMARK(BM_Frame_Layer)->Iterations(50'000);

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    // The median over --benchmark_repetitions when there are several, else the one run.
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      if (r.run_type == Run::RT_Iteration && median_.count(r.run_name.str()) == 0)
        ns_[r.run_name.str()] = r.GetAdjustedCPUTime();
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name == "median") {
        median_[r.run_name.str()] = true;
        ns_[r.run_name.str()] = r.GetAdjustedCPUTime();
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
  void print_ratios() const {
    auto ratio = [&](const char* what, const char* a, const char* b) {
      const auto ia = ns_.find(a), ib = ns_.find(b);
      if (ia == ns_.end() || ib == ns_.end() || !(ib->second > 0.0)) {
        std::printf("%-58s n/a\n", what);
        return;
      }
      std::printf("%-58s %.3f  (%.0f ns / %.0f ns, +%.0f ns)\n", what, ia->second / ib->second, ia->second, ib->second,
                  ia->second - ib->second);
    };
    std::printf("\nratios (CPU time per operation%s):\n", median_.empty() ? "" : ", medians");
    ratio("xrLocateSpace gaze (layer) / VIEW (no layer)", "BM_LocateGaze_Layer", "BM_LocateView_NoLayer");
    ratio("xrLocateSpace VIEW (layer) / VIEW (no layer)", "BM_LocateView_Layer", "BM_LocateView_NoLayer");
    ratio("frame + xrSyncActions (layer) / (no layer)", "BM_Frame_Layer/iterations:50000",
          "BM_Frame_NoLayer/iterations:50000");
  }

 private:
  std::map<std::string, double> ns_;
  std::map<std::string, bool> median_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  std::filesystem::create_directories(std::filesystem::path(trace_path()).parent_path());
  write_trace();
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratios();
  benchmark::Shutdown();
  return 0;
}
