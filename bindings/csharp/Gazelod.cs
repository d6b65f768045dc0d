// SPDX-License-Identifier: Apache-2.0
// Gazelod.cs: C# bindings for gazelod's C ABI (include/gazelod/gazelod.h, libgazelod.so.1).
//
// Two layers in three files (drop the three into a Unity project's Assets, or compile them
// together with mcs/csc):
//   Gazelod.Types.cs    every struct and enum of the header under its C name, field for field
//                       ([StructLayout(Sequential)], enums int-sized, gzl_bool32 as uint, handles
//                       as ulong, pointers as IntPtr). bindings/csharp/tests/GazelodTest.cs checks
//                       each struct's size and each field's offset against the C compiler's
//                       (struct_sizes.c).
//   Gazelod.Native.cs   Gazelod.Native: P/Invoke declarations for every GZL_API function, and the
//                       plugin handle as a SafeHandle (PluginHandle, released with gzl_destroy).
//   Gazelod.cs          Gazelod.Plugin, a small wrapper whose methods throw GazelodException (the
//                       gzl_result and gazelod's message) instead of returning codes.
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
            // hmdPreset, when given, replaces config.hmd_preset; else the caller's own pointer stays
            // (it was overwritten with null: a preset set in the struct was dropped unseen).
            if (hmdPreset != null)
            {
                presetPtr = Marshal.StringToHGlobalAnsi(hmdPreset);
                c.hmd_preset = presetPtr;
            }
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
