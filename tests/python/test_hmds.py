# SPDX-License-Identifier: Apache-2.0
"""gazelod.hmds, thresholds and compare: their structure, and agreement with each other and
with the gazelod program's `hmds --json` and `thresholds --json`."""
import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

import gazelod
from support import program_json


def test_hmds_is_the_program():
    presets = gazelod.hmds()
    assert presets == program_json("hmds", "--json")
    assert isinstance(presets, list) and len(presets) >= 2
    names = [h["name"] for h in presets]
    assert len(set(names)) == len(names) and {"questpro", "quest3"} <= set(names)
    for h in presets:
        assert {"name", "pixels", "fov_deg", "fov_rad", "xi_cpd", "eccentricity_threshold_deg",
                "velocity_threshold_dps", "source", "views"} <= set(h), h["name"]
        assert h["xi_cpd"] > 0 and len(h["pixels"]) == 2 and h["views"] in (1, 2, 4)
        assert gazelod._gazelod.xi_cpd(h["name"]) == h["xi_cpd"]


@pytest.mark.parametrize("hmd", ["questpro", "quest3"])
def test_thresholds_match_hmds(hmd):
    t = gazelod.thresholds(hmd)
    assert t == program_json("thresholds", "--hmd", hmd, "--json")
    h = next(h for h in gazelod.hmds() if h["name"] == hmd)
    assert t["display"] == hmd
    for key in ("xi_cpd", "eccentricity_threshold_deg", "velocity_threshold_dps", "xi_h_cpd", "xi_v_cpd"):
        assert t[key] == h[key], key
    assert t["pixels"] == h["pixels"] and t["fov_deg"] == pytest.approx(h["fov_deg"], rel=1e-12)


def test_thresholds_of_a_described_display():
    questpro = next(h for h in gazelod.hmds() if h["name"] == "questpro")
    described = gazelod.thresholds(pixels=questpro["pixels"], fov_deg=questpro["fov_deg"])
    assert described["xi_cpd"] == pytest.approx(questpro["xi_cpd"], rel=1e-12)
    with pytest.raises(ValueError, match="nope"):
        gazelod.thresholds("nope")


def test_compare_rows():
    hmds = ["questpro", "quest3"]
    rows = gazelod.compare(hmds, frames=120)
    assert isinstance(rows, list) and [r["hmd"] for r in rows] == hmds
    presets = {h["name"]: h for h in gazelod.hmds()}
    for r in rows:
        assert {"hmd", "xi_cpd", "eccentricity_threshold_deg", "velocity_threshold_dps", "frames", "shares",
                "audit", "report"} <= set(r)
        p = presets[r["hmd"]]
        assert r["xi_cpd"] == p["xi_cpd"]
        assert r["eccentricity_threshold_deg"] == p["eccentricity_threshold_deg"]
        assert r["velocity_threshold_dps"] == p["velocity_threshold_dps"]
        assert r["frames"] == 120
        assert set(r["shares"]) >= {"size", "eccentricity", "velocity"}
        assert sum(r["shares"][k] for k in ("size", "eccentricity", "velocity", "interaction")) == pytest.approx(1.0)
        assert r["report"]["hmd"] == r["hmd"]
    assert rows[0]["xi_cpd"] != rows[1]["xi_cpd"]
    with pytest.raises(ValueError, match="unknown display preset 'nope'"):
        gazelod.compare(["questpro", "nope"], frames=10)


def test_compare_takes_no_progress_argument():
    """compare's runs are quiet (one JSON document at the end): no progress to report."""
    with pytest.raises(TypeError):
        gazelod.compare(["questpro"], frames=10, progress=lambda done, total: None)


CHILD = textwrap.dedent("""
    import gazelod
    print("started", flush=True)
    try:
        gazelod.compare(["questpro", "quest3", "index", "psvr2", "varjoxr4"], frames=10000)  # ~5 s
    except KeyboardInterrupt:
        print("interrupted", flush=True)
        raise
    print("finished", flush=True)
""")


def test_ctrl_c_stops_compare():
    """SIGINT half a second into compare's first run: KeyboardInterrupt from compare() itself."""
    child = subprocess.Popen([sys.executable, "-c", CHILD], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             env=dict(os.environ))
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(0.5)
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        stdout, stderr = child.communicate(timeout=60)
        stopped_after = time.monotonic() - sent
    finally:
        if child.poll() is None:
            child.kill()
            child.communicate()
    assert stopped_after < 1.5, f"compare took {stopped_after:.1f} s to stop after Ctrl-C"
    assert "KeyboardInterrupt" in stderr and child.returncode != 0
    assert "Error" not in stderr, stderr[-2000:]
    assert stdout.split() == ["interrupted"], (stdout, stderr[-2000:])
