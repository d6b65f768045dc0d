// SPDX-License-Identifier: Apache-2.0
/* gazelod: gaze-contingent level of detail, C ABI (C99; also valid C++17).
 *
 * One opaque handle, gzl_plugin, created in one of two modes:
 *   OpenXR mode  gzl_create_openxr: from the application's XrInstance, XrSession, base XrSpace
 *                and its xrGetInstanceProcAddr. Every OpenXR call goes through that pointer;
 *                libgazelod links no OpenXR loader. Head pose, views and (depending on
 *                gzl_gaze_input) eye gaze are read from the runtime at each frame's display time.
 *   data mode    gzl_create_data: no OpenXR at all. Each frame the application gives the head
 *                pose and the views, and pushes timestamped gaze samples.
 * The same inputs give the same decisions in both modes.
 *
 * Conventions (those of OpenXR's own C API):
 *   - Every input struct starts with `type` (its gzl_structure_type) and `next` (NULL, or an
 *     extension struct); a wrong type is GZL_ERROR_STRUCT_TYPE. Zero-initialised fields mean
 *     "the default" wherever a field says so.
 *   - Every function but gzl_version, gzl_result_to_string and gzl_destroy returns a gzl_result;
 *     on failure gzl_get_last_error gives a message that names the field at fault and the
 *     remedy (a message longer than the buffer is cut; *length says its full size). No exception and no C++ type
 * crosses the boundary; the per-frame calls do not allocate.
 *   - Inputs are copied before a call returns (create infos, views, configs and their strings,
 *     levels, samples, frame inputs): nothing the application passes must outlive the call.
 *     Lent OpenXR handles (base and gaze spaces) are used until replaced or gzl_shutdown.
 *   - Axes are OpenXR's (-Z forward, +Y up, +X right); times are nanoseconds on the clock the
 *     application's frame loop uses (XrTime in OpenXR mode); angles in radians unless a name
 *     says _deg; lengths in metres.
 *
 * Threads (docs/integration.md has the table): every function may be called from any thread;
 * calls on one plugin are serialised by the plugin (registration and gzl_on_session_state from
 * an application thread wait for a frame being decided on the render thread). gzl_get_levels,
 * gzl_get_frame_info, gzl_get_foveal_cone, gzl_get_frame_record, gzl_get_gaze_status and
 * gzl_get_last_error read under short locks of their own and never wait for a frame in
 * progress: frame N stays readable while N+1 is decided. gzl_destroy must be the last call.
 */
#ifndef GAZELOD_GAZELOD_H_
#define GAZELOD_GAZELOD_H_ 1

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32) && defined(GZL_BUILDING_LIBRARY)
#define GZL_API __declspec(dllexport)
#elif defined(_WIN32)
#define GZL_API __declspec(dllimport)
#elif defined(__GNUC__)
#define GZL_API __attribute__((visibility("default")))
#else
#define GZL_API
#endif

/* ---- versions ----------------------------------------------------------------------------
 * The major version is the ABI: libgazelod.so.<major>. A minor version adds functions,
 * structure types or enum values, never changes an existing one. */
#define GZL_MAKE_VERSION(major, minor, patch) \
  ((((uint32_t)(major)) << 22) | (((uint32_t)(minor)) << 12) | ((uint32_t)(patch)))
#define GZL_VERSION_MAJOR(version) (((uint32_t)(version) >> 22) & 0x3ffU)
#define GZL_VERSION_MINOR(version) (((uint32_t)(version) >> 12) & 0x3ffU)
#define GZL_VERSION_PATCH(version) ((uint32_t)(version)&0xfffU)
#define GZL_HEADER_VERSION GZL_MAKE_VERSION(1, 0, 0)

/* The version of the library loaded at run time (compare with GZL_HEADER_VERSION). */
GZL_API uint32_t gzl_version(void);

/* ---- results ------------------------------------------------------------------------------ */
typedef enum gzl_result {
  GZL_SUCCESS = 0,
  GZL_ERROR_NULL_HANDLE = -1,       /* the gzl_plugin is NULL */
  GZL_ERROR_NULL_POINTER = -2,      /* a required pointer argument or field is NULL */
  GZL_ERROR_STRUCT_TYPE = -3,       /* a struct's `type` is not the one this call takes */
  GZL_ERROR_INVALID_ARGUMENT = -4,  /* not finite, out of range, inconsistent (the message says which field) */
  GZL_ERROR_TIME_OUT_OF_ORDER = -5, /* a gaze sample older than the last one pushed */
  GZL_ERROR_TIME_IN_FUTURE = -6,    /* a gaze sample later than the frame clock allows */
  GZL_ERROR_OBJECT_INVALID = -7,    /* an object handle that was removed or never issued */
  GZL_ERROR_WRONG_MODE = -8,        /* an OpenXR-mode call on a data-mode plugin, or the reverse */
  GZL_ERROR_OPENXR_CALL = -9,       /* an OpenXR call failed; the message names it and its XrResult */
  GZL_ERROR_OPENXR_FUNCTION = -10,  /* xrGetInstanceProcAddr gave no pointer for a function gazelod needs */
  GZL_ERROR_CAPACITY = -11,         /* an output array is too small (the needed count is written) */
  GZL_ERROR_SHUT_DOWN = -12, /* the plugin was shut down (gzl_shutdown): only the readers and gzl_destroy remain */
  GZL_ERROR_OUT_OF_MEMORY = -13,
  GZL_ERROR_INTERNAL = -14, /* a bug in gazelod: please report the message */
  GZL_RESULT_MAX_ENUM = 0x7fffffff
} gzl_result;

/* "GZL_SUCCESS", "GZL_ERROR_TIME_OUT_OF_ORDER", ...; "GZL_RESULT_UNKNOWN" for other values.
 * The strings are static. */
GZL_API const char* gzl_result_to_string(gzl_result result);

typedef uint32_t gzl_bool32;

typedef enum gzl_structure_type {
  GZL_TYPE_UNKNOWN = 0,
  GZL_TYPE_CONFIG = 1,
  GZL_TYPE_DATA_CREATE_INFO = 2,
  GZL_TYPE_OPENXR_CREATE_INFO = 3,
  GZL_TYPE_OBJECT_DESC = 4,
  GZL_TYPE_GAZE_SAMPLE = 5,
  GZL_TYPE_FRAME_INPUT = 6,
  GZL_TYPE_FRAME_INFO = 7,
  GZL_TYPE_FOVEAL_CONE = 8,
  GZL_TYPE_GAZE_BINDING = 9,
  GZL_TYPE_FRAME_RECORD = 10,
  GZL_STRUCTURE_TYPE_MAX_ENUM = 0x7fffffff
} gzl_structure_type;

typedef struct gzl_plugin_T* gzl_plugin;

/* A stable object handle: never reused, 0 is no object. Opaque: not an index, and not ordered
 * (a handle from another plugin is refused with GZL_ERROR_OBJECT_INVALID). */
typedef uint64_t gzl_object;
#define GZL_NULL_OBJECT ((gzl_object)0)

/* ---- plain geometry ---------------------------------------------------------------------- */
typedef struct gzl_vec3 {
  double x, y, z;
} gzl_vec3;
typedef struct gzl_quat { /* unit quaternion, x y z w as XrQuaternionf */
  double x, y, z, w;
} gzl_quat;
typedef struct gzl_fov { /* as XrFovf: radians, left and down negative */
  double angle_left, angle_right, angle_up, angle_down;
} gzl_fov;

/* One rendered view: its field of view, where it sits in the head (VIEW space), and the
 * render resolution actually used for it (not the runtime's recommendation). */
typedef struct gzl_view {
  gzl_fov fov;
  gzl_quat orientation_in_head; /* zero quaternion = identity */
  gzl_vec3 position_in_head_m;
  uint32_t width_px, height_px;
} gzl_view;

#define GZL_MAX_VIEWS 4u

/* ---- configuration (both modes; NULL or all zero = the defaults) ------------------------- */
typedef enum gzl_criterion_bits {
  GZL_CRITERION_SIZE = 1,         /* the object's angular size (Reddy 1998) */
  GZL_CRITERION_ECCENTRICITY = 2, /* distance from the gaze, through the foveal cone */
  GZL_CRITERION_VELOCITY = 4      /* retinal velocity: head rotation, object motion, pursuit */
} gzl_criterion_bits;

typedef struct gzl_config {
  gzl_structure_type type; /* GZL_TYPE_CONFIG */
  const void* next;
  uint32_t disabled_criteria;       /* gzl_criterion_bits that may not coarsen a level */
  gzl_bool32 disable_switch_policy; /* draw each frame's perceptual level (levels then flicker) */
  double frame_budget_ms;           /* 0: no budget; else Mason's (1999) incremental knapsack */
  double gaze_accuracy_deg;         /* 0: 1.5; the floor of the gaze uncertainty (widens the cone) */
  double head_fixed_cone_deg;       /* 0: 20; the cone without gaze (where eyes usually are) */
  double gaze_silence_timeout_s;    /* 0: 1.0; a gaze input silent this long after focus is distrusted */
  double max_gaze_sample_age_s;     /* 0: 0.1; pushed samples older than this at a frame are not used */
  const char* hmd_preset;           /* NULL or "": xi from the views; else a preset ("questpro", ...) */
} gzl_config;

/* ---- data mode ---------------------------------------------------------------------------- */
typedef struct gzl_data_create_info {
  gzl_structure_type type; /* GZL_TYPE_DATA_CREATE_INFO */
  const void* next;
  uint32_t view_count; /* 1, 2 or 4 (quad views: primary left, right, inset left, right) */
  const gzl_view* views;
  const gzl_config* config; /* NULL: defaults */
} gzl_data_create_info;

/* Writes the new plugin to *plugin. On failure *plugin is NULL and gzl_get_last_error(NULL, ...)
 * on the same thread gives the reason. */
GZL_API gzl_result gzl_create_data(const gzl_data_create_info* info, gzl_plugin* plugin);

/* ---- OpenXR mode -------------------------------------------------------------------------- */
typedef void (*gzl_void_function)(void);

/* Where the plugin's eye gaze comes from in OpenXR mode. OpenXR lets a session attach action
 * sets once, and a second suggestion for an interaction profile replaces the first: the
 * application owns actions, so the plugin never suggests, attaches or syncs unless asked to
 * (GZL_GAZE_INPUT_PLUGIN_ACTIONS). */
typedef enum gzl_gaze_input {
  /* The application already has an eye-gaze action (XR_EXT_eye_gaze_interaction): it passes
   * the action space it created (gaze_space) and, optionally, the action (gaze_action, for
   * isActive). The plugin only locates the space. The usual choice for engines. */
  GZL_GAZE_INPUT_APP_SPACE = 0,
  /* The plugin creates an action set with one pose action and hands its binding out
   * (gzl_get_gaze_binding): the application adds it to its own suggestion for
   * /interaction_profiles/ext/eye_gaze_interaction, includes the set in its single
   * xrAttachSessionActionSets and in every xrSyncActions, then calls gzl_action_sets_attached.
   * Create the plugin before the application attaches its sets. */
  GZL_GAZE_INPUT_MERGE_BINDING = 1,
  /* The application pushes samples (gzl_push_gaze_sample): an engine's own input system, a
   * vendor SDK, a HID tracker. */
  GZL_GAZE_INPUT_PUSHED = 2,
  /* For applications with no action sets at all: the plugin creates, suggests, attaches and
   * syncs its own set. Fails with a message if the application attached sets already. */
  GZL_GAZE_INPUT_PLUGIN_ACTIONS = 3,
  /* No eye gaze: head-fixed gaze with a widened cone. */
  GZL_GAZE_INPUT_NONE = 4,
  GZL_GAZE_INPUT_MAX_ENUM = 0x7fffffff
} gzl_gaze_input;

typedef struct gzl_openxr_create_info {
  gzl_structure_type type; /* GZL_TYPE_OPENXR_CREATE_INFO */
  const void* next;
  /* The application's PFN_xrGetInstanceProcAddr, cast: (gzl_void_function)xrGetInstanceProcAddr
   * (or the pointer an engine hands its plugins). */
  gzl_void_function get_instance_proc_addr;
  uint64_t instance;   /* XrInstance, cast with GZL_XR_HANDLE */
  uint64_t system_id;  /* XrSystemId */
  uint64_t session;    /* XrSession */
  uint64_t base_space; /* XrSpace the objects are placed in (gzl_set_base_space changes it);
                        * lent, not owned: keep it alive until it is replaced or gzl_shutdown */
  /* XrViewConfigurationType: 0 means PRIMARY_STEREO; PRIMARY_MONO (1) and
   * PRIMARY_QUAD_VARJO (1000037000, XR_VARJO_quad_views) are accepted too. */
  uint32_t view_configuration_type;
  gzl_gaze_input gaze_input;
  /* GZL_GAZE_INPUT_APP_SPACE: the application's eye-gaze action space and, optionally, its
   * XrAction. Both may be 0 at creation and given later with gzl_set_gaze_space (an engine
   * whose actions exist only after it attached them). Lent, not owned. */
  uint64_t gaze_space;
  uint64_t gaze_action;
  const gzl_config* config;
} gzl_openxr_create_info;

/* XR handles as this header takes them (pointers on 64-bit platforms, uint64_t on 32-bit). */
#define GZL_XR_HANDLE(handle) ((uint64_t)(handle))

GZL_API gzl_result gzl_create_openxr(const gzl_openxr_create_info* info, gzl_plugin* plugin);

/* GZL_GAZE_INPUT_MERGE_BINDING only (GZL_ERROR_WRONG_MODE otherwise): what to merge into the
 * application's own calls. Handles are
 * XrActionSet / XrAction values; the paths are strings for xrStringToPath. */
typedef struct gzl_gaze_binding {
  gzl_structure_type type; /* GZL_TYPE_GAZE_BINDING */
  void* next;
  uint64_t action_set;
  uint64_t action;
  const char* interaction_profile; /* "/interaction_profiles/ext/eye_gaze_interaction" (static) */
  const char* binding_path;        /* "/user/eyes_ext/input/gaze_ext/pose" (static) */
} gzl_gaze_binding;

GZL_API gzl_result gzl_get_gaze_binding(gzl_plugin plugin, gzl_gaze_binding* binding);
/* GZL_GAZE_INPUT_MERGE_BINDING: after the application's xrAttachSessionActionSets. */
GZL_API gzl_result gzl_action_sets_attached(gzl_plugin plugin);
/* GZL_GAZE_INPUT_APP_SPACE: the application's eye-gaze action space (and optionally its action),
 * given or replaced after creation. The gaze input is trusted afresh from then on. */
GZL_API gzl_result gzl_set_gaze_space(gzl_plugin plugin, uint64_t gaze_space, uint64_t gaze_action);
/* Both modes, from the application's event loop: an XrSessionState value and the event's time
 * (the gaze input's silence timer runs only while the session is FOCUSED). Optional in data mode. */
GZL_API gzl_result gzl_on_session_state(gzl_plugin plugin, int32_t xr_session_state, int64_t time_ns);
/* A new base space (recentring, a new application space); objects keep their coordinates. */
GZL_API gzl_result gzl_set_base_space(gzl_plugin plugin, uint64_t base_space);
/* Both modes: the render resolution actually used for one view (per frame if it changes). In
 * OpenXR mode the runtime's recommended size is used until this is called. */
GZL_API gzl_result gzl_set_view_resolution(gzl_plugin plugin, uint32_t view_index, uint32_t width_px,
                                           uint32_t height_px);
/* OpenXR mode: at xrWaitFrame's predicted display time. */
GZL_API gzl_result gzl_begin_frame_openxr(gzl_plugin plugin, int64_t predicted_display_time);

/* ---- objects (both modes) ------------------------------------------------------------------ */
typedef enum gzl_level_metric {
  /* The level's largest geometric error (surface deviation), metres. */
  GZL_LEVEL_GEOMETRIC_ERROR_M = 0,
  /* Reddy's (1998) measure: the highest spatial frequency the level removes, in cycles per
   * object diameter. */
  GZL_LEVEL_REMOVED_CYCLES_PER_DIAMETER = 1,
  /* Engine style (a Unity LODGroup transition): the level is good enough while the object's
   * bounding sphere covers at most this share (0..1] of the view's height. Converted once, at
   * gzl_add_object, to a geometric error of one pixel at that share: 2 r / (share * H), H the
   * largest vertical resolution among the primary views then (views 0 and 1 with quad views;
   * later resolution changes do not convert it again). */
  GZL_LEVEL_SCREEN_HEIGHT_SHARE = 2,
  /* Engine style: the level's error in pixels when the bounding sphere spans the whole view
   * height: a geometric error of pixels * 2 r / H (H as above). Converted once, at gzl_add_object. */
  GZL_LEVEL_PIXELS_AT_FULL_HEIGHT = 3,
  GZL_LEVEL_METRIC_MAX_ENUM = 0x7fffffff
} gzl_level_metric;

typedef struct gzl_level {
  double value;       /* in the object's metric; level 0 (full detail) is ignored */
  uint32_t triangles; /* for the frame budget and reports */
} gzl_level;

typedef struct gzl_object_desc {
  gzl_structure_type type; /* GZL_TYPE_OBJECT_DESC */
  const void* next;
  gzl_vec3 center_m; /* bounding sphere, in the base space */
  double radius_m;
  gzl_vec3 velocity_m_s;
  double importance; /* 0..1 for the frame budget; 0 means 1 */
  gzl_level_metric metric;
  uint32_t level_count; /* 1..255, level 0 = full detail */
  const gzl_level* levels;
} gzl_object_desc;

/* The levels are copied. A disabled object's triangles count in no total. */
GZL_API gzl_result gzl_add_object(gzl_plugin plugin, const gzl_object_desc* desc, gzl_object* object);
GZL_API gzl_result gzl_remove_object(gzl_plugin plugin, gzl_object object);
/* A disabled object keeps its handle and its place; gzl_get_levels gives it GZL_LEVEL_DISABLED. */
GZL_API gzl_result gzl_set_object_enabled(gzl_plugin plugin, gzl_object object, gzl_bool32 enabled);
GZL_API gzl_result gzl_set_object_motion(gzl_plugin plugin, gzl_object object, const gzl_vec3* center_m,
                                         const gzl_vec3* velocity_m_s);

/* ---- gaze samples (data mode; OpenXR mode with GZL_GAZE_INPUT_PUSHED) ------------------- */
typedef enum gzl_gaze_sample_flag_bits {
  GZL_GAZE_SAMPLE_VALID = 1,    /* clear for a blink or lost tracking */
  GZL_GAZE_SAMPLE_IN_WORLD = 2, /* direction is in the base space, not the head */
  /* head_orientation is the head's orientation at the sample's time (else it is taken from
   * the head poses given with the frames, interpolated) */
  GZL_GAZE_SAMPLE_HEAD_ORIENTATION = 4
} gzl_gaze_sample_flag_bits;

typedef struct gzl_gaze_sample {
  gzl_structure_type type; /* GZL_TYPE_GAZE_SAMPLE */
  const void* next;
  /* When the eye was measured, on the frame loop's clock: non-decreasing from push to push
   * (else GZL_ERROR_TIME_OUT_OF_ORDER), at most 1 s after the last frame's display time (else
   * GZL_ERROR_TIME_IN_FUTURE: another clock). */
  int64_t time_ns;
  gzl_vec3 direction;        /* unit (normalised here), head space unless GZL_GAZE_SAMPLE_IN_WORLD */
  gzl_vec3 origin_m;         /* cyclopean eye, head space (zero: the head's origin) */
  uint32_t flags;            /* gzl_gaze_sample_flag_bits */
  gzl_quat head_orientation; /* with GZL_GAZE_SAMPLE_HEAD_ORIENTATION: head to base space */
} gzl_gaze_sample;

GZL_API gzl_result gzl_push_gaze_sample(gzl_plugin plugin, const gzl_gaze_sample* sample);

/* ---- frames ------------------------------------------------------------------------------- */
typedef enum gzl_head_flag_bits {
  GZL_HEAD_POSE_VALID = 1,
  GZL_HEAD_ANGULAR_VELOCITY_VALID = 2, /* else from successive poses */
  GZL_HEAD_LINEAR_VELOCITY_VALID = 4
} gzl_head_flag_bits;

typedef struct gzl_head_pose { /* the head (VIEW space) in the base space */
  gzl_quat orientation;
  gzl_vec3 position_m;
  gzl_vec3 angular_velocity_rad_s; /* base-space axes */
  gzl_vec3 linear_velocity_m_s;
  uint32_t flags; /* gzl_head_flag_bits */
} gzl_head_pose;

typedef struct gzl_frame_input {
  gzl_structure_type type; /* GZL_TYPE_FRAME_INPUT */
  const void* next;
  int64_t display_time_ns; /* increasing from frame to frame */
  gzl_head_pose head;
  uint32_t view_count; /* 0: the views given at creation (or last frame) */
  const gzl_view* views;
} gzl_frame_input;

/* Data mode: decide the frame displayed at input->display_time_ns. */
GZL_API gzl_result gzl_begin_frame_data(gzl_plugin plugin, const gzl_frame_input* input);
/* Both modes, after the frame: its measured frame time, for the frame budget's cost model
 * (config->frame_budget_ms). Optional without a budget. */
GZL_API gzl_result gzl_end_frame(gzl_plugin plugin, double measured_frame_ms);

/* ---- outputs of the last published frame -------------------------------------------------- */
#define GZL_LEVEL_DISABLED ((uint8_t)255)

/* levels[i] = the level to draw for objects[i] (0 = full detail), GZL_LEVEL_DISABLED for a
 * disabled object. A removed handle fails with GZL_ERROR_OBJECT_INVALID (nothing written past
 * the levels already filled). Objects added after the last frame read level 0. */
GZL_API gzl_result gzl_get_levels(gzl_plugin plugin, uint32_t count, const gzl_object* objects, uint8_t* levels);

typedef enum gzl_gaze_source {
  GZL_GAZE_SOURCE_HEAD_FIXED = 0, /* no usable gaze: straight ahead, widened cone */
  GZL_GAZE_SOURCE_OPENXR = 1,     /* the eye-gaze action (app space, merged or plugin binding) */
  GZL_GAZE_SOURCE_PUSHED = 2,     /* gzl_push_gaze_sample */
  GZL_GAZE_SOURCE_MAX_ENUM = 0x7fffffff
} gzl_gaze_source;

typedef enum gzl_eye_motion {
  GZL_EYE_FIXATION = 0,
  GZL_EYE_SACCADE = 1,
  GZL_EYE_PURSUIT = 2,
  GZL_EYE_LOSS = 3,
  GZL_EYE_MOTION_MAX_ENUM = 0x7fffffff
} gzl_eye_motion;

typedef struct gzl_frame_info {
  gzl_structure_type type; /* GZL_TYPE_FRAME_INFO */
  void* next;
  uint64_t frame_index; /* frames published so far (0: none yet) */
  int64_t display_time_ns;
  uint32_t object_count; /* objects registered (enabled or not) */
  gzl_gaze_source gaze_source;
  gzl_eye_motion eye_motion;
  gzl_bool32 gaze_suppressed; /* saccade or blink: vision suppressed, switches hidden */
  gzl_bool32 head_valid;
  gzl_vec3 gaze_direction_base; /* conditioned, predicted to the display time */
  gzl_vec3 eye_position_base_m;
  /* The rest of the viewer the frame was decided for (lod/select.hpp's Viewer): the head's
   * rotation and translation, and the eye's rotation in the head (a pursuit; zero without gaze). */
  gzl_vec3 head_angular_velocity_rad_s;
  gzl_vec3 head_linear_velocity_m_s;
  gzl_vec3 gaze_angular_velocity_in_head_rad_s;
  double gaze_uncertainty_deg;
  double xi_cpd;            /* the display's limit used (cycles per degree) */
  uint64_t triangles_drawn; /* sum over enabled objects of their level's triangles */
  uint64_t triangles_full;
} gzl_frame_info;

GZL_API gzl_result gzl_get_frame_info(gzl_plugin plugin, gzl_frame_info* info);

/* The foveal cone (Reddy 1995) of the last frame, seen from one view: a cone at the eye along
 * the conditioned gaze, half-angle the fovea (5 deg) plus the gaze's uncertainty. Use it to
 * centre a foveated inset or a variable-rate-shading image; it does not decide levels by
 * itself (every object's level comes from the acuity model at its own eccentricity). */
typedef struct gzl_foveal_cone {
  gzl_structure_type type; /* GZL_TYPE_FOVEAL_CONE */
  void* next;
  gzl_vec3 direction_in_view; /* unit, the view's axes */
  double fovea_deg;
  double uncertainty_deg;
  double half_angle_deg; /* fovea_deg + uncertainty_deg, at most 180 */
  /* In the view's normalised image coordinates: u from the left edge (0) to the right (1), v
   * from the top (0) to the bottom (1). radius_u, radius_v: the half-angle's extent along u
   * and v at the centre. in_view: the gaze direction lies inside the view's field of view.
   * Scalars, not arrays, so the struct is blittable (C#, Rust) and read without copies. */
  double center_u, center_v; /* (0.5, 0.5) when the gaze points behind the view */
  double radius_u, radius_v; /* 0 when the gaze points behind the view */
  gzl_bool32 in_view;
} gzl_foveal_cone;

GZL_API gzl_result gzl_get_foveal_cone(gzl_plugin plugin, uint32_t view_index, gzl_foveal_cone* cone);

/* What the last frame read, in data mode's terms: replaying these records through a data-mode
 * plugin (gzl_push_gaze_sample, then gzl_begin_frame_data) gives the same decisions. */
typedef struct gzl_frame_record {
  gzl_structure_type type; /* GZL_TYPE_FRAME_RECORD */
  void* next;
  int64_t display_time_ns;
  gzl_head_pose head;
  uint32_t view_count;
  gzl_view views[GZL_MAX_VIEWS];
  gzl_bool32 has_gaze_sample;  /* the gaze input has given a sample (this frame or earlier) */
  gzl_gaze_sample gaze_sample; /* in head space, with the head's orientation at its time; a frame that
                                * read none repeats the last with GZL_GAZE_SAMPLE_VALID cleared, as a
                                * replay must push it */
} gzl_frame_record;

GZL_API gzl_result gzl_get_frame_record(gzl_plugin plugin, gzl_frame_record* record);

/* Why the gaze source is what it is, as of the last change ("openxr eye gaze delivered",
 * "openxr delivered no usable eye gaze in 1.000 s (gazelod's eye-gaze binding was replaced by the
 * application's own suggestion for ...)", "... head-fixed gaze with a widened cone"); copied
 * like gzl_get_last_error. Empty before the first frame. */
GZL_API gzl_result gzl_get_gaze_status(gzl_plugin plugin, char* buffer, size_t capacity, size_t* length);

/* ---- errors and teardown ------------------------------------------------------------------ */
/* Copies the last error message on this plugin ("gazelod: ..." with the remedy), or with a NULL
 * plugin the calling thread's last failed create, into buffer (always NUL-terminated when
 * capacity > 0). *length (optional) receives the message's full length. */
GZL_API gzl_result gzl_get_last_error(gzl_plugin plugin, char* buffer, size_t capacity, size_t* length);

/* Releases everything the plugin holds in OpenXR (its spaces, its action set). Call it before
 * xrDestroySession / xrDestroyInstance; safe before or after the session ends, and twice. */
GZL_API gzl_result gzl_shutdown(gzl_plugin plugin);
/* Shuts down if needed and frees the plugin. NULL is accepted. */
GZL_API void gzl_destroy(gzl_plugin plugin);

#ifdef __cplusplus
}
#endif

#endif /* GAZELOD_GAZELOD_H_ */
