"""Time of an animation: 10 nutation periods of the released top at 30 frames/s.

Target (issue: see it move): under 20 s on a 2-core machine, simulation and
rendering included. Prints the frames, the seconds of each stage and the
cost of one panel frame (the constant commands/animate.py uses to refuse long
requests before they start).

    .venv/bin/python benchmarks/bench_animate.py [--periods 10] [--fps 30] [--runs 3]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from gyro_cli.commands.animate import build_scene  # noqa: E402
from gyro_cli.render import animate  # noqa: E402


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--periods", type=float, default=10.0)
    ap.add_argument("--fps", type=float, default=30.0)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--file", default=str(ROOT / "problems" / "11_2_released_top.yaml"))
    args = ap.parse_args()
    rows = []
    for _ in range(args.runs):
        t0 = time.perf_counter()
        scene, _ = build_scene(args.file, periods=args.periods, fps=args.fps)
        t1 = time.perf_counter()
        gif = animate.gif_bytes(scene)
        t2 = time.perf_counter()
        html = animate.html_page(scene)
        t3 = time.perf_counter()
        rows.append((t1 - t0, t2 - t1, t3 - t2, len(gif), len(html), scene.frames))
    sim, gif_s, html_s = (statistics.median(r[k] for r in rows) for k in range(3))
    frames = rows[0][5]
    print(f"{args.periods:g} nutation periods at {args.fps:g} frames/s: {frames} frames")
    print(f"  simulation + scene  {sim:7.2f} s (median of {args.runs})")
    print(f"  GIF                 {gif_s:7.2f} s  {rows[0][3] / 1e6:.1f} MB  "
          f"({1000 * gif_s / frames:.1f} ms a frame)")
    print(f"  HTML                {html_s:7.2f} s  {rows[0][4] / 1e6:.1f} MB")
    print(f"  total to GIF        {sim + gif_s:7.2f} s   (target < 20 s)")


if __name__ == "__main__":
    main()
