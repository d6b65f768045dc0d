# SPDX-License-Identifier: Apache-2.0
"""gazelod for Python: gaze traces, their classification, the perceptual core on numpy arrays,
the C ABI's data-mode plugin frame by frame, and the main job (`run`) and HMD comparison.

    import gazelod
    trace = gazelod.read_trace("recording.csv")             # dict of numpy arrays
    events = gazelod.classify("recording.csv")               # I-VT labels, saccades, fixations
    result = gazelod.run(frames=900, hmd="questpro")         # decisions: frames x objects
    table = gazelod.compare(["questpro", "quest3"], frames=900)

docs/python.md has a worked example. Errors in inputs raise ValueError with the file, line
and column (or the field) at fault; Ctrl-C stops a long run cleanly (KeyboardInterrupt).
"""
import json as _json
import operator as _operator
import os as _os
import re as _re
import tempfile as _tempfile
from dataclasses import dataclass as _dataclass, field as _field

import numpy as _np

from . import _gazelod
from ._gazelod import ObjectSet, Plugin, abi_version, select, xi_cpd

__version__ = _gazelod.__version__
__all__ = ["ObjectSet", "Plugin", "RunResult", "abi_version", "classify", "compare", "hmds", "read_trace", "run",
           "select", "stereo_views", "thresholds", "trace_stats", "xi_cpd"]


def read_trace(path, format="auto", lenient=False):
    """A recording in any format `gazelod trace` reads, as a dict of numpy arrays: t_ns (int64),
    valid (bool), direction (N, 3, head space), origin_m, confidence, and with head poses
    head_valid, head_orientation_xyzw, head_position_m; 'format' the layout read. A bad file
    raises ValueError naming the file, line and column."""
    return _gazelod.read_trace(_os.fsencode(path), format, lenient)


def classify(path, format="auto"):
    """The I-VT classification `gazelod trace stats` counts: per-sample label (0 fixation,
    1 saccade, 2 invalid, 3 unknown) and velocity_deg_s, the saccade and fixation events, and
    the stats (classified in the world where the trace has head poses)."""
    return _gazelod.classify(_os.fsencode(path), format)


def _installed_runtime_manifest():
    """The simulated runtime's manifest of an installed package: <prefix>/share/openxr/1/."""
    here = _os.path.dirname(_os.path.abspath(__file__))
    for _ in range(6):
        here = _os.path.dirname(here)
        candidate = _os.path.join(here, "share", "openxr", "1", "gazelod_xr_runtime.json")
        if _os.path.isfile(candidate):
            return candidate
    return None


if "XR_RUNTIME_JSON" not in _os.environ:
    _manifest = _installed_runtime_manifest()
    if _manifest:
        _os.environ["XR_RUNTIME_JSON"] = _manifest


def _frames(frames):
    """A frame count as given: int(1.7) ran one frame."""
    try:
        return _operator.index(frames)
    except TypeError:
        raise TypeError(f"frames must be an integer, got {frames!r}") from None


def _command(args, on_line=None):
    """Runs a gazelod command in-process; raises ValueError with its message when it fails."""
    # Paths as the file system's bytes (os.fsencode): a name that is not UTF-8 reached pybind11
    # as a str it could not convert, and str(b"...") passed "b'...'" as the path.
    rc, out, err = _gazelod._cli([_os.fsencode(a) if isinstance(a, (str, bytes, _os.PathLike)) else str(a)
                                  for a in args], on_line)
    if rc != 0:
        lines = [l for l in err.splitlines() if l.strip() and " frame " not in l]
        raise ValueError(lines[-1] if lines else f"gazelod {args[0]} failed ({rc})")
    return out, err


def hmds():
    """The display presets as a list of dicts (name, pixels, fov_deg, xi_cpd, thresholds, source)."""
    out, _ = _command(["hmds", "--json"])
    return _json.loads(out)


def thresholds(hmd=None, *, pixels=None, fov_deg=None):
    """The acuity model's thresholds for a preset or a described display (as `gazelod thresholds`)."""
    args = ["thresholds", "--json"]
    if hmd is not None:
        args += ["--hmd", hmd]
    if pixels is not None:
        args += ["--pixels", f"{pixels[0]}x{pixels[1]}"]
    if fov_deg is not None:
        args += ["--fov", f"{fov_deg[0]}x{fov_deg[1]}"]
    out, _ = _command(args)
    return _json.loads(out)


def trace_stats(path, format="auto"):
    """`gazelod trace stats --json` as a dict."""
    out, _ = _command(["trace", "stats", _os.fspath(path), "--format", format, "--json"])
    return _json.loads(out)


def stereo_views(hmd):
    """A preset's views for Plugin(views=...): both eyes with the preset's FOV and pixels."""
    for d in hmds():
        if d["name"] == hmd:
            f = d["fov_rad"]
            fov = (f["angle_left"], f["angle_right"], f["angle_up"], f["angle_down"])
            mirrored = (-f["angle_right"], -f["angle_left"], f["angle_up"], f["angle_down"])
            w, h = d["pixels"]
            return [dict(fov=fov, width_px=w, height_px=h, position_in_head_m=(-0.032, 0, 0)),
                    dict(fov=mirrored, width_px=w, height_px=h, position_in_head_m=(0.032, 0, 0))][: d["views"]]
    raise ValueError(f"unknown HMD preset '{hmd}' (gazelod.hmds() lists them)")


def _progress_printer(progress):
    """progress: None, True (tqdm when installed, else nothing), or a callable(done, total)."""
    if progress is None or progress is False:
        return None, None
    bar = None
    if progress is True:
        try:
            from tqdm import tqdm
        except ImportError:
            return None, None
        bar = tqdm(unit="frame")

        def progress(done, total):
            bar.total = total
            bar.n = done
            bar.refresh()

    pattern = _re.compile(r"frame (\d+)/(\d+)")

    def on_line(line):
        m = pattern.search(line)
        if m:
            progress(int(m.group(1)), int(m.group(2)))

    return on_line, bar


@_dataclass
class RunResult:
    """What `run` returns: the levels drawn per frame and object, and the report."""
    decisions: _np.ndarray          # (frames, objects) uint8: the drawn level (0 = full detail)
    object_names: list
    frame: _np.ndarray              # (frames,) int64: the frame numbers `--decisions` writes
    t_ns: _np.ndarray               # (frames,) int64: predicted display time from the scenario's start
    summary: dict = _field(repr=False)  # summary.json


def _read_decisions(path):
    with open(path, newline="") as f:
        import csv
        header = next(csv.reader([f.readline()]))
        table = _np.loadtxt(f, delimiter=",", dtype=_np.int64, ndmin=2)
    return header[2:], table[:, 0], table[:, 1], table[:, 2:].astype(_np.uint8)


def run(scenario=None, *, frames=None, hmd=None, trace=None, audit=True, criteria=None, gaze_error_deg=None,
        progress=None, out=None):
    """The main job without rendering (`gazelod run --no-render`), in-process.

    scenario: a scenario JSON path (None: the embedded default); frames: how many (None: the
    scenario's duration); hmd: a preset replacing the scenario's display; trace: a recording
    replayed as the gaze source (any format `gazelod trace` reads); progress: a callable
    (done, total) or True for tqdm; out: a folder for the report files (None: a temporary one).
    """
    with _tempfile.TemporaryDirectory(prefix="gazelod-run-") as tmp:
        folder = _os.fspath(out) if out is not None else _os.path.join(tmp, "out")
        decisions = _os.path.join(tmp, "decisions.csv")
        args = ["run", "--no-render", "--out", folder, "--decisions", decisions]
        if scenario is not None:
            args += ["--scenario", _os.fspath(scenario)]
        if frames is not None:
            args += ["--frames", _frames(frames)]
        if hmd is not None:
            args += ["--hmd", hmd]
        if trace is not None:
            args += ["--trace", _os.fspath(trace)]
        if not audit:
            args.append("--no-audit")
        if criteria is not None:
            args += ["--criteria", criteria if isinstance(criteria, str) else ",".join(criteria)]
        if gaze_error_deg is not None:
            args += ["--gaze-error-deg", gaze_error_deg]
        on_line, bar = _progress_printer(progress)
        try:
            _command(args, on_line)
        finally:
            if bar is not None:
                bar.close()
        names, frame, t_ns, levels = _read_decisions(decisions)
        with open(_os.path.join(folder, "summary.json")) as f:
            summary = _json.load(f)
    return RunResult(levels, names, frame, t_ns, summary)


def compare(hmds, scenario=None, *, frames=None):
    """`gazelod compare` as a table: one dict per HMD (hand it to pandas.DataFrame). Its runs
    print no progress; Ctrl-C stops it (KeyboardInterrupt)."""
    with _tempfile.TemporaryDirectory(prefix="gazelod-compare-") as tmp:
        args = ["compare", "--json", "--out", tmp]
        for h in [hmds] if isinstance(hmds, str) else hmds:  # one name, or several
            args += ["--hmd", h]
        if scenario is not None:
            args += ["--scenario", scenario]
        if frames is not None:
            args += ["--frames", _frames(frames)]
        out, _ = _command(args)
    rows = []
    for e in _json.loads(out)["hmds"]:
        audit = e.get("audit", {})
        rows.append({
            "hmd": e["hmd"],
            "xi_cpd": e["xi_cpd"],
            "eccentricity_threshold_deg": e["eccentricity_threshold_deg"],
            "velocity_threshold_dps": e["velocity_threshold_dps"],
            "frames": e["frames"],
            "shares": e.get("shares"),
            "audit": audit,
            "report": e,
        })
    return rows
