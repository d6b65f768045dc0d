// SPDX-License-Identifier: Apache-2.0
// Gazelod.Types.cs: every enum and struct of include/gazelod/gazelod.h under its C name, field
// for field (the bindings' first layer; Gazelod.cs says how the three files fit together).

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
}
