// SPDX-License-Identifier: Apache-2.0
/* data_mode.c: gazelod in data mode, with no OpenXR at all.
 *
 * What an application with its own display and eye tracker (a desktop simulator, a custom HMD
 * SDK, a replay tool) does: describe the display once (gzl_create_data), register objects with
 * their LOD chains, push timestamped gaze samples as the tracker delivers them, and each frame
 * give the head pose (gzl_begin_frame_data), then read the levels to draw and the foveal cone
 * (for a foveated inset or a variable-rate-shading image).
 *
 * The scene: a 3x3 grid of objects 3 m ahead, 1.2 m apart, with geometric-error LODs, and one
 * object with engine-style LODs (a Unity LODGroup's screen-height shares). The head is still;
 * the eyes fixate the grid's left object, make one saccade, and fixate its right object.
 * The program checks what a user would see: the fixated object is drawn finer than the one
 * on the opposite side, and the foveal cone follows the gaze. It then shows the error path
 * (an out-of-order sample, a removed handle). Exit status 0 only if every check holds.
 */
#include <gazelod/gazelod.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846
#define FRAME_NS 11111111LL   /* 90 Hz display */
#define SAMPLE_NS 8333333LL   /* 120 Hz eye tracker */
#define LATENCY_NS 25000000LL /* the frame is decided ~25 ms before it is shown */
/* Each half lasts 1.5 s. An object no longer fixated coarsens after the switch policy's
 * 0.2 s hold, then waits up to 1 s for a saccade or blink to hide the change, so a
 * steady fixation needs up to 1.2 s before the far object is drawn coarser. */
#define HALF_FRAMES 135
#define GRID 3
#define GRID_SPACING_M 1.2
#define GRID_DISTANCE_M 3.0

static int g_failures = 0;

/* Every call goes through here: a failure prints the result and gazelod's message (which names
 * the field at fault), and is counted, so the run goes on and reports everything it saw. */
static int ok(gzl_plugin plugin, gzl_result r, const char* call) {
  char msg[512];
  if (r == GZL_SUCCESS) return 1;
  msg[0] = '\0';
  gzl_get_last_error(plugin, msg, sizeof msg, NULL);
  fprintf(stderr, "FAIL %s -> %s\n     %s\n", call, gzl_result_to_string(r), msg);
  ++g_failures;
  return 0;
}
#define CALL(plugin, expr) ok((plugin), (expr), #expr)

static void check(int condition, const char* what) {
  printf("%s %s\n", condition ? "ok  " : "FAIL", what);
  if (!condition) ++g_failures;
}

/* Where the eyes look at time t (head space = base space: the head is still at the origin).
 * A saccade follows the main sequence: duration 21 ms + 2.2 ms/deg, smooth velocity profile. */
static gzl_vec3 gaze_at(int64_t t_ns, int64_t saccade_start_ns, double yaw_from, double yaw_to) {
  const double amplitude_deg = fabs(yaw_to - yaw_from) * 180.0 / PI;
  const double duration_ns = (0.021 + 0.0022 * amplitude_deg) * 1e9;
  double f = (double)(t_ns - saccade_start_ns) / duration_ns;
  double yaw;
  gzl_vec3 d;
  if (f < 0.0) f = 0.0;
  if (f > 1.0) f = 1.0;
  yaw = yaw_from + (yaw_to - yaw_from) * (0.5 - 0.5 * cos(PI * f));
  d.x = sin(yaw);
  d.y = 0.0;
  d.z = -cos(yaw); /* -Z is forward */
  return d;
}

int main(void) {
  /* Quest-Pro-like per-eye FOV, mirrored for the right eye; eyes 64 mm apart. */
  gzl_view views[2];
  gzl_data_create_info create;
  gzl_plugin plugin = NULL;
  /* Geometric error of each level (m); level 0 is full detail. */
  static const gzl_level geo_levels[4] = {{0.0, 20000}, {0.0005, 5000}, {0.002, 1250}, {0.008, 312}};
  /* Engine style: LOD n is good enough while the object covers at most this share of the
   * view's height (as a Unity LODGroup's transition heights). */
  static const gzl_level engine_levels[4] = {{0.0, 8000}, {0.6, 2000}, {0.3, 500}, {0.1, 120}};
  gzl_object objects[GRID * GRID + 1];
  uint8_t levels[GRID * GRID + 1];
  const uint32_t object_count = GRID * GRID + 1;
  const int left = GRID * (GRID / 2), right = left + GRID - 1; /* middle row's ends */
  const double yaw_left = atan2(-GRID_SPACING_M, GRID_DISTANCE_M);
  const double yaw_right = atan2(GRID_SPACING_M, GRID_DISTANCE_M);
  const int64_t t0 = 1000000000LL; /* first display time: any clock, nanoseconds */
  const int64_t saccade_ns = t0 + HALF_FRAMES * FRAME_NS - LATENCY_NS;
  int64_t next_sample_ns = t0 - 100000000LL;
  int64_t last_sample_ns = 0;
  gzl_frame_info info;
  gzl_foveal_cone cone;
  uint8_t end_levels[2][GRID * GRID + 1];
  double end_u[2] = {0.0, 0.0};
  gzl_gaze_source end_source[2] = {GZL_GAZE_SOURCE_HEAD_FIXED, GZL_GAZE_SOURCE_HEAD_FIXED};
  int frame, i;

  if (GZL_VERSION_MAJOR(gzl_version()) != GZL_VERSION_MAJOR(GZL_HEADER_VERSION)) {
    fprintf(stderr, "libgazelod ABI %u, this program was built for %u\n", (unsigned)GZL_VERSION_MAJOR(gzl_version()),
            (unsigned)GZL_VERSION_MAJOR(GZL_HEADER_VERSION));
    return 1;
  }

  memset(views, 0, sizeof views); /* zero orientation = identity */
  for (i = 0; i < 2; ++i) {
    const double outer = 0.942, inner = 0.698;
    views[i].fov.angle_left = i == 0 ? -outer : -inner;
    views[i].fov.angle_right = i == 0 ? inner : outer;
    views[i].fov.angle_up = 0.768;
    views[i].fov.angle_down = -0.873;
    views[i].position_in_head_m.x = i == 0 ? -0.032 : 0.032;
    views[i].width_px = 1832;
    views[i].height_px = 1920;
  }
  memset(&create, 0, sizeof create);
  create.type = GZL_TYPE_DATA_CREATE_INFO;
  create.view_count = 2;
  create.views = views;
  create.config = NULL; /* the defaults: all criteria, switch policy on, no frame budget */
  if (!CALL(NULL, gzl_create_data(&create, &plugin))) return 1;

  for (i = 0; i < GRID * GRID + 1; ++i) {
    gzl_object_desc desc;
    memset(&desc, 0, sizeof desc);
    desc.type = GZL_TYPE_OBJECT_DESC;
    if (i < GRID * GRID) {
      desc.center_m.x = (i % GRID - GRID / 2) * GRID_SPACING_M;
      desc.center_m.y = (i / GRID - GRID / 2) * GRID_SPACING_M * 0.5;
      desc.center_m.z = -GRID_DISTANCE_M;
      desc.radius_m = 0.1;
      desc.metric = GZL_LEVEL_GEOMETRIC_ERROR_M;
      desc.levels = geo_levels;
    } else { /* the engine-style object, below the grid */
      desc.center_m.y = -1.0;
      desc.center_m.z = -GRID_DISTANCE_M;
      desc.radius_m = 0.3;
      desc.metric = GZL_LEVEL_SCREEN_HEIGHT_SHARE;
      desc.levels = engine_levels;
    }
    desc.level_count = 4;
    if (!CALL(plugin, gzl_add_object(plugin, &desc, &objects[i]))) {
      gzl_destroy(plugin);
      return 1;
    }
  }

  for (frame = 0; frame < 2 * HALF_FRAMES; ++frame) {
    const int64_t display_ns = t0 + frame * FRAME_NS;
    gzl_frame_input input;
    /* The tracker's samples that have arrived by now (decision time = display - latency). */
    while (next_sample_ns <= display_ns - LATENCY_NS) {
      gzl_gaze_sample s;
      memset(&s, 0, sizeof s);
      s.type = GZL_TYPE_GAZE_SAMPLE;
      s.time_ns = next_sample_ns;
      s.direction = gaze_at(next_sample_ns, saccade_ns, yaw_left, yaw_right);
      s.flags = GZL_GAZE_SAMPLE_VALID; /* head space; head orientation from the frames */
      CALL(plugin, gzl_push_gaze_sample(plugin, &s));
      last_sample_ns = next_sample_ns;
      next_sample_ns += SAMPLE_NS;
    }
    memset(&input, 0, sizeof input);
    input.type = GZL_TYPE_FRAME_INPUT;
    input.display_time_ns = display_ns;
    input.head.orientation.w = 1.0; /* still, at the base space's origin */
    input.head.flags = GZL_HEAD_POSE_VALID | GZL_HEAD_ANGULAR_VELOCITY_VALID | GZL_HEAD_LINEAR_VELOCITY_VALID;
    input.view_count = 0; /* the views given at creation */
    CALL(plugin, gzl_begin_frame_data(plugin, &input));

    /* What the renderer reads: the levels to draw, and where to centre foveated shading. */
    CALL(plugin, gzl_get_levels(plugin, object_count, objects, levels));
    memset(&info, 0, sizeof info);
    info.type = GZL_TYPE_FRAME_INFO;
    CALL(plugin, gzl_get_frame_info(plugin, &info));
    memset(&cone, 0, sizeof cone);
    cone.type = GZL_TYPE_FOVEAL_CONE;
    CALL(plugin, gzl_get_foveal_cone(plugin, 0, &cone));
    /* (A real renderer would now draw, then report its time for the frame budget.) */
    CALL(plugin, gzl_end_frame(plugin, 8.0));

    if (frame == HALF_FRAMES - 1 || frame == 2 * HALF_FRAMES - 1) {
      const int h = frame / HALF_FRAMES;
      memcpy(end_levels[h], levels, sizeof levels);
      end_u[h] = cone.center_u;
      end_source[h] = info.gaze_source;
      printf(
          "%s half, frame %llu: gaze source %d, cone centre (%.3f, %.3f) radius %.1f deg, "
          "triangles %llu of %llu\n  grid levels:",
          h == 0 ? "first" : "second", (unsigned long long)info.frame_index, (int)info.gaze_source, cone.center_u,
          cone.center_v, cone.half_angle_deg, (unsigned long long)info.triangles_drawn,
          (unsigned long long)info.triangles_full);
      for (i = 0; i < GRID * GRID; ++i) printf("%s%u", i % GRID == 0 ? "  " : " ", (unsigned)levels[i]);
      printf("   engine-style object: %u\n", (unsigned)levels[GRID * GRID]);
    }
  }

  check(end_source[0] == GZL_GAZE_SOURCE_PUSHED && end_source[1] == GZL_GAZE_SOURCE_PUSHED,
        "the pushed samples are the gaze source");
  check(end_levels[0][left] < end_levels[0][right], "first half: the fixated left object is finer than the right");
  check(end_levels[1][right] < end_levels[1][left], "second half: the fixated right object is finer than the left");
  check(end_u[0] < 0.5 && end_u[1] > 0.5, "the foveal cone moves from the left half of view 0 to the right half");
  check(end_levels[1][GRID * GRID] < 4, "the engine-style object has a valid level");

  /* The error path. A sample older than the last one is refused, with a message. */
  {
    gzl_gaze_sample s;
    char msg[512];
    size_t length = 0;
    gzl_result r;
    memset(&s, 0, sizeof s);
    s.type = GZL_TYPE_GAZE_SAMPLE;
    s.time_ns = last_sample_ns - 1000000LL;
    s.direction.z = -1.0;
    s.flags = GZL_GAZE_SAMPLE_VALID;
    r = gzl_push_gaze_sample(plugin, &s);
    printf("out-of-order sample -> %s\n", gzl_result_to_string(r));
    check(r == GZL_ERROR_TIME_OUT_OF_ORDER, "an out-of-order sample is refused with GZL_ERROR_TIME_OUT_OF_ORDER");
    msg[0] = '\0';
    CALL(plugin, gzl_get_last_error(plugin, msg, sizeof msg, &length));
    printf("  message: %s\n", msg);
    check(strncmp(msg, "gazelod:", 8) == 0 && length == strlen(msg), "the message starts with \"gazelod:\"");
  }
  /* A removed object's handle is invalid at once, and stays so. */
  {
    const gzl_object removed = objects[right];
    uint8_t level = 0;
    gzl_frame_input input;
    gzl_result r;
    CALL(plugin, gzl_remove_object(plugin, removed));
    r = gzl_get_levels(plugin, 1, &removed, &level);
    printf("levels of a removed object -> %s\n", gzl_result_to_string(r));
    check(r == GZL_ERROR_OBJECT_INVALID, "a removed handle fails with GZL_ERROR_OBJECT_INVALID");
    /* The plugin goes on after errors: one more frame, without the removed object. */
    memset(&input, 0, sizeof input);
    input.type = GZL_TYPE_FRAME_INPUT;
    input.display_time_ns = t0 + 2 * HALF_FRAMES * FRAME_NS;
    input.head.orientation.w = 1.0;
    input.head.flags = GZL_HEAD_POSE_VALID;
    CALL(plugin, gzl_begin_frame_data(plugin, &input));
    memset(&info, 0, sizeof info);
    info.type = GZL_TYPE_FRAME_INFO;
    CALL(plugin, gzl_get_frame_info(plugin, &info));
    check(info.object_count == object_count - 1, "after the next frame, one object fewer is registered");
    check(gzl_get_levels(plugin, 1, &removed, &level) == GZL_ERROR_OBJECT_INVALID,
          "the removed handle stays invalid after the next frame");
  }

  gzl_destroy(plugin);
  printf("%s: %d failure(s)\n", g_failures == 0 ? "PASS" : "FAIL", g_failures);
  return g_failures == 0 ? 0 : 1;
}
