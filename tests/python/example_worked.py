# SPDX-License-Identifier: Apache-2.0
"""The worked example of docs/python.md (the same code; tests/python/test_docs_example.py runs it
and checks that the document still carries it word for word).

    python3 example_worked.py htc_vive_pro_eye_unity_log.csv out/

Loads a real HTC Vive Pro Eye recording, classifies it, replays it as the gaze of the default
scenario on two headsets, and plots the triangles drawn per frame and the share of objects at
each level per headset into out/replay.png.
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt
import numpy as np

import gazelod

HMDS = {"questpro": "Meta Quest Pro", "quest3": "Meta Quest 3"}


def main(recording, out_dir):
    recording, out_dir = str(recording), pathlib.Path(out_dir)

    # 1. The recording and its eye movements (I-VT, as `gazelod trace stats`).
    trace = gazelod.read_trace(recording)
    events = gazelod.classify(recording)
    s = events["stats"]
    print(f"{s['samples']} {trace['format']} samples, {s['duration_s']:.1f} s at {s['rate_hz']:.0f} Hz: "
          f"{s['saccades']} saccades, {s['fixations']} fixations, {s['invalid']} invalid samples "
          f"(classified in the {s['classified_in']})")
    labels = np.bincount(events["label"], minlength=4)
    print("samples labelled fixation {}, saccade {}, invalid {}, unknown {}".format(*labels))

    # 2. Replay it as the gaze (and, as it has them, the head poses) of the default scenario,
    # for as many 90 Hz frames as the recording lasts, on each headset. out= keeps the report
    # files: frames.csv has one row per frame, triangles included.
    frames = int(s["duration_s"] * 90)
    runs = {}
    for hmd in HMDS:
        result = gazelod.run(trace=recording, hmd=hmd, frames=frames, out=out_dir / hmd)
        with open(out_dir / hmd / "frames.csv", newline="") as f:
            rows = list(csv.DictReader(f))
        runs[hmd] = dict(
            result=result,
            t_s=np.array([float(r["t_s"]) for r in rows]),
            drawn=np.array([int(r["triangles_drawn"]) for r in rows]),
            full=np.array([int(r["triangles_full"]) for r in rows]),
        )
        sm = result.summary
        print(f"{hmd}: {sm['triangles_drawn'] / sm['triangles_full']:.1%} of the full-detail triangles drawn "
              f"over {sm['frames']} frames of {len(result.object_names)} objects")

    # 3. The figure: triangles per frame over time (the recording's saccades shaded), and the
    # share of object-frames drawn at each level.
    fig, (ax_t, ax_l) = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw=dict(width_ratios=[2.2, 1]),
                                     layout="constrained")
    t0 = trace["t_ns"][0]
    for i, (start, end) in enumerate(zip(events["saccades"]["start_ns"], events["saccades"]["end_ns"])):
        ax_t.axvspan((start - t0) * 1e-9, (end - t0) * 1e-9, color="0.85", lw=0,
                     label="saccade (recording)" if i == 0 else None)
    for hmd, name in HMDS.items():
        r = runs[hmd]
        ax_t.plot(r["t_s"], 100.0 * r["drawn"] / r["full"], lw=1.2, label=name)
    top = max(100.0 * np.max(r["drawn"] / r["full"]) for r in runs.values())
    ax_t.set_xlim(0, frames / 90)
    ax_t.set_ylim(0, 10 * np.ceil(top * 1.3 / 10))  # headroom for the legend
    ax_t.set_xlabel("time (s)")
    ax_t.set_ylabel("triangles drawn (% of full detail)")
    ax_t.set_title("Triangles per frame, recorded gaze and head")
    ax_t.legend(loc="upper center", ncol=3, framealpha=1.0, edgecolor="none")

    levels = max(int(r["result"].decisions.max()) for r in runs.values()) + 1
    width = 0.8 / len(HMDS)
    for k, (hmd, name) in enumerate(HMDS.items()):
        d = runs[hmd]["result"].decisions
        share = 100.0 * np.bincount(d.ravel(), minlength=levels) / d.size
        ax_l.bar(np.arange(levels) + (k - (len(HMDS) - 1) / 2) * width, share, width, label=name)
    ax_l.set_xticks(np.arange(levels), [f"L{i}" + (" (full)" if i == 0 else "") for i in range(levels)])
    ax_l.set_xlabel("level drawn")
    ax_l.set_ylabel("object-frames (%)")
    ax_l.set_title("Levels drawn")
    ax_l.legend(loc="upper left")

    png = out_dir / "replay.png"
    fig.savefig(png, dpi=120)
    plt.close(fig)
    print(f"wrote {png}")
    return runs, png


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else ".")
