# SPDX-License-Identifier: Apache-2.0
"""Shared helpers of the Python package's tests (tests/python/, registered by CMakeLists.txt).

CTest passes GAZELOD_SOURCE_DIR (the repository) and GAZELOD_PROGRAM (the gazelod program) and
puts the built package on PYTHONPATH. The real recordings are in <repository>/../shared/data/gaze
(not part of the repository): a test that needs one skips without it, but fails under CI
(CI=true), as tests/skip_or_fail.hpp does for the C++ tests.
"""
import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("GAZELOD_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
PROGRAM = pathlib.Path(os.environ.get("GAZELOD_PROGRAM", SOURCE_DIR / "build" / "apps" / "gazelod" / "gazelod"))
GAZE_DATA = SOURCE_DIR / ".." / "shared" / "data" / "gaze"
VIVE = "htc_vive_pro_eye_unity_log.csv"  # SRanipal (HTC Vive Pro Eye through a Unity logger)
PUPIL_CLOUD = "pupil_cloud_invisible_gaze.csv"  # Pupil Cloud export of a Pupil Invisible recording
RECORDINGS = {VIVE: "sranipal", PUPIL_CLOUD: "pupil_cloud"}


def required_by_ci():
    return os.environ.get("CI") in ("true", "1")


def skip_or_fail(why):
    """tests/skip_or_fail.hpp's policy: skip on a developer's machine, fail under CI."""
    if required_by_ci():
        pytest.fail(f"required under CI (CI=true): {why}", pytrace=False)
    pytest.skip(why)


def recording(name):
    """The path of a real recording in ../shared/data/gaze (skips, or fails under CI, without it)."""
    path = GAZE_DATA / name
    if not path.is_file():
        skip_or_fail(f"no {path} (../shared/data/gaze, evaluation data)")
    return path.resolve()


def program(*args, check=True, **kw):
    """Runs the gazelod program itself (not the package's in-process copy of it)."""
    if not PROGRAM.is_file():
        skip_or_fail(f"no gazelod program at {PROGRAM} (build the target gazelod)")
    r = subprocess.run([str(PROGRAM), *map(str, args)], capture_output=True, text=True, **kw)
    if check and r.returncode != 0:
        raise AssertionError(f"gazelod {' '.join(map(str, args))} failed ({r.returncode}):\n{r.stderr}")
    return r


def program_json(*args):
    return json.loads(program(*args).stdout)

