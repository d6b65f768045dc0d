// SPDX-License-Identifier: Apache-2.0
// Gazelod.Native.cs: the plugin handle and the P/Invoke declaration of every GZL_API function
// (the bindings' first layer; Gazelod.cs says how the three files fit together).

using System;
using System.Runtime.InteropServices;
using System.Text;

namespace Gazelod
{
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
}
