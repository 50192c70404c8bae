"""Wall time of `gyro check` on 1000 generated problem files against `gyro solve` of one.

The files are variants of problems/11_3.yaml made by `gyro vary` (each with its
own data and computed answer key), written to a temporary directory. Target:
checking all 1000 costs at most 3x solving one file (median of the runs,
interleaved so machine noise hits both alike). Also asserts that every file
was checked and passed, so the number is not flattered by skipped work.

    .venv/bin/python benchmarks/bench_check.py [--runs 5] [--count 1000]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

SOURCE = textwrap.dedent("""\
    id: "bench"
    title: Top with two possible rates of steady precession
    kind: steady_precession
    given:
      weight: 3 oz
      k_axial: 0.84 in
      k_pivot: 1.80 in
      cg_distance: 1.5 in
      spin: 1800 rpm
      theta: 30 deg
    find:
      precession: rpm
      min_spin: rpm
    expected:
      precession: [45.13 rpm, 533.5 rpm]
      min_spin: 965.4 rpm
    tolerance: 1%
    vary:
      spin: [0.7, 1.5]
      theta: [15 deg, 60 deg]
      weight: [0.5, 2.0]
      cg_distance: [0.8, 1.2]
    """)


def gyro_cmd() -> list[str]:
    gyro = Path(sys.executable).with_name("gyro")
    return [str(gyro)] if gyro.exists() else [sys.executable, "-m", "gyro_cli"]


def wall(cmd: list[str], ok: tuple[int, ...] = (0,)) -> float:
    start = time.perf_counter()
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, cwd=ROOT)
    elapsed = time.perf_counter() - start
    if done.returncode not in ok:
        raise SystemExit(f"{' '.join(cmd)} exited {done.returncode}: {done.stderr.decode()}")
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--count", type=int, default=1000)
    args = parser.parse_args()
    gyro = gyro_cmd()
    with tempfile.TemporaryDirectory() as tmp:
        source = os.path.join(tmp, "bench.yaml")
        Path(source).write_text(SOURCE)
        out = os.path.join(tmp, "set")
        subprocess.run(gyro + ["vary", source, "--count", str(args.count), "--seed", "1",
                               "-o", out], check=True, stdout=subprocess.DEVNULL, cwd=ROOT)
        one = os.path.join(out, sorted(os.listdir(out))[0])
        report = subprocess.run(gyro + ["check", out, "--format", "json"], cwd=ROOT,
                                capture_output=True, text=True)
        summary = json.loads(report.stdout)["summary"]
        if report.returncode != 0 or summary["checked"] != args.count:
            raise SystemExit(f"check did not pass on the generated set: {summary}")
        solve_cmd, check_cmd = gyro + ["solve", one], gyro + ["check", out]
        wall(solve_cmd), wall(check_cmd)  # warm pint's cache and the OS's
        solve_times, check_times = [], []
        for _ in range(args.runs):
            solve_times.append(wall(solve_cmd))
            check_times.append(wall(check_cmd))
    solve, check = statistics.median(solve_times), statistics.median(check_times)
    print(f"gyro solve (1 file):          {solve * 1000:8.1f} ms")
    print(f"gyro check ({args.count} files):     {check * 1000:8.1f} ms  "
          f"({summary['answers']} answers, all passed)")
    print(f"ratio: {check / solve:.2f}x (target <= 3.00x), median of {args.runs}")


if __name__ == "__main__":
    main()
