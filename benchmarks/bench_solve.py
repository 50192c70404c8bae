"""Wall time of `gyro solve problems/11_3.yaml` against the bare-minimum baseline.

The baseline is Python importing pint, yaml and click and building one cached
unit registry: what any pint-based CLI must pay. Target: solve <= 1.3x baseline
(median of 10 runs each, interleaved so machine noise hits both alike).

    .venv/bin/python benchmarks/bench_solve.py [--runs 10] [FILE]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BASELINE = "import pint, yaml, click; pint.UnitRegistry(cache_folder=':auto:')"


def wall(cmd: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, cwd=ROOT)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("file", nargs="?", default="problems/11_3.yaml")
    args = parser.parse_args()
    gyro = str(Path(sys.executable).with_name("gyro"))
    solve_cmd = [gyro, "solve", args.file] if os.path.exists(gyro) else \
        [sys.executable, "-m", "gyro_cli", "solve", args.file]
    base_cmd = [sys.executable, "-c", BASELINE]
    wall(solve_cmd), wall(base_cmd)  # warm the caches (pint's and the OS's)
    solve_times, base_times = [], []
    for _ in range(args.runs):
        base_times.append(wall(base_cmd))
        solve_times.append(wall(solve_cmd))
    base, solve = statistics.median(base_times), statistics.median(solve_times)
    print(f"baseline (python + pint + yaml + click + one cached registry): {base * 1000:7.1f} ms")
    print(f"gyro solve {args.file}: {solve * 1000:7.1f} ms")
    print(f"ratio: {solve / base:.2f}x (target <= 1.30x), median of {args.runs}")


if __name__ == "__main__":
    main()
