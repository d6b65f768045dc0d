# SPDX-License-Identifier: Apache-2.0
"""The Python binding's call overhead on the selection (docs/python.md, bench/RESULTS.md):
gazelod.select on 100k objects against the same selection timed inside C++
(gazelod._gazelod._time_select_cpp) on the same ObjectSet and viewer. The difference is what a
Python call costs on top: argument parsing, the viewer's kwargs, two output arrays.

    PYTHONPATH=build/bindings/python /usr/bin/python3 bench/python/bench_select.py [--objects N]

Prints both times per call (best of several repetitions) and their ratio (target <= 1.2).
"""
import argparse
import timeit

import numpy as np

import gazelod


def object_field(n, seed=0):
    """The default scenario's kind of field: 4-level chains, objects 2-120 m ahead, moving."""
    rng = np.random.default_rng(seed)
    centers = np.column_stack([rng.uniform(-20, 20, n), rng.uniform(-4, 4, n), rng.uniform(-120, -2, n)])
    radii = rng.uniform(0.2, 1.5, n)
    base = rng.uniform(0.0005, 0.01, n)
    levels = np.column_stack([np.zeros(n)] + [base * 4.0**k for k in range(3)])
    velocities = rng.normal(0.0, 1.0, (n, 3))
    return gazelod.ObjectSet(centers, radii, levels, velocities=velocities)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--objects", type=int, default=100_000)
    ap.add_argument("--repetitions", type=int, default=15, help="batches; the best one counts")
    ap.add_argument("--calls", type=int, default=20, help="calls per batch")
    args = ap.parse_args()

    objects = object_field(args.objects)  # built once
    viewer = dict(gaze_direction=np.array([0.1, 0.05, -1.0]), eye_position_m=np.array([0.0, 1.6, 0.0]),
                  head_angular_velocity_rad_s=np.array([0.0, 0.3, 0.0]), xi_cpd=10.0, tracker_error_deg=1.5)
    # The same levels either way (and a warm cache for both).
    levels = gazelod.select(objects, **viewer)["level"]
    assert len(levels) == args.objects and len(np.unique(levels)) > 1

    # Interleaved, so both see the same machine load; best batch of each.
    py_best = cpp_best = float("inf")
    for _ in range(args.repetitions):
        py = min(timeit.repeat(lambda: gazelod.select(objects, **viewer), number=args.calls, repeat=1)) / args.calls
        cpp = gazelod._gazelod._time_select_cpp(objects, 1, args.calls, **viewer)
        py_best, cpp_best = min(py_best, py), min(cpp_best, cpp)

    ratio = py_best / cpp_best
    print(f"objects                 {args.objects}")
    print(f"gazelod.select          {py_best * 1e3:.3f} ms per call (best of {args.repetitions} x {args.calls})")
    print(f"C++ select_lods         {cpp_best * 1e3:.3f} ms per call (best of {args.repetitions} x {args.calls})")
    print(f"Python overhead         {(py_best - cpp_best) * 1e6:.1f} us per call")
    print(f"ratio Python / C++      {ratio:.3f} (target <= 1.2: {'met' if ratio <= 1.2 else 'NOT met'})")
    return 0 if ratio <= 1.2 else 1


if __name__ == "__main__":
    raise SystemExit(main())
