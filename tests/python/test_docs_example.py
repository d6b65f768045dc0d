# SPDX-License-Identifier: Apache-2.0
"""docs/python.md's worked example: example_worked.py runs on the real Vive recording and writes
its figure, and the document carries the file's code word for word."""
import csv
import importlib.util
import pathlib
import re

import numpy as np

from support import SOURCE_DIR, VIVE, program_json, recording

HERE = pathlib.Path(__file__).resolve().parent


def load_example():
    spec = importlib.util.spec_from_file_location("example_worked", HERE / "example_worked.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def example_code():
    """example_worked.py without its licence line and module docstring: what the document shows."""
    text = (HERE / "example_worked.py").read_text()
    text = re.sub(r"^# SPDX-License-Identifier: .*\n", "", text, count=1)
    return re.sub(r'^""".*?"""\n', "", text, count=1, flags=re.S).strip()


def test_document_carries_the_example():
    doc = (SOURCE_DIR / "docs" / "python.md").read_text()
    blocks = re.findall(r"<!-- tests/python/example_worked\.py -->\n```python\n(.*?)```", doc, flags=re.S)
    assert len(blocks) == 1, "docs/python.md must hold the example once, after its marker comment"
    assert blocks[0].strip() == example_code()


def test_worked_example_runs_and_plots(tmp_path, capsys):
    vive = recording(VIVE)
    stats = program_json("trace", "stats", vive, "--json")
    runs, png = load_example().main(vive, tmp_path)
    printed = capsys.readouterr().out
    assert f"{stats['saccades']} saccades, {stats['fixations']} fixations" in printed
    assert f"wrote {png}" in printed

    frames = int(stats["duration_s"] * 90)
    assert set(runs) == {"questpro", "quest3"}
    for hmd, r in runs.items():
        result = r["result"]
        assert result.decisions.shape == (frames, len(result.object_names))
        assert len(r["t_s"]) == len(r["drawn"]) == frames
        assert np.all(r["drawn"] <= r["full"]) and np.all(r["drawn"] > 0)
        assert int(r["drawn"].sum()) == result.summary["triangles_drawn"]
        # frames.csv's per-frame level counts are the decisions' (what the histogram plots).
        with open(tmp_path / hmd / "frames.csv", newline="") as f:
            rows = list(csv.DictReader(f))
        levels = sorted(k for k in rows[0] if re.fullmatch(r"lod\d+", k))
        counts = np.array([[int(row[k]) for k in levels] for row in rows])
        expected = np.stack([np.bincount(d, minlength=len(levels)) for d in result.decisions])
        assert np.array_equal(counts, expected)
    # The two displays draw differently.
    assert not np.array_equal(runs["questpro"]["drawn"], runs["quest3"]["drawn"])

    import matplotlib.image
    image = matplotlib.image.imread(png)
    assert image.shape[0] >= 400 and image.shape[1] >= 1000
    assert image[..., :3].std() > 0.05  # not blank
