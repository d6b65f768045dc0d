// SPDX-License-Identifier: Apache-2.0
// GazelodTest.cs: the C# bindings (bindings/csharp/Gazelod*.cs) against libgazelod, as an engine
// would use them. A console program:
//   mono gazelod_csharp_test.exe <struct sizes file> <gazelod.h> [--skip-openxr]
//   layout     every struct's Marshal.SizeOf and every field's Marshal.OffsetOf equal the C
//              compiler's sizeof/offsetof (the file written by struct_sizes.c), every enum is
//              int-sized with the C values, and every gzl_* struct declared in C# is in the file
//              and vice versa; every GZL_API function of the header has a DllImport and vice versa;
//   data mode  2 views, a grid of objects; the eyes fixate the left object, make one saccade,
//              fixate the right one: the fixated object is drawn finer. Then the error paths
//              (an out-of-order sample, a failed create, wrong-mode calls, a removed handle,
//              a shut-down plugin), each with a "gazelod:" message;
//   OpenXR     the Khronos loader P/Invoked for xrGetInstanceProcAddr only, every other xr*
//              function through it (Marshal.GetDelegateForFunctionPointer), a headless session
//              with XR_EXT_eye_gaze_interaction against the simulated runtime, and gazelod given
//              the loader's xrGetInstanceProcAddr as a raw pointer (dlsym), as Unity hands it
//              to native plugins, with GZL_GAZE_INPUT_PLUGIN_ACTIONS.
// Exit status 0 only if every check holds; each failed check is printed.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Text;
using Gazelod;

static class GazelodTest
{
    static int failures = 0;

    static void Check(bool condition, string what)
    {
        Console.WriteLine("{0} {1}", condition ? "ok  " : "FAIL", what);
        if (!condition) ++failures;
    }

    static void Fail(string what)
    {
        Console.WriteLine("FAIL {0}", what);
        ++failures;
    }

    // Runs a wrapper call that must fail with `expected` and a "gazelod:" message.
    static void ExpectError(gzl_result expected, string what, Action call)
    {
        try
        {
            call();
            Fail(what + ": succeeded, expected " + expected);
        }
        catch (GazelodException e)
        {
            Console.WriteLine("     {0}", e.Message);
            Check(e.Result == expected && e.NativeMessage.StartsWith("gazelod:"),
                  what + " -> " + Plugin.ResultToString(e.Result) + " with a \"gazelod:\" message");
        }
    }

    static int Main(string[] args)
    {
        if (args.Length < 2 || args.Length > 3 || (args.Length == 3 && args[2] != "--skip-openxr"))
        {
            Console.Error.WriteLine("usage: mono gazelod_csharp_test.exe <struct sizes file> <gazelod.h> [--skip-openxr]");
            return 2;
        }
        try
        {
            uint v = Plugin.LibraryVersion;
            Console.WriteLine("libgazelod {0}.{1}.{2}, bindings for ABI {3}.{4}.{5}", Native.VersionMajor(v),
                              Native.VersionMinor(v), Native.VersionPatch(v), Native.AbiVersionMajor,
                              Native.AbiVersionMinor, Native.AbiVersionPatch);
            Check(Native.VersionMajor(v) == Native.AbiVersionMajor, "gzl_version()'s major is the bindings' ABI major");
            Check(Native.GZL_HEADER_VERSION == Native.MakeVersion(1, 0, 0), "GZL_HEADER_VERSION is GZL_MAKE_VERSION(1, 0, 0)");
            Check(Plugin.ResultToString(gzl_result.GZL_ERROR_TIME_OUT_OF_ORDER) == "GZL_ERROR_TIME_OUT_OF_ORDER",
                  "gzl_result_to_string gives the enumerant's name");

            Console.WriteLine("== layout");
            LayoutCheck(args[0]);
            FunctionCheck(args[1]);
            Console.WriteLine("== data mode");
            DataMode();
            ConfigPresetInTheStruct();
            Console.WriteLine("== OpenXR mode");
            if (args.Length == 3) Console.WriteLine("skipped (--skip-openxr: no simulated OpenXR runtime in this build)");
            else OpenXrMode();
        }
        catch (Exception e)
        {
            Fail("unexpected exception: " + e);
        }
        Console.WriteLine("{0}: {1} failure(s)", failures == 0 ? "PASS" : "FAIL", failures);
        return failures == 0 ? 0 : 1;
    }

    // ---- layout --------------------------------------------------------------------------------

    static void LayoutCheck(string path)
    {
        var assembly = typeof(Plugin).Assembly;
        var structsInFile = new HashSet<string>();
        var enumerantsInFile = new HashSet<string>();
        int lines = 0, mismatches = 0;
        foreach (string raw in File.ReadAllLines(path))
        {
            string line = raw.Trim();
            if (line.Length == 0) continue;
            ++lines;
            string[] parts = line.Split(' ');
            try
            {
                if (parts[0] == "enum")
                {
                    Type t = assembly.GetType("Gazelod." + parts[1], true);
                    int cSize = int.Parse(parts[2]);
                    int size = Marshal.SizeOf(Enum.GetUnderlyingType(t));
                    if (!t.IsEnum || size != cSize)
                    {
                        Fail(string.Format("enum {0}: C sizeof {1}, C# {2}", parts[1], cSize, size));
                        ++mismatches;
                    }
                }
                else if (parts[0] == "value") // an enumerant: C# must declare it, with the same value
                {
                    string[] tv = parts[1].Split('.');
                    Type t = assembly.GetType("Gazelod." + tv[0], true);
                    long cValue = long.Parse(parts[2]);
                    object member = Enum.Parse(t, tv[1]);
                    long value = Convert.ToInt64(member);
                    enumerantsInFile.Add(parts[1]);
                    if (value != cValue)
                    {
                        Fail(string.Format("{0}: C {1}, C# {2}", parts[1], cValue, value));
                        ++mismatches;
                    }
                }
                else if (parts[0] == "const") // a macro Native mirrors under the same name
                {
                    var field = typeof(Native).GetField(parts[1]);
                    if (field == null) throw new Exception("Gazelod.Native does not declare " + parts[1]);
                    ulong cValue = ulong.Parse(parts[2]);
                    ulong value = Convert.ToUInt64(field.GetValue(null));
                    if (value != cValue)
                    {
                        Fail(string.Format("{0}: C {1}, C# {2}", parts[1], cValue, value));
                        ++mismatches;
                    }
                }
                else if (parts[0].Contains("."))
                {
                    string[] tf = parts[0].Split('.');
                    Type t = assembly.GetType("Gazelod." + tf[0], true);
                    int cOffset = int.Parse(parts[1]);
                    int offset = (int)Marshal.OffsetOf(t, tf[1]);
                    if (offset != cOffset)
                    {
                        Fail(string.Format("{0}: C offsetof {1}, C# Marshal.OffsetOf {2}", parts[0], cOffset, offset));
                        ++mismatches;
                    }
                }
                else
                {
                    Type t = assembly.GetType("Gazelod." + parts[0], true);
                    structsInFile.Add(parts[0]);
                    int cSize = int.Parse(parts[1]);
                    int size = Marshal.SizeOf(t);
                    if (size != cSize)
                    {
                        Fail(string.Format("{0}: C sizeof {1}, C# Marshal.SizeOf {2}", parts[0], cSize, size));
                        ++mismatches;
                    }
                }
            }
            catch (Exception e) // a type or field the C# side does not declare, or a bad line
            {
                Fail(string.Format("\"{0}\": {1}", line, e.Message));
                ++mismatches;
            }
        }
        // Every struct the C# side declares must have been measured in C (a struct added to
        // Gazelod.Types.cs but not to struct_sizes.c would go unchecked).
        var declared = assembly.GetTypes()
            .Where(t => t.Namespace == "Gazelod" && t.Name.StartsWith("gzl_") && t.IsValueType && !t.IsEnum)
            .Select(t => t.Name).ToList();
        foreach (string name in declared)
            if (!structsInFile.Contains(name))
            {
                Fail("struct " + name + " is declared in C# but not measured by struct_sizes.c");
                ++mismatches;
            }
        // ...and every enumerant (one the C header lacks would be a value the library refuses).
        foreach (Type t in assembly.GetTypes().Where(t => t.Namespace == "Gazelod" && t.Name.StartsWith("gzl_") && t.IsEnum))
            foreach (string member in Enum.GetNames(t))
                if (!enumerantsInFile.Contains(t.Name + "." + member))
                {
                    Fail("enumerant " + t.Name + "." + member + " is declared in C# but not in the C header");
                    ++mismatches;
                }
        Check(structsInFile.Count >= 16 && declared.Count == structsInFile.Count,
              string.Format("{0} structs measured in C, {1} declared in C#", structsInFile.Count, declared.Count));
        Check(mismatches == 0 && enumerantsInFile.Count > 0,
              string.Format("{0} lines from {1} (sizes, offsets, enumerants, constants) agree with the C# declarations", lines, path));
    }

    // Every GZL_API function of the header has a DllImport in Native, and every DllImport is one.
    static void FunctionCheck(string headerPath)
    {
        string header = File.ReadAllText(headerPath);
        var inHeader = new HashSet<string>(
            System.Text.RegularExpressions.Regex.Matches(header, @"^GZL_API\s+[\w\s\*]*?\b(gzl_\w+)\s*\(",
                                                         System.Text.RegularExpressions.RegexOptions.Multiline)
                .Cast<System.Text.RegularExpressions.Match>().Select(m => m.Groups[1].Value));
        var imported = new HashSet<string>(
            typeof(Native).GetMethods(System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.Static)
                .Where(m => (m.Attributes & System.Reflection.MethodAttributes.PinvokeImpl) != 0)
                .Select(m => m.Name)); // named as their entry points
        foreach (string f in inHeader.Except(imported)) Fail("GZL_API " + f + " has no DllImport in Gazelod.Native");
        foreach (string f in imported.Except(inHeader)) Fail("DllImport " + f + " is not a GZL_API function of " + headerPath);
        Check(inHeader.Count >= 26 && inHeader.SetEquals(imported),
              string.Format("{0} GZL_API functions in the header, {1} imported", inHeader.Count, imported.Count));
    }

    // ---- data mode -----------------------------------------------------------------------------

    const long FrameNs = 11111111L;    // 90 Hz display
    const long SampleNs = 8333333L;    // 120 Hz eye tracker
    const long LatencyNs = 25000000L;  // the frame is decided ~25 ms before it is shown
    // Each half lasts 1.5 s: an object no longer fixated coarsens after the switch policy's 0.2 s
    // hold, then waits up to 1 s for a saccade or blink to hide the change.
    const int HalfFrames = 135;
    const int Grid = 3;
    const double GridSpacingM = 1.2, GridDistanceM = 3.0;

    // Where the eyes look at time t (head space = base space: the head is still at the origin).
    // A main-sequence saccade: 21 ms + 2.2 ms/deg, smooth velocity profile.
    static gzl_vec3 GazeAt(long tNs, long saccadeStartNs, double yawFrom, double yawTo)
    {
        double amplitudeDeg = Math.Abs(yawTo - yawFrom) * 180.0 / Math.PI;
        double durationNs = (0.021 + 0.0022 * amplitudeDeg) * 1e9;
        double f = Math.Max(0.0, Math.Min(1.0, (tNs - saccadeStartNs) / durationNs));
        double yaw = yawFrom + (yawTo - yawFrom) * (0.5 - 0.5 * Math.Cos(Math.PI * f));
        return new gzl_vec3(Math.Sin(yaw), 0.0, -Math.Cos(yaw));
    }

    static gzl_view[] QuestProViews()
    {
        var views = new gzl_view[2]; // zero orientation = identity
        for (int i = 0; i < 2; ++i)
        {
            const double outer = 0.942, inner = 0.698;
            views[i].fov.angle_left = i == 0 ? -outer : -inner;
            views[i].fov.angle_right = i == 0 ? inner : outer;
            views[i].fov.angle_up = 0.768;
            views[i].fov.angle_down = -0.873;
            views[i].position_in_head_m.x = i == 0 ? -0.032 : 0.032;
            views[i].width_px = 1832;
            views[i].height_px = 1920;
        }
        return views;
    }

    static gzl_head_pose StillHead()
    {
        var head = new gzl_head_pose();
        head.orientation = gzl_quat.Identity;
        head.flags = (uint)(gzl_head_flag_bits.GZL_HEAD_POSE_VALID | gzl_head_flag_bits.GZL_HEAD_ANGULAR_VELOCITY_VALID |
                            gzl_head_flag_bits.GZL_HEAD_LINEAR_VELOCITY_VALID);
        return head;
    }

    // A preset set in gzl_config.hmd_preset itself reaches gzl_create_data: MarshalConfig wrote
    // null over it, so a preset given that way was dropped (the default xi) and a bogus one taken.
    static void ConfigPresetInTheStruct()
    {
        IntPtr bogus = Marshal.StringToHGlobalAnsi("nope"), questpro = Marshal.StringToHGlobalAnsi("questpro");
        try
        {
            var c = gzl_config.Create();
            c.hmd_preset = bogus;
            ExpectError(gzl_result.GZL_ERROR_INVALID_ARGUMENT, "a bogus preset in the config struct",
                        () => Plugin.CreateData(QuestProViews(), c).Dispose());
            c.hmd_preset = questpro;
            using (Plugin plugin = Plugin.CreateData(QuestProViews(), c))
            {
                plugin.BeginFrameData(1000000000L, StillHead());
                Check(Math.Abs(plugin.GetFrameInfo().xi_cpd - 10.0) < 1e-9, "the struct's preset sets xi (Quest Pro: 10 c/deg)");
            }
        }
        finally
        {
            Marshal.FreeHGlobal(bogus);
            Marshal.FreeHGlobal(questpro);
        }
    }

    static void DataMode()
    {
        var geoLevels = new[] { new gzl_level(0.0, 20000), new gzl_level(0.0005, 5000), new gzl_level(0.002, 1250),
                                new gzl_level(0.008, 312) };
        // Engine style: a Unity LODGroup's screen-height shares.
        var engineLevels = new[] { new gzl_level(0.0, 8000), new gzl_level(0.6, 2000), new gzl_level(0.3, 500),
                                   new gzl_level(0.1, 120) };
        const int objectCount = Grid * Grid + 1;
        int left = Grid * (Grid / 2), right = left + Grid - 1; // the middle row's ends
        double yawLeft = Math.Atan2(-GridSpacingM, GridDistanceM), yawRight = Math.Atan2(GridSpacingM, GridDistanceM);
        const long t0 = 1000000000L;
        long saccadeNs = t0 + HalfFrames * FrameNs - LatencyNs;
        long nextSampleNs = t0 - 100000000L, lastSampleNs = 0;
        var objects = new ulong[objectCount];
        var levels = new byte[objectCount];
        var endLevels = new byte[2][];
        var endU = new double[2];
        var endSource = new gzl_gaze_source[2];
        var head = StillHead();

        using (Plugin plugin = Plugin.CreateData(QuestProViews()))
        {
            for (int i = 0; i < objectCount; ++i)
            {
                if (i < Grid * Grid)
                    objects[i] = plugin.AddObject(new gzl_vec3((i % Grid - Grid / 2) * GridSpacingM,
                                                               (i / Grid - Grid / 2) * GridSpacingM * 0.5, -GridDistanceM),
                                                  0.1, gzl_level_metric.GZL_LEVEL_GEOMETRIC_ERROR_M, geoLevels);
                else
                    objects[i] = plugin.AddObject(new gzl_vec3(0.0, -1.0, -GridDistanceM), 0.3,
                                                  gzl_level_metric.GZL_LEVEL_SCREEN_HEIGHT_SHARE, engineLevels);
            }
            Check(objects.All(o => o != Native.GZL_NULL_OBJECT) && objects.Distinct().Count() == objectCount,
                  "gzl_add_object gives distinct non-null handles");
            plugin.SetViewResolution(0, 1832, 1920); // what the renderer really uses (as given at creation)
            plugin.OnSessionState(5 /* XR_SESSION_STATE_FOCUSED */, t0 - 200000000L); // optional in data mode

            gzl_frame_info info = default(gzl_frame_info);
            gzl_foveal_cone cone = default(gzl_foveal_cone);
            for (int frame = 0; frame < 2 * HalfFrames; ++frame)
            {
                long displayNs = t0 + frame * FrameNs;
                while (nextSampleNs <= displayNs - LatencyNs) // the samples that have arrived by now
                {
                    var s = gzl_gaze_sample.Create();
                    s.time_ns = nextSampleNs;
                    s.direction = GazeAt(nextSampleNs, saccadeNs, yawLeft, yawRight);
                    s.flags = (uint)gzl_gaze_sample_flag_bits.GZL_GAZE_SAMPLE_VALID;
                    plugin.PushGazeSample(s);
                    lastSampleNs = nextSampleNs;
                    nextSampleNs += SampleNs;
                }
                plugin.BeginFrameData(displayNs, head);
                plugin.GetLevels(objects, levels);
                info = plugin.GetFrameInfo();
                cone = plugin.GetFovealCone(0);
                plugin.EndFrame(8.0);
                if (frame == HalfFrames - 1 || frame == 2 * HalfFrames - 1)
                {
                    int h = frame / HalfFrames;
                    endLevels[h] = (byte[])levels.Clone();
                    endU[h] = cone.center_u;
                    endSource[h] = info.gaze_source;
                    Console.WriteLine("{0} half, frame {1}: gaze source {2}, cone centre ({3:F3}, {4:F3}) radius {5:F1} deg, " +
                                      "triangles {6} of {7}; grid levels {8}, engine-style object {9}",
                                      h == 0 ? "first" : "second", info.frame_index, info.gaze_source, cone.center_u,
                                      cone.center_v, cone.half_angle_deg, info.triangles_drawn, info.triangles_full,
                                      string.Join(" ", levels.Take(Grid * Grid)), levels[Grid * Grid]);
                }
            }
            Check(endSource[0] == gzl_gaze_source.GZL_GAZE_SOURCE_PUSHED && endSource[1] == gzl_gaze_source.GZL_GAZE_SOURCE_PUSHED,
                  "the pushed samples are the gaze source");
            Check(endLevels[0][left] < endLevels[0][right], "first half: the fixated left object is finer than the right");
            Check(endLevels[1][right] < endLevels[1][left], "second half: the fixated right object is finer than the left");
            Check(endU[0] < 0.5 && endU[1] > 0.5, "the foveal cone moves from the left half of view 0 to the right half");
            Check(endLevels[1][Grid * Grid] < 4, "the engine-style object has a valid level");
            Check(info.frame_index == 2 * HalfFrames && info.object_count == objectCount && info.head_valid == 1 &&
                  info.display_time_ns == t0 + (2 * HalfFrames - 1) * FrameNs,
                  "gzl_frame_info: frame index, object count, head_valid and display time as given");
            Check(info.gaze_direction_base.x > 0.3 && info.gaze_direction_base.z < -0.8 && info.xi_cpd > 0.0 &&
                  info.triangles_drawn > 0 && info.triangles_drawn <= info.triangles_full,
                  "gzl_frame_info: gaze to the right, a display limit, triangle totals");
            Check(cone.type == gzl_structure_type.GZL_TYPE_FOVEAL_CONE && cone.in_view == 1 && cone.half_angle_deg >= 5.0 &&
                  cone.radius_u > 0.0 && cone.radius_v > 0.0 && cone.direction_in_view.z < 0.0,
                  "gzl_foveal_cone: in view, at least the fovea, its arrays read");

            gzl_frame_record record = plugin.GetFrameRecord();
            Check(record.display_time_ns == info.display_time_ns && record.view_count == 2 &&
                  record.views[0].width_px == 1832 && record.views[1].height_px == 1920 &&
                  Math.Abs(record.views[1].position_in_head_m.x - 0.032) < 1e-12 &&
                  Math.Abs(record.head.orientation.w - 1.0) < 1e-12,
                  "gzl_frame_record: the frame's time, views (the fixed array) and head as given");
            Check(record.has_gaze_sample == 1 && record.gaze_sample.time_ns <= lastSampleNs &&
                  record.gaze_sample.direction.x > 0.3,
                  "gzl_frame_record: the gaze sample read (the nested struct after the array)");
            string status = plugin.GazeStatus;
            Console.WriteLine("gaze status: \"{0}\"", status);
            Check(status.Length > 0, "gzl_get_gaze_status gives a reason");

            // The error path: a sample older than the last one is refused, with a message.
            {
                var s = gzl_gaze_sample.Create();
                s.time_ns = lastSampleNs - 1000000L;
                s.direction = new gzl_vec3(0.0, 0.0, -1.0);
                s.flags = (uint)gzl_gaze_sample_flag_bits.GZL_GAZE_SAMPLE_VALID;
                // The raw call, as the C ABI gives it...
                gzl_result r = Native.gzl_push_gaze_sample(plugin.Handle, ref s);
                Console.WriteLine("out-of-order sample -> {0}", Plugin.ResultToString(r));
                Check(r == gzl_result.GZL_ERROR_TIME_OUT_OF_ORDER, "an out-of-order sample is refused with GZL_ERROR_TIME_OUT_OF_ORDER");
                var buffer = new byte[512];
                UIntPtr length;
                Check(Native.gzl_get_last_error(plugin.Handle, buffer, (UIntPtr)buffer.Length, out length) == gzl_result.GZL_SUCCESS,
                      "gzl_get_last_error succeeds");
                int nul = Array.IndexOf(buffer, (byte)0);
                string msg = Encoding.UTF8.GetString(buffer, 0, nul < 0 ? 0 : nul);
                Console.WriteLine("     message: {0}", msg);
                Check(msg.StartsWith("gazelod:") && (ulong)length == (ulong)msg.Length,
                      "the message starts with \"gazelod:\" and *length is its length");
                // ...and through the wrapper, as an exception.
                ExpectError(gzl_result.GZL_ERROR_TIME_OUT_OF_ORDER, "Plugin.PushGazeSample out of order", () => plugin.PushGazeSample(s));
                // A message longer than the buffer is cut, NUL-terminated, and *length gives its full size.
                var small = new byte[9];
                UIntPtr full;
                Native.gzl_get_last_error(plugin.Handle, small, (UIntPtr)small.Length, out full);
                Check(small[8] == 0 && Encoding.ASCII.GetString(small, 0, 8) == "gazelod:" && (ulong)full == (ulong)msg.Length,
                      "a cut message is NUL-terminated and *length is the full size");
            }
            // Calls for the other mode.
            ExpectError(gzl_result.GZL_ERROR_WRONG_MODE, "gzl_begin_frame_openxr on a data-mode plugin", () => plugin.BeginFrameOpenXr(t0));
            ExpectError(gzl_result.GZL_ERROR_WRONG_MODE, "gzl_get_gaze_binding on a data-mode plugin", () => plugin.GetGazeBinding());
            ExpectError(gzl_result.GZL_ERROR_WRONG_MODE, "gzl_action_sets_attached on a data-mode plugin", () => plugin.ActionSetsAttached());
            ExpectError(gzl_result.GZL_ERROR_WRONG_MODE, "gzl_set_gaze_space on a data-mode plugin", () => plugin.SetGazeSpace(1, 2));
            ExpectError(gzl_result.GZL_ERROR_WRONG_MODE, "gzl_set_base_space on a data-mode plugin", () => plugin.SetBaseSpace(1));
            ExpectError(gzl_result.GZL_ERROR_INVALID_ARGUMENT, "gzl_set_view_resolution for view 2 of 2", () => plugin.SetViewResolution(2, 100, 100));

            // Motion, disabling and removal, seen at the next frame.
            long nextDisplay = t0 + 2 * HalfFrames * FrameNs;
            ulong engineObject = objects[Grid * Grid], removed = objects[right];
            plugin.SetObjectMotion(objects[0], new gzl_vec3(-1.2, -0.6, -2.9), new gzl_vec3(0.0, 0.0, 0.1));
            plugin.SetObjectEnabled(engineObject, false);
            plugin.RemoveObject(removed);
            ExpectError(gzl_result.GZL_ERROR_OBJECT_INVALID, "gzl_get_levels of a removed object",
                        () => plugin.GetLevels(new[] { removed }, new byte[1]));
            plugin.BeginFrameData(nextDisplay, head);
            info = plugin.GetFrameInfo();
            Check(info.object_count == objectCount - 1, "after the next frame, one object fewer is registered");
            var one = new byte[1];
            plugin.GetLevels(new[] { engineObject }, one);
            Check(one[0] == Native.GZL_LEVEL_DISABLED, "a disabled object reads GZL_LEVEL_DISABLED");
            plugin.SetObjectEnabled(engineObject, true);
            plugin.BeginFrameData(nextDisplay + FrameNs, head);
            plugin.GetLevels(new[] { engineObject }, one);
            Check(one[0] < 4, "re-enabled, it has a level again");

            // gzl_shutdown: every later call but gzl_destroy refuses.
            plugin.Shutdown();
            plugin.Shutdown(); // safe twice
            ExpectError(gzl_result.GZL_ERROR_SHUT_DOWN, "gzl_begin_frame_data after gzl_shutdown",
                        () => plugin.BeginFrameData(nextDisplay + 2 * FrameNs, head));
            plugin.Dispose();
            Check(plugin.Handle.IsClosed, "Dispose closes the handle (gzl_destroy)");
            try
            {
                plugin.GetFrameInfo();
                Fail("a call after Dispose must not reach the library");
            }
            catch (ObjectDisposedException)
            {
                Check(true, "a call after Dispose throws ObjectDisposedException (no call on a destroyed plugin)");
            }
        } // using: Dispose twice is harmless

        // A failed create: the message comes from gzl_get_last_error(NULL, ...) on this thread.
        ExpectError(gzl_result.GZL_ERROR_INVALID_ARGUMENT, "gzl_create_data with 3 views", () => Plugin.CreateData(new gzl_view[3]));
        ExpectError(gzl_result.GZL_ERROR_INVALID_ARGUMENT, "gzl_create_data with an unknown hmd_preset",
                    () => Plugin.CreateData(QuestProViews(), null, "no-such-headset"));
        // A config marshalled by the wrapper (the struct, and its string): a coarser gaze
        // accuracy floor widens the gaze uncertainty the plugin reports.
        {
            var config = gzl_config.Create();
            config.disabled_criteria = (uint)gzl_criterion_bits.GZL_CRITERION_VELOCITY;
            config.gaze_accuracy_deg = 4.0;
            double[] uncertainty = new double[2], xi = new double[2];
            for (int k = 0; k < 2; ++k)
                using (Plugin p = k == 0 ? Plugin.CreateData(QuestProViews()) : Plugin.CreateData(QuestProViews(), config, "questpro"))
                {
                    p.AddObject(new gzl_vec3(0.0, 0.0, -3.0), 0.1, gzl_level_metric.GZL_LEVEL_GEOMETRIC_ERROR_M, geoLevels);
                    var s = gzl_gaze_sample.Create();
                    s.time_ns = t0 - 20000000L;
                    s.direction = new gzl_vec3(0.0, 0.0, -1.0);
                    s.flags = (uint)gzl_gaze_sample_flag_bits.GZL_GAZE_SAMPLE_VALID;
                    p.PushGazeSample(s);
                    p.BeginFrameData(t0, head, QuestProViews()); // views given with the frame, too
                    gzl_frame_info fi = p.GetFrameInfo();
                    uncertainty[k] = fi.gaze_uncertainty_deg;
                    xi[k] = fi.xi_cpd;
                    Console.WriteLine("{0}: gaze source {1}, uncertainty {2:F2} deg, xi {3:F1} cpd", k == 0 ? "defaults" : "config",
                                      fi.gaze_source, fi.gaze_uncertainty_deg, fi.xi_cpd);
                    Check(fi.frame_index == 1 && fi.gaze_source == gzl_gaze_source.GZL_GAZE_SOURCE_PUSHED && fi.xi_cpd > 0.0,
                          (k == 0 ? "default config" : "a config with an hmd_preset string") + ": one frame on pushed gaze");
                }
            Check(uncertainty[0] < 4.0 && uncertainty[1] >= 4.0, "the config's gaze_accuracy_deg (4) reaches the plugin");
            Check(xi[0] != xi[1], "the config's hmd_preset string reaches the plugin (another display limit)");
        }
    }

    // ---- OpenXR mode -----------------------------------------------------------------------------

    // The OpenXR types this program uses (openxr.h 1.0, 64-bit: handles are pointers, here ulong).
    const int XR_SUCCESS = 0;
    const int XR_EVENT_UNAVAILABLE = 4;
    const int XR_TYPE_INSTANCE_CREATE_INFO = 3, XR_TYPE_SYSTEM_GET_INFO = 4, XR_TYPE_SYSTEM_PROPERTIES = 5,
              XR_TYPE_SESSION_CREATE_INFO = 8, XR_TYPE_SESSION_BEGIN_INFO = 10, XR_TYPE_FRAME_END_INFO = 12,
              XR_TYPE_EVENT_DATA_BUFFER = 16, XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING = 17,
              XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED = 18, XR_TYPE_FRAME_WAIT_INFO = 33,
              XR_TYPE_REFERENCE_SPACE_CREATE_INFO = 37, XR_TYPE_FRAME_STATE = 44, XR_TYPE_FRAME_BEGIN_INFO = 46,
              XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT = 1000030000;
    const int XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY = 1, XR_REFERENCE_SPACE_TYPE_LOCAL = 2,
              XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO = 2, XR_ENVIRONMENT_BLEND_MODE_OPAQUE = 1;
    const int XR_SESSION_STATE_READY = 2, XR_SESSION_STATE_STOPPING = 6, XR_SESSION_STATE_LOSS_PENDING = 7,
              XR_SESSION_STATE_EXITING = 8;
    const int XrEventDataBufferSize = 4016; // sizeof(XrEventDataBuffer)

    [StructLayout(LayoutKind.Sequential)]
    struct XrApplicationInfo
    {
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 128)] public byte[] applicationName;
        public uint applicationVersion;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 128)] public byte[] engineName;
        public uint engineVersion;
        public ulong apiVersion;
    }
    [StructLayout(LayoutKind.Sequential)]
    struct XrInstanceCreateInfo
    {
        public int type;
        public IntPtr next;
        public ulong createFlags;
        public XrApplicationInfo applicationInfo;
        public uint enabledApiLayerCount;
        public IntPtr enabledApiLayerNames;
        public uint enabledExtensionCount;
        public IntPtr enabledExtensionNames; // const char* const*
    }
    [StructLayout(LayoutKind.Sequential)]
    struct XrSystemGetInfo { public int type; public IntPtr next; public int formFactor; }
    [StructLayout(LayoutKind.Sequential)]
    struct XrSystemProperties
    {
        public int type;
        public IntPtr next;
        public ulong systemId;
        public uint vendorId;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 256)] public byte[] systemName;
        public uint maxSwapchainImageHeight, maxSwapchainImageWidth, maxLayerCount; // XrSystemGraphicsProperties
        public uint orientationTracking, positionTracking; // XrSystemTrackingProperties
    }
    [StructLayout(LayoutKind.Sequential)]
    struct XrSystemEyeGazeInteractionPropertiesEXT { public int type; public IntPtr next; public uint supportsEyeGazeInteraction; }
    [StructLayout(LayoutKind.Sequential)]
    struct XrSessionCreateInfo { public int type; public IntPtr next; public ulong createFlags; public ulong systemId; }
    [StructLayout(LayoutKind.Sequential)]
    struct XrPosef { public float qx, qy, qz, qw, px, py, pz; }
    [StructLayout(LayoutKind.Sequential)]
    struct XrReferenceSpaceCreateInfo { public int type; public IntPtr next; public int referenceSpaceType; public XrPosef poseInReferenceSpace; }
    [StructLayout(LayoutKind.Sequential)]
    struct XrSessionBeginInfo { public int type; public IntPtr next; public int primaryViewConfigurationType; }
    [StructLayout(LayoutKind.Sequential)]
    struct XrFrameWaitInfo { public int type; public IntPtr next; }
    [StructLayout(LayoutKind.Sequential)]
    struct XrFrameState { public int type; public IntPtr next; public long predictedDisplayTime; public long predictedDisplayPeriod; public uint shouldRender; }
    [StructLayout(LayoutKind.Sequential)]
    struct XrFrameBeginInfo { public int type; public IntPtr next; }
    [StructLayout(LayoutKind.Sequential)]
    struct XrFrameEndInfo { public int type; public IntPtr next; public long displayTime; public int environmentBlendMode; public uint layerCount; public IntPtr layers; }

    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrCreateInstance(ref XrInstanceCreateInfo info, out ulong instance);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrDestroyInstance(ulong instance);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrGetSystem(ulong instance, ref XrSystemGetInfo info, out ulong systemId);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrGetSystemProperties(ulong instance, ulong systemId, IntPtr properties);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrCreateSession(ulong instance, ref XrSessionCreateInfo info, out ulong session);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrDestroySession(ulong session);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrBeginSession(ulong session, ref XrSessionBeginInfo info);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrEndSession(ulong session);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrRequestExitSession(ulong session);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrPollEvent(ulong instance, IntPtr eventData);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrWaitFrame(ulong session, ref XrFrameWaitInfo info, ref XrFrameState state);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrBeginFrame(ulong session, ref XrFrameBeginInfo info);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrEndFrame(ulong session, ref XrFrameEndInfo info);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrCreateReferenceSpace(ulong session, ref XrReferenceSpaceCreateInfo info, out ulong space);
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int PFN_xrDestroySpace(ulong space);

    // The loader, P/Invoked for its one entry point; everything else comes through it.
    [DllImport("libopenxr_loader.so.1", CallingConvention = CallingConvention.Cdecl)]
    static extern int xrGetInstanceProcAddr(ulong instance, [MarshalAs(UnmanagedType.LPStr)] string name, out IntPtr function);

    // The same function as a raw pointer, for gazelod (what Unity hands a native plugin).
    const int RTLD_NOW = 2;
    [DllImport("libdl.so.2")] static extern IntPtr dlopen(string file, int mode);
    [DllImport("libdl.so.2")] static extern IntPtr dlsym(IntPtr handle, string name);
    [DllImport("libdl.so.2")] static extern IntPtr dlerror();

    static T Load<T>(ulong instance, string name) where T : class
    {
        IntPtr fn;
        int r = xrGetInstanceProcAddr(instance, name, out fn);
        if (r != XR_SUCCESS || fn == IntPtr.Zero) throw new Exception("xrGetInstanceProcAddr(" + name + ") -> XrResult " + r);
        return (T)(object)Marshal.GetDelegateForFunctionPointer(fn, typeof(T));
    }

    static bool Xr(int r, string call)
    {
        if (r >= 0) return true; // XR_SUCCEEDED: success codes are >= 0
        Fail(call + " -> XrResult " + r);
        return false;
    }

    static byte[] FixedString(string s, int size)
    {
        var b = new byte[size];
        Encoding.ASCII.GetBytes(s, 0, s.Length, b, 0);
        return b;
    }

    const int FrameCount = 300, WarmupFrames = 100;
    const int XrGrid = 7; // 7x7 objects every 10 deg over +-30 deg,
    const double XrDistanceM = 40.0; // far: the default scenario walks ahead at 1.4 m/s

    static void OpenXrMode()
    {
        IntPtr lib = dlopen("libopenxr_loader.so.1", RTLD_NOW);
        IntPtr gipa = lib == IntPtr.Zero ? IntPtr.Zero : dlsym(lib, "xrGetInstanceProcAddr");
        if (gipa == IntPtr.Zero)
        {
            Fail("dlopen/dlsym of libopenxr_loader.so.1: " + Marshal.PtrToStringAnsi(dlerror()));
            return;
        }
        var createInstance = Load<PFN_xrCreateInstance>(0, "xrCreateInstance");

        // A headless instance with eye-gaze interaction.
        string[] extensions = { "XR_EXT_eye_gaze_interaction", "XR_MND_headless" };
        var names = extensions.Select(e => Marshal.StringToHGlobalAnsi(e)).ToArray();
        IntPtr nameArray = Marshal.AllocHGlobal(IntPtr.Size * names.Length);
        ulong instance = 0;
        try
        {
            Marshal.Copy(names, 0, nameArray, names.Length);
            var ci = new XrInstanceCreateInfo();
            ci.type = XR_TYPE_INSTANCE_CREATE_INFO;
            ci.applicationInfo.applicationName = FixedString("gazelod C# test", 128);
            ci.applicationInfo.engineName = FixedString("mono", 128);
            ci.applicationInfo.apiVersion = (1UL << 48); // XR_MAKE_VERSION(1, 0, 0)
            ci.enabledExtensionCount = (uint)names.Length;
            ci.enabledExtensionNames = nameArray;
            if (!Xr(createInstance(ref ci, out instance), "xrCreateInstance")) return;
        }
        finally
        {
            Marshal.FreeHGlobal(nameArray);
            foreach (IntPtr n in names) Marshal.FreeHGlobal(n);
        }

        var destroyInstance = Load<PFN_xrDestroyInstance>(instance, "xrDestroyInstance");
        var getSystem = Load<PFN_xrGetSystem>(instance, "xrGetSystem");
        var getSystemProperties = Load<PFN_xrGetSystemProperties>(instance, "xrGetSystemProperties");
        var createSession = Load<PFN_xrCreateSession>(instance, "xrCreateSession");
        var destroySession = Load<PFN_xrDestroySession>(instance, "xrDestroySession");
        var beginSession = Load<PFN_xrBeginSession>(instance, "xrBeginSession");
        var endSession = Load<PFN_xrEndSession>(instance, "xrEndSession");
        var requestExitSession = Load<PFN_xrRequestExitSession>(instance, "xrRequestExitSession");
        var pollEvent = Load<PFN_xrPollEvent>(instance, "xrPollEvent");
        var waitFrame = Load<PFN_xrWaitFrame>(instance, "xrWaitFrame");
        var beginFrame = Load<PFN_xrBeginFrame>(instance, "xrBeginFrame");
        var endFrame = Load<PFN_xrEndFrame>(instance, "xrEndFrame");
        var createReferenceSpace = Load<PFN_xrCreateReferenceSpace>(instance, "xrCreateReferenceSpace");
        var destroySpace = Load<PFN_xrDestroySpace>(instance, "xrDestroySpace");

        ulong system = 0, session = 0, local = 0;
        var sys = new XrSystemGetInfo { type = XR_TYPE_SYSTEM_GET_INFO, formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY };
        if (!Xr(getSystem(instance, ref sys, out system), "xrGetSystem"))
        {
            destroyInstance(instance);
            return;
        }
        {
            var eye = new XrSystemEyeGazeInteractionPropertiesEXT { type = XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT };
            var props = new XrSystemProperties { type = XR_TYPE_SYSTEM_PROPERTIES, systemName = new byte[256] };
            IntPtr eyePtr = Marshal.AllocHGlobal(Marshal.SizeOf(typeof(XrSystemEyeGazeInteractionPropertiesEXT)));
            IntPtr propsPtr = Marshal.AllocHGlobal(Marshal.SizeOf(typeof(XrSystemProperties)));
            try
            {
                Marshal.StructureToPtr(eye, eyePtr, false);
                props.next = eyePtr;
                Marshal.StructureToPtr(props, propsPtr, false);
                Xr(getSystemProperties(instance, system, propsPtr), "xrGetSystemProperties");
                props = (XrSystemProperties)Marshal.PtrToStructure(propsPtr, typeof(XrSystemProperties));
                eye = (XrSystemEyeGazeInteractionPropertiesEXT)Marshal.PtrToStructure(eyePtr, typeof(XrSystemEyeGazeInteractionPropertiesEXT));
            }
            finally
            {
                Marshal.FreeHGlobal(propsPtr);
                Marshal.FreeHGlobal(eyePtr);
            }
            int nul = Array.IndexOf(props.systemName, (byte)0);
            Console.WriteLine("system \"{0}\", eye gaze {1}", Encoding.ASCII.GetString(props.systemName, 0, nul < 0 ? 256 : nul),
                              eye.supportsEyeGazeInteraction != 0 ? "supported" : "NOT supported");
            Check(eye.supportsEyeGazeInteraction != 0, "the runtime supports eye-gaze interaction");
        }
        var sci = new XrSessionCreateInfo { type = XR_TYPE_SESSION_CREATE_INFO, systemId = system }; // headless: no graphics binding
        if (!Xr(createSession(instance, ref sci, out session), "xrCreateSession"))
        {
            destroyInstance(instance);
            return;
        }
        var rci = new XrReferenceSpaceCreateInfo { type = XR_TYPE_REFERENCE_SPACE_CREATE_INFO, referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL };
        rci.poseInReferenceSpace.qw = 1.0f;
        Xr(createReferenceSpace(session, ref rci, out local), "xrCreateReferenceSpace");

        Plugin plugin = null;
        IntPtr eventBuffer = Marshal.AllocHGlobal(XrEventDataBufferSize);
        try
        {
            // The application has no action sets: gazelod makes, suggests, attaches and syncs its own.
            plugin = Plugin.CreateOpenXr(gipa, instance, system, session, local, gzl_gaze_input.GZL_GAZE_INPUT_PLUGIN_ACTIONS);
            Check(true, "gzl_create_openxr with the loader's xrGetInstanceProcAddr (dlsym) and GZL_GAZE_INPUT_PLUGIN_ACTIONS");
            // gzl_get_gaze_binding is for MERGE_BINDING: show what this mode answers (not checked).
            try
            {
                GazeBinding b = plugin.GetGazeBinding();
                Console.WriteLine("gaze binding: set {0:x}, action {1:x}, {2} {3}", b.ActionSet, b.Action, b.InteractionProfile, b.BindingPath);
            }
            catch (GazelodException e)
            {
                Console.WriteLine("gaze binding: {0}", e.Message);
            }

            var lod = new[] { new gzl_level(0.0, 20000), new gzl_level(0.01, 5000), new gzl_level(0.04, 1250), new gzl_level(0.16, 312) };
            var objects = new ulong[XrGrid * XrGrid];
            var levels = new byte[XrGrid * XrGrid];
            for (int i = 0; i < objects.Length; ++i)
            {
                double deg = Math.PI / 180.0;
                double yaw = (i % XrGrid - XrGrid / 2) * 10.0 * deg, pitch = (i / XrGrid - XrGrid / 2) * 10.0 * deg;
                objects[i] = plugin.AddObject(new gzl_vec3(XrDistanceM * Math.Cos(pitch) * Math.Sin(yaw), XrDistanceM * Math.Sin(pitch),
                                                           -XrDistanceM * Math.Cos(pitch) * Math.Cos(yaw)),
                                              1.5, gzl_level_metric.GZL_LEVEL_GEOMETRIC_ERROR_M, lod);
            }

            bool running = false, quit = false, exitRequested = false;
            int frames = 0, checkedFrames = 0, openxrFrames = 0, variedFrames = 0, idlePolls = 0;
            var sourceCounts = new Dictionary<gzl_gaze_source, int>();
            gzl_frame_info info = default(gzl_frame_info);
            while (!quit)
            {
                int r;
                while (true)
                {
                    Marshal.WriteInt32(eventBuffer, 0, XR_TYPE_EVENT_DATA_BUFFER);
                    Marshal.WriteIntPtr(eventBuffer, 8, IntPtr.Zero);
                    r = pollEvent(instance, eventBuffer);
                    if (r != XR_SUCCESS) break;
                    int type = Marshal.ReadInt32(eventBuffer, 0);
                    if (type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) quit = true;
                    if (type != XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) continue;
                    // XrEventDataSessionStateChanged: type, next, session (16), state (24), time (32)
                    int state = Marshal.ReadInt32(eventBuffer, 24);
                    long time = Marshal.ReadInt64(eventBuffer, 32);
                    plugin.OnSessionState(state, time);
                    if (state == XR_SESSION_STATE_READY)
                    {
                        var begin = new XrSessionBeginInfo { type = XR_TYPE_SESSION_BEGIN_INFO,
                                                             primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO };
                        running = Xr(beginSession(session, ref begin), "xrBeginSession");
                    }
                    else if (state == XR_SESSION_STATE_STOPPING)
                    {
                        Xr(endSession(session), "xrEndSession");
                        running = false;
                    }
                    else if (state == XR_SESSION_STATE_EXITING || state == XR_SESSION_STATE_LOSS_PENDING)
                    {
                        quit = true;
                    }
                }
                if (r != XR_EVENT_UNAVAILABLE && !Xr(r, "xrPollEvent")) break;
                if (quit) break;
                if (!running) // not begun yet, or ended: wait for the next state, not for ever
                {
                    if (++idlePolls > 5000 || failures > 0) break;
                    System.Threading.Thread.Sleep(1);
                    continue;
                }
                if (frames == FrameCount && !exitRequested)
                {
                    exitRequested = true;
                    if (!Xr(requestExitSession(session), "xrRequestExitSession")) break;
                }
                var wait = new XrFrameWaitInfo { type = XR_TYPE_FRAME_WAIT_INFO };
                var frameState = new XrFrameState { type = XR_TYPE_FRAME_STATE };
                var beginInfo = new XrFrameBeginInfo { type = XR_TYPE_FRAME_BEGIN_INFO };
                if (!Xr(waitFrame(session, ref wait, ref frameState), "xrWaitFrame") ||
                    !Xr(beginFrame(session, ref beginInfo), "xrBeginFrame"))
                    break;
                plugin.BeginFrameOpenXr(frameState.predictedDisplayTime);
                plugin.GetLevels(objects, levels);
                info = plugin.GetFrameInfo();
                var end = new XrFrameEndInfo { type = XR_TYPE_FRAME_END_INFO, displayTime = frameState.predictedDisplayTime,
                                               environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE };
                Xr(endFrame(session, ref end), "xrEndFrame"); // zero layers
                plugin.EndFrame(11.0);
                bool varied = levels.Skip(1).Any(l => l != levels[0]);
                if (frames >= WarmupFrames && frames < FrameCount)
                {
                    ++checkedFrames;
                    if (info.gaze_source == gzl_gaze_source.GZL_GAZE_SOURCE_OPENXR) ++openxrFrames;
                    if (varied) ++variedFrames;
                    int n;
                    sourceCounts.TryGetValue(info.gaze_source, out n);
                    sourceCounts[info.gaze_source] = n + 1;
                }
                if (frames == FrameCount - 1)
                {
                    Console.WriteLine("frame {0}: gaze source {1}, eye motion {2}, uncertainty {3:F2} deg, triangles {4} of {5}",
                                      info.frame_index, info.gaze_source, info.eye_motion, info.gaze_uncertainty_deg,
                                      info.triangles_drawn, info.triangles_full);
                    for (int row = 0; row < XrGrid; ++row)
                        Console.WriteLine("  " + string.Join(" ", levels.Skip(row * XrGrid).Take(XrGrid)));
                    Console.WriteLine("gaze status: \"{0}\"", plugin.GazeStatus);
                }
                ++frames;
            }
            Console.WriteLine("{0} frames; in frames {1}..{2} ({3}): gaze source {4}; levels differing across objects in {5}",
                              frames, WarmupFrames, FrameCount - 1, checkedFrames,
                              string.Join(", ", sourceCounts.Select(kv => kv.Key + " " + kv.Value)), variedFrames);
            Check(checkedFrames == FrameCount - WarmupFrames, string.Format("the session ran the {0} frames to check", FrameCount));
            Check(openxrFrames * 10 >= checkedFrames * 8,
                  "eye gaze through the loader's xrGetInstanceProcAddr drives most frames (GZL_GAZE_SOURCE_OPENXR in >= 80% after frame 100)");
            Check(checkedFrames > 0 && variedFrames == checkedFrames, "levels differ across the grid in every checked frame");

            // gazelod releases its spaces and action set while the session and instance still exist.
            plugin.Shutdown();
            Check(true, "gzl_shutdown before xrDestroySession");
        }
        catch (GazelodException e)
        {
            Fail(e.Message);
        }
        finally
        {
            Marshal.FreeHGlobal(eventBuffer);
            if (plugin != null) // before the session goes (a no-op if done above)
            {
                try { plugin.Shutdown(); }
                catch (GazelodException e) { Fail(e.Message); }
            }
            if (local != 0) Xr(destroySpace(local), "xrDestroySpace");
            Xr(destroySession(session), "xrDestroySession");
            Xr(destroyInstance(instance), "xrDestroyInstance");
            if (plugin != null) plugin.Dispose(); // gzl_destroy after the OpenXR handles: shut down already
        }
    }
}
