# SPDX-License-Identifier: Apache-2.0
"""gazelod.Plugin (the C ABI's data mode) on bad input: ValueError with the library's
"gazelod: ..." message (and the gzl_result), never a crash; the plugin stays usable."""
import numpy as np
import pytest

import gazelod

CENTERS = np.array([[0, 0, -5.0], [1, 0, -5], [-1, 0.5, -8]])
RADII = np.array([0.5, 0.5, 0.3])
LEVELS = np.array([[0, 0.002, 0.008], [0, 0.002, 0.008], [0, 0.002, np.nan]])
AHEAD = np.array([0, 0, -1.0])


class Held:
    """A Plugin and the handles of its objects (a pybind11 class takes no new attributes)."""

    def __init__(self, plugin, handles):
        self.plugin, self.handles = plugin, handles

    def __getattr__(self, name):
        return getattr(self.plugin, name)


@pytest.fixture
def plugin():
    p = gazelod.Plugin(gazelod.stereo_views("questpro"), disable_switch_policy=True)
    handles = p.add_objects(CENTERS, RADII, LEVELS)
    assert handles.dtype == np.uint64 and len(np.unique(handles)) == 3
    p.push_gaze(np.array([1_000]), AHEAD)
    p.begin_frame(10_000)
    return Held(p, handles)


def still_works(p, t_ns):
    p.push_gaze(np.array([t_ns - 1_000]), AHEAD)
    p.begin_frame(t_ns)
    assert p.frame_info()["display_time_ns"] == t_ns
    return p.levels(p.handles)


def gzl_error(p, call, message, result):
    with pytest.raises(ValueError) as e:
        call()
    text = str(e.value)
    assert text.startswith("gazelod: "), text
    assert message in text and text.endswith(f"[{result}]"), text
    return text


def test_nan_and_zero_gaze_direction(plugin):
    for bad in ([np.nan, 0, -1], [0, 0, 0], [np.inf, 0, -1]):
        gzl_error(plugin, lambda: plugin.push_gaze(np.array([2_000]), np.array(bad)),
                  "gaze sample direction must be finite and non-zero", "GZL_ERROR_INVALID_ARGUMENT")
    # A blink is pushed as an invalid sample, and any direction goes then.
    plugin.push_gaze(np.array([3_000]), np.array([0, 0, 0.0]), valid=np.array([False]))
    assert still_works(plugin, 20_000).shape == (3,)


def test_out_of_order_sample(plugin):
    plugin.push_gaze(np.array([5_000]), AHEAD)
    gzl_error(plugin, lambda: plugin.push_gaze(np.array([4_000]), AHEAD),
              "gaze sample at 4000 ns is older than the previous one (5000 ns)", "GZL_ERROR_TIME_OUT_OF_ORDER")
    # Arrays of samples: the one out of order is refused.
    gzl_error(plugin, lambda: plugin.push_gaze(np.array([6_000, 5_500]), np.array([AHEAD, AHEAD])),
              "gaze sample at 5500 ns is older than the previous one (6000 ns)", "GZL_ERROR_TIME_OUT_OF_ORDER")
    assert still_works(plugin, 20_000).shape == (3,)


def test_frame_out_of_order_and_bad_pose(plugin):
    gzl_error(plugin, lambda: plugin.begin_frame(5_000),
              "input->display_time_ns 5000 is not after the last frame's (10000)", "GZL_ERROR_TIME_OUT_OF_ORDER")
    gzl_error(plugin, lambda: plugin.begin_frame(20_000, orientation_xyzw=(0, 0, 0, 0)),
              "input->head.orientation must be a finite, non-zero quaternion", "GZL_ERROR_INVALID_ARGUMENT")
    gzl_error(plugin, lambda: plugin.begin_frame(20_000, position_m=(np.nan, 0, 0)),
              "input->head.position_m is not finite", "GZL_ERROR_INVALID_ARGUMENT")
    assert still_works(plugin, 30_000).shape == (3,)


def test_removed_handle(plugin):
    gone = plugin.handles[:1]
    plugin.remove(gone)
    gzl_error(plugin, lambda: plugin.levels(plugin.handles), "objects[0] = ", "GZL_ERROR_OBJECT_INVALID")
    gzl_error(plugin, lambda: plugin.remove(gone), "was removed", "GZL_ERROR_OBJECT_INVALID")
    gzl_error(plugin, lambda: plugin.set_enabled(gone, False), "was removed", "GZL_ERROR_OBJECT_INVALID")
    plugin.handles = plugin.handles[1:]
    assert still_works(plugin, 20_000).shape == (2,)
    assert plugin.frame_info()["object_count"] == 2


def test_bad_objects(plugin):
    gzl_error(plugin, lambda: plugin.add_objects(CENTERS[:1], np.array([-0.5]), LEVELS[:1]),
              "desc->radius_m must be finite and >= 0", "GZL_ERROR_INVALID_ARGUMENT")
    gzl_error(plugin, lambda: plugin.add_objects(CENTERS[:1], RADII[:1], np.array([[0, 0.01, 0.001]])),
              "desc->levels: level 2: must remove no finer detail than level 1", "GZL_ERROR_INVALID_ARGUMENT")
    with pytest.raises(ValueError, match="metric must be geometric_error_m"):
        plugin.add_objects(CENTERS, RADII, LEVELS, metric="pixels")
    with pytest.raises(ValueError, match=r"centers must be an \(N, 3\) array"):
        plugin.add_objects(CENTERS[:, :2], RADII, LEVELS)
    with pytest.raises(ValueError, match=r"radii must be an \(N,\) array"):
        plugin.add_objects(CENTERS, RADII[:2], LEVELS)
    still_works(plugin, 20_000)
    assert plugin.frame_info()["object_count"] == 3


def test_bad_velocity_shape_raises_value_error(plugin):
    with pytest.raises(ValueError, match="velocities"):
        plugin.add_objects(CENTERS, RADII, LEVELS, velocities=np.zeros((3, 2)))


def test_refused_add_objects_adds_nothing(plugin):
    with pytest.raises(ValueError):
        plugin.add_objects(CENTERS[:2], np.array([0.5, -1.0]), LEVELS[:2])  # the second is refused
    still_works(plugin, 20_000)
    assert plugin.frame_info()["object_count"] == 3


def test_bad_views_and_config():
    views = gazelod.stereo_views("questpro")
    with pytest.raises(ValueError, match=r"^gazelod: info->views: view_count 0"):
        gazelod.Plugin([])
    with pytest.raises(ValueError, match=r"^gazelod: unknown HMD preset 'nope'"):
        gazelod.Plugin(views, hmd_preset="nope")
    with pytest.raises(ValueError, match=r"^gazelod: info->views\[0\].fov: horizontal FOV"):
        gazelod.Plugin([dict(fov=(0, 0, 0, 0), width_px=10, height_px=10)])
    with pytest.raises(ValueError, match=r"views\[0\].fov is \(left, right, up, down\)"):
        gazelod.Plugin([dict(fov=(0, 0, 0), width_px=10, height_px=10)])
    with pytest.raises(ValueError, match="unknown HMD preset 'nope'"):
        gazelod.stereo_views("nope")


def test_shapes_and_views(plugin):
    with pytest.raises(ValueError, match=r"direction is \(3,\) with one time, or \(N, 3\) with N times"):
        plugin.push_gaze(np.array([2_000, 3_000]), AHEAD)
    with pytest.raises(ValueError, match="orientation_xyzw must be"):
        plugin.begin_frame(20_000, orientation_xyzw=(0, 0, 1))
    gzl_error(plugin, lambda: plugin.foveal_cone(7), "view 7 out of range: the last frame had 2 views",
              "GZL_ERROR_INVALID_ARGUMENT")
    cone = plugin.foveal_cone(0)
    assert cone["in_view"] and cone["half_angle_deg"] == cone["fovea_deg"] + cone["uncertainty_deg"]
    assert plugin.gaze_status() == "pushed eye gaze delivered"
    assert plugin.frame_info()["gaze_source"] == "pushed"


def test_abi_version():
    assert gazelod._gazelod.abi_version() == (1, 0, 0)


def test_package_exports_abi_version_and_xi_cpd():
    assert gazelod.abi_version()[0] == 1
    assert gazelod.xi_cpd("questpro") == 10.0


def test_disabled_criteria_by_name():
    """Without eccentricity, a row fixated at its middle is drawn alike; an unknown name raises."""
    def row_levels(disabled):
        p = gazelod.Plugin(gazelod.stereo_views("questpro"), disabled_criteria=disabled)
        yaws = np.radians([-30.0, 0.0, 30.0])
        centers = np.stack([-2 * np.sin(yaws), np.zeros(3), -2 * np.cos(yaws)], axis=1)
        h = p.add_objects(centers, np.full(3, 0.1), np.tile([0, 0.0005, 0.002, 0.008], (3, 1)))
        for f in range(1, 91):
            t = f * 11_111_111
            p.push_gaze(np.array([t - 5_000_000]), np.array([0.0, 0.0, -1.0]))
            p.begin_frame(t)
        return p.levels(h)
    everything = row_levels([])
    assert everything[1] < everything[0] and everything[1] < everything[2]
    no_ecc = row_levels(["eccentricity"])
    assert list(no_ecc) == [everything[1]] * 3
    with pytest.raises(ValueError, match="disabled_criteria: 'colour'"):
        gazelod.Plugin(gazelod.stereo_views("questpro"), disabled_criteria=["colour"])
