"""Time of the exact theta(t) (and phi, psi) of the heavy top at 10^6 points.

    .venv/bin/python benchmarks/bench_motion.py

Problem 11/3's top released from rest at 30 deg with 1800 rpm, over 1000 nutation periods.
"""

from __future__ import annotations

import math
import time

import numpy as np

from gyro_cli.physics.motion import angles_of_t, theta_of_t
from gyro_cli.physics.nutation import Start, Top, analyse

G = 32.2 * 0.3048
M = 3 * 0.45359237 * 9.80665 / 16 / G
TOP = Top(I=M * (1.80 * 0.0254) ** 2, J=M * (0.84 * 0.0254) ** 2, mgl=M * G * 1.5 * 0.0254)
START = Start(math.radians(30), 1800 * math.pi / 30)


def best_of(fn, repeat: int = 5) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    nut = analyse(TOP, START)
    t = np.linspace(0.0, 1000 * nut.nutation_period, 10 ** 6)
    theta_of_t(TOP, START, t[:10])                       # imports out of the timing
    print(f"analyse (roots, elliptic period, mean precession): "
          f"{1e6 * best_of(lambda: analyse(TOP, START), 50):.0f} us")
    print(f"theta(t) at 10^6 points:            {best_of(lambda: theta_of_t(TOP, START, t)):.3f} s")
    print(f"theta, phi, psi (t) at 10^6 points: "
          f"{best_of(lambda: angles_of_t(TOP, START, t), 3):.3f} s")


if __name__ == "__main__":
    main()
