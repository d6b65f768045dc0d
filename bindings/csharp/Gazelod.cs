// SPDX-License-Identifier: Apache-2.0
// Gazelod.cs: C# bindings for gazelod's C ABI (include/gazelod/gazelod.h, libgazelod.so.1).
//
// Two layers, one file (drop it into a Unity project's Assets, or compile it with mcs/csc):
//   Gazelod.Native   P/Invoke declarations for every GZL_API function, and every struct and enum
//                    of the header under its C name, field for field ([StructLayout(Sequential)],
//                    enums int-sized, gzl_bool32 as uint, handles as ulong, pointers as IntPtr).
//                    bindings/csharp/tests/GazelodTest.cs checks each struct's size and each
//                    field's offset against the C compiler's (struct_sizes.c).
//   Gazelod.Plugin   a small wrapper: the plugin handle as a SafeHandle (PluginHandle, released
//                    with gzl_destroy), methods that throw GazelodException (the gzl_result and
//                    gazelod's message) instead of returning codes.
//
// The library is found as "gazelod": libgazelod.so on Linux (the development symlink, or put
// libgazelod.so.1 on the loader path under that name), gazelod.dll on Windows, libgazelod.dylib
// on macOS. The major version of the loaded library is checked against AbiVersionMajor the
// first time Plugin is used (Plugin.CheckVersion).
//
// Conventions are the header's: every input struct starts with `type` and `next`; the Create()
// helpers set the type. Times are nanoseconds on the frame loop's clock (XrTime in OpenXR mode),
// axes OpenXR's (-Z forward, +Y up, +X right), lengths in metres, angles in radians.
using System;
using System.Runtime.InteropServices;
using System.Text;

namespace Gazelod
{
    // ---- enums (all int-sized, as C enums with a 0x7fffffff MAX_ENUM are) -----------------------

    public enum gzl_result : int
    {
        GZL_SUCCESS = 0,
        GZL_ERROR_NULL_HANDLE = -1,
        GZL_ERROR_NULL_POINTER = -2,
        GZL_ERROR_STRUCT_TYPE = -3,
        GZL_ERROR_INVALID_ARGUMENT = -4,
        GZL_ERROR_TIME_OUT_OF_ORDER = -5,
        GZL_ERROR_TIME_IN_FUTURE = -6,
        GZL_ERROR_OBJECT_INVALID = -7,
        GZL_ERROR_WRONG_MODE = -8,
        GZL_ERROR_OPENXR_CALL = -9,
        GZL_ERROR_OPENXR_FUNCTION = -10,
        GZL_ERROR_CAPACITY = -11,
        GZL_ERROR_SHUT_DOWN = -12,
        GZL_ERROR_OUT_OF_MEMORY = -13,
        GZL_ERROR_INTERNAL = -14,
        GZL_RESULT_MAX_ENUM = 0x7fffffff
    }

    public enum gzl_structure_type : int
    {
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
    }

    [Flags]
    public enum gzl_criterion_bits : uint
    {
        GZL_CRITERION_SIZE = 1,
        GZL_CRITERION_ECCENTRICITY = 2,
        GZL_CRITERION_VELOCITY = 4
    }

    public enum gzl_gaze_input : int
    {
        GZL_GAZE_INPUT_APP_SPACE = 0,
        GZL_GAZE_INPUT_MERGE_BINDING = 1,
        GZL_GAZE_INPUT_PUSHED = 2,
        GZL_GAZE_INPUT_PLUGIN_ACTIONS = 3,
        GZL_GAZE_INPUT_NONE = 4,
        GZL_GAZE_INPUT_MAX_ENUM = 0x7fffffff
    }

    public enum gzl_level_metric : int
    {
        GZL_LEVEL_GEOMETRIC_ERROR_M = 0,
        GZL_LEVEL_REMOVED_CYCLES_PER_DIAMETER = 1,
        GZL_LEVEL_SCREEN_HEIGHT_SHARE = 2,
        GZL_LEVEL_PIXELS_AT_FULL_HEIGHT = 3,
        GZL_LEVEL_METRIC_MAX_ENUM = 0x7fffffff
    }

    [Flags]
    public enum gzl_gaze_sample_flag_bits : uint
    {
        GZL_GAZE_SAMPLE_VALID = 1,
        GZL_GAZE_SAMPLE_IN_WORLD = 2,
        GZL_GAZE_SAMPLE_HEAD_ORIENTATION = 4
    }

    [Flags]
    public enum gzl_head_flag_bits : uint
    {
        GZL_HEAD_POSE_VALID = 1,
        GZL_HEAD_ANGULAR_VELOCITY_VALID = 2,
        GZL_HEAD_LINEAR_VELOCITY_VALID = 4
    }

    public enum gzl_gaze_source : int
    {
        GZL_GAZE_SOURCE_HEAD_FIXED = 0,
        GZL_GAZE_SOURCE_OPENXR = 1,
        GZL_GAZE_SOURCE_PUSHED = 2,
        GZL_GAZE_SOURCE_MAX_ENUM = 0x7fffffff
    }

    public enum gzl_eye_motion : int
    {
        GZL_EYE_FIXATION = 0,
        GZL_EYE_SACCADE = 1,
        GZL_EYE_PURSUIT = 2,
        GZL_EYE_LOSS = 3,
        GZL_EYE_MOTION_MAX_ENUM = 0x7fffffff
    }

    // ---- structs: the header's, in its order, field for field ----------------------------------

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_vec3
    {
        public double x, y, z;
        public gzl_vec3(double x, double y, double z) { this.x = x; this.y = y; this.z = z; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_quat
    {
        public double x, y, z, w;
        public gzl_quat(double x, double y, double z, double w) { this.x = x; this.y = y; this.z = z; this.w = w; }
        public static readonly gzl_quat Identity = new gzl_quat(0.0, 0.0, 0.0, 1.0);
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_fov
    {
        public double angle_left, angle_right, angle_up, angle_down;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_view
    {
        public gzl_fov fov;
        public gzl_quat orientation_in_head; // zero quaternion = identity
        public gzl_vec3 position_in_head_m;
        public uint width_px, height_px;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_config
    {
        public gzl_structure_type type; // GZL_TYPE_CONFIG
        public IntPtr next;
        public uint disabled_criteria; // gzl_criterion_bits
        public uint disable_switch_policy; // gzl_bool32
        public double frame_budget_ms;
        public double gaze_accuracy_deg;
        public double head_fixed_cone_deg;
        public double gaze_silence_timeout_s;
        public double max_gaze_sample_age_s;
        public IntPtr hmd_preset; // const char*: Plugin takes a string and marshals it
        public static gzl_config Create() { var c = new gzl_config(); c.type = gzl_structure_type.GZL_TYPE_CONFIG; return c; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_data_create_info
    {
        public gzl_structure_type type; // GZL_TYPE_DATA_CREATE_INFO
        public IntPtr next;
        public uint view_count;
        public IntPtr views; // const gzl_view*
        public IntPtr config; // const gzl_config*
        public static gzl_data_create_info Create()
        {
            var c = new gzl_data_create_info(); c.type = gzl_structure_type.GZL_TYPE_DATA_CREATE_INFO; return c;
        }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_openxr_create_info
    {
        public gzl_structure_type type; // GZL_TYPE_OPENXR_CREATE_INFO
        public IntPtr next;
        public IntPtr get_instance_proc_addr; // gzl_void_function: PFN_xrGetInstanceProcAddr
        public ulong instance; // XrInstance
        public ulong system_id; // XrSystemId
        public ulong session; // XrSession
        public ulong base_space; // XrSpace
        public uint view_configuration_type; // XrViewConfigurationType, 0 = PRIMARY_STEREO
        public gzl_gaze_input gaze_input;
        public ulong gaze_space; // XrSpace
        public ulong gaze_action; // XrAction
        public IntPtr config; // const gzl_config*
        public static gzl_openxr_create_info Create()
        {
            var c = new gzl_openxr_create_info(); c.type = gzl_structure_type.GZL_TYPE_OPENXR_CREATE_INFO; return c;
        }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_gaze_binding
    {
        public gzl_structure_type type; // GZL_TYPE_GAZE_BINDING
        public IntPtr next;
        public ulong action_set; // XrActionSet
        public ulong action; // XrAction
        public IntPtr interaction_profile; // const char*, static: Marshal.PtrToStringAnsi
        public IntPtr binding_path; // const char*, static
        public static gzl_gaze_binding Create()
        {
            var c = new gzl_gaze_binding(); c.type = gzl_structure_type.GZL_TYPE_GAZE_BINDING; return c;
        }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_level
    {
        public double value; // in the object's metric; level 0 is ignored
        public uint triangles;
        public gzl_level(double value, uint triangles) { this.value = value; this.triangles = triangles; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_object_desc
    {
        public gzl_structure_type type; // GZL_TYPE_OBJECT_DESC
        public IntPtr next;
        public gzl_vec3 center_m;
        public double radius_m;
        public gzl_vec3 velocity_m_s;
        public double importance;
        public gzl_level_metric metric;
        public uint level_count;
        public IntPtr levels; // const gzl_level*
        public static gzl_object_desc Create()
        {
            var c = new gzl_object_desc(); c.type = gzl_structure_type.GZL_TYPE_OBJECT_DESC; return c;
        }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_gaze_sample
    {
        public gzl_structure_type type; // GZL_TYPE_GAZE_SAMPLE
        public IntPtr next;
        public long time_ns;
        public gzl_vec3 direction;
        public gzl_vec3 origin_m;
        public uint flags; // gzl_gaze_sample_flag_bits
        public gzl_quat head_orientation;
        public static gzl_gaze_sample Create()
        {
            var c = new gzl_gaze_sample(); c.type = gzl_structure_type.GZL_TYPE_GAZE_SAMPLE; return c;
        }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_head_pose
    {
        public gzl_quat orientation;
        public gzl_vec3 position_m;
        public gzl_vec3 angular_velocity_rad_s;
        public gzl_vec3 linear_velocity_m_s;
        public uint flags; // gzl_head_flag_bits
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_frame_input
    {
        public gzl_structure_type type; // GZL_TYPE_FRAME_INPUT
        public IntPtr next;
        public long display_time_ns;
        public gzl_head_pose head;
        public uint view_count; // 0: the views given at creation (or last frame)
        public IntPtr views; // const gzl_view*
        public static gzl_frame_input Create()
        {
            var c = new gzl_frame_input(); c.type = gzl_structure_type.GZL_TYPE_FRAME_INPUT; return c;
        }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_frame_info
    {
        public gzl_structure_type type; // GZL_TYPE_FRAME_INFO
        public IntPtr next;
        public ulong frame_index;
        public long display_time_ns;
        public uint object_count;
        public gzl_gaze_source gaze_source;
        public gzl_eye_motion eye_motion;
        public uint gaze_suppressed; // gzl_bool32
        public uint head_valid; // gzl_bool32
        public gzl_vec3 gaze_direction_base;
        public gzl_vec3 eye_position_base_m;
        public gzl_vec3 head_angular_velocity_rad_s;
        public gzl_vec3 head_linear_velocity_m_s;
        public gzl_vec3 gaze_angular_velocity_in_head_rad_s;
        public double gaze_uncertainty_deg;
        public double xi_cpd;
        public ulong triangles_drawn;
        public ulong triangles_full;
        public static gzl_frame_info Create()
        {
            var c = new gzl_frame_info(); c.type = gzl_structure_type.GZL_TYPE_FRAME_INFO; return c;
        }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_foveal_cone
    {
        public gzl_structure_type type; // GZL_TYPE_FOVEAL_CONE
        public IntPtr next;
        public gzl_vec3 direction_in_view;
        public double fovea_deg;
        public double uncertainty_deg;
        public double half_angle_deg;
        public double center_u, center_v; // scalars: the struct is blittable, read without copies
        public double radius_u, radius_v;
        public uint in_view; // gzl_bool32
        public static gzl_foveal_cone Create()
        {
            var c = new gzl_foveal_cone();
            c.type = gzl_structure_type.GZL_TYPE_FOVEAL_CONE;
            return c;
        }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct gzl_frame_record
    {
        public gzl_structure_type type; // GZL_TYPE_FRAME_RECORD
        public IntPtr next;
        public long display_time_ns;
        public gzl_head_pose head;
        public uint view_count;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 4)] public gzl_view[] views; // GZL_MAX_VIEWS
        public uint has_gaze_sample; // gzl_bool32
        public gzl_gaze_sample gaze_sample;
        public static gzl_frame_record Create()
        {
            var c = new gzl_frame_record();
            c.type = gzl_structure_type.GZL_TYPE_FRAME_RECORD;
            c.views = new gzl_view[Native.GZL_MAX_VIEWS];
            return c;
        }
    }

    // ---- the plugin handle -----------------------------------------------------------------------

    // gzl_plugin as a SafeHandle: released with gzl_destroy (which shuts down first if needed).
    // The runtime keeps it alive through every P/Invoke that takes it, so a finalizer never
    // destroys a plugin under a call in progress; gzl_destroy is then the last call, as required.
    public sealed class PluginHandle : SafeHandle
    {
        public PluginHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid { get { return handle == IntPtr.Zero; } }
        protected override bool ReleaseHandle()
        {
            Native.gzl_destroy(handle);
            return true;
        }
    }

    // ---- P/Invoke: every GZL_API function ------------------------------------------------------

    public static class Native
    {
        public const string Library = "gazelod";

        // The ABI this file was written for (GZL_HEADER_VERSION = GZL_MAKE_VERSION(1, 0, 0)).
        public const uint AbiVersionMajor = 1;
        public const uint AbiVersionMinor = 0;
        public const uint AbiVersionPatch = 0;
        public const uint GZL_HEADER_VERSION = (AbiVersionMajor << 22) | (AbiVersionMinor << 12) | AbiVersionPatch;
        public static uint MakeVersion(uint major, uint minor, uint patch) { return (major << 22) | (minor << 12) | patch; }
        public static uint VersionMajor(uint version) { return (version >> 22) & 0x3ffu; }
        public static uint VersionMinor(uint version) { return (version >> 12) & 0x3ffu; }
        public static uint VersionPatch(uint version) { return version & 0xfffu; }

        public const uint GZL_MAX_VIEWS = 4;
        public const ulong GZL_NULL_OBJECT = 0;
        public const byte GZL_LEVEL_DISABLED = 255;

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern uint gzl_version();

        // A static string: Marshal.PtrToStringAnsi (Plugin.ResultToString does it).
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern IntPtr gzl_result_to_string(gzl_result result);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_create_data(ref gzl_data_create_info info, out PluginHandle plugin);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_create_openxr(ref gzl_openxr_create_info info, out PluginHandle plugin);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_get_gaze_binding(PluginHandle plugin, ref gzl_gaze_binding binding);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_action_sets_attached(PluginHandle plugin);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_set_gaze_space(PluginHandle plugin, ulong gaze_space, ulong gaze_action);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_on_session_state(PluginHandle plugin, int xr_session_state, long time_ns);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_set_base_space(PluginHandle plugin, ulong base_space);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_set_view_resolution(PluginHandle plugin, uint view_index, uint width_px,
                                                                uint height_px);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_begin_frame_openxr(PluginHandle plugin, long predicted_display_time);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_add_object(PluginHandle plugin, ref gzl_object_desc desc, out ulong obj);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_remove_object(PluginHandle plugin, ulong obj);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_set_object_enabled(PluginHandle plugin, ulong obj, uint enabled);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_set_object_motion(PluginHandle plugin, ulong obj, ref gzl_vec3 center_m,
                                                              ref gzl_vec3 velocity_m_s);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_push_gaze_sample(PluginHandle plugin, ref gzl_gaze_sample sample);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_begin_frame_data(PluginHandle plugin, ref gzl_frame_input input);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_end_frame(PluginHandle plugin, double measured_frame_ms);

        // objects and levels are blittable arrays: pinned for the call, no copy.
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_get_levels(PluginHandle plugin, uint count, [In] ulong[] objects,
                                                       [Out] byte[] levels);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_get_frame_info(PluginHandle plugin, ref gzl_frame_info info);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_get_foveal_cone(PluginHandle plugin, uint view_index, ref gzl_foveal_cone cone);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_get_frame_record(PluginHandle plugin, ref gzl_frame_record record);

        // size_t as UIntPtr. The text is UTF-8/ASCII, NUL-terminated in buffer when capacity > 0.
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_get_gaze_status(PluginHandle plugin, [Out] byte[] buffer, UIntPtr capacity,
                                                            out UIntPtr length);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_get_last_error(PluginHandle plugin, [Out] byte[] buffer, UIntPtr capacity,
                                                           out UIntPtr length);

        // The same function with a NULL plugin (pass IntPtr.Zero): the calling thread's last failed
        // create. A SafeHandle cannot be null, hence this overload.
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_get_last_error(IntPtr plugin, [Out] byte[] buffer, UIntPtr capacity,
                                                           out UIntPtr length);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern gzl_result gzl_shutdown(PluginHandle plugin);

        // Called by PluginHandle.ReleaseHandle: do not call it on a handle a PluginHandle owns.
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern void gzl_destroy(IntPtr plugin);
    }

    // ---- the wrapper -----------------------------------------------------------------------------

    public class GazelodException : Exception
    {
        public gzl_result Result { get; private set; }
        public string Call { get; private set; }
        public string NativeMessage { get; private set; } // gazelod's message ("gazelod: ...")

        public GazelodException(gzl_result result, string call, string nativeMessage)
            : base(call + " -> " + Marshal.PtrToStringAnsi(Native.gzl_result_to_string(result)) + ": " + nativeMessage)
        {
            Result = result;
            Call = call;
            NativeMessage = nativeMessage;
        }
    }

    // What gzl_get_gaze_binding gives, with its strings read.
    public struct GazeBinding
    {
        public ulong ActionSet, Action;
        public string InteractionProfile, BindingPath;
    }

    // One gazelod plugin. Every method throws GazelodException on failure; Dispose (or the
    // finalizer of the handle) calls gzl_destroy. Calls may come from any thread (the library
    // serialises them). The per-frame methods (PushGazeSample, BeginFrame*, GetLevels,
    // GetFrameInfo) allocate nothing on the managed heap; GetFovealCone and GetFrameRecord
    // copy their fixed arrays into managed arrays.
    public sealed class Plugin : IDisposable
    {
        private readonly PluginHandle handle_;

        static Plugin() { CheckVersion(); }

        private Plugin(PluginHandle handle) { handle_ = handle; }

        public PluginHandle Handle { get { return handle_; } }

        // The loaded library's version (GZL_MAKE_VERSION layout).
        public static uint LibraryVersion { get { return Native.gzl_version(); } }

        // Throws if the loaded library's ABI major differs from the one these bindings declare.
        public static void CheckVersion()
        {
            uint v = Native.gzl_version();
            if (Native.VersionMajor(v) != Native.AbiVersionMajor)
                throw new GazelodException(gzl_result.GZL_ERROR_INTERNAL, "gzl_version",
                    string.Format("gazelod: the loaded libgazelod has ABI {0}.{1}.{2}; these C# bindings are for ABI {3}.x",
                                  Native.VersionMajor(v), Native.VersionMinor(v), Native.VersionPatch(v),
                                  Native.AbiVersionMajor));
        }

        public static string ResultToString(gzl_result result)
        {
            return Marshal.PtrToStringAnsi(Native.gzl_result_to_string(result));
        }

        // Data mode: 1, 2 or 4 views; config null for the defaults.
        public static Plugin CreateData(gzl_view[] views, gzl_config? config = null, string hmdPreset = null)
        {
            if (views == null) throw new ArgumentNullException("views");
            var info = gzl_data_create_info.Create();
            info.view_count = (uint)views.Length;
            var pinned = GCHandle.Alloc(views, GCHandleType.Pinned);
            IntPtr configPtr = IntPtr.Zero, presetPtr = IntPtr.Zero;
            try
            {
                configPtr = MarshalConfig(config, hmdPreset, out presetPtr);
                info.views = pinned.AddrOfPinnedObject();
                info.config = configPtr;
                PluginHandle h;
                gzl_result r = Native.gzl_create_data(ref info, out h);
                if (r != gzl_result.GZL_SUCCESS) throw new GazelodException(r, "gzl_create_data", CreateError());
                return new Plugin(h);
            }
            finally
            {
                pinned.Free();
                FreeConfig(configPtr, presetPtr);
            }
        }

        // OpenXR mode. getInstanceProcAddr: the application's PFN_xrGetInstanceProcAddr (what an
        // engine hands its native plugins, e.g. Unity's OpenXRFeature.HookGetInstanceProcAddr /
        // xrGetInstanceProcAddr). Handles are the XrInstance, XrSystemId, XrSession and XrSpace
        // values as 64-bit integers (ulong).
        public static Plugin CreateOpenXr(IntPtr getInstanceProcAddr, ulong instance, ulong systemId, ulong session,
                                          ulong baseSpace, gzl_gaze_input gazeInput, ulong gazeSpace = 0,
                                          ulong gazeAction = 0, uint viewConfigurationType = 0,
                                          gzl_config? config = null, string hmdPreset = null)
        {
            var info = gzl_openxr_create_info.Create();
            info.get_instance_proc_addr = getInstanceProcAddr;
            info.instance = instance;
            info.system_id = systemId;
            info.session = session;
            info.base_space = baseSpace;
            info.view_configuration_type = viewConfigurationType;
            info.gaze_input = gazeInput;
            info.gaze_space = gazeSpace;
            info.gaze_action = gazeAction;
            IntPtr configPtr = IntPtr.Zero, presetPtr = IntPtr.Zero;
            try
            {
                configPtr = MarshalConfig(config, hmdPreset, out presetPtr);
                info.config = configPtr;
                PluginHandle h;
                gzl_result r = Native.gzl_create_openxr(ref info, out h);
                if (r != gzl_result.GZL_SUCCESS) throw new GazelodException(r, "gzl_create_openxr", CreateError());
                return new Plugin(h);
            }
            finally
            {
                FreeConfig(configPtr, presetPtr);
            }
        }

        // ---- OpenXR mode ----
        public GazeBinding GetGazeBinding()
        {
            var b = gzl_gaze_binding.Create();
            Check(Native.gzl_get_gaze_binding(handle_, ref b), "gzl_get_gaze_binding");
            var g = new GazeBinding();
            g.ActionSet = b.action_set;
            g.Action = b.action;
            g.InteractionProfile = Marshal.PtrToStringAnsi(b.interaction_profile);
            g.BindingPath = Marshal.PtrToStringAnsi(b.binding_path);
            return g;
        }
        public void ActionSetsAttached() { Check(Native.gzl_action_sets_attached(handle_), "gzl_action_sets_attached"); }
        public void SetGazeSpace(ulong gazeSpace, ulong gazeAction = 0)
        {
            Check(Native.gzl_set_gaze_space(handle_, gazeSpace, gazeAction), "gzl_set_gaze_space");
        }
        public void SetBaseSpace(ulong baseSpace) { Check(Native.gzl_set_base_space(handle_, baseSpace), "gzl_set_base_space"); }
        public void BeginFrameOpenXr(long predictedDisplayTime)
        {
            Check(Native.gzl_begin_frame_openxr(handle_, predictedDisplayTime), "gzl_begin_frame_openxr");
        }

        // ---- both modes ----
        public void OnSessionState(int xrSessionState, long timeNs)
        {
            Check(Native.gzl_on_session_state(handle_, xrSessionState, timeNs), "gzl_on_session_state");
        }
        public void SetViewResolution(uint viewIndex, uint widthPx, uint heightPx)
        {
            Check(Native.gzl_set_view_resolution(handle_, viewIndex, widthPx, heightPx), "gzl_set_view_resolution");
        }

        // The levels are copied by the library: the array need not outlive the call.
        public ulong AddObject(gzl_vec3 centerM, double radiusM, gzl_level_metric metric, gzl_level[] levels,
                               gzl_vec3 velocityMS = default(gzl_vec3), double importance = 0.0)
        {
            if (levels == null) throw new ArgumentNullException("levels");
            var desc = gzl_object_desc.Create();
            desc.center_m = centerM;
            desc.radius_m = radiusM;
            desc.velocity_m_s = velocityMS;
            desc.importance = importance;
            desc.metric = metric;
            desc.level_count = (uint)levels.Length;
            var pinned = GCHandle.Alloc(levels, GCHandleType.Pinned);
            try
            {
                desc.levels = pinned.AddrOfPinnedObject();
                ulong obj;
                Check(Native.gzl_add_object(handle_, ref desc, out obj), "gzl_add_object");
                return obj;
            }
            finally
            {
                pinned.Free();
            }
        }
        public void RemoveObject(ulong obj) { Check(Native.gzl_remove_object(handle_, obj), "gzl_remove_object"); }
        public void SetObjectEnabled(ulong obj, bool enabled)
        {
            Check(Native.gzl_set_object_enabled(handle_, obj, enabled ? 1u : 0u), "gzl_set_object_enabled");
        }
        public void SetObjectMotion(ulong obj, gzl_vec3 centerM, gzl_vec3 velocityMS)
        {
            Check(Native.gzl_set_object_motion(handle_, obj, ref centerM, ref velocityMS), "gzl_set_object_motion");
        }

        // The type is set here.
        public void PushGazeSample(gzl_gaze_sample sample)
        {
            sample.type = gzl_structure_type.GZL_TYPE_GAZE_SAMPLE;
            Check(Native.gzl_push_gaze_sample(handle_, ref sample), "gzl_push_gaze_sample");
        }

        // Data mode. views: null for the views given at creation (or last frame).
        public void BeginFrameData(long displayTimeNs, gzl_head_pose head, gzl_view[] views = null)
        {
            var input = gzl_frame_input.Create();
            input.display_time_ns = displayTimeNs;
            input.head = head;
            if (views == null || views.Length == 0)
            {
                Check(Native.gzl_begin_frame_data(handle_, ref input), "gzl_begin_frame_data");
                return;
            }
            input.view_count = (uint)views.Length;
            var pinned = GCHandle.Alloc(views, GCHandleType.Pinned);
            try
            {
                input.views = pinned.AddrOfPinnedObject();
                Check(Native.gzl_begin_frame_data(handle_, ref input), "gzl_begin_frame_data");
            }
            finally
            {
                pinned.Free();
            }
        }
        public void EndFrame(double measuredFrameMs) { Check(Native.gzl_end_frame(handle_, measuredFrameMs), "gzl_end_frame"); }

        // levels[i] for objects[i] (GZL_LEVEL_DISABLED for a disabled object); levels.Length >= objects.Length.
        public void GetLevels(ulong[] objects, byte[] levels)
        {
            if (objects == null) throw new ArgumentNullException("objects");
            if (levels == null || levels.Length < objects.Length) throw new ArgumentException("levels is shorter than objects");
            Check(Native.gzl_get_levels(handle_, (uint)objects.Length, objects, levels), "gzl_get_levels");
        }
        public gzl_frame_info GetFrameInfo()
        {
            var info = gzl_frame_info.Create();
            Check(Native.gzl_get_frame_info(handle_, ref info), "gzl_get_frame_info");
            return info;
        }
        public gzl_foveal_cone GetFovealCone(uint viewIndex)
        {
            var cone = gzl_foveal_cone.Create();
            Check(Native.gzl_get_foveal_cone(handle_, viewIndex, ref cone), "gzl_get_foveal_cone");
            return cone;
        }
        public gzl_frame_record GetFrameRecord()
        {
            var record = gzl_frame_record.Create();
            Check(Native.gzl_get_frame_record(handle_, ref record), "gzl_get_frame_record");
            return record;
        }
        public string GazeStatus
        {
            get
            {
                var buffer = new byte[256];
                UIntPtr length;
                Check(Native.gzl_get_gaze_status(handle_, buffer, (UIntPtr)buffer.Length, out length), "gzl_get_gaze_status");
                if ((ulong)length >= (ulong)buffer.Length)
                {
                    buffer = new byte[(int)length + 1];
                    Check(Native.gzl_get_gaze_status(handle_, buffer, (UIntPtr)buffer.Length, out length), "gzl_get_gaze_status");
                }
                return Text(buffer, length);
            }
        }

        // The last error message on this plugin ("gazelod: ..."), "" if none.
        public string LastError { get { return ErrorText(handle_, IntPtr.Zero); } }

        // Before xrDestroySession / xrDestroyInstance. Safe twice.
        public void Shutdown() { Check(Native.gzl_shutdown(handle_), "gzl_shutdown"); }

        // gzl_destroy (after gzl_shutdown if that was not called).
        public void Dispose() { handle_.Dispose(); }

        // ---- helpers ----
        private void Check(gzl_result r, string call)
        {
            if (r != gzl_result.GZL_SUCCESS) throw new GazelodException(r, call, LastError);
        }

        // The calling thread's last failed create (gzl_get_last_error with a NULL plugin).
        private static string CreateError() { return ErrorText(null, IntPtr.Zero); }

        // plugin, or (plugin null) the raw pointer: IntPtr.Zero for the thread's last failed create.
        private static string ErrorText(PluginHandle plugin, IntPtr raw)
        {
            var buffer = new byte[512];
            for (int attempt = 0; attempt < 2; ++attempt)
            {
                UIntPtr length;
                gzl_result r = plugin != null
                    ? Native.gzl_get_last_error(plugin, buffer, (UIntPtr)buffer.Length, out length)
                    : Native.gzl_get_last_error(raw, buffer, (UIntPtr)buffer.Length, out length);
                if (r != gzl_result.GZL_SUCCESS) return "";
                if ((ulong)length < (ulong)buffer.Length) return Text(buffer, length);
                buffer = new byte[(int)length + 1]; // cut: once more with room for all of it
            }
            return Text(buffer, (UIntPtr)(buffer.Length - 1));
        }

        private static string Text(byte[] buffer, UIntPtr length)
        {
            int n = (int)Math.Min((ulong)length, (ulong)(buffer.Length - 1));
            return Encoding.UTF8.GetString(buffer, 0, n);
        }

        private static IntPtr MarshalConfig(gzl_config? config, string hmdPreset, out IntPtr presetPtr)
        {
            presetPtr = IntPtr.Zero;
            if (config == null && hmdPreset == null) return IntPtr.Zero;
            gzl_config c = config ?? gzl_config.Create();
            c.type = gzl_structure_type.GZL_TYPE_CONFIG;
            if (hmdPreset != null) presetPtr = Marshal.StringToHGlobalAnsi(hmdPreset);
            c.hmd_preset = presetPtr;
            IntPtr p = Marshal.AllocHGlobal(Marshal.SizeOf(typeof(gzl_config)));
            Marshal.StructureToPtr(c, p, false);
            return p;
        }

        private static void FreeConfig(IntPtr configPtr, IntPtr presetPtr)
        {
            if (configPtr != IntPtr.Zero) Marshal.FreeHGlobal(configPtr);
            if (presetPtr != IntPtr.Zero) Marshal.FreeHGlobal(presetPtr);
        }
    }
}
