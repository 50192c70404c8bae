"""``gyro simulate FILE``: the analytic answer beside a full numerical integration.

For a ``released_top`` file the analytic side is nutation.analyse (Eqs. 11.14-11.26);
for a ``steady_precession`` file it is the slow root of Eq. 11.13 with thetaddot = 0
(theta constant). The numerical side is simulate.simulate: Euler's equations with a
quaternion attitude, which uses neither. Both are reported with their differences
and the drift of the three integrals of the motion.
"""

from __future__ import annotations

import json
import math
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..core.errors import InputError, terminal_text
from ..core.work import num

RPM = 2 * math.pi / 60
#: what a kind may declare `gyro simulate` integrates (Kind.simulation), in message order
SIMULATIONS = ("released", "steady")
SAMPLES_PER_PERIOD = 200
MAX_SAMPLES = 2_000_001
CSV_HEADER = "t_s,theta_rad,phi_rad,psi_rad,thetadot_rad_s,phidot_rad_s,psidot_rad_s"


@dataclass
class Setup:
    """What to integrate, what theory says, and over how long."""

    problem: Any                       # solving.problem.Problem
    params: Any                        # simulate.Params
    analytic: dict                     # theta_min, theta_max, nutation_period, mean_precession, motion
    period: float                      # the time unit of --periods
    period_meaning: str
    notes: list[str] = field(default_factory=list)


def prepare(path: str) -> Setup:
    """Load the file and work out the analytic answer; InputError if it cannot be simulated."""
    from ..solving.problem import load
    from ..solving.solve import solve

    problem = load(path)
    if problem.kind.simulation not in SIMULATIONS:
        from ..kinds import offering

        raise InputError(f"simulate integrates the heavy top: kinds "
                         f"{', '.join(offering('simulation', SIMULATIONS))}; this "
                         f"file is kind {problem.kind.name!r}", file=path, key="kind")
    result = solve(problem)        # every check the kind makes on its input
    given = problem.given
    body = given.body
    try:
        if problem.kind.simulation == "released":
            return _released(problem, given, body)
        return _steady(problem, given, body, result)
    except InputError as err:
        raise err.located(file=path, line=problem.line(err.key)) from None


def _released(problem, given, body) -> Setup:
    from ..physics.nutation import Start, Top, analyse
    from ..physics.simulate import Params

    top = Top(I=body.I_pivot, J=body.J, mgl=body.mgl)
    start = Start(theta0=given["theta0"], spin=given["spin"],
                  precession0=given.get("precession0", 0.0) or 0.0,
                  theta_rate0=given.get("theta_rate0", 0.0) or 0.0)
    nut = analyse(top, start)
    params = Params(top.I, top.J, top.mgl, start.theta0, start.spin, start.precession0,
                    start.theta_rate0)
    analytic = {"theta_min": nut.theta_min, "theta_max": nut.theta_max,
                "nutation_period": _finite(nut.nutation_period),
                "mean_precession": _finite(nut.mean_precession), "motion": nut.motion}
    period, meaning = _time_unit(params, analytic)
    return Setup(problem, params, analytic, period, meaning)


def _steady(problem, given, body, result) -> Setup:
    from ..physics.simulate import Params

    if "moment" in given:
        raise InputError("simulate integrates gravity's torque (cg_distance); a file with an "
                         "applied moment is not simulated", key="given.moment")
    answers = result.solution.answers
    if "precession" not in answers or "spin" not in answers:
        raise InputError("simulate needs a motion: give spin, axial_rate or precession",
                         key="given.spin")
    if body.I_pivot is None:
        raise InputError("simulate integrates the full equations, which need the transverse "
                         "inertia even where the steady answer does not: give I_pivot, k_pivot, "
                         "I_cg or k_cg (with cg_distance) or a shape", key="given.I_pivot")
    pairs = list(zip(answers["precession"].si_values, answers["spin"].si_values))
    precession, spin = min(pairs, key=lambda pair: abs(pair[0]))     # the slow root
    theta = given["theta"]
    params = Params(body.I_pivot, body.J, body.mgl, theta, spin, precession, 0.0)
    analytic = {"theta_min": theta, "theta_max": theta, "nutation_period": None,
                "mean_precession": precession, "motion": "steady"}
    period, meaning = _time_unit(params, analytic)
    notes = []
    if len(pairs) > 1:
        notes.append("two steady precessions: simulated the slow one, phidot = "
                     f"{num(precession)} rad/s ({num(precession / RPM)} rpm)")
    return Setup(problem, params, analytic, period, meaning, notes)


def _finite(value) -> float | None:
    return float(value) if value is not None and math.isfinite(value) else None


def _time_unit(p, analytic: dict) -> tuple[float, str]:
    """The time one of --periods stands for."""
    period = analytic.get("nutation_period")
    if period:
        return period, "nutation periods"
    precession = analytic.get("mean_precession")
    if precession:
        return 2 * math.pi / abs(precession), "precession revolutions (no nutation)"
    omega_z = p.spin + p.precession0 * math.cos(p.theta0)
    if omega_z:
        return 2 * math.pi * p.I / (p.J * abs(omega_z)), \
            "times 2 pi I / (J omega_z), the fast top's nutation period (no nutation)"
    return 2 * math.pi * math.sqrt(p.I / p.mgl) if p.mgl else 1.0, "pendulum periods"


def check_outputs(paths: list[str | None], force: bool) -> None:
    """Fail before integrating if an output exists (no --force) or has a bad name."""
    from ..render.plot import FORMATS

    named = [p for p in paths if p]
    if len(set(map(str, named))) < len(named):
        raise InputError("--csv and --plot name the same file")
    for path in named:
        from ..core.files import refuse_special

        refuse_special(path)
        target = Path(path)
        if target.is_dir():
            raise InputError("is a directory, expected a file to write", file=str(path))
        if target.exists() and not force:
            raise InputError("exists; not overwritten (use --force to replace it)",
                             file=str(path))
        if not (target.parent if str(target.parent) else Path(".")).is_dir():
            raise InputError(f"cannot write: no such directory {str(target.parent)!r}",
                             file=str(path))
    plot = paths[1] if len(paths) > 1 else None
    if plot and Path(plot).suffix.lower() not in FORMATS:
        raise InputError("plot format not supported; name the file .png, .svg or .pdf",
                         file=str(plot))


def run(setup: Setup, periods: float, progress: Callable[[float], None] | None = None):
    """Integrate ``periods`` time units; returns the Simulation."""
    from ..physics.simulate import simulate

    t_end = periods * setup.period
    samples = int(min(MAX_SAMPLES, max(201, round(periods * SAMPLES_PER_PERIOD) + 1)))
    try:
        return simulate(setup.params, setup.params, t_end, samples=samples, progress=progress,
                        theta_range=_theta_range(setup.analytic))
    except (ValueError, RuntimeError) as err:
        raise InputError(f"cannot simulate: {err}", file=setup.problem.file) from None


def _shortest_run(setup: Setup) -> float:
    """The least run whose constant theta means a steady motion: a nutation would show
    within 2 pi I / (J omega_z), the fast top's nutation period (or within one unit of
    --periods, if shorter)."""
    p = setup.params
    omega_z = abs(p.spin + p.precession0 * math.cos(p.theta0))
    fast = 2 * math.pi * p.I / (p.J * omega_z) if omega_z and p.J else math.inf
    return min(setup.period, fast)


def _theta_range(analytic: dict) -> tuple[float, float] | None:
    """The analytic nutation bounds, if finite (they bound the rates of the whole run)."""
    lo, hi = analytic.get("theta_min"), analytic.get("theta_max")
    if lo is None or hi is None or not (math.isfinite(lo) and math.isfinite(hi)):
        return None
    # a hair of margin: the integrated theta may pass the bound by round-off
    return max(0.0, min(lo, hi) - 1e-6), min(math.pi, max(lo, hi) + 1e-6)


def comparison(setup: Setup, sim) -> dict:
    """Analytic, simulated and their differences, SI; plus drifts. The JSON object."""
    from ..physics.simulate import TOO_SHORT, motion_of

    simulated = {"theta_min": sim.theta_min, "theta_max": sim.theta_max,
                 "nutation_period": sim.nutation_period,
                 "mean_precession": sim.mean_precession if sim.precession_resolved else None,
                 "motion": motion_of(sim, shortest=_shortest_run(setup))}
    unreached = []
    if sim.theta_varies:
        # theta's largest (least) value in a run without a maximum (minimum) is at an end
        # of the run, not a turning point: not a measure of theta_max (theta_min)
        for key, times in (("theta_min", sim.t_theta_min), ("theta_max", sim.t_theta_max)):
            if not len(times):
                unreached.append(f"no theta {key[6:]}imum in the run: {key} is not measured "
                                 f"(theta reached {math.degrees(simulated[key]):.6g} deg at an "
                                 "end of the run)")
                simulated[key] = None
    difference: dict[str, Any] = {}
    for key in ("theta_min", "theta_max", "nutation_period", "mean_precession"):
        a, s = setup.analytic.get(key), simulated.get(key)
        if a is None or s is None:
            difference[key] = None
            continue
        difference[key] = {"absolute": s - a, "relative": (s - a) / abs(a) if a else None}
    difference["motion"] = (None if simulated["motion"] == TOO_SHORT
                            else simulated["motion"] == setup.analytic["motion"])
    p = setup.params
    problem = setup.problem
    return {
        "id": problem.id, "kind": problem.kind.name, "file": problem.file,
        "method": "Euler's equations in body axes (I, I, J) with gravity's torque and a unit "
                  "quaternion attitude; scipy DOP853, rtol 1e-12",
        "params": {"I": p.I, "J": p.J, "mgl": p.mgl, "theta0": p.theta0, "spin": p.spin,
                   "precession0": p.precession0, "theta_rate0": p.theta_rate0},
        "t_end": float(sim.t[-1]), "period_unit": setup.period,
        "period_meaning": setup.period_meaning,
        "analytic": setup.analytic, "simulated": simulated, "difference": difference,
        "invariants": {"energy": sim.energy0, "P1": sim.P1, "P2": sim.P2},
        "drift": {"energy": sim.energy_drift, "energy_varying": sim.energy_drift_varying,
                  "P1": sim.P1_drift, "P2": sim.P2_drift, "quaternion_norm": sim.norm_drift},
        "theta_range": float(sim.theta.max() - sim.theta.min()),
        "steps": sim.steps, "evaluations": sim.nfev, "cpu_seconds": sim.cpu_seconds,
        "notes": setup.notes + unreached + sim.notes,
    }


def _value(key: str, value) -> str:
    if value is None:
        return "-"
    if isinstance(value, str):
        return value
    if key.startswith("theta"):
        return f"{math.degrees(value):.10g}"
    if key == "mean_precession":
        return f"{value / RPM:.10g}"
    return f"{value:.10g}"


def text(report: dict, periods: float) -> str:
    """The side-by-side report."""
    p = report["params"]
    problem_line = f"{report['id']}  [{report['kind']}]  {report['file']}"
    lines = [problem_line, "",
             "Simulated: Euler's equations in body axes (I, I, J) with gravity's torque, unit",
             "quaternion attitude (no gimbal lock), scipy DOP853 at rtol 1e-12",
             f"  I = {num(p['I'])} kg m^2, J = {num(p['J'])} kg m^2, m g l = {num(p['mgl'])} N m",
             f"  start (Eqs. 11.5-11.8, z-x-z): theta0 = {num(math.degrees(p['theta0']))} deg, "
             f"psidot0 = {num(p['spin'])} rad/s,",
             f"    phidot0 = {num(p['precession0'])} rad/s, thetadot0 = "
             f"{num(p['theta_rate0'])} rad/s",
             f"  t = 0 .. {num(report['t_end'])} s: {periods:g} {report['period_meaning']} "
             f"of {num(report['period_unit'])} s",
             f"  {report['steps']} steps, {report['evaluations']} evaluations, "
             f"{report['cpu_seconds']:.2f} s CPU",
             "",
             f"  {'':<24}{'analytic':>18}{'simulated':>18}{'difference':>13}{'relative':>11}"]
    rows = (("theta_min", "theta_min (deg)"), ("theta_max", "theta_max (deg)"),
            ("nutation_period", "nutation period (s)"),
            ("mean_precession", "mean precession (rpm)"), ("motion", "motion"))
    for key, label in rows:
        a, s = report["analytic"].get(key), report["simulated"].get(key)
        d = report["difference"].get(key)
        if key == "motion":
            diff, rel = ("not compared" if d is None else "same" if d else "DIFFERENT"), ""
        elif isinstance(d, dict):
            scale = 180 / math.pi if key.startswith("theta") else (1 / RPM if key ==
                                                                    "mean_precession" else 1)
            diff = f"{d['absolute'] * scale:.2e}"
            rel = f"{d['relative']:.1e}" if d["relative"] is not None else "-"
        else:
            diff, rel = "-", "-"
        shown = _value(key, s)
        lines.append(f"  {label:<24}{_value(key, a):>18}{shown:>{max(18, len(shown) + 2)}}"
                     f"{diff:>13}{rel:>11}")
    drift = report["drift"]
    inv = report["invariants"]
    integrals: tuple[tuple[str, str, float, str], ...] = (("energy T + V, Eqs. 11.10-11.11", f"{num(inv['energy'], 10)} J",
             drift["energy"], "T0 + m g l"),
            ("  the same, its varying part", "", drift["energy_varying"],
             "max I (w_x^2 + w_y^2)/2 + m g l"),
            ("P1 = p_phi, vertical H, Eq. 11.14", f"{num(inv['P1'], 10)} kg m^2/s", drift["P1"],
             "|H|"),
            ("P2 = p_psi, axial H, Eq. 11.14", f"{num(inv['P2'], 10)} kg m^2/s", drift["P2"],
             "|H| (J omega_z' = 0 exactly)"),
            ("quaternion norm |q|", "1", drift["quaternion_norm"], "not renormalised"))
    lines += ["", f"  {'integral of the motion':<34}{'at t = 0':>24}{'max drift':>11}  relative to"]
    for label, value, d, against in integrals:
        lines.append(f"  {label:<34}{value:>24}{d:>11.1e}  {against}")
    lines.append(f"  theta range over the run: {math.degrees(report['theta_range']):.6g} deg")
    for note in report["notes"]:
        lines.append(f"Note: {note}")
    for kind, path in report.get("outputs", {}).items():
        lines.append(f"Wrote {kind}: {path}")
    # the id and file names come from the user: no escape sequence reaches the terminal
    return "\n".join(terminal_text(line) for line in lines) + "\n"


def csv_text(sim) -> str:
    """The time series, SI, one row per sample."""
    import numpy as np

    table = np.column_stack([sim.t, sim.theta, sim.phi, sim.psi, sim.theta_rate, sim.phidot,
                             sim.psidot])
    rows = [",".join(f"{v:.17g}" for v in row) for row in table.tolist()]
    return CSV_HEADER + "\n" + "\n".join(rows) + "\n"


def terminal_progress(stream=None) -> Callable[[float], None] | None:
    """A progress bar on stderr, only when it is a terminal and the run takes a while."""
    stream = stream or sys.stderr
    if not stream.isatty():
        return None
    started: list[float] = []
    shown = [False]

    def show(fraction: float) -> None:
        if not started:
            started.append(time.monotonic())
        if time.monotonic() - started[0] < 0.5 and fraction < 1.0:
            return
        if fraction >= 1.0 and not shown[0]:
            return
        width = 30
        filled = int(round(width * fraction))
        end = "\r" if fraction < 1.0 else "\r" + " " * (width + 24) + "\r"
        stream.write(f"\rsimulating [{'#' * filled}{'.' * (width - filled)}] "
                     f"{100 * fraction:5.1f}%" + ("" if fraction < 1.0 else end))
        stream.flush()
        shown[0] = True

    return show


def simulate_file(path: str, periods: float = 5.0, fmt: str = "text", csv: str | None = None,
                  plot: str | None = None, force: bool = False,
                  progress: Callable[[float], None] | None = None) -> str:
    """The whole command: returns what to print; InputError on bad input."""
    from ..core.files import write_atomic

    if not (math.isfinite(periods) and periods > 0):
        raise InputError("--periods must be a positive number")
    check_outputs([csv, plot], force)
    setup = prepare(path)
    sim = run(setup, periods, progress)
    report = comparison(setup, sim)
    outputs = {}
    if csv:
        write_atomic(csv, csv_text(sim), force=force)
        outputs["csv"] = str(csv)
    if plot:
        from ..render import plot as plots

        problem = setup.problem
        title = f"{problem.id}  {problem.title}".strip()
        data = plots.from_simulation(sim, title=title, motion=report["simulated"]["motion"])
        plots.save(plots.with_rate_unit(data, problem), plot, force=force)
        outputs["plot"] = str(plot)
    report["outputs"] = outputs
    if fmt == "json":
        return json.dumps(_clean(report), allow_nan=False, default=_json_default) + "\n"
    return text(report, periods)


def _clean(value):
    """Non-finite numbers become null (JSON has no NaN); numpy scalars become floats."""
    if isinstance(value, dict):
        return {k: _clean(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_clean(v) for v in value]
    if hasattr(value, "item") and not isinstance(value, (str, bytes)):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def _json_default(value):
    import numpy as np

    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"not JSON: {type(value).__name__}")
