"""CPU time of the full integration (simulate.py) over 100 nutation periods, and of
the exact theta(t) (nutation/motion.theta_of_t) at 10^6 points, each with its
energy drift. Targets: simulate < 2 s CPU with energy drift < 1e-10 relative.

    .venv/bin/python benchmarks/bench_simulate.py [--periods 100] [--points 1000000] [--runs 3]

Tops: problem 11/3's (3 ozf, k_z 0.84 in, k_O 1.80 in, l 1.5 in, 1800 rpm) released
at 30 deg (cusps), and the same top started at 60 deg with phidot0 = -3 rad/s (loops).
Energy drift of the integration: max |E - E0| over every step / (T0 + m g l). Of the
exact theta(t): E from Eq. 11.17 with thetadot by 4th-order central differences on
the 10^6-point grid, same scale.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from gyro_cli.physics.simulate import Params, simulate  # noqa: E402

M = 3 * 0.27801385 / (32.2 * 0.3048)
BODY = dict(I=M * (1.80 * 0.0254) ** 2, J=M * (0.84 * 0.0254) ** 2,
            mgl=M * 32.2 * 0.3048 * 1.5 * 0.0254)
TOPS = {
    "cusps (11/3 top released at 30 deg)": Params(theta0=math.radians(30), spin=1800 * math.pi / 30,
                                                  **BODY),
    "loops (60 deg, phidot0 = -3 rad/s)": Params(theta0=math.radians(60), spin=150.0,
                                                 precession0=-3.0, **BODY),
}


def analytic():
    """(Top, Start, analyse, theta_of_t) from the analytic module, or None."""
    try:
        from gyro_cli.physics import nutation
    except ImportError:
        return None
    theta_of_t = getattr(nutation, "theta_of_t", None)
    if theta_of_t is None:
        try:
            from gyro_cli.physics.motion import theta_of_t
        except ImportError:
            return None
    return nutation.Top, nutation.Start, nutation.analyse, theta_of_t


def period_of(p: Params, tools) -> float:
    if tools:
        Top, Start, analyse, _ = tools
        return analyse(Top(p.I, p.J, p.mgl), Start(p.theta0, p.spin, p.precession0,
                                                    p.theta_rate0)).nutation_period
    return simulate(p, p, t_end=1.0, samples=3).nutation_period   # measured, 1 s run


def energy_of_theta(p: Params, t: np.ndarray, theta: np.ndarray) -> tuple[float, float]:
    """Max relative energy error of a theta(t) series (Eq. 11.17), thetadot by finite
    differences (4th order, interior points)."""
    c0, s0 = math.cos(p.theta0), math.sin(p.theta0)
    P2 = p.J * (p.spin + p.precession0 * c0)
    P1 = p.I * p.precession0 * s0 ** 2 + P2 * c0
    T0 = 0.5 * (p.I * (p.theta_rate0 ** 2 + (p.precession0 * s0) ** 2) + P2 ** 2 / p.J)
    E0 = T0 + p.mgl * c0
    dt = t[1] - t[0]
    thd = (theta[:-4] - 8 * theta[1:-3] + 8 * theta[3:-1] - theta[4:]) / (12 * dt)
    th = theta[2:-2]
    s = np.sin(th)
    phidot = (P1 - P2 * np.cos(th)) / (p.I * s * s)
    E = 0.5 * (p.I * (thd ** 2 + phidot ** 2 * s * s) + P2 ** 2 / p.J) + p.mgl * np.cos(th)
    return float(np.max(np.abs(E - E0)) / (T0 + p.mgl)), dt


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--periods", type=float, default=100.0)
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--runs", type=int, default=3, help="best of RUNS")
    args = parser.parse_args()
    tools = analytic()
    for name, p in TOPS.items():
        period = period_of(p, tools)
        print(f"{name}: nutation period {period:.10g} s")
        best = None
        for _ in range(args.runs):
            sim = simulate(p, p, t_end=args.periods * period, samples=1001)
            best = sim if best is None or sim.cpu_seconds < best.cpu_seconds else best
        print(f"  simulate, {args.periods:g} periods: {best.cpu_seconds:.3f} s CPU "
              f"(best of {args.runs}), {best.steps} steps, {best.nfev} evaluations; "
              f"energy drift {best.energy_drift:.2e}, P1 {best.P1_drift:.2e}, "
              f"P2 {best.P2_drift:.2e}; measured period {best.nutation_period:.12g} s")
        if tools is None:
            print("  exact theta(t): not available (gyro_cli.physics.nutation not built yet)")
            continue
        Top, Start, _, theta_of_t = tools
        top, start = Top(p.I, p.J, p.mgl), Start(p.theta0, p.spin, p.precession0,
                                                  p.theta_rate0)
        t = np.linspace(0.0, args.periods * period, args.points)
        times = []
        for _ in range(args.runs):
            clock = time.process_time()
            theta = np.asarray(theta_of_t(top, start, t))
            times.append(time.process_time() - clock)
        drift, dt = energy_of_theta(p, t, theta)
        print(f"  exact theta(t) at {args.points} points: {min(times):.3f} s CPU (best of "
              f"{args.runs}); energy drift {drift:.2e} (thetadot by finite differences, "
              f"dt = {dt:.2e} s)")


if __name__ == "__main__":
    main()
