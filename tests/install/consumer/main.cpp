// gazelod_consumer: an OpenXR application built against an INSTALLED gazelod (find_package or
// pkg-config), run by tests/install/install_test.sh. Headless (XR_MND_headless, no graphics)
// on whatever runtime XR_RUNTIME_JSON names, which must be set: the test points it at the
// installed simulated runtime's manifest, with a still head and centred gaze (still_gaze.json).
//
//   XR_RUNTIME_JSON=<prefix>/share/openxr/1/gazelod_xr_runtime.json gazelod_consumer [SCENARIO]
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

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

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
gazelod::ObjectDesc object_desc() {
  gazelod::ObjectDesc d;
  d.center_m = glm::dvec3(0.0, 0.0, -10.0);
  d.radius_m = 0.4;
  d.lods = {{20000, 10002, gazelod::lod::DetailKind::removed_cycles_per_diameter, 0.0},
            {5000, 2502, gazelod::lod::DetailKind::removed_cycles_per_diameter, 35.36},
            {1250, 627, gazelod::lod::DetailKind::removed_cycles_per_diameter, 17.68},
            {312, 158, gazelod::lod::DetailKind::removed_cycles_per_diameter, 8.83}};
  return d;
}

constexpr int kLevels = 4;
constexpr int kFrames = 240;       // frames with objects placed around the gaze
constexpr double kPi = 3.14159265358979323846;

int run() {
  const char* manifest = std::getenv("XR_RUNTIME_JSON");
  if (manifest == nullptr || *manifest == '\0')
    throw std::runtime_error("XR_RUNTIME_JSON is not set (point it at gazelod_xr_runtime.json)");
  std::printf("consumer: XR_RUNTIME_JSON=%s\n", manifest);

  Xr xr;
  open_headless(xr);
  auto plugin = gazelod::LodPlugin::create(xr.instance, xr.system, xr.session, xr.local, gazelod::PluginConfig{});
  const std::uint32_t near_id = plugin->add_object(object_desc());
  const std::uint32_t far_id = plugin->add_object(object_desc());
  const std::uint32_t periph_id = plugin->add_object(object_desc());

  int placed_frames = 0, bad = 0;
  bool running = false, done = false, asked_exit = false, have_gaze = false;
  glm::dvec3 eye{0.0}, gaze{0.0, 0.0, -1.0};
  std::uint8_t last[3] = {0, 0, 0}, why[3] = {0, 0, 0};
  gazelod::GazeSourceKind source = gazelod::GazeSourceKind::head_fixed;
  bool gaze_valid = false;
  double xi_cpd = 0.0;
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
    if (placed_frames >= kFrames) {
      if (!asked_exit) check(xrRequestExitSession(xr.session), "xrRequestExitSession");
      asked_exit = true;
    }
    XrFrameState fs{XR_TYPE_FRAME_STATE};
    check(xrWaitFrame(xr.session, nullptr, &fs), "xrWaitFrame");
    check(xrBeginFrame(xr.session, nullptr), "xrBeginFrame");
    if (have_gaze) {  // around last frame's gaze: the scenario holds head and eyes still
      const glm::dvec3 right = glm::normalize(glm::cross(gaze, glm::dvec3(0.0, 1.0, 0.0)));
      const double a = 30.0 * kPi / 180.0;
      const glm::dvec3 off = std::cos(a) * gaze + std::sin(a) * right;
      const glm::dvec3 still{0.0};
      plugin->set_object_motion(near_id, eye + 10.0 * gaze, still);
      plugin->set_object_motion(far_id, eye + 80.0 * gaze, still);
      plugin->set_object_motion(periph_id, eye + 10.0 * off, still);
    }
    const gazelod::FrameDecisions& d = plugin->begin_frame(fs.predictedDisplayTime);
    const gazelod::FrameDiagnostics& diag = plugin->diagnostics();
    if (d.lod.size() != 3 || d.limited_by.size() != 3) {
      std::printf("consumer: FAIL begin_frame gave %zu levels and %zu reasons for 3 objects\n",
                  d.lod.size(), d.limited_by.size());
      return 1;
    }
    for (std::size_t i = 0; i < 3; ++i) {
      if (d.lod[i] >= kLevels || d.limited_by[i] > 5) {
        if (bad++ < 5)
          std::printf("consumer: FAIL object %zu: level %d of %d, limited_by %d\n", i, d.lod[i], kLevels,
                      d.limited_by[i]);
      }
    }
    if (!asked_exit) {  // the decisions checked: the last frame before the session winds down
      for (std::size_t i = 0; i < 3; ++i) {
        last[i] = d.lod[i];
        why[i] = d.limited_by[i];
      }
      source = d.gaze_source;
      gaze_valid = d.gaze_valid;
      xi_cpd = diag.xi_cpd;
    }
    if (diag.head_valid && d.gaze_valid) {
      if (have_gaze) ++placed_frames;
      have_gaze = true;
      eye = diag.eye_position_world;
      gaze = glm::normalize(diag.gaze_direction_world);
    }
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = fs.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    check(xrEndFrame(xr.session, &end), "xrEndFrame");
    plugin->end_frame(2.0);
  }

  std::printf("consumer: %d frames around the gaze, source %s (valid %d), xi %.1f cpd; "
              "near L%d (limited by %d), far L%d (%d), peripheral L%d (%d)\n",
              placed_frames, gazelod::to_string(source), gaze_valid ? 1 : 0, xi_cpd,
              last[0], why[0], last[1], why[1], last[2], why[2]);
  bool ok = bad == 0;
  auto expect = [&ok](bool cond, const char* what) {
    if (!cond) {
      std::printf("consumer: FAIL %s\n", what);
      ok = false;
    }
  };
  expect(placed_frames >= kFrames, "the session ended before the frames asked for");
  expect(source == gazelod::GazeSourceKind::openxr && gaze_valid, "gaze did not come from the runtime");
  expect(last[0] == 0, "the near object at the gaze is not at full detail");
  expect(last[1] > last[0], "the far object is not coarser than the near one");
  expect(last[2] > last[0], "the peripheral object is not coarser than the one at the gaze");
  using gazelod::lod::Criterion;
  expect(why[1] == static_cast<std::uint8_t>(Criterion::size), "the far object's level is not limited by its size");
  expect(why[2] == static_cast<std::uint8_t>(Criterion::eccentricity) ||
             why[2] == static_cast<std::uint8_t>(Criterion::combined),
         "the peripheral object's level is not limited by eccentricity");
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
