// SPDX-License-Identifier: Apache-2.0
/* openxr_private_loader.c: gazelod in OpenXR mode, integrated the way an engine does it.
 *
 * Engines (Unity, Unreal, Godot) load the OpenXR loader privately: they dlopen it, take
 * xrGetInstanceProcAddr from it and reach every other xr* function through that pointer. No
 * OpenXR symbol is linked, so a plugin linking its own loader would talk to a different loader
 * instance, with other handles. gazelod links no loader: it is given the application's handles
 * and its xrGetInstanceProcAddr, and makes every OpenXR call through them. This program does
 * that (XR_NO_PROTOTYPES: a loader symbol would not even compile) with a headless session
 * (XR_MND_headless), and its own actions, as every real application has them:
 *   app-space (default)  the application owns an eye-gaze action (XR_EXT_eye_gaze_interaction)
 *                        and hands gazelod its action space (GZL_GAZE_INPUT_APP_SPACE);
 *   merge                gazelod creates its own eye-gaze action set; the application merges
 *                        gazelod's binding into its single suggestion for the eye-gaze profile
 *                        and attaches both sets in its one xrAttachSessionActionSets
 *                        (GZL_GAZE_INPUT_MERGE_BINDING).
 * After 100 frames it checks that eye gaze reaches gazelod through the private loader (gaze
 * source OPENXR in every frame where the app's own gaze pose is tracked: blinks are not) and
 * that levels differ across a grid of objects. Exit 0 on success. Run it against the simulated
 * runtime: XR_RUNTIME_JSON=build/sim/runtime/gazelod_xr_runtime.json GAZELOD_SIM_PACED=0
 */
#define _POSIX_C_SOURCE 200809L /* dlopen, dlsym, nanosleep */
#define XR_NO_PROTOTYPES        /* types only: no loader symbol can be referenced */
#include <openxr/openxr.h>

#include <gazelod/gazelod.h>

#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#define FRAME_COUNT 300
#define WARMUP_FRAMES 100 /* gaze must have arrived by then */
#define GRID 7            /* 7x7 objects, every 10 deg over +-30 deg, */
#define DISTANCE_M 40.0   /* far: the default scenario's viewer walks ahead at 1.4 m/s */

#if XR_PTR_SIZE == 8 /* gazelod takes handles as uint64_t (GZL_XR_HANDLE); back again: */
#define FROM_GZL(type, value) ((type)(uintptr_t)(value))
#else
#define FROM_GZL(type, value) ((type)(value))
#endif

/* The OpenXR functions this application uses, all from xrGetInstanceProcAddr. */
#define XR_FUNCTIONS(X)                                                                                           \
  X(DestroyInstance)                                                                                              \
  X(GetSystem) X(GetSystemProperties) X(CreateSession) X(DestroySession) X(BeginSession) X(EndSession)            \
      X(RequestExitSession) X(PollEvent) X(WaitFrame) X(BeginFrame) X(EndFrame) X(CreateReferenceSpace)           \
          X(DestroySpace) X(StringToPath) X(CreateActionSet) X(CreateAction) X(SuggestInteractionProfileBindings) \
              X(AttachSessionActionSets) X(CreateActionSpace) X(SyncActions) X(GetActionStatePose) X(LocateSpace)
static struct {
  PFN_xrGetInstanceProcAddr GetInstanceProcAddr;
  PFN_xrCreateInstance CreateInstance;
#define X(name) PFN_xr##name name;
  XR_FUNCTIONS(X)
#undef X
} xr;

static int g_failures = 0;
static gzl_plugin g_plugin = NULL;

/* Every call is checked; a failure prints the call and, for gazelod, its message (which names
 * the field at fault and the remedy), and is counted. */
static int xr_ok(XrResult r, const char* call) {
  if (XR_SUCCEEDED(r)) return 1;
  fprintf(stderr, "FAIL %s -> XrResult %d\n", call, (int)r);
  return ++g_failures, 0;
}
static int gzl_ok(gzl_result r, const char* call) {
  char msg[512] = "";
  if (r == GZL_SUCCESS) return 1;
  gzl_get_last_error(g_plugin, msg, sizeof msg, NULL);
  fprintf(stderr, "FAIL %s -> %s\n     %s\n", call, gzl_result_to_string(r), msg);
  return ++g_failures, 0;
}
#define XR(expr) xr_ok((expr), #expr)
#define GZL(expr) gzl_ok((expr), #expr)

/* xrGetInstanceProcAddr into a typed pointer (a function-pointer cast, defined in C). */
static PFN_xrVoidFunction g_fn;
#define LOAD(instance, name) \
  (XR(xr.GetInstanceProcAddr((instance), "xr" #name, &g_fn)) ? (xr.name = (PFN_xr##name)g_fn, 1) : 0)

static XrPath path(XrInstance instance, const char* s) {
  XrPath p = XR_NULL_PATH;
  XR(xr.StringToPath(instance, s, &p));
  return p;
}

static XrAction make_action(XrActionSet set, XrActionType type, const char* name, const char* localized) {
  XrActionCreateInfo info = {.type = XR_TYPE_ACTION_CREATE_INFO, .actionType = type};
  XrAction action = XR_NULL_HANDLE;
  strcpy(info.actionName, name);
  strcpy(info.localizedActionName, localized);
  XR(xr.CreateAction(set, &info, &action));
  return action;
}

int main(int argc, char** argv) {
  const int merge = argc > 1 && strcmp(argv[1], "merge") == 0;
  const char* const extensions[] = {XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME};
  const char* const eye_profile = "/interaction_profiles/ext/eye_gaze_interaction";
  void* loader;
  void* symbol = NULL;
  XrInstance instance = XR_NULL_HANDLE;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  XrSession session = XR_NULL_HANDLE;
  XrSpace local = XR_NULL_HANDLE, gaze_space = XR_NULL_HANDLE;
  XrActionSet app_set = XR_NULL_HANDLE;
  XrAction select_action, gaze_action;
  XrActiveActionSet active[2] = {{XR_NULL_HANDLE, XR_NULL_PATH}, {XR_NULL_HANDLE, XR_NULL_PATH}};
  uint32_t active_count = 1;
  XrSessionState state = XR_SESSION_STATE_UNKNOWN;
  gzl_object objects[GRID * GRID];
  uint8_t levels[GRID * GRID];
  int running = 0, quit = 0, exit_requested = 0, idle_polls = 0, i;
  int frames = 0, checked = 0, tracked_frames = 0, openxr_frames = 0, varied_frames = 0;

  if (argc > 2 || (argc == 2 && !merge && strcmp(argv[1], "app-space") != 0)) {
    fprintf(stderr, "usage: %s [app-space|merge]\n", argv[0]);
    return 2;
  }
  /* The loader, private to this program (RTLD_LOCAL: its symbols stay out of the global scope). */
  loader = dlopen("libopenxr_loader.so.1", RTLD_NOW | RTLD_LOCAL);
  if (loader == NULL || (symbol = dlsym(loader, "xrGetInstanceProcAddr")) == NULL) {
    fprintf(stderr, "FAIL loading the OpenXR loader: %s\n", dlerror());
    return 1;
  }
  memcpy(&xr.GetInstanceProcAddr, &symbol, sizeof symbol); /* POSIX: data and code pointers alike */

  if (!LOAD(XR_NULL_HANDLE, CreateInstance)) return 1;
  {
    XrInstanceCreateInfo info = {
        .type = XR_TYPE_INSTANCE_CREATE_INFO, .enabledExtensionCount = 2, .enabledExtensionNames = extensions};
    int loaded = 1;
    strcpy(info.applicationInfo.applicationName, "gazelod example");
    info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    if (!XR(xr.CreateInstance(&info, &instance))) return 1;
#define X(name) loaded = loaded && LOAD(instance, name);
    XR_FUNCTIONS(X)
#undef X
    if (!loaded) return 1;
  }
  {
    XrSystemGetInfo sys = {.type = XR_TYPE_SYSTEM_GET_INFO, .formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY};
    XrSystemEyeGazeInteractionPropertiesEXT eye = {.type = XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT};
    XrSystemProperties props = {.type = XR_TYPE_SYSTEM_PROPERTIES, .next = &eye};
    XrSessionCreateInfo info = {.type = XR_TYPE_SESSION_CREATE_INFO}; /* headless: no graphics binding */
    XrReferenceSpaceCreateInfo ref = {.type = XR_TYPE_REFERENCE_SPACE_CREATE_INFO,
                                      .referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL};
    if (!XR(xr.GetSystem(instance, &sys, &system))) return 1;
    XR(xr.GetSystemProperties(instance, system, &props));
    printf("system \"%s\", eye gaze %s, mode %s\n", props.systemName,
           eye.supportsEyeGazeInteraction ? "supported" : "NOT supported", merge ? "merge" : "app-space");
    info.systemId = system;
    if (!XR(xr.CreateSession(instance, &info, &session))) return 1;
    ref.poseInReferenceSpace.orientation.w = 1.0f;
    XR(xr.CreateReferenceSpace(session, &ref, &local));
  }
  /* The application's own input: a "select" button and its own eye-gaze pose. */
  {
    XrActionSetCreateInfo set = {.type = XR_TYPE_ACTION_SET_CREATE_INFO};
    strcpy(set.actionSetName, "example_app");
    strcpy(set.localizedActionSetName, "Example app");
    XR(xr.CreateActionSet(instance, &set, &app_set));
    select_action = make_action(app_set, XR_ACTION_TYPE_BOOLEAN_INPUT, "select", "Select");
    gaze_action = make_action(app_set, XR_ACTION_TYPE_POSE_INPUT, "eye_gaze", "Eye gaze");
    active[0].actionSet = app_set;
  }
  {
    gzl_openxr_create_info info = {.type = GZL_TYPE_OPENXR_CREATE_INFO};
    gzl_gaze_binding binding = {.type = GZL_TYPE_GAZE_BINDING};
    XrActionSuggestedBinding eye[2], hand;
    XrInteractionProfileSuggestedBinding suggest = {.type = XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
    XrActionSet sets[2];
    XrSessionActionSetsAttachInfo attach = {.type = XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO, .actionSets = sets};
    XrActionSpaceCreateInfo space = {.type = XR_TYPE_ACTION_SPACE_CREATE_INFO, .action = gaze_action};
    info.get_instance_proc_addr = (gzl_void_function)xr.GetInstanceProcAddr;
    info.instance = GZL_XR_HANDLE(instance);
    info.system_id = system;
    info.session = GZL_XR_HANDLE(session);
    info.base_space = GZL_XR_HANDLE(local);
    eye[0].action = gaze_action;
    eye[0].binding = path(instance, "/user/eyes_ext/input/gaze_ext/pose");
    if (merge) { /* gazelod comes before the one attach; its binding joins the application's */
      info.gaze_input = GZL_GAZE_INPUT_MERGE_BINDING;
      if (!GZL(gzl_create_openxr(&info, &g_plugin)) || !GZL(gzl_get_gaze_binding(g_plugin, &binding))) return 1;
      if (strcmp(binding.interaction_profile, eye_profile) != 0) {
        fprintf(stderr, "FAIL gazelod binds for %s, not %s\n", binding.interaction_profile, eye_profile);
        return 1;
      }
      eye[1].action = FROM_GZL(XrAction, binding.action);
      eye[1].binding = path(instance, binding.binding_path);
      active[1].actionSet = FROM_GZL(XrActionSet, binding.action_set);
      active_count = 2;
    }
    /* One suggestion per profile: a second one for the same profile would replace the first,
     * so both eye-gaze bindings (the app's and gazelod's, same path) go in one call. */
    suggest.interactionProfile = path(instance, eye_profile);
    suggest.countSuggestedBindings = active_count;
    suggest.suggestedBindings = eye;
    XR(xr.SuggestInteractionProfileBindings(instance, &suggest));
    hand.action = select_action;
    hand.binding = path(instance, "/user/hand/right/input/select/click");
    suggest.interactionProfile = path(instance, "/interaction_profiles/khr/simple_controller");
    suggest.countSuggestedBindings = 1;
    suggest.suggestedBindings = &hand;
    XR(xr.SuggestInteractionProfileBindings(instance, &suggest));
    /* OpenXR allows one attach per session: every set goes in it. */
    for (i = 0; i < (int)active_count; ++i) sets[i] = active[i].actionSet;
    attach.countActionSets = active_count;
    if (!XR(xr.AttachSessionActionSets(session, &attach))) return 1;
    space.poseInActionSpace.orientation.w = 1.0f;
    XR(xr.CreateActionSpace(session, &space, &gaze_space));
    if (merge) {
      if (!GZL(gzl_action_sets_attached(g_plugin))) return 1;
    } else { /* gazelod only locates the application's gaze space: no action of its own */
      info.gaze_input = GZL_GAZE_INPUT_APP_SPACE;
      info.gaze_space = GZL_XR_HANDLE(gaze_space);
      info.gaze_action = GZL_XR_HANDLE(gaze_action);
      if (!GZL(gzl_create_openxr(&info, &g_plugin))) return 1;
    }
  }
  for (i = 0; i < GRID * GRID; ++i) {
    static const gzl_level lod[4] = {{0.0, 20000}, {0.01, 5000}, {0.04, 1250}, {0.16, 312}};
    const double deg = 3.14159265358979323846 / 180.0;
    const double yaw = (i % GRID - GRID / 2) * 10.0 * deg, pitch = (i / GRID - GRID / 2) * 10.0 * deg;
    gzl_object_desc desc = {.type = GZL_TYPE_OBJECT_DESC,
                            .radius_m = 1.5,
                            .metric = GZL_LEVEL_GEOMETRIC_ERROR_M,
                            .level_count = 4,
                            .levels = lod};
    desc.center_m.x = DISTANCE_M * cos(pitch) * sin(yaw);
    desc.center_m.y = DISTANCE_M * sin(pitch);
    desc.center_m.z = -DISTANCE_M * cos(pitch) * cos(yaw);
    if (!GZL(gzl_add_object(g_plugin, &desc, &objects[i]))) return 1;
  }

  /* The event loop drives the session; frames run while it runs. */
  while (!quit) {
    XrEventDataBuffer event = {.type = XR_TYPE_EVENT_DATA_BUFFER};
    XrResult r;
    while ((r = xr.PollEvent(instance, &event)) == XR_SUCCESS) {
      const XrEventDataSessionStateChanged* changed = (const XrEventDataSessionStateChanged*)&event;
      if (event.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) quit = 1;
      if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
        state = changed->state;
        GZL(gzl_on_session_state(g_plugin, (int32_t)state, changed->time));
        if (state == XR_SESSION_STATE_READY) {
          XrSessionBeginInfo begin = {.type = XR_TYPE_SESSION_BEGIN_INFO,
                                      .primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO};
          running = XR(xr.BeginSession(session, &begin));
        } else if (state == XR_SESSION_STATE_STOPPING) { /* our request, or the runtime's end */
          XR(xr.EndSession(session));
          running = 0;
        } else if (state == XR_SESSION_STATE_EXITING || state == XR_SESSION_STATE_LOSS_PENDING) {
          quit = 1;
        }
      }
      event.type = XR_TYPE_EVENT_DATA_BUFFER;
      event.next = NULL;
    }
    if (!XR(r) || quit) break;
    if (!running) { /* not begun yet, or ended: wait for the next state, not for ever */
      const struct timespec ms = {0, 1000000L};
      if (++idle_polls > 5000 || g_failures > 0) break;
      nanosleep(&ms, NULL);
      continue;
    }
    if (frames == FRAME_COUNT && !exit_requested) { /* done: end the session the OpenXR way */
      exit_requested = 1;
      if (!XR(xr.RequestExitSession(session))) break;
    }
    {
      XrFrameWaitInfo wait = {.type = XR_TYPE_FRAME_WAIT_INFO};
      XrFrameState frame = {.type = XR_TYPE_FRAME_STATE};
      XrFrameBeginInfo begin = {.type = XR_TYPE_FRAME_BEGIN_INFO};
      XrFrameEndInfo end = {.type = XR_TYPE_FRAME_END_INFO, .environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE};
      XrActionsSyncInfo sync = {.type = XR_TYPE_ACTIONS_SYNC_INFO, .activeActionSets = active};
      gzl_frame_info info = {.type = GZL_TYPE_FRAME_INFO};
      XrActionStateGetInfo get = {.type = XR_TYPE_ACTION_STATE_GET_INFO, .action = gaze_action};
      XrActionStatePose pose = {.type = XR_TYPE_ACTION_STATE_POSE};
      XrSpaceLocation gaze = {.type = XR_TYPE_SPACE_LOCATION};
      int varied = 0, tracked;
      if (!XR(xr.WaitFrame(session, &wait, &frame)) || !XR(xr.BeginFrame(session, &begin))) break;
      sync.countActiveActionSets = active_count; /* the app's set, and gazelod's when merged */
      XR(xr.SyncActions(session, &sync));        /* XR_SESSION_NOT_FOCUSED is a success code */
      GZL(gzl_begin_frame_openxr(g_plugin, frame.predictedDisplayTime));
      /* The application's own use of its gaze action (gaze UI, say): the runtime delivers no
       * pose during a blink, and then gazelod may rightly fall back to head-fixed gaze. */
      tracked = XR(xr.GetActionStatePose(session, &get, &pose)) && pose.isActive &&
                XR(xr.LocateSpace(gaze_space, local, frame.predictedDisplayTime, &gaze)) &&
                (gaze.locationFlags & XR_SPACE_LOCATION_ORIENTATION_VALID_BIT) != 0;
      GZL(gzl_get_levels(g_plugin, GRID * GRID, objects, levels));
      GZL(gzl_get_frame_info(g_plugin, &info));
      /* (A renderer would draw objects[i] at levels[i] here and submit its layers.) */
      end.displayTime = frame.predictedDisplayTime;
      XR(xr.EndFrame(session, &end));
      for (i = 1; i < GRID * GRID; ++i) varied |= levels[i] != levels[0];
      if (frames >= WARMUP_FRAMES && frames < FRAME_COUNT) {
        ++checked;
        tracked_frames += tracked;
        openxr_frames += tracked && info.gaze_source == GZL_GAZE_SOURCE_OPENXR;
        varied_frames += varied;
      }
      if (frames == FRAME_COUNT - 1) {
        printf("frame %llu: gaze source %d, eye motion %d, uncertainty %.2f deg, triangles %llu of %llu\n",
               (unsigned long long)info.frame_index, (int)info.gaze_source, (int)info.eye_motion,
               info.gaze_uncertainty_deg, (unsigned long long)info.triangles_drawn,
               (unsigned long long)info.triangles_full);
        for (i = 0; i < GRID * GRID; ++i) printf(i % GRID == GRID - 1 ? " %u\n" : " %u", (unsigned)levels[i]);
      }
      ++frames;
    }
  }

  printf(
      "%d frames; in frames %d..%d (%d): eye gaze tracked in %d, gaze source OPENXR in %d of those; "
      "levels differing across objects in %d\n",
      frames, WARMUP_FRAMES, FRAME_COUNT - 1, checked, tracked_frames, openxr_frames, varied_frames);
  if (checked < FRAME_COUNT - WARMUP_FRAMES) {
    fprintf(stderr, "FAIL the session ended after %d frames, before the %d to check\n", frames, FRAME_COUNT);
    ++g_failures;
  }
  if (tracked_frames < checked / 2 || openxr_frames != tracked_frames || varied_frames != checked) {
    fprintf(stderr,
            "FAIL eye gaze through the application's loader must drive every tracked frame, "
            "and levels must differ across objects in every frame\n");
    ++g_failures;
  }

  /* gazelod releases its spaces and action set while the session and instance still exist. */
  GZL(gzl_shutdown(g_plugin));
  if (gaze_space != XR_NULL_HANDLE) XR(xr.DestroySpace(gaze_space));
  if (local != XR_NULL_HANDLE) XR(xr.DestroySpace(local));
  XR(xr.DestroySession(session));
  XR(xr.DestroyInstance(instance));
  gzl_destroy(g_plugin);
  dlclose(loader);
  printf("%s: %d failure(s)\n", g_failures == 0 ? "PASS" : "FAIL", g_failures);
  return g_failures == 0 ? 0 : 1;
}
