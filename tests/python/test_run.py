# SPDX-License-Identifier: Apache-2.0
"""gazelod.run against the gazelod program's `run --no-render`, replaying a real recording on two
HMDs, its progress callback, and Ctrl-C (KeyboardInterrupt) in a long run."""
import csv
import json
import os
import pathlib
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import gazelod
from support import VIVE, program, recording

FRAMES = 300
# summary.json's keys that hold measured times: they differ between two runs of the same
# frames (found by diffing two `gazelod run` summaries); every other key is a pure function of
# the scenario and the frames. The summary holds no paths (files are named on stdout only).
TIMING_KEYS = {"frame_time_ms", "selection_time_ms"}
REPORT_FILES = {"summary.json", "frames.csv", "frames.svg", "audit.svg"}


def read_decisions_csv(path):
    """`--decisions` parsed here, without the package: frame, t_ns, then one column per object."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    assert header[:2] == ["frame", "t_ns"]
    table = np.array([[int(v) for v in row] for row in body], dtype=np.int64)
    return header[2:], table[:, 0], table[:, 1], table[:, 2:]


def cli_run(tmp_path, name, *args):
    out, decisions = tmp_path / name, tmp_path / f"{name}_decisions.csv"
    program("run", "--no-render", "--quiet", "--out", out, "--decisions", decisions, *args)
    names, frame, t_ns, levels = read_decisions_csv(decisions)
    summary = json.loads((out / "summary.json").read_text())
    return names, frame, t_ns, levels, summary


def without_timings(summary):
    return {k: v for k, v in summary.items() if k not in TIMING_KEYS}


@pytest.fixture(scope="module")
def cli_default(tmp_path_factory):
    return cli_run(tmp_path_factory.mktemp("cli"), "default", "--frames", FRAMES)


def test_run_equals_the_program(cli_default, tmp_path):
    names, frame, t_ns, levels, summary = cli_default
    r = gazelod.run(frames=FRAMES, out=tmp_path / "py")
    assert r.decisions.dtype == np.uint8 and r.decisions.shape == (FRAMES, len(names))
    assert np.array_equal(r.decisions, levels)
    assert r.object_names == names
    assert np.array_equal(r.frame, frame) and np.array_equal(r.frame, np.arange(FRAMES))
    assert np.array_equal(r.t_ns, t_ns)
    assert TIMING_KEYS <= set(summary) and set(r.summary) == set(summary)
    assert without_timings(r.summary) == without_timings(summary)
    assert r.summary["frames"] == FRAMES and r.summary["scenario"] == "default"
    # The summary's level histogram counts the decisions.
    assert r.summary["lod_histogram"] == np.bincount(r.decisions.ravel()).tolist()
    # out= got the report files, and the summary is the one returned.
    assert REPORT_FILES <= {p.name for p in (tmp_path / "py").iterdir()}
    assert json.loads((tmp_path / "py" / "summary.json").read_text()) == r.summary


def test_two_program_runs_differ_only_in_timings(cli_default, tmp_path):
    """The exclusion list above is exactly what differs: everything else repeats bit for bit."""
    names, frame, t_ns, levels, summary = cli_default
    again = cli_run(tmp_path, "again", "--frames", FRAMES)
    assert np.array_equal(again[3], levels)
    assert without_timings(again[4]) == without_timings(summary)
    assert gazelod.run(frames=FRAMES).summary["triangles_drawn"] == summary["triangles_drawn"]


def test_replayed_recording_on_two_hmds(tmp_path):
    trace = recording(VIVE)
    frames = 600
    quest_pro = gazelod.run(trace=str(trace), hmd="questpro", frames=frames)
    quest3 = gazelod.run(trace=str(trace), hmd="quest3", frames=frames)
    for r, hmd in ((quest_pro, "questpro"), (quest3, "quest3")):
        assert r.decisions.shape == (frames, len(r.object_names))
        assert r.summary["hmd"] == hmd and r.summary["frames"] == frames
        assert r.summary["audit"]["available"] is False  # a replayed trace has no ground truth
        assert r.summary["lod_histogram"] == np.bincount(r.decisions.ravel(), minlength=4).tolist()
    assert quest_pro.object_names == quest3.object_names
    assert not np.array_equal(quest_pro.decisions, quest3.decisions)
    # Quest 3's finer display (more cycles per degree) keeps more detail.
    xi = {h["name"]: h["xi_cpd"] for h in gazelod.hmds()}
    assert xi["quest3"] > xi["questpro"]
    assert quest3.decisions.mean() < quest_pro.decisions.mean()
    # The program, given the same replay, decides the same.
    cli = cli_run(tmp_path, "cli_quest3", "--trace", trace, "--hmd", "quest3", "--frames", frames)
    assert np.array_equal(cli[3], quest3.decisions)
    assert without_timings(cli[4]) == without_timings(quest3.summary)


def test_progress_is_called_with_increasing_counts():
    # `gazelod run` prints "frame N/TOTAL" at most once a second and at the last frame
    # (apps/gazelod/run/session.cpp): 20000 frames take ~2 s here, so several calls.
    frames = 20000
    calls = []
    started = time.monotonic()
    r = gazelod.run(frames=frames, audit=False, progress=lambda done, total: calls.append((done, total)))
    elapsed = time.monotonic() - started
    assert r.decisions.shape[0] == frames
    assert calls, "the progress callback was never called"
    assert calls[-1] == (frames, frames)
    done = [d for d, _ in calls]
    assert all(total == frames for _, total in calls)
    assert all(a < b for a, b in zip(done, done[1:])), calls
    if elapsed > 1.5:
        assert len(calls) >= 2, (elapsed, calls)


def test_progress_callback_that_raises_stops_the_run_without_crashing():
    def fail(done, total):
        raise RuntimeError(f"stop at {done}/{total}")

    with pytest.raises(Exception):
        gazelod.run(frames=50, progress=fail)
    assert gazelod.run(frames=5).decisions.shape[0] == 5  # and the next run is fine


def test_progress_callback_exception_propagates():
    def fail(done, total):
        raise RuntimeError(f"stop at {done}/{total}")

    with pytest.raises(RuntimeError, match="stop at 50/50"):
        gazelod.run(frames=50, progress=fail)


CHILD = textwrap.dedent("""
    import sys, gazelod
    print("started", flush=True)
    try:
        gazelod.run(frames=100000, out=sys.argv[1])
    except KeyboardInterrupt:
        print("interrupted", flush=True)
        again = gazelod.run(frames=20)  # the package still works after the interrupt
        print("again", again.decisions.shape[0], flush=True)
        raise
    print("finished", flush=True)
""")


def test_ctrl_c_stops_a_long_run_cleanly(tmp_path):
    """SIGINT 2 s into a 100000-frame run (~10 s): KeyboardInterrupt within a second or so, no
    partial file in out=, no temporary left, and the package usable afterwards."""
    out, tmp = tmp_path / "out", tmp_path / "tmp"
    tmp.mkdir()
    env = dict(os.environ, TMPDIR=str(tmp))
    child = subprocess.Popen([sys.executable, "-c", CHILD, str(out)], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=env)
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(2.0)
        assert child.poll() is None, "the 100000-frame run ended before Ctrl-C"
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        stdout, stderr = child.communicate(timeout=10)
        stopped_after = time.monotonic() - sent
    finally:
        if child.poll() is None:
            child.kill()
            child.communicate()
    assert stopped_after < 3.0, f"took {stopped_after:.1f} s to stop"
    assert child.returncode != 0
    assert "KeyboardInterrupt" in stderr, stderr
    # KeyboardInterrupt raised by run() itself, not another error first (then the interrupt
    # lands wherever Python happens to be, e.g. in TemporaryDirectory's clean-up).
    assert "Error" not in stderr, stderr[-2000:]
    assert stdout.split() == ["interrupted", "again", "20"], (stdout, stderr[-2000:])
    # No partial output: `gazelod run` stops at a frame boundary and writes the report of the
    # frames done, whole and marked interrupted (apps/gazelod/run/signals.hpp), or none.
    left = {p.name for p in out.iterdir()} if out.exists() else set()
    assert not [n for n in left if ".tmp" in n], left
    assert left <= REPORT_FILES | {"scenario.json"}, left
    if "summary.json" in left:
        summary = json.loads((out / "summary.json").read_text())
        assert summary["interrupted"] == "SIGINT"
        assert 0 < summary["frames"] < 100000
        with open(out / "frames.csv", newline="") as f:
            assert len(list(csv.DictReader(f))) == summary["frames"]
    if "scenario.json" in left:
        json.loads((out / "scenario.json").read_text())
    assert list(tmp.iterdir()) == [], "a temporary folder of the run was left behind"
