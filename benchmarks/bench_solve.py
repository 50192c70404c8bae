"""Wall time of `gyro solve problems/11_3.yaml` against Python's own start.

Warm: the unit table on disk already knows the file's units, so gyro needs
neither pint nor numpy; its floor is `python -c "import yaml, click"`.
Target: warm solve <= 1.3x that floor. Cold: an empty unit cache every run,
so pint builds its registry; it is set against python + pint + yaml + click
+ one cached registry, what any pint-based CLI pays (target <= 1.3x, no slower
than before the unit table). Median of 10 runs each, interleaved.

    .venv/bin/python benchmarks/bench_solve.py [--runs 10] [FILE]

``--instructions``: the warm solve and the floor counted in instructions by valgrind
(callgrind), one run each: the same on a machine shared with other work, where wall
times are not.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FLOOR = "import yaml, click"
PINT_FLOOR = "import pint, yaml, click; pint.UnitRegistry(cache_folder=':auto:')"


def wall(cmd: list[str], env: dict | None = None) -> float:
    start = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, cwd=ROOT, env=env)
    return time.perf_counter() - start


def instructions(cmd: list[str], env: dict | None = None) -> int:
    """The instructions ``cmd`` runs, counted by valgrind's callgrind."""
    done = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
                           *cmd], capture_output=True, text=True, check=True, cwd=ROOT,
                          env=env)
    return int(done.stderr.rsplit("Collected : ", 1)[1].split()[0])


def count(solve_cmd: list[str], floor_cmd: list[str], warm_env: dict) -> None:
    floor, warm = instructions(floor_cmd), instructions(solve_cmd, warm_env)
    print(f"python -c '{FLOOR}':                       {floor / 1e6:7.1f} M instructions")
    print(f"gyro solve (warm unit cache):                 {warm / 1e6:7.1f} M instructions   "
          f"ratio {warm / floor:.3f}x")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("file", nargs="?", default="problems/11_3.yaml")
    parser.add_argument("--instructions", action="store_true",
                        help="count instructions (valgrind) instead of timing")
    args = parser.parse_args()
    gyro = str(Path(sys.executable).with_name("gyro"))
    solve_cmd = [gyro, "solve", args.file] if os.path.exists(gyro) else \
        [sys.executable, "-m", "gyro_cli", "solve", args.file]
    warm_dir, cold_dir = tempfile.mkdtemp(), tempfile.mkdtemp()
    warm_env = dict(os.environ, GYRO_CACHE_DIR=warm_dir)
    cold_env = dict(os.environ, GYRO_CACHE_DIR=cold_dir)
    floor_cmd = [sys.executable, "-c", FLOOR]
    pint_cmd = [sys.executable, "-c", PINT_FLOOR]
    # bytecode, as an installed package has it (yaml and click's came with pip install)
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(ROOT / "gyro_cli")], check=True)
    wall(solve_cmd, warm_env), wall(solve_cmd, cold_env)  # fill the caches
    if args.instructions:
        count(solve_cmd, floor_cmd, warm_env)
        shutil.rmtree(warm_dir, ignore_errors=True)
        shutil.rmtree(cold_dir, ignore_errors=True)
        return
    wall(floor_cmd), wall(pint_cmd)
    times: dict[str, list[float]] = {"floor": [], "warm": [], "pint": [], "cold": []}
    for _ in range(args.runs):
        times["floor"].append(wall(floor_cmd))
        times["warm"].append(wall(solve_cmd, warm_env))
        times["pint"].append(wall(pint_cmd))
        # the unit table only: pint's own disk cache (kept in the same folder) stays, as
        # the floor's does
        Path(cold_dir, "units.json").unlink(missing_ok=True)
        times["cold"].append(wall(solve_cmd, cold_env))
    m = {k: statistics.median(v) * 1000 for k, v in times.items()}
    print(f"python -c '{FLOOR}':                       {m['floor']:7.1f} ms")
    print(f"gyro solve {args.file} (warm unit cache): {m['warm']:7.1f} ms   "
          f"ratio {m['warm'] / m['floor']:.2f}x (target <= 1.30x)")
    print(f"python + pint + yaml + click + registry:         {m['pint']:7.1f} ms")
    print(f"gyro solve {args.file} (empty unit cache):{m['cold']:7.1f} ms   "
          f"ratio {m['cold'] / m['pint']:.2f}x (target <= 1.30x)")
    print(f"median of {args.runs}")
    shutil.rmtree(warm_dir, ignore_errors=True)
    shutil.rmtree(cold_dir, ignore_errors=True)


if __name__ == "__main__":
    main()
