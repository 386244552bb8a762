"""The Python API's time overhead over the CLI: `gearloss.run(scene)` (the library call, the report
folder read into memory, bytes to Python) against `gearloss run scene --out DIR` (the same library
call in a fresh process), median of runs, for a one-point scene and a 10 000-point sweep.

    target/python-venv/bin/python tests/python/bench_overhead.py [path/to/gearloss] [runs]

README ("From Python") prints its figures. Not a test: timings belong to benchmarks.
"""

import statistics
import subprocess
import sys
import tempfile
import time

import gearloss

CLI = sys.argv[1] if len(sys.argv) > 1 else "target/release/gearloss"
RUNS = int(sys.argv[2]) if len(sys.argv) > 2 else 7

one_point = gearloss.Scene.from_file("specs/fzg_type_c.gear").replace(
    pinion_torque="239.3 N*m", pinion_speed="1000 rpm"
)
sweep = gearloss.Scene.from_file("specs/fzg_type_c.gear").replace(
    pinion_torque="100..400 N*m count 100", pinion_speed="100..3000 rpm count 100"
)


def median(f):
    times = []
    for _ in range(RUNS):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


for label, scene in [("one point", one_point), ("10 000 points", sweep)]:
    with tempfile.TemporaryDirectory() as tmp:
        path = f"{tmp}/scene.gear"
        with open(path, "w", encoding="utf-8") as f:
            f.write(scene.text)
        cli = median(lambda: subprocess.run([CLI, "run", path, "--out", tmp], check=True, capture_output=True))
        py = median(lambda: gearloss.run(scene))
        print(f"{label}: CLI {cli * 1e3:.1f} ms, Python {py * 1e3:.1f} ms, overhead {(py - cli) * 1e3:+.1f} ms ({py / cli:.2f}x)")
