# SPDX-License-Identifier: Apache-2.0
"""gazelod.select on numpy arrays against the C++ selection inside the C ABI's data-mode plugin
(gazelod.Plugin, include/gazelod/gazelod.h): the same objects and viewer give the same levels,
bit for bit; and bad input to either raises, never crashes."""
import math

import numpy as np
import pytest

import gazelod

FRAME_NS = 11_111_111  # 90 Hz
LATENCY_NS = 12_000_000


def object_field(seed, n=600, metric="geometric_error_m", moving=True):
    """A random field like the default scenario's: objects 2-120 m ahead, 4-level chains."""
    rng = np.random.default_rng(seed)
    centers = np.column_stack([rng.uniform(-20, 20, n), rng.uniform(-4, 4, n), rng.uniform(-120, -2, n)])
    radii = rng.uniform(0.2, 1.5, n)
    if metric == "geometric_error_m":
        base = rng.uniform(0.0005, 0.01, n)
    else:  # removed_cycles_per_diameter: the finest cycles a level drops, fewer at coarser levels
        base = rng.uniform(20.0, 200.0, n)
    ratio = 4.0 if metric == "geometric_error_m" else 0.25
    levels = np.column_stack([np.zeros(n)] + [base * ratio**k for k in range(3)])
    # Some chains are shorter: NaN pads them.
    levels[rng.random(n) < 0.2, 3] = np.nan
    velocities = rng.normal(0.0, 2.0, (n, 3)) if moving else None
    triangles = np.column_stack([np.full(n, 20000), np.full(n, 5000), np.full(n, 1250), np.full(n, 313)]).astype(np.uint32)
    return dict(centers=centers, radii=radii, levels=levels, velocities=velocities, triangles=triangles)


def yaw_pitch(yaw_deg, pitch_deg):
    y, p = math.radians(yaw_deg), math.radians(pitch_deg)
    return np.array([math.sin(y) * math.cos(p), math.sin(p), -math.cos(y) * math.cos(p)])


def quat_yaw(deg):
    a = math.radians(deg) / 2
    return (0.0, math.sin(a), 0.0, math.cos(a))


CASES = {
    # name: (display views, Plugin kwargs, metric, gaze in head, head orientation, head position)
    "questpro_ahead": ("questpro", {}, "geometric_error_m", yaw_pitch(0, 0), quat_yaw(0), (0, 0, 0)),
    "quest3_off_axis": ("quest3", {}, "geometric_error_m", yaw_pitch(12, -6), quat_yaw(20), (0.3, 1.6, -0.5)),
    "preset_and_accuracy": ("index", dict(hmd_preset="visionpro", gaze_accuracy_deg=2.5), "geometric_error_m",
                            yaw_pitch(-20, 8), quat_yaw(-35), (-1, 1.7, 2)),
    "cycles_metric": ("varjoxr4", {}, "removed_cycles_per_diameter", yaw_pitch(5, 3), quat_yaw(10), (0, 1.5, 0)),
}


def drive(case, frames=12, seed=1):
    """A still head, one fixed gaze pushed every frame: the plugin's levels and frame info."""
    hmd, kwargs, metric, gaze, orientation, position = CASES[case]
    field = object_field(seed, metric=metric)
    plugin = gazelod.Plugin(gazelod.stereo_views(hmd), disable_switch_policy=True, **kwargs)
    handles = plugin.add_objects(field["centers"], field["radii"], field["levels"], metric=metric,
                                 velocities=field["velocities"], triangles=field["triangles"])
    for f in range(1, frames + 1):
        t = f * FRAME_NS
        plugin.push_gaze(np.array([t - LATENCY_NS]), gaze)
        plugin.begin_frame(t, orientation_xyzw=orientation, position_m=position)
        yield field, plugin.levels(handles), plugin.frame_info()


@pytest.mark.parametrize("case", sorted(CASES))
def test_select_equals_the_plugin_bit_for_bit(case):
    hmd, kwargs, metric, gaze, orientation, position = CASES[case]
    kind = metric
    objects = None
    seen = 0
    for field, plugin_levels, info in drive(case):
        if objects is None:
            objects = gazelod.ObjectSet(field["centers"], field["radii"], field["levels"], kind=kind,
                                        velocities=field["velocities"], triangles=field["triangles"])
            assert len(objects) == len(field["radii"])
        assert info["gaze_source"] == "pushed" and info["eye_motion"] == "fixation"
        assert info["head_valid"] and not info["gaze_suppressed"]
        assert np.array_equal(info["eye_position_base_m"], np.array(position, float))
        if "hmd_preset" in kwargs:
            assert info["xi_cpd"] == gazelod._gazelod.xi_cpd(kwargs["hmd_preset"])
        out = gazelod.select(objects, gaze_direction=info["gaze_direction_base"],
                             tracker_error_deg=info["gaze_uncertainty_deg"], xi_cpd=info["xi_cpd"],
                             eye_position_m=info["eye_position_base_m"])
        assert out["level"].dtype == np.uint8 and out["level"].shape == plugin_levels.shape
        assert np.array_equal(out["level"], plugin_levels), \
            f"{np.count_nonzero(out['level'] != plugin_levels)} objects differ"
        assert len(np.unique(plugin_levels)) >= 3  # the field spans levels: a real comparison
        assert set(np.unique(out["limited_by"])) <= {0, 1, 2, 3, 4}
        # frame_info's triangles are the chosen levels' triangles.
        assert info["triangles_drawn"] == int(field["triangles"][np.arange(len(plugin_levels)), plugin_levels].sum())
        assert info["triangles_full"] == int(field["triangles"][:, 0].sum())
        seen += 1
    assert seen == 12


def test_select_hmd_is_its_xi():
    field = object_field(3)
    objects = gazelod.ObjectSet(field["centers"], field["radii"], field["levels"], velocities=field["velocities"])
    for h in gazelod.hmds():
        by_name = gazelod.select(objects, hmd=h["name"], gaze_direction=yaw_pitch(3, 1))
        by_xi = gazelod.select(objects, xi_cpd=h["xi_cpd"], gaze_direction=yaw_pitch(3, 1))
        assert np.array_equal(by_name["level"], by_xi["level"]), h["name"]
        assert np.array_equal(by_name["limited_by"], by_xi["limited_by"]), h["name"]


def test_select_criteria_switches():
    field = object_field(4)
    objects = gazelod.ObjectSet(field["centers"], field["radii"], field["levels"], velocities=field["velocities"])
    viewer = dict(xi_cpd=10.0, gaze_direction=yaw_pitch(0, 0), head_angular_velocity_rad_s=(0, 1.0, 0))
    everything = gazelod.select(objects, **viewer)["level"]
    size_only = gazelod.select(objects, use_eccentricity=False, use_velocity=False, **viewer)["level"]
    none = gazelod.select(objects, use_size=False, use_eccentricity=False, use_velocity=False, **viewer)["level"]
    assert np.all(none == 0)
    assert np.all(everything >= size_only) and np.any(everything > size_only)


# While the eye moves (a pursuit) the plugin's viewer has the eye's rotation in the head and the
# head's motion: frame_info() gives them, so select() is given the same viewer.
def test_select_equals_the_plugin_while_the_eye_moves():
    field = object_field(5)
    objects = gazelod.ObjectSet(field["centers"], field["radii"], field["levels"], velocities=field["velocities"])
    plugin = gazelod.Plugin(gazelod.stereo_views("quest3"), disable_switch_policy=True)
    handles = plugin.add_objects(field["centers"], field["radii"], field["levels"], velocities=field["velocities"])
    moving = 0
    for f in range(1, 41):
        t = f * FRAME_NS
        plugin.push_gaze(np.array([t - LATENCY_NS]), yaw_pitch(max(0, f - 20) * 0.5, 3))  # 45 deg/s after 20 frames
        plugin.begin_frame(t)
        info = plugin.frame_info()
        moving += info["eye_motion"] == "pursuit"
        levels = gazelod.select(objects, gaze_direction=info["gaze_direction_base"],
                                tracker_error_deg=info["gaze_uncertainty_deg"], xi_cpd=info["xi_cpd"],
                                eye_position_m=info["eye_position_base_m"],
                                head_angular_velocity_rad_s=info["head_angular_velocity_rad_s"],
                                eye_velocity_m_s=info["head_linear_velocity_m_s"],
                                gaze_angular_velocity_in_head_rad_s=info["gaze_angular_velocity_in_head_rad_s"])["level"]
        differ = int(np.count_nonzero(levels != plugin.levels(handles)))
        assert differ == 0, f"frame {f} ({info['eye_motion']}): {differ} of {len(levels)} objects differ"
    assert moving > 0


# --- bad input: ValueError (or TypeError for a wrong argument), never a crash -----------------

def small_objects():
    return gazelod.ObjectSet(np.array([[0, 0, -5.0], [1, 0, -5]]), np.array([0.5, 0.5]),
                             np.array([[0, 0.01], [0, 0.01]]))


@pytest.mark.parametrize("viewer, error, message", [
    (dict(gaze_direction=[0, 0, -1, 0]), ValueError, "gaze_direction must have 3 components"),
    (dict(gaze_direction=np.zeros((1, 3))), ValueError, "gaze_direction must have 3 components"),
    (dict(gaze_direction=[0, 0, 0]), ValueError, "viewer: gaze_direction must be finite and non-zero"),
    (dict(gaze_direction=[np.nan, 0, -1]), ValueError, "viewer: gaze_direction must be finite and non-zero"),
    (dict(eye_position_m=[0, 0]), ValueError, "eye_position_m must have 3 components"),
    (dict(xi_cpd=-1.0), ValueError, r"viewer: xi_cpd must be finite and > 0, got -1"),
    (dict(tracker_error_deg=90.0), ValueError, r"viewer: tracker_error_deg must be in \[0, 90\)"),
    (dict(scale=0.0), ValueError, r"viewer: scale must be in \(0, 1\]"),
    (dict(hmd="nope"), ValueError, r"unknown HMD preset 'nope' \(gazelod.hmds\(\) lists them\)"),
    (dict(gaze=[0, 0, -1]), TypeError, "select\\(\\) got an unexpected viewer field 'gaze'"),
])
def test_select_bad_viewer_raises(viewer, error, message):
    with pytest.raises(error, match=message):
        gazelod.select(small_objects(), **viewer)


def test_select_wrong_type_raises_type_error():
    with pytest.raises(TypeError, match="xi_cpd"):
        gazelod.select(small_objects(), xi_cpd="ten")


@pytest.mark.parametrize("args, message", [
    ((np.zeros((2, 2)), np.ones(2), np.zeros((2, 2))), r"centers must be an \(N, 3\) array"),
    ((np.zeros((2, 3)), np.ones(3), np.zeros((2, 2))), r"radii must be an \(N,\) array"),
    ((np.zeros((2, 3)), np.ones(2), np.zeros((3, 2))), r"levels must be an \(N, L\) array"),
    ((np.zeros((2, 3)), np.ones(2), np.zeros((2, 0))), r"levels must be an \(N, L\) array"),
    ((np.zeros((1, 3)), -np.ones(1), np.array([[0, 0.01]])), "object 0: radius_m must be finite and >= 0"),
    ((np.zeros((1, 3)), np.ones(1), np.array([[0, 0.1, 0.01]])), "object 0: level 2: must remove no finer detail"),
])
def test_object_set_bad_shapes_raise(args, message):
    with pytest.raises(ValueError, match=message):
        gazelod.ObjectSet(*args)


def test_object_set_bad_kind_and_velocities_raise():
    c, r, l = np.zeros((2, 3)), np.ones(2), np.array([[0, 0.01], [0, 0.01]])
    with pytest.raises(ValueError, match="kind must be 'geometric_error_m' or 'removed_cycles_per_diameter'"):
        gazelod.ObjectSet(c, r, l, kind="pixels")
    with pytest.raises(ValueError, match=r"velocities must be an \(N, 3\) array"):
        gazelod.ObjectSet(c, r, l, velocities=np.zeros((2, 2)))


def test_object_set_bad_triangles_shape_raises_value_error():
    with pytest.raises(ValueError, match="triangles"):
        gazelod.ObjectSet(np.zeros((2, 3)), np.ones(2), np.array([[0, 0.01], [0, 0.01]]),
                          triangles=np.ones((1, 1), np.uint32))


def test_select_empty_object_set():
    objects = gazelod.ObjectSet(np.zeros((0, 3)), np.zeros(0), np.zeros((0, 1)))
    out = gazelod.select(objects)
    assert len(objects) == 0 and out["level"].shape == (0,) and out["limited_by"].shape == (0,)


def test_xi_cpd_of_presets():
    for h in gazelod.hmds():
        assert gazelod._gazelod.xi_cpd(h["name"]) == h["xi_cpd"]
    with pytest.raises(ValueError, match="unknown HMD preset 'nope'"):
        gazelod._gazelod.xi_cpd("nope")
