# SPDX-License-Identifier: Apache-2.0
"""gazelod.read_trace and gazelod.classify against the gazelod program's `trace stats` and
`trace convert` on the real recordings (../shared/data/gaze), and on malformed files."""
import numpy as np
import pytest

import gazelod
from support import VIVE, program, program_json, recording

FORMATS = ["gazelod", "gazebasevr", "pupil", "pupil_cloud", "sranipal"]
ARRAYS = ["t_ns", "valid", "direction", "origin_m", "confidence"]
HEAD_ARRAYS = ["head_valid", "head_orientation_xyzw", "head_position_m"]


def test_reader_matches_trace_stats(real_recording):
    path, fmt = real_recording
    stats = program_json("trace", "stats", path, "--json")
    assert stats["format"] == fmt
    for given in ("auto", fmt):
        t = gazelod.read_trace(str(path), format=given)
        assert t["format"] == fmt
        n = stats["samples"]
        assert len(t["t_ns"]) == n and t["t_ns"].dtype == np.int64
        assert t["direction"].shape == (n, 3) and t["origin_m"].shape == (n, 3)
        assert t["valid"].dtype == bool and t["valid"].shape == (n,) and t["confidence"].shape == (n,)
        # `trace stats --json` gives no first/last time, only their difference, computed as
        # double(last - first) * 1e-9: the same operation here gives the same double.
        assert float(int(t["t_ns"][-1] - t["t_ns"][0])) * 1e-9 == stats["duration_s"]
        assert np.all(np.diff(t["t_ns"]) >= 0)
        assert int(np.count_nonzero(~t["valid"])) / n == stats["invalid_fraction"]
        assert (int(np.count_nonzero(t["head_valid"])) if "head_valid" in t else 0) == stats["samples_with_head"]
        assert np.isfinite(t["direction"]).all()
        assert np.allclose(np.linalg.norm(t["direction"][t["valid"]], axis=1), 1.0)


def test_every_other_reader_refuses_the_recording(real_recording):
    path, fmt = real_recording
    for other in FORMATS:
        if other == fmt:
            continue
        with pytest.raises(ValueError, match=r"missing required .*column") as e:
            gazelod.read_trace(str(path), format=other)
        assert f"{path}:1:" in str(e.value)


@pytest.mark.parametrize("time", ["ns", "s"])
def test_converted_trace_reads_back_identically(real_recording, tmp_path, time):
    path, _ = real_recording
    out = tmp_path / "converted.csv"
    r = program("trace", "convert", "--time", time, path, out)
    n = program_json("trace", "stats", path, "--json")["samples"]
    assert f"wrote {n} samples" in r.stdout + r.stderr
    original = gazelod.read_trace(str(path))
    back = gazelod.read_trace(str(out))
    assert back["format"] == "gazelod"
    # The program's own times, parsed here without the package.
    lines = out.read_text().splitlines()
    assert lines[0] == "# gazelod-trace 1"
    header = lines[1].split(",")
    column = [row.split(",")[header.index("t_" + time)] for row in lines[2:]]
    assert len(column) == n
    if time == "ns":
        cli_t = np.array(column, dtype=np.int64)
    else:  # docs/gaze.md: t_s is read as llround(t_s * 1e9)
        cli_t = np.array([int(np.rint(float(c) * 1e9)) for c in column], dtype=np.int64)
    assert np.array_equal(back["t_ns"], cli_t)
    if time == "ns" or original["t_ns"][-1] < 2**53 // 1000:
        # Lossless: the first and last timestamps (and every one between) are read_trace's.
        assert np.array_equal(cli_t, original["t_ns"])
    else:
        # Seconds since 1970 in a double keep ~0.24 us, and t_ns * 1e-9 then t_s * 1e9 round
        # three times: the SRanipal log's Unix times come back within 0.5 us, not exactly
        # (t_s is lossy for absolute clocks; t_ns, the default, is exact).
        error = np.abs(cli_t - original["t_ns"])
        assert 0 < np.max(error) <= 512
    for key in ARRAYS[1:] + (HEAD_ARRAYS if "head_valid" in original else []):
        assert np.array_equal(back[key], original[key]), key
    assert ("head_valid" in back) == ("head_valid" in original)


def test_classify_matches_trace_stats(real_recording):
    path, _ = real_recording
    stats = program_json("trace", "stats", path, "--json")
    c = gazelod.classify(str(path))
    s = c["stats"]
    for key in ("samples", "saccades", "fixations", "classified_in", "duration_s", "rate_hz",
                "mean_saccade_amplitude_deg", "max_saccade_peak_velocity_deg_s"):
        assert s[key] == stats[key], key
    assert s["invalid"] / s["samples"] == stats["invalid_fraction"]
    assert s["with_head"] == stats["samples_with_head"]
    assert s["saccades"] > 0 and s["fixations"] > 0

    label = c["label"]
    assert label.dtype == np.uint8 and len(label) == stats["samples"]
    assert set(np.unique(label)) <= {0, 1, 2, 3}  # fixation, saccade, invalid, unknown
    t = gazelod.read_trace(str(path))
    assert np.array_equal(label == 2, ~t["valid"])  # invalid: exactly the invalid samples
    assert len(c["velocity_deg_s"]) == stats["samples"]
    assert np.all(c["velocity_deg_s"][label >= 2] == 0)

    sac, fix = c["saccades"], c["fixations"]
    for key in ("start_ns", "end_ns", "amplitude_deg", "peak_velocity_deg_s"):
        assert len(sac[key]) == stats["saccades"], key
    assert len(fix["start_ns"]) == len(fix["end_ns"]) == stats["fixations"]
    assert np.all(sac["start_ns"] <= sac["end_ns"]) and np.all(fix["start_ns"] <= fix["end_ns"])
    assert np.all(np.diff(sac["start_ns"]) > 0)
    # Events begin and end on samples.
    assert np.isin(sac["start_ns"], t["t_ns"]).all() and np.isin(sac["end_ns"], t["t_ns"]).all()
    assert np.mean(sac["amplitude_deg"]) == pytest.approx(stats["mean_saccade_amplitude_deg"], rel=1e-12)
    assert np.max(sac["peak_velocity_deg_s"]) == stats["max_saccade_peak_velocity_deg_s"]
    # Every saccade covers samples labelled saccade.
    first = np.searchsorted(t["t_ns"], sac["start_ns"])
    assert np.all(label[first] == 1)


def test_trace_stats_wrapper_is_the_program(real_recording):
    path, _ = real_recording
    assert gazelod.trace_stats(path) == program_json("trace", "stats", path, "--json")


# Malformed inputs: ValueError naming the file, the line and (where the reader has one) the
# column; never a crash. (file contents, message after "<path>:")
GAZELOD_HEADER = "# gazelod-trace 1\nt_ns,gaze_x,gaze_y,gaze_z,valid\n"
BAD_FILES = {
    "bad_number": (GAZELOD_HEADER + "0,0,0,-1,1\n1000,0,abc,-1,1\n", "4:8: gaze_y: 'abc' is not a number"),
    "missing_column": ("# gazelod-trace 1\nt_ns,gaze_x,gaze_y,valid\n0,0,0,1\n", "2: missing required column(s): gaze_z"),
    "short_row": (GAZELOD_HEADER + "0,0,0,-1\n", "3: row has 4 fields, header has 5"),
    "time_backwards": (GAZELOD_HEADER + "100,0,0,-1,1\n50,0,0,-1,1\n", "4:1: time goes backwards: 50 ns after 100 ns"),
    "binary": ("garbage\x00\n", "1:8: NUL byte"),
    "empty": ("", " empty file (0 bytes)"),
}


@pytest.mark.parametrize("reader", [gazelod.read_trace, gazelod.classify], ids=["read_trace", "classify"])
@pytest.mark.parametrize("case", sorted(BAD_FILES))
def test_malformed_file_raises_value_error_with_file_line_column(tmp_path, case, reader):
    text, message = BAD_FILES[case]
    path = tmp_path / f"{case}.csv"
    path.write_text(text)
    with pytest.raises(ValueError) as e:
        reader(str(path))
    assert str(e.value).startswith(f"{path}:{message}"), str(e.value)
    # The program says the same.
    r = program("trace", "stats", path, check=False)
    assert r.returncode != 0 and f"{path}:{message}" in r.stderr


@pytest.mark.parametrize("reader", [gazelod.read_trace, gazelod.classify], ids=["read_trace", "classify"])
def test_directory_and_missing_path_raise_value_error(tmp_path, reader):
    with pytest.raises(ValueError, match="is a directory, not a trace file") as e:
        reader(str(tmp_path))
    assert str(e.value).startswith(str(tmp_path))
    missing = tmp_path / "nonexistent.csv"
    with pytest.raises(ValueError, match="cannot open file for reading: No such file or directory") as e:
        reader(str(missing))
    assert str(e.value).startswith(str(missing))


def test_malformed_real_recording_names_line_and_column(tmp_path):
    """A real SRanipal log with one number spoiled: the error points at it."""
    lines = recording(VIVE).read_text().splitlines(keepends=True)
    header = lines[0].rstrip("\r\n").split(";")
    fields = lines[10].rstrip("\r\n").split(";")
    col = header.index("gaze_direct_L.x")
    fields[col] = "1,5"  # a decimal comma
    lines[10] = ";".join(fields) + "\n"
    bad = tmp_path / "spoiled_vive.csv"
    bad.write_text("".join(lines))
    with pytest.raises(ValueError) as e:
        gazelod.read_trace(str(bad))
    message = str(e.value)
    column = sum(len(f) + 1 for f in fields[:col]) + 1
    assert message.startswith(f"{bad}:11:{column}:"), message


def test_lenient_skips_bad_lines(tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text(BAD_FILES["bad_number"][0] + "2000,0,0,-1,1\n")
    t = gazelod.read_trace(str(path), lenient=True)
    assert t["t_ns"].tolist() == [0, 2000]


def test_unknown_format_raises(real_recording):
    path, _ = real_recording
    with pytest.raises(ValueError, match="format 'bogus' is not one of"):
        gazelod.read_trace(str(path), format="bogus")
    with pytest.raises(ValueError, match="format 'bogus' is not one of"):
        gazelod.classify(str(path), format="bogus")


def test_readers_accept_pathlib_paths(real_recording):
    path, _ = real_recording
    assert len(gazelod.read_trace(path)["t_ns"]) == len(gazelod.classify(path)["label"])
