// SPDX-License-Identifier: Apache-2.0
// gazelod_soak: the plugin's frame loop for a long unpaced, headless session against the
// simulated OpenXR runtime (XR_MND_headless: no Vulkan), measuring resident memory as it goes.
// Per frame, as an application would: xrPollEvent, xrWaitFrame, xrBeginFrame, the scenario's
// object motion into the plugin, LodPlugin::begin_frame, xrEndFrame (no layers), end_frame.
// Nothing is recorded per frame, so memory must stay flat: the program fails (exit 1) when RSS
// after the warm-up grows by more than --max-growth-kib.
//
//   gazelod_soak --frames 324000 [--scenario FILE] [--samples 40] [--max-growth-kib 1024]
//
// Prints a progress line per sample ("soak: frame F/N t=S s rss=K KiB") and a summary line.
#include "plugin/lod_plugin.hpp"
#include "sim/simulator.hpp"

#include <openxr/openxr.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Options {
  long long frames = 324000;
  std::string scenario;  // "" = the embedded default
  int samples = 40;
  long long max_growth_kib = 1024;
};

constexpr const char* kUsage =
    "usage: gazelod_soak [--frames N] [--scenario FILE] [--samples K] [--max-growth-kib G]\n";

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr, "gazelod_soak: %s\n%s", why.c_str(), kUsage);
  std::exit(2);
}

long long parse_int(const char* flag, const char* text, long long lo, long long hi) {
  char* end = nullptr;
  const long long v = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || v < lo || v > hi)
    usage(std::string(flag) + ": '" + text + "' is not an integer in [" + std::to_string(lo) + ", " +
          std::to_string(hi) + "]");
  return v;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::printf(
          "%s  --frames N          frames to run (default 324000: one hour at 90 Hz)\n"
          "  --scenario FILE     scenario JSON (default: the embedded one)\n"
          "  --samples K         RSS samples (default 40)\n"
          "  --max-growth-kib G  RSS growth after the first tenth that fails the run (default 1024)\n",
          kUsage);
      std::exit(0);
    }
    if (a != "--frames" && a != "--scenario" && a != "--samples" && a != "--max-growth-kib")
      usage("unknown option " + a);
    if (i + 1 >= argc) usage(a + ": missing value");
    const char* v = argv[++i];
    if (a == "--frames")
      o.frames = parse_int("--frames", v, 1, 100'000'000);
    else if (a == "--scenario")
      o.scenario = v;
    else if (a == "--samples")
      o.samples = static_cast<int>(parse_int("--samples", v, 2, 10000));
    else if (a == "--max-growth-kib")
      o.max_growth_kib = parse_int("--max-growth-kib", v, 0, 1LL << 40);
    else
      usage("unknown option " + a);
  }
  return o;
}

// Resident set size of this process (VmRSS), KiB; -1 if /proc is unavailable.
long long rss_kib() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::atoll(line.c_str() + 6);
  return -1;
}

void check(XrResult r, const char* call) {
  if (XR_FAILED(r)) throw std::runtime_error(std::string(call) + " failed: XrResult " + std::to_string(r));
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) usage("--scenario: cannot open '" + path + "'");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Xr {
  XrInstance instance = XR_NULL_HANDLE;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  XrSession session = XR_NULL_HANDLE;
  XrSpace local = XR_NULL_HANDLE;
  ~Xr() {
    if (local != XR_NULL_HANDLE) xrDestroySpace(local);
    if (session != XR_NULL_HANDLE) xrDestroySession(session);
    if (instance != XR_NULL_HANDLE) xrDestroyInstance(instance);
  }
};

void open_headless(Xr& xr) {
  const char* exts[] = {"XR_MND_headless", "XR_EXT_eye_gaze_interaction"};
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strncpy(info.applicationInfo.applicationName, "gazelod_soak", XR_MAX_APPLICATION_NAME_SIZE - 1);
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  info.enabledExtensionCount = 2;
  info.enabledExtensionNames = exts;
  check(xrCreateInstance(&info, &xr.instance), "xrCreateInstance");
  XrSystemGetInfo sys{XR_TYPE_SYSTEM_GET_INFO};
  sys.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  check(xrGetSystem(xr.instance, &sys, &xr.system), "xrGetSystem");
  XrSessionCreateInfo si{XR_TYPE_SESSION_CREATE_INFO};
  si.systemId = xr.system;
  check(xrCreateSession(xr.instance, &si, &xr.session), "xrCreateSession");
  XrReferenceSpaceCreateInfo space{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  space.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  space.poseInReferenceSpace.orientation.w = 1.0f;
  check(xrCreateReferenceSpace(xr.session, &space, &xr.local), "xrCreateReferenceSpace");
}

int soak(const Options& opt) {
  const std::string text =
      opt.scenario.empty() ? std::string(gazelod::sim::default_scenario_json()) : read_file(opt.scenario);
  gazelod::sim::Simulator simulator(
      gazelod::sim::load_scenario_json(text, opt.scenario.empty() ? "<default>" : opt.scenario));
  const auto& scenario = simulator.scenario();
  const double rate_hz = scenario.display.refresh_hz;
  // The runtime serves the same scenario, unpaced, a little longer than the frames asked for.
  if (!std::getenv("XR_RUNTIME_JSON")) setenv("XR_RUNTIME_JSON", GAZELOD_XR_RUNTIME_JSON, 1);
  if (!opt.scenario.empty()) setenv("GAZELOD_SIM_SCENARIO", opt.scenario.c_str(), 1);
  setenv("GAZELOD_SIM_DURATION_S", std::to_string(static_cast<double>(opt.frames) / rate_hz + 10.0).c_str(), 1);
  setenv("GAZELOD_SIM_PACED", "0", 1);

  Xr xr;
  open_headless(xr);
  gazelod::PluginConfig config;
  config.compute_breakdown = true;  // the most work per frame, as `gazelod run` does
  auto plugin = gazelod::LodPlugin::create(xrGetInstanceProcAddr, xr.instance, xr.system, xr.session, xr.local, config);
  for (const auto& o : scenario.objects) {
    gazelod::ObjectDesc d;
    d.center_m = o.position_m;
    d.radius_m = o.radius_m;
    d.velocity_m_s = o.velocity_m_s;
    d.lods = o.lods;
    d.importance = o.importance;
    plugin->add_object(d);
  }
  std::printf("soak: %lld frames at %.6g Hz (%.1f simulated s), %zu objects, unpaced, headless\n", opt.frames, rate_hz,
              static_cast<double>(opt.frames) / rate_hz, scenario.objects.size());

  const long long every = std::max(1LL, opt.frames / opt.samples);
  std::vector<long long> rss;
  long long frames = 0, coarse = 0;
  bool running = false, done = false;
  const auto t0 = std::chrono::steady_clock::now();
  while (!done) {
    XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER};
    while (xrPollEvent(xr.instance, &e) == XR_SUCCESS) {
      if (e.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
        const auto& s = *reinterpret_cast<XrEventDataSessionStateChanged*>(&e);
        plugin->on_session_state(s.state, s.time);
        if (s.state == XR_SESSION_STATE_READY) {
          XrSessionBeginInfo b{XR_TYPE_SESSION_BEGIN_INFO};
          b.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
          check(xrBeginSession(xr.session, &b), "xrBeginSession");
          running = true;
        } else if (s.state == XR_SESSION_STATE_STOPPING) {
          check(xrEndSession(xr.session), "xrEndSession");
          running = false;
        } else if (s.state == XR_SESSION_STATE_EXITING || s.state == XR_SESSION_STATE_LOSS_PENDING) {
          done = true;
        }
      }
      e = {XR_TYPE_EVENT_DATA_BUFFER};
    }
    if (done || !running) continue;
    if (frames == opt.frames) {
      check(xrRequestExitSession(xr.session), "xrRequestExitSession");
      frames = opt.frames + 1;  // asked once
    }
    XrFrameState fs{XR_TYPE_FRAME_STATE};
    check(xrWaitFrame(xr.session, nullptr, &fs), "xrWaitFrame");
    const auto frame_t0 = std::chrono::steady_clock::now();
    check(xrBeginFrame(xr.session, nullptr), "xrBeginFrame");
    const auto objects = simulator.objects_at(fs.predictedDisplayTime - 1'000'000'000);  // runtime's base
    for (std::size_t i = 0; i < objects.size(); ++i)
      plugin->set_object_motion(static_cast<std::uint32_t>(i), objects[i].position_m, objects[i].velocity_m_s);
    const gazelod::FrameDecisions& d = plugin->begin_frame(fs.predictedDisplayTime);
    for (std::uint8_t l : d.lod) coarse += l;
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = fs.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    check(xrEndFrame(xr.session, &end), "xrEndFrame");
    plugin->end_frame(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frame_t0).count());
    if (frames >= opt.frames) continue;
    ++frames;
    if (frames % every == 0 || frames == opt.frames) {
      rss.push_back(rss_kib());
      const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("soak: frame %lld/%lld t=%.1f s rss=%lld KiB wall=%.1f s\n", frames, opt.frames,
                  static_cast<double>(frames) / rate_hz, rss.back(), wall_s);
      std::fflush(stdout);
    }
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const long long done_frames = std::min(frames, opt.frames);
  if (done_frames < opt.frames) {
    std::printf("soak: FAIL the session ended after %lld of %lld frames\n", done_frames, opt.frames);
    return 1;
  }
  // Warm-up: the first tenth of the samples (allocator pools, first-frame buffers).
  const std::size_t warm = std::max<std::size_t>(1, rss.size() / 10);
  const long long base = rss[warm - 1];
  const long long peak = *std::max_element(rss.begin() + static_cast<std::ptrdiff_t>(warm - 1), rss.end());
  const long long growth = peak - base;
  std::printf(
      "soak: %s frames=%lld wall=%.1f s (%.0f frames/s) rss_after_warmup=%lld KiB "
      "rss_final=%lld KiB rss_peak=%lld KiB growth=%lld KiB (limit %lld) mean_lod=%.3f\n",
      growth <= opt.max_growth_kib ? "PASS" : "FAIL", done_frames, wall_s, static_cast<double>(done_frames) / wall_s,
      base, rss.back(), peak, growth, opt.max_growth_kib,
      static_cast<double>(coarse) /
          static_cast<double>(done_frames * std::max<std::size_t>(1, plugin->object_count())));
  return growth <= opt.max_growth_kib ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return soak(parse(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gazelod_soak: %s\n", e.what());
    return 1;
  }
}
