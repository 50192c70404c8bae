"""The heavy symmetric top integrated from the full equations of motion.

Independent of the analytic path (``nutation.py``): no Euler-angle equation and no
momentum integral is used to move the top. The state is

    y = (q_w, q_x, q_y, q_z, omega_x, omega_y, omega_z)

with q a quaternion for the attitude (body axes -> fixed axes; no gimbal lock at
theta = 0) and omega the angular velocity in body axes (principal axes at the fixed
point, inertias I, I, J; Eq. 11.9). The equations are

    q' = q (x) (0, omega) / 2                                   (attitude kinematics)
    I omega_x' = (I - J) omega_y omega_z + m g l K_y            (Euler's equations,
    I omega_y' = (J - I) omega_z omega_x - m g l K_x             gravity torque
    J omega_z' = 0                                               l k x (-m g K))

where K = (K_x, K_y, K_z) is the upward vertical in body axes. K is computed from q
with the homogeneous (norm-free) rotation formula, so the flow is exact for any
non-zero q: the norm of q, an invariant of the exact flow, is never forced back
inside the right-hand side; q is normalised only when angles are read out.

Initial conditions come from Eqs. 11.5-11.8 (z-x-z Euler angles, phi = psi = 0):
q = rotation by theta0 about x, omega = (thetadot0, phidot0 sin theta0,
psidot0 + phidot0 cos theta0). The chapter's invariants are measured along the way:
energy T + V (Eqs. 11.10, 11.11, 11.17), P1 = p_phi = H . K (vertical component of
H) and P2 = p_psi = J omega_z (axial component of H), Eq. 11.14.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np

RTOL = 1e-12
STEADY_AMPLITUDE = 1e-9   # rad: a theta range below this is no measurable nutation
MAX_STEPS = 1_000_000     # about a minute of CPU; beyond it a run is refused, not started
STEPS_PER_TURN = 30       # DOP853 at rtol 1e-12 takes about this many steps per turn of the body
TOO_SHORT = "too short to classify"   # motion_of a run that saw too few theta extrema


class TopLike(Protocol):
    """Anything with the top's inertias about the fixed point and m g l (SI)."""

    I: float
    J: float
    mgl: float


class StartLike(Protocol):
    """Initial theta, spin psidot, precession phidot and thetadot (SI)."""

    theta0: float
    spin: float
    precession0: float
    theta_rate0: float


@dataclass(frozen=True)
class Params:
    """Plain floats for the integrator: a top and how it starts."""

    I: float
    J: float
    mgl: float
    theta0: float
    spin: float
    precession0: float = 0.0
    theta_rate0: float = 0.0


@dataclass
class Simulation:
    """The integrated motion: a time series, the invariants and what was measured.

    Angles in rad, rates in rad/s. Drifts are max |X(t) - X(0)| over every
    integrator step, divided by a scale: energy by T0 + |m g l| (the energy can
    pass through zero), P1 and P2 by |H0|, the magnitude of the angular momentum.
    ``energy_drift_varying`` divides the same energy error by the part of the energy
    that varies, max over the run of I (omega_x^2 + omega_y^2) / 2 plus |m g l|: the
    spin energy J omega_z^2 / 2 is constant (J omega_z' = 0) and, for a fast top,
    would otherwise make any error look small.

    ``mean_precession`` is taken over whole nutation periods only (between the first
    and last extremum of one kind); it is None when theta varies but the run holds no
    whole period. Without nutation it is the advance of phi over the run / its time.
    """

    params: Params
    t: np.ndarray
    theta: np.ndarray
    phi: np.ndarray
    psi: np.ndarray
    theta_rate: np.ndarray
    phidot: np.ndarray
    psidot: np.ndarray
    energy0: float
    P1: float
    P2: float
    energy_drift: float
    energy_drift_varying: float  # the same error relative to the energy that varies
    P1_drift: float
    P2_drift: float
    norm_drift: float            # max | |q| - 1 |
    t_theta_min: np.ndarray      # times of the theta minima (thetadot = 0, root-refined)
    t_theta_max: np.ndarray
    theta_min: float             # smallest theta reached (at the minima, or in the series)
    theta_max: float
    phidot_at_min: np.ndarray    # phidot at each theta minimum (cusps: 0 there)
    phidot_at_max: np.ndarray
    theta_at_min: np.ndarray     # theta at each minimum (root-refined)
    theta_at_max: np.ndarray
    nutation_period: float | None
    mean_precession: float | None
    precession_resolved: bool    # False when the axis passes too near the vertical to unwrap phi
    steps: int
    nfev: int
    cpu_seconds: float
    notes: list[str] = field(default_factory=list)

    @property
    def nutates(self) -> bool:
        return self.nutation_period is not None

    @property
    def theta_varies(self) -> bool:
        """theta changes by more than STEADY_AMPLITUDE over the run."""
        return self.theta_max - self.theta_min > STEADY_AMPLITUDE


# ---- the equations of motion ------------------------------------------------

def initial_state(p: Params) -> list[float]:
    """q and body omega at t = 0 from (theta0, psidot0, phidot0, thetadot0), Eqs. 11.5-11.8."""
    half = 0.5 * p.theta0
    omega_x = p.theta_rate0                                  # psi = 0 in Eq. 11.8
    omega_y = p.precession0 * math.sin(p.theta0)
    omega_z = p.spin + p.precession0 * math.cos(p.theta0)
    return [math.cos(half), math.sin(half), 0.0, 0.0, omega_x, omega_y, omega_z]


def make_rhs(p: Params) -> Callable[[float, np.ndarray], list[float]]:
    """The right-hand side on plain floats (faster than numpy for 7 numbers)."""
    a = (p.I - p.J) / p.I
    b = p.mgl / p.I

    def rhs(t: float, y: np.ndarray) -> list[float]:
        w, x, yy, z, ox, oy, oz = y.tolist()
        n2 = w * w + x * x + yy * yy + z * z
        kx = 2.0 * (x * z - w * yy) / n2        # upward vertical in body axes
        ky = 2.0 * (yy * z + w * x) / n2
        return [
            -0.5 * (x * ox + yy * oy + z * oz),
            0.5 * (w * ox + yy * oz - z * oy),
            0.5 * (w * oy + z * ox - x * oz),
            0.5 * (w * oz + x * oy - yy * ox),
            a * oy * oz + b * ky,
            -a * oz * ox - b * kx,
            0.0,
        ]

    return rhs


def vertical_in_body(y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """K = (K_x, K_y, K_z) in body axes from rows of states (normalised quaternion)."""
    w, x, yy, z = y[..., 0], y[..., 1], y[..., 2], y[..., 3]
    n2 = w * w + x * x + yy * yy + z * z
    return (2 * (x * z - w * yy) / n2, 2 * (yy * z + w * x) / n2,
            (w * w + z * z - x * x - yy * yy) / n2)


def axis_in_space(y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The symmetry axis k in fixed axes: (sin th sin phi, -sin th cos phi, cos th)."""
    w, x, yy, z = y[..., 0], y[..., 1], y[..., 2], y[..., 3]
    n2 = w * w + x * x + yy * yy + z * z
    return (2 * (x * z + w * yy) / n2, 2 * (yy * z - w * x) / n2,
            (w * w + z * z - x * x - yy * yy) / n2)


def invariants(p: Params, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Energy T + V (Eqs. 11.10-11.11), P1 = H . K and P2 = J omega_z (Eq. 11.14)."""
    kx, ky, kz = vertical_in_body(y)
    ox, oy, oz = y[..., 4], y[..., 5], y[..., 6]
    energy = 0.5 * (p.I * (ox * ox + oy * oy) + p.J * oz * oz) + p.mgl * kz
    P1 = p.I * (ox * kx + oy * ky) + p.J * oz * kz
    P2 = p.J * oz
    return energy, P1, P2


def euler_angles(p: Params, y: np.ndarray) -> dict[str, np.ndarray]:
    """theta, phi (wrapped), psi (wrapped) and their rates from states (rows).

    theta = atan2(sqrt(K_x^2 + K_y^2), K_z); from K' = K x omega (K is fixed in
    space): sin th thetadot = K_y omega_x - K_x omega_y and sin^2 th phidot =
    K_x omega_x + K_y omega_y (Eq. 11.8 with K = (sin th sin psi, sin th cos psi,
    cos th)); psidot = omega_z - phidot cos th.
    """
    kx, ky, kz = vertical_in_body(y)
    sx, sy, _ = axis_in_space(y)
    ox, oy, oz = y[..., 4], y[..., 5], y[..., 6]
    s2 = kx * kx + ky * ky
    s = np.sqrt(s2)
    theta = np.arctan2(s, kz)
    with np.errstate(invalid="ignore", divide="ignore"):
        theta_rate = np.where(s > 0, (ky * ox - kx * oy) / np.where(s > 0, s, 1.0), 0.0)
        # on the vertical only phi + psi is defined: phidot = 0 there, psidot = omega_z
        phidot = np.where(s2 > 0, (kx * ox + ky * oy) / np.where(s2 > 0, s2, 1.0), 0.0)
    psidot = oz - phidot * kz
    # 0.0 - sy, not -sy: on the vertical sy = +0.0 and atan2(0, -0.0) would be pi
    return {"theta": theta, "phi": np.arctan2(sx, 0.0 - sy), "psi": np.arctan2(kx, ky),
            "theta_rate": theta_rate, "phidot": phidot, "psidot": psidot}


# ---- dense output of chosen steps, vectorised -----------------------------------

class _Dense:
    """DOP853's continuous extension on the steps where it was kept.

    Holds scipy's Dop853DenseOutput step data (t_old, h, y_old, F) and evaluates
    the same polynomial (Hairer's 7th-order extension) with numpy for many t at once.
    """

    def __init__(self, pieces: list) -> None:
        self.t_old = np.array([s.t_old for s in pieces])
        self.h = np.array([s.h for s in pieces])
        self.y_old = np.array([s.y_old for s in pieces])
        self.F = np.array([s.F for s in pieces])        # (steps, 7, n)

    def covers(self, t: np.ndarray) -> np.ndarray:
        """Whether each t lies in a kept step."""
        t = np.asarray(t, dtype=float)
        if not len(self.h):
            return np.zeros(t.shape, bool)
        k = np.clip(np.searchsorted(self.t_old, t, side="right") - 1, 0, len(self.h) - 1)
        return (t >= self.t_old[k]) & (t <= self.t_old[k] + self.h[k] * (1 + 1e-12))

    def __call__(self, t: np.ndarray) -> np.ndarray:
        """States (rows) at times t, each inside a kept step."""
        t = np.asarray(t, dtype=float)
        k = np.clip(np.searchsorted(self.t_old, t, side="right") - 1, 0, len(self.h) - 1)
        x = ((t - self.t_old[k]) / self.h[k])[:, None]
        F = self.F[k]
        y = np.zeros_like(self.y_old[k])
        last = F.shape[1] - 1
        for i in range(last, -1, -1):
            y += F[:, i, :]
            y *= x if (last - i) % 2 == 0 else 1 - x
        return y + self.y_old[k]


def _piece_at(piece, t: float) -> np.ndarray:
    """One step's dense output at one time (scalar brentq calls)."""
    x = (t - piece.t_old) / piece.h
    y = np.zeros_like(piece.y_old)
    for i, f in enumerate(reversed(piece.F)):
        y += f
        y *= x if i % 2 == 0 else 1 - x
    return y + piece.y_old


# ---- the simulation -----------------------------------------------------------

def as_params(top: TopLike, start: StartLike) -> Params:
    return Params(float(top.I), float(top.J), float(top.mgl), float(start.theta0),
                  float(start.spin), float(getattr(start, "precession0", 0.0)),
                  float(getattr(start, "theta_rate0", 0.0)))


def _slope(y: Sequence[float] | np.ndarray) -> float:
    """sin(theta) thetadot = K_y omega_x - K_x omega_y (its sign is thetadot's)."""
    w, x, yy, z, ox, oy = y[:6]
    return 2.0 * ((yy * z + w * x) * ox - (x * z - w * yy) * oy)


def _phi(y: Sequence[float] | np.ndarray) -> float:
    """phi from the axis in fixed axes (sin th sin phi, -sin th cos phi, cos th)."""
    w, x, yy, z = y[:4]
    return math.atan2(x * z + w * yy, w * x - yy * z)


def largest_rate(p: Params, theta_range: tuple[float, float] | None = None) -> float:
    """The largest |omega| over the whole motion, from the energy (Eqs. 11.10-11.11).

    J omega_z is constant (Euler's third equation), so T + V = E gives
    I (omega_x^2 + omega_y^2) / 2 = T_0 + m g l (cos(theta0) - cos(theta)): the
    transverse rate is largest where m g l cos(theta) is least over the theta the
    top reaches (the nutation bounds ``theta_range``; without them, 0 .. pi).
    """
    w = initial_state(p)[4:]
    lo, hi = theta_range if theta_range is not None else (0.0, math.pi)
    least_potential = min(p.mgl * math.cos(lo), p.mgl * math.cos(hi))
    transverse_sq = w[0] ** 2 + w[1] ** 2 + \
        max(0.0, 2 * (p.mgl * math.cos(p.theta0) - least_potential) / p.I)
    return math.sqrt(w[2] ** 2 + transverse_sq)


def estimated_steps(p: Params, t_end: float,
                    theta_range: tuple[float, float] | None = None) -> float:
    """Steps DOP853 will take to t_end: at most STEPS_PER_TURN per turn of the body at
    its largest angular speed over the motion (measured: 16,000 steps for 100 periods of
    the 11/3 top; 49 a period for a 60 rpm top that falls from 30 to 174 deg, where the
    starting |omega| alone predicted 12)."""
    return STEPS_PER_TURN * t_end * largest_rate(p, theta_range) / (2 * math.pi)


def simulate(top: TopLike, start: StartLike, t_end: float, samples: int = 2001,
             rtol: float = RTOL, progress: Callable[[float], None] | None = None,
             theta_range: tuple[float, float] | None = None) -> Simulation:
    """Integrate from t = 0 to t_end; ``samples`` evenly spaced output points.

    Steps with DOP853 (scipy's stepper, driven here so the continuous extension,
    three extra evaluations a step, is built only for steps that hold an output
    time, a sign change of thetadot or a large turn of phi). ``progress(fraction)``
    is called about 100 times along the way. ``theta_range`` (the nutation bounds, when
    known) sharpens the estimate of the cost, which is refused before starting when it
    exceeds MAX_STEPS.
    """
    from scipy.integrate import DOP853
    from scipy.optimize import brentq

    p = as_params(top, start)
    _check(p, t_end, samples)
    needed = estimated_steps(p, t_end, theta_range)
    if needed > MAX_STEPS:
        raise ValueError(f"this run needs about {needed:.2g} integration steps, more than "
                         f"{MAX_STEPS:,}: the "
                         f"body turns up to {needed / STEPS_PER_TURN:.3g} times in it, at up "
                         f"to {largest_rate(p, theta_range):.4g} rad/s; simulate at most "
                         f"{MAX_STEPS / needed * t_end:.3g} s (fewer --periods)")
    clock = time.process_time()
    y0 = initial_state(p)
    rate_scale = max(abs(v) for v in y0[4:]) or 1.0
    atol = rtol * 1e-2 * np.array([1.0] * 4 + [rate_scale] * 3)
    solver = DOP853(make_rhs(p), 0.0, np.array(y0), t_end, rtol=rtol, atol=atol)
    t_out = np.linspace(0.0, t_end, samples)
    node_t, node_y = [0.0], [y0]
    pieces: list[Any] = []                   # scipy's step dense outputs, kept
    brackets: list[tuple[int, bool]] = []    # (piece, theta was decreasing: a minimum)
    j, next_report = 0, 0.01
    slope_old, phi_old = _slope(y0), _phi(y0)
    while solver.status == "running":
        if len(node_t) > 2 * MAX_STEPS:  # a backstop: the estimate was far off
            raise RuntimeError(f"more than {2 * MAX_STEPS:,} steps by t = {solver.t:.6g} s")
        message = solver.step()
        if solver.status == "failed":
            raise RuntimeError(f"integration failed at t = {solver.t:.6g} s: {message}")
        y = solver.y.tolist()
        slope, phi = _slope(y), _phi(y)
        keep = False
        while j < samples and t_out[j] <= solver.t:
            keep, j = True, j + 1
        if slope * slope_old < 0:
            keep = True
            brackets.append((len(pieces), slope_old < 0))
        if abs(math.remainder(phi - phi_old, 2 * math.pi)) > 1.0:
            keep = True
        if keep:
            pieces.append(solver.dense_output())
        node_t.append(solver.t)
        node_y.append(y)
        slope_old, phi_old = slope, phi
        if progress and solver.t >= next_report * t_end:
            progress(min(1.0, solver.t / t_end))
            next_report = solver.t / t_end + 0.01
    if progress:
        progress(1.0)
    nfev = solver.nfev
    dense = _Dense(pieces)
    nodes = np.array(node_y)
    times = np.array(node_t)

    energy, P1, P2 = invariants(p, nodes)
    T0 = energy[0] - p.mgl * vertical_in_body(nodes[:1])[2][0]
    H0 = math.sqrt(p.I ** 2 * (y0[4] ** 2 + y0[5] ** 2) + (p.J * y0[6]) ** 2)
    energy_scale = T0 + abs(p.mgl) or 1.0
    transverse = 0.5 * p.I * (nodes[:, 4] ** 2 + nodes[:, 5] ** 2)
    varying_scale = float(transverse.max()) + abs(p.mgl) or 1.0
    H_scale = H0 or 1.0
    norm = np.sqrt(np.sum(nodes[:, :4] ** 2, axis=1))

    kx, ky, kz = vertical_in_body(nodes)
    theta_nodes = np.arctan2(np.hypot(kx, ky), kz)
    amplitude = float(theta_nodes.max() - theta_nodes.min())
    notes: list[str] = []
    mins: list[float] = []
    maxs: list[float] = []
    if amplitude > STEADY_AMPLITUDE:
        for k, decreasing in brackets:
            piece = pieces[k]
            root = brentq(lambda t: _slope(_piece_at(piece, t)), piece.t_old, piece.t,  # noqa: B023 (called in this iteration)
                          xtol=1e-15 * max(1.0, abs(piece.t)), rtol=4 * np.finfo(float).eps)
            (mins if decreasing else maxs).append(root)
    if p.theta_rate0 == 0.0 and amplitude > STEADY_AMPLITUDE:
        # released with thetadot = 0: t = 0 is itself an extremum (no sign change brackets
        # it), a minimum if theta first grows; theta is monotonic up to the first extremum
        moved = theta_nodes[np.abs(theta_nodes - theta_nodes[0]) > 0.5 * STEADY_AMPLITUDE]
        (mins if moved[0] > theta_nodes[0] else maxs).insert(0, 0.0)
    t_min, t_max = np.array(mins), np.array(maxs)

    at_ext = {name: (euler_angles(p, dense(ts)) if len(ts) else
                     {"theta": np.array([]), "phidot": np.array([])})
              for name, ts in (("min", t_min), ("max", t_max))}
    theta_ext = {name: at_ext[name]["theta"] for name in at_ext}
    theta_min = float(min(theta_ext["min"].min(initial=np.inf), theta_nodes.min()))
    theta_max = float(max(theta_ext["max"].max(initial=-np.inf), theta_nodes.max()))

    periods = [(ts[-1] - ts[0]) / (len(ts) - 1) for ts in (t_min, t_max) if len(ts) >= 2]
    period = float(np.mean(periods)) if periods else None
    if period is None and amplitude > STEADY_AMPLITUDE:
        notes.append("fewer than two theta extrema of one kind: integrate longer to measure "
                     "the nutation period")

    # phi followed through every step node, the extrema and the output times
    extra = np.concatenate([t_out, t_min, t_max])
    all_t = np.concatenate([times, extra])
    all_y = np.vstack([nodes, dense(extra)]) if len(extra) else nodes
    order = np.argsort(all_t, kind="stable")
    all_t, all_y = all_t[order], all_y[order]
    phi_all, resolved = _unwrap_phi(p, dense, all_t, all_y)
    if period is not None and theta_min < 1e-6:
        notes.append("the axis passes through the vertical (P1 = P2, Eq. 11.14): phi is "
                     "undefined there and jumps by 180 deg")
    elif not resolved and theta_max > 1e-9:
        notes.append("the axis passes too near the vertical for phi to be followed: the mean "
                     "precession is not reliable")

    def phi_at(t: np.ndarray) -> np.ndarray:
        return phi_all[np.searchsorted(all_t, t)]

    # mean precession: phi advance over whole nutation periods / their time, never a part
    mean_precession: float | None = None
    if period is not None:
        ts = t_max if len(t_max) >= 2 else t_min
        a, b = float(ts[0]), float(ts[-1])
        notes.append(f"means over whole periods only: the mean precession is the advance of phi "
                     f"over {len(ts) - 1} whole nutation period{'s' * (len(ts) > 2)}, t = "
                     f"{a:.6g} .. {b:.6g} s")
    elif amplitude > STEADY_AMPLITUDE:
        a = b = 0.0
        notes.append("the run holds no whole nutation period: the mean precession is not "
                     "measured (means are taken over whole periods only); integrate longer")
    else:
        a, b = 0.0, float(t_end)
    if b > a:
        phi_a, phi_b = phi_at(np.array([a, b]))
        mean_precession = float((phi_b - phi_a) / (b - a))

    angles = euler_angles(p, dense(t_out))
    clock = time.process_time() - clock
    return Simulation(
        params=p, t=t_out, theta=angles["theta"], phi=phi_at(t_out),
        psi=np.unwrap(angles["psi"]), theta_rate=angles["theta_rate"],
        phidot=angles["phidot"], psidot=angles["psidot"],
        energy0=float(energy[0]), P1=float(P1[0]), P2=float(P2[0]),
        energy_drift=float(np.max(np.abs(energy - energy[0]))) / energy_scale,
        energy_drift_varying=float(np.max(np.abs(energy - energy[0]))) / varying_scale,
        P1_drift=float(np.max(np.abs(P1 - P1[0]))) / H_scale,
        P2_drift=float(np.max(np.abs(P2 - P2[0]))) / H_scale,
        norm_drift=float(np.max(np.abs(norm - 1.0))),
        t_theta_min=t_min, t_theta_max=t_max, theta_min=theta_min, theta_max=theta_max,
        phidot_at_min=at_ext["min"]["phidot"], phidot_at_max=at_ext["max"]["phidot"],
        theta_at_min=theta_ext["min"], theta_at_max=theta_ext["max"],
        nutation_period=period, mean_precession=mean_precession,
        precession_resolved=resolved, steps=len(times) - 1, nfev=int(nfev),
        cpu_seconds=clock, notes=notes)


def _unwrap_phi(p: Params, dense: _Dense, t: np.ndarray,
                y: np.ndarray) -> tuple[np.ndarray, bool]:
    """phi unwrapped along sorted times; a jump over 1 rad is subdivided on the
    dense output (kept for exactly those steps) until it is not ambiguous."""
    phi = euler_angles(p, y)["phi"]
    steps = np.angle(np.exp(1j * np.diff(phi)))
    resolved = True
    for i in np.nonzero(np.abs(steps) > 1.0)[0]:
        sub = np.linspace(t[i], t[i + 1], 2)
        for _ in range(8):
            sub = np.linspace(t[i], t[i + 1], 2 * len(sub) - 1)
            if not dense.covers(sub[1:-1]).all():
                resolved = False
                break
            inner = euler_angles(p, dense(sub[1:-1]))["phi"]
            path = np.concatenate([[phi[i]], inner, [phi[i + 1]]])
            jumps = np.angle(np.exp(1j * np.diff(path)))
            if np.abs(jumps).max() <= 1.0:
                steps[i] = jumps.sum()
                break
        else:
            resolved = False
    return np.concatenate([[phi[0]], phi[0] + np.cumsum(steps)]), resolved


def _check(p: Params, t_end: float, samples: int) -> None:
    for name in ("I", "J", "theta0", "spin", "precession0", "theta_rate0", "mgl"):
        if not math.isfinite(getattr(p, name)):
            raise ValueError(f"{name} must be a finite number")
    if p.I <= 0 or p.J <= 0:
        raise ValueError("I and J must be positive")
    if not (math.isfinite(t_end) and t_end > 0):
        raise ValueError("t_end must be positive")
    if samples < 2:
        raise ValueError("need at least 2 samples")


def motion_of(sim: Simulation, zero: float = 1e-6, shortest: float = 0.0) -> str:
    """The kind of path, read off the simulated motion (cf. Figs. 11-7 to 11-10).

    phidot = (P1 - P2 cos th) / (I sin^2 th) (Eq. 11.16) has a numerator linear in
    cos th, so its extreme signs over a nutation are those at theta_min and
    theta_max: opposite signs -> loops, zero at one of them -> cusps, one sign ->
    waves. No nutation: steady, or sleeping when the axis stays vertical.
    ``zero`` is relative to the largest |phidot| at the extrema.

    A run shorter than a nutation period is classified from the extrema it saw: one
    theta minimum and one maximum are enough (phidot's extreme signs are there). With
    extrema of one kind only, or none, theta's range is not known; phidot of both signs
    along the run still means loops, else the answer is TOO_SHORT. So is a constant
    theta over a run shorter than ``shortest`` (a time in which a nutation would have
    shown, such as 2 pi I / (J omega_z)): --periods 1e-6 sees no motion, not a steady one.
    """
    if sim.theta_max < 1e-9 or sim.theta_min > math.pi - 1e-9:
        return "sleeping"
    if not sim.theta_varies:
        return "steady" if float(sim.t[-1]) >= shortest else TOO_SHORT
    if not sim.nutates and not (len(sim.t_theta_min) and len(sim.t_theta_max)):
        off_vertical = (sim.theta > 1e-6) & (sim.theta < math.pi - 1e-6)
        rates = sim.phidot[off_vertical]
        scale = float(np.max(np.abs(rates))) if len(rates) else 0.0
        if scale and rates.min() < -1e-6 * scale and rates.max() > 1e-6 * scale:
            return "loops"
        return TOO_SHORT
    # on the vertical itself phi is undefined (the axis passes through the pole, P1 = P2):
    # phidot's sign is read at the other extreme
    ends = np.concatenate([sim.phidot_at_min[sim.theta_at_min > 1e-6],
                           sim.phidot_at_max[sim.theta_at_max < math.pi - 1e-6]])
    scale = float(np.max(np.abs(ends))) if len(ends) else 0.0
    if not scale:
        return "cusps" if len(ends) else "waves"
    lo, hi = float(ends.min()) / scale, float(ends.max()) / scale
    if min(abs(lo), abs(hi)) < zero:
        return "cusps"
    return "loops" if lo < 0 < hi else "waves"
