# SPDX-License-Identifier: Apache-2.0
"""gazelod.Plugin's arguments as numpy users pass them: strided views (a table's column,
ts[::2]) read element by element, integers never truncated or wrapped, every refusal a
ValueError naming the argument. Each case failed before: a strided t_ns pushed 1000, 1500,
2000 for a column holding 1000, 2000, 3000; -1 triangles became 4294967295; 1000.9 ns became
1000; a float width_px raised pybind11's "Unable to cast Python instance"."""
import numpy as np
import pytest

import gazelod

AHEAD = np.array([0, 0, -1.0])
CENTERS = np.array([[0, 0, -5.0], [1, 0, -5]])
RADII = np.array([0.5, 0.5])
LEVELS = np.array([[0, 0.002, 0.008], [0, 0.002, 0.008]])


def new_plugin():
    return gazelod.Plugin(gazelod.stereo_views("questpro"), disable_switch_policy=True)


def test_strided_times_are_read_as_the_view_shows_them():
    p = new_plugin()
    table = np.array([[1_000, 1_500], [2_000, 2_500], [3_000, 3_500]], dtype=np.int64)
    p.push_gaze(table[:, 0], np.array([AHEAD, AHEAD, AHEAD]))
    # The last time pushed was 3000: 2500 is older (it was accepted after a "last" of 2000).
    with pytest.raises(ValueError, match=r"gaze sample at 2500 ns is older than the previous one \(3000 ns\)"):
        p.push_gaze(np.array([2_500]), AHEAD)
    reversed_times = np.array([6_000, 5_000, 4_000], dtype=np.int64)[::-1]
    p.push_gaze(reversed_times, np.array([AHEAD, AHEAD, AHEAD]))
    with pytest.raises(ValueError, match=r"older than the previous one \(6000 ns\)"):
        p.push_gaze(np.array([5_500]), AHEAD)


def test_strided_and_short_valid_flags():
    p = new_plugin()
    flags = np.array([True, True, False, False])[::2]  # [True, False]
    # The second sample is a blink: any direction goes, a zero one too.
    p.push_gaze(np.array([1_000, 2_000]), np.array([AHEAD, [0, 0, 0.0]]), valid=flags)
    with pytest.raises(ValueError, match=r"valid is one flag or \(N,\) flags, one per sample; got 2 for 5"):
        p.push_gaze(np.arange(3_000, 8_000, 1_000), np.tile(AHEAD, (5, 1)), valid=np.array([True, False]))
    with pytest.raises(ValueError, match=r"got 0 for 1"):
        p.push_gaze(np.array([9_000]), AHEAD, valid=np.array([], dtype=bool))
    p.push_gaze(10_000, AHEAD, valid=True)  # one sample, as scalars
    p.begin_frame(20_000)
    assert p.frame_info()["gaze_source"] == "pushed"


def test_times_must_be_integer_nanoseconds():
    p = new_plugin()
    for bad in (np.array([1_000.9]), np.array([np.nan]), [1.5]):
        with pytest.raises(ValueError, match=r"t_ns must hold integers, got dtype float64"):
            p.push_gaze(bad, AHEAD)
    with pytest.raises(ValueError, match=r"t_ns: 18446744073709551615 is past int64"):
        p.push_gaze(np.array([2**64 - 1], dtype=np.uint64), AHEAD)
    with pytest.raises(ValueError, match=r"direction is \(3,\) with one time"):
        p.push_gaze(np.array([[1_000, 2_000], [3_000, 4_000]]), np.tile(AHEAD, (4, 1)))
    for bad_direction in (None, 0.0, np.zeros((2, 3, 1))):
        with pytest.raises(ValueError, match=r"direction is \(3,\) with one time"):
            p.push_gaze(np.array([1_000]), bad_direction)
    p.push_gaze(np.array([1_000], dtype=np.int32), AHEAD)  # any integer dtype


def test_triangle_counts_are_refused_outside_32_bits():
    p = new_plugin()
    with pytest.raises(ValueError, match=r"triangles\[0, 0\] = -1 is not a triangle count \(0 to 4294967295\)"):
        p.add_objects(CENTERS, RADII, LEVELS, triangles=[[-1, -2, -3], [10, 5, 1]])
    with pytest.raises(ValueError, match=r"triangles\[1, 2\] = 4294967301 is not a triangle count"):
        p.add_objects(CENTERS, RADII, LEVELS, triangles=[[100, 50, 10], [100, 50, 2**32 + 5]])
    with pytest.raises(ValueError, match=r"triangles must hold integers, got dtype float64"):
        p.add_objects(CENTERS, RADII, LEVELS, triangles=np.array([[100.5, 50, 10], [100, 50, 10]]))
    with pytest.raises(ValueError, match=r"triangles must be an \(N, L\) array like levels"):
        p.add_objects(CENTERS, RADII, LEVELS, triangles=[100, 50, 10])
    # A column of a wider table, as stored: strided, read as shown.
    table = np.array([[100, 0, 50, 0, 10, 0], [200, 0, 80, 0, 20, 0]], dtype=np.int64)
    h = p.add_objects(CENTERS, RADII, LEVELS, triangles=table[:, ::2])
    p.push_gaze(np.array([1_000]), AHEAD)
    p.begin_frame(10_000)
    assert p.frame_info()["object_count"] == 2 and h.shape == (2,)
    assert p.frame_info()["triangles_full"] == 300


def test_a_level_after_a_nan_pad_is_refused():
    p = new_plugin()
    with pytest.raises(ValueError, match=r"levels\[1, 2\] follows a NaN \(NaN only pads a shorter chain at its end\)"):
        p.add_objects(CENTERS, RADII, np.array([[0, 0.002, 0.008], [0, np.nan, 0.008]]))
    h = p.add_objects(CENTERS, RADII, np.array([[0, 0.002, 0.008], [0, 0.002, np.nan]]))
    assert h.shape == (2,)


def test_views_name_the_field():
    fov = (-0.8, 0.8, 0.8, -0.8)
    with pytest.raises(ValueError, match=r"views\[0\].width_px must be a positive integer \(pixels\), got 1920.0"):
        gazelod.Plugin([dict(fov=fov, width_px=1920.0, height_px=1080)])
    with pytest.raises(ValueError, match=r"views\[1\].height_px must be a positive integer \(pixels\), got -1"):
        gazelod.Plugin([dict(fov=fov, width_px=10, height_px=10), dict(fov=fov, width_px=10, height_px=-1)])
    with pytest.raises(ValueError, match=r"views\[0\].width_px must be a positive integer \(pixels\), got True"):
        gazelod.Plugin([dict(fov=fov, width_px=True, height_px=10)])
    with pytest.raises(ValueError, match=r"views\[0\] has no height_px"):
        gazelod.Plugin([dict(fov=fov, width_px=10)])
    with pytest.raises(ValueError, match=r"views\[0\] must be a dict"):
        gazelod.Plugin([(fov, 10, 10)])
    with pytest.raises(ValueError, match=r"views\[0\].fov must be numbers"):
        gazelod.Plugin([dict(fov="wide", width_px=10, height_px=10)])
    p = gazelod.Plugin([dict(fov=fov, width_px=np.int64(1920), height_px=np.uint32(1080))])  # numpy ints
    assert p.frame_info()["object_count"] == 0


def test_handles_in_any_shape():
    p = new_plugin()
    h = p.add_objects(CENTERS, RADII, LEVELS)
    column = h.reshape(2, 1)
    p.set_enabled(column, False)
    p.set_enabled(column, True)
    p.remove(column)
    with pytest.raises(ValueError, match="was removed"):
        p.remove(h[:1])


def test_object_set_follows_the_plugins_rules():
    """ObjectSet (select's objects) refuses what Plugin.add_objects refuses: a level after a NaN
    pad was dropped, 2**32 + 5 triangles wrapped to 5, -1 to 4294967295."""
    with pytest.raises(ValueError, match=r"levels\[0, 2\] follows a NaN"):
        gazelod.ObjectSet(CENTERS[:1], RADII[:1], np.array([[0, np.nan, 0.01, 0.1]]))
    with pytest.raises(ValueError, match=r"triangles\[0, 0\] = 4294967301 is not a triangle count"):
        gazelod.ObjectSet(CENTERS[:1], RADII[:1], LEVELS[:1], triangles=np.array([[2**32 + 5, 50, 10]]))
    with pytest.raises(ValueError, match=r"triangles\[0, 1\] = -1 is not a triangle count"):
        gazelod.ObjectSet(CENTERS[:1], RADII[:1], LEVELS[:1], triangles=[[100, -1, 10]])
    with pytest.raises(ValueError, match=r"triangles must hold integers"):
        gazelod.ObjectSet(CENTERS[:1], RADII[:1], LEVELS[:1], triangles=[[100.5, 50, 10]])
    objects = gazelod.ObjectSet(CENTERS, RADII, np.array([[0, 0.002, 0.008], [0, 0.002, np.nan]]))
    assert len(objects) == 2


def test_select_viewer_fields_are_not_guessed():
    objects = gazelod.ObjectSet(CENTERS, RADII, LEVELS)
    with pytest.raises(ValueError, match=r"give xi_cpd or hmd \(a preset's xi\), not both"):
        gazelod.select(objects, hmd="questpro", xi_cpd=1.0)
    with pytest.raises(TypeError, match=r"viewer field 'use_size' is None"):
        gazelod.select(objects, use_size=None)
    with pytest.raises(ValueError, match=r"gaze_direction must be numbers, got 'abc'"):
        gazelod.select(objects, gaze_direction="abc")


def test_paths_that_are_not_utf8(tmp_path):
    """A recording named in Latin-1 (os.listdir gives it surrogate-escaped) opens, and its
    errors name it; bytes paths work in every call (str(b"...") passed "b'...'")."""
    good = tmp_path / "caf\udce9.csv"  # the bytes b"caf\xe9.csv" on disk
    with open(good, "w") as f:
        f.write("t_ns,gaze_x,gaze_y,gaze_z\n0,0,0,-1\n4000000,0,0,-1\n8000000,0,0,-1\n")
    assert gazelod.read_trace(good)["t_ns"].tolist() == [0, 4_000_000, 8_000_000]
    assert gazelod.read_trace(bytes(good))["t_ns"].size == 3
    assert gazelod.trace_stats(bytes(good))["samples"] == 3
    assert gazelod.trace_stats(good)["samples"] == 3
    bad = tmp_path / "bad\udce9.csv"
    with open(bad, "w") as f:
        f.write("t_ns,gaze_x,gaze_y,gaze_z\n0,0,0\n")
    with pytest.raises(ValueError, match="bad\ufffd.csv:2"):
        gazelod.read_trace(bad)


def test_run_and_compare_arguments():
    with pytest.raises(TypeError, match="frames must be an integer, got 1.7"):
        gazelod.run(frames=1.7)
    rows = gazelod.compare("questpro", frames=3)  # one name, not its letters
    assert [r["hmd"] for r in rows] == ["questpro"]
