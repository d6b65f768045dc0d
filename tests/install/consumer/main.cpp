// SPDX-License-Identifier: Apache-2.0
// gazelod_consumer: an OpenXR application built against an INSTALLED gazelod (find_package or
// pkg-config), run by tests/install/install_test.sh. Headless (XR_MND_headless, no graphics)
// on whatever runtime XR_RUNTIME_JSON names, which must be set: the test points it at the
// installed simulated runtime's manifest, with a still head and centred gaze (still_gaze.json).
//
//   XR_RUNTIME_JSON=<prefix>/share/openxr/1/gazelod_xr_runtime.json gazelod_consumer [SCENARIO]
//
// The application owns its OpenXR loader (it links it) and hands gazelod only handles and its
// xrGetInstanceProcAddr, through the installed C ABI's C++17 wrapper.
//
// Registers three objects with the same four-level chain (radius 0.4 m), kept each frame
// relative to the gaze the plugin reported the frame before: "near" on the gaze at 10 m, "far"
// on the gaze at 80 m, "peripheral" 30 deg off the gaze at 10 m. Checks every frame that the levels are in
// range, and at the end that the gaze came from the runtime, that the near one is at full
// detail, the far one coarser because of its size and the peripheral one coarser because of
// its eccentricity.
// Exit 0 when all hold, 1 otherwise.
#include <gazelod/gazelod.hpp>

#include <openxr/openxr.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace {

void check(XrResult r, const char* call) {
  if (XR_FAILED(r)) throw std::runtime_error(std::string(call) + " failed: XrResult " + std::to_string(r));
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
  std::strncpy(info.applicationInfo.applicationName, "gazelod_consumer", XR_MAX_APPLICATION_NAME_SIZE - 1);
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  info.enabledExtensionCount = 2;
  info.enabledExtensionNames = exts;
  check(xrCreateInstance(&info, &xr.instance), "xrCreateInstance");
  XrInstanceProperties props{XR_TYPE_INSTANCE_PROPERTIES};
  check(xrGetInstanceProperties(xr.instance, &props), "xrGetInstanceProperties");
  std::printf("consumer: runtime \"%s\"\n", props.runtimeName);
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

// Four levels, each removing half the detail of the one before (cycles per object diameter).
gzl_object_desc object_desc() {
  static const gzl_level levels[4] = {{0.0, 20000}, {35.36, 5000}, {17.68, 1250}, {8.83, 312}};
  gzl_object_desc d{};
  d.type = GZL_TYPE_OBJECT_DESC;
  d.center_m = {0.0, 0.0, -10.0};
  d.radius_m = 0.4;
  d.metric = GZL_LEVEL_REMOVED_CYCLES_PER_DIAMETER;
  d.level_count = 4;
  d.levels = levels;
  return d;
}

// Three-vectors without a maths library: the application brings its own.
struct Vec {
  double x, y, z;
};
Vec add(Vec a, Vec b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Vec scale(Vec a, double s) {
  return {a.x * s, a.y * s, a.z * s};
}
Vec cross(Vec a, Vec b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec normalize(Vec a) {
  return scale(a, 1.0 / std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z));
}
gzl_vec3 to_gzl(Vec a) {
  return {a.x, a.y, a.z};
}

constexpr int kLevels = 4;
constexpr int kFrames = 240;  // frames with objects placed around the gaze
constexpr double kPi = 3.14159265358979323846;

int run() {
  const char* manifest = std::getenv("XR_RUNTIME_JSON");
  if (manifest == nullptr || *manifest == '\0')
    throw std::runtime_error("XR_RUNTIME_JSON is not set (point it at gazelod_xr_runtime.json)");
  std::printf("consumer: XR_RUNTIME_JSON=%s\n", manifest);

  Xr xr;
  open_headless(xr);
  gzl_openxr_create_info info{};
  info.type = GZL_TYPE_OPENXR_CREATE_INFO;
  info.get_instance_proc_addr = reinterpret_cast<gzl_void_function>(xrGetInstanceProcAddr);
  info.instance = GZL_XR_HANDLE(xr.instance);
  info.system_id = xr.system;
  info.session = GZL_XR_HANDLE(xr.session);
  info.base_space = GZL_XR_HANDLE(xr.local);
  info.gaze_input = GZL_GAZE_INPUT_PLUGIN_ACTIONS;  // this application has no action sets
  gazelod::Plugin plugin = gazelod::Plugin::openxr(info);
  const gzl_object_desc desc = object_desc();
  const gzl_object ids[3] = {plugin.add_object(desc), plugin.add_object(desc), plugin.add_object(desc)};
  const gzl_object near_id = ids[0], far_id = ids[1], periph_id = ids[2];

  int placed_frames = 0, bad = 0;
  bool running = false, done = false, asked_exit = false, have_gaze = false;
  Vec eye{0.0, 0.0, 0.0}, gaze{0.0, 0.0, -1.0};
  std::uint8_t last[3] = {0, 0, 0};
  gzl_gaze_source source = GZL_GAZE_SOURCE_HEAD_FIXED;
  double xi_cpd = 0.0;
  while (!done) {
    XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER};
    while (xrPollEvent(xr.instance, &e) == XR_SUCCESS) {
      if (e.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
        const auto& s = *reinterpret_cast<XrEventDataSessionStateChanged*>(&e);
        plugin.on_session_state(s.state, s.time);
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
    if (placed_frames >= kFrames) {
      if (!asked_exit) check(xrRequestExitSession(xr.session), "xrRequestExitSession");
      asked_exit = true;
    }
    XrFrameState fs{XR_TYPE_FRAME_STATE};
    check(xrWaitFrame(xr.session, nullptr, &fs), "xrWaitFrame");
    check(xrBeginFrame(xr.session, nullptr), "xrBeginFrame");
    if (have_gaze) {  // around last frame's gaze: the scenario holds head and eyes still
      const Vec right = normalize(cross(gaze, Vec{0.0, 1.0, 0.0}));
      const double a = 30.0 * kPi / 180.0;
      const Vec off = add(scale(gaze, std::cos(a)), scale(right, std::sin(a)));
      const gzl_vec3 still{0.0, 0.0, 0.0};
      plugin.set_object_motion(near_id, to_gzl(add(eye, scale(gaze, 10.0))), still);
      plugin.set_object_motion(far_id, to_gzl(add(eye, scale(gaze, 80.0))), still);
      plugin.set_object_motion(periph_id, to_gzl(add(eye, scale(off, 10.0))), still);
    }
    plugin.begin_frame(static_cast<int64_t>(fs.predictedDisplayTime));
    std::uint8_t levels[3];
    plugin.levels(3, ids, levels);
    const gzl_frame_info info_now = plugin.frame_info();
    for (std::size_t i = 0; i < 3; ++i) {
      if (levels[i] >= kLevels && bad++ < 5)
        std::printf("consumer: FAIL object %zu: level %d of %d\n", i, levels[i], kLevels);
    }
    if (!asked_exit) {  // the decisions checked: the last frame before the session winds down
      for (std::size_t i = 0; i < 3; ++i) last[i] = levels[i];
      source = info_now.gaze_source;
      xi_cpd = info_now.xi_cpd;
    }
    if (info_now.head_valid && info_now.gaze_source == GZL_GAZE_SOURCE_OPENXR) {
      if (have_gaze) ++placed_frames;
      have_gaze = true;
      eye = {info_now.eye_position_base_m.x, info_now.eye_position_base_m.y, info_now.eye_position_base_m.z};
      gaze = normalize(
          Vec{info_now.gaze_direction_base.x, info_now.gaze_direction_base.y, info_now.gaze_direction_base.z});
    }
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = fs.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    check(xrEndFrame(xr.session, &end), "xrEndFrame");
    plugin.end_frame(2.0);
  }
  plugin.shutdown();  // before the session and the instance go

  std::printf("consumer: %d frames around the gaze, source %d, xi %.1f cpd; near L%d, far L%d, peripheral L%d\n",
              placed_frames, static_cast<int>(source), xi_cpd, last[0], last[1], last[2]);
  bool ok = bad == 0;
  auto expect = [&ok](bool cond, const char* what) {
    if (!cond) {
      std::printf("consumer: FAIL %s\n", what);
      ok = false;
    }
  };
  expect(placed_frames >= kFrames, "the session ended before the frames asked for");
  expect(source == GZL_GAZE_SOURCE_OPENXR, "gaze did not come from the runtime");
  expect(last[0] == 0, "the near object at the gaze is not at full detail");
  expect(last[1] > last[0], "the far object is not coarser than the near one");
  expect(last[2] > last[0], "the peripheral object is not coarser than the one at the gaze");
  std::printf("consumer: %s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) setenv("GAZELOD_SIM_SCENARIO", argv[1], 1);
  try {
    return run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gazelod_consumer: %s\n", e.what());
    return 1;
  }
}
