"""A disk (or hoop) rolling without slipping on a horizontal plane along a circle.

Two arrangements:

``axle_pivot`` (problem 11/6): the disk's axle is horizontal and pinned to the
vertical shaft at the height of the disk's centre; the shaft turns at Omega. With
k along the axle, outward from the shaft, and R the radius of the circle
(contact point directly below the centre), rolling gives the spin
psidot = -Omega R / r, and the angular momentum about the pin O,
H_O = J psidot k + I_O Omega K, changes at dH_O/dt = J psidot Omega n (n = K x k).
Moments about O of gravity (m g R) and of the normal force (-N R) give
N = m g + J Omega^2 / r. The pin takes the centripetal force, the plane none.

``free``: the disk rolls by itself, tilted by beta from the vertical toward the
centre of the circle. With rho the radius of the circle of the centre G, the
contact point's circle has radius R = rho + r sin(beta); rolling gives
omega_z = -v / r and the moment about G gives

    m g r sin(beta) = Omega^2 cos(beta) [rho (m r + J / r) + I_G sin(beta)],  v = Omega rho,

so tan(beta) -> (m r^2 + J) v^2 / (m g r^2 rho) for a large circle (3 v^2 / (2 g rho)
for a thin disk). Given two of path_radius, speed, tilt, the third follows.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..core.errors import InputError
from ..core.given import Given
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work, num, qty

RPM = 2 * math.pi / 60


# ---- physics on floats ------------------------------------------------------

def axle_pivot_spin(precession: float, path_radius: float, radius: float) -> float:
    """Rolling without slipping: psidot = -Omega R / r (about k, outward along the axle)."""
    return -precession * path_radius / radius


def axle_pivot_normal_force(m: float, g: float, J: float, precession: float,
                            radius: float) -> float:
    """N = m g + J Omega^2 / r (moments about the pin, Eq. 11.29 with psidot = -Omega R / r)."""
    return m * g + J * precession * precession / radius


@dataclass(frozen=True)
class FreeDisk:
    """Steady rolling on a circle, SI: tilt beta, centre circle rho, contact circle R, rates."""

    tilt: float
    centre_radius: float
    path_radius: float
    speed: float
    precession: float
    spin: float        # psidot, relative to the precessing frame, about k (outward-up normal)
    axial_rate: float  # omega_z = -v / r


def free_residual(m: float, g: float, r: float, J: float, I: float, tilt: float, rho: float,
                  speed: float) -> float:
    """m g r sin(b) rho^2 - v^2 cos(b) [rho (m r + J / r) + I sin(b)]: zero in steady rolling."""
    s, c = math.sin(tilt), math.cos(tilt)
    return m * g * r * s * rho * rho - speed * speed * c * (rho * (m * r + J / r) + I * s)


def free_state(m: float, r: float, tilt: float, rho: float, speed: float) -> FreeDisk:
    """The rates of a steady motion from tilt, centre circle and speed."""
    precession = speed / rho
    R = rho + r * math.sin(tilt)
    return FreeDisk(tilt, rho, R, speed, precession, -precession * R / r, -speed / r)


def free_from_tilt_and_path(m: float, g: float, r: float, J: float, I: float, tilt: float,
                            path_radius: float) -> FreeDisk | None:
    """Speed for a given tilt and contact circle; None if rho <= 0."""
    rho = path_radius - r * math.sin(tilt)
    if rho <= 0:
        return None
    s, c = math.sin(tilt), math.cos(tilt)
    precession_sq = m * g * r * s / (c * (rho * (m * r + J / r) + I * s))
    return free_state(m, r, tilt, rho, math.sqrt(precession_sq) * rho)


def free_from_speed_and_tilt(m: float, g: float, r: float, J: float, I: float, tilt: float,
                             speed: float) -> FreeDisk:
    """Centre circle for a given speed and tilt: the positive root of a quadratic in rho."""
    s, c = math.sin(tilt), math.cos(tilt)
    a, b, cc = m * g * r * s, -speed * speed * c * (m * r + J / r), -speed * speed * c * I * s
    rho = (-b + math.sqrt(b * b - 4 * a * cc)) / (2 * a)
    return free_state(m, r, tilt, rho, speed)


def free_from_speed_and_path(m: float, g: float, r: float, J: float, I: float, speed: float,
                             path_radius: float) -> list[FreeDisk]:
    """Every tilt in (0, 90 deg) with rho > 0 for a given speed and contact circle.

    The residual of ``free_residual`` is scanned on a grid and each change of sign
    bisected. It is written out here with its constant factors taken out (the same
    operations in the same order, so the same floats as ``free_residual``): the scan is
    most of the time a rolling-disk problem takes.
    """
    top = math.pi / 2 if path_radius >= r else math.asin(path_radius / r)
    mgr, v2, inertia = m * g * r, speed * speed, m * r + J / r
    sin, cos = math.sin, math.cos

    def f(tilt: float) -> float:
        s = sin(tilt)
        rho = path_radius - r * s
        return mgr * s * rho * rho - v2 * cos(tilt) * (rho * inertia + I * s)

    n = 4000
    # evenly in tilt, and geometrically below the first step (a nearly upright disk on a
    # large circle tilts by less than 0.02 deg: tan(beta) ~ 3 v^2 / (2 g rho) for a disk)
    fine = [top / n * 10 ** (-k / 8) for k in range(96, 0, -1)]
    grid = fine + [top * i / n for i in range(1, n)]
    roots = []
    for k in _sign_changes(grid, f, mgr, v2, inertia, I, path_radius, r):
        f0 = f(grid[k])
        if f0 == 0:
            roots.append(grid[k])
        elif f0 * f(grid[k + 1]) < 0:
            lo, hi, flo = grid[k], grid[k + 1], f0
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                fm = f(mid)
                if (fm < 0) == (flo < 0):
                    lo, flo = mid, fm
                else:
                    hi = mid
                if hi - lo < 1e-15:
                    break
            roots.append(0.5 * (lo + hi))
    return [free_state(m, r, t, path_radius - r * math.sin(t), speed) for t in roots]


def _sign_changes(grid: list[float], f, mgr: float, v2: float, inertia: float, I: float,  # type: ignore[no-untyped-def]
                  path_radius: float, r: float) -> list[int]:
    """Every k where ``f`` may be 0 at grid[k] or change sign from grid[k] to grid[k + 1]
    (the caller decides each with ``f``, as the scan point by point did).

    The residual is evaluated over the whole grid at once (numpy: the same operations in
    the same order; only sin and cos may round differently, by an ulp). Where a value is
    so near 0 that such a difference could flip its sign, it is evaluated again with
    ``f``, so every sign, and every exact 0, is the one ``f`` gives.
    """
    import numpy as np

    t = np.array(grid)
    s, c = np.sin(t), np.cos(t)
    rho = path_radius - r * s
    first = mgr * s * rho * rho
    second = v2 * c * (rho * inertia + I * s)
    values = first - second
    doubtful = np.abs(values) <= 1e-9 * (np.abs(first) + np.abs(second))
    doubtful |= ~np.isfinite(values)
    for k in np.flatnonzero(doubtful).tolist():
        values[k] = f(grid[k])
    # every k that may hold a root: the caller decides each with f, as the scan did
    negative = values < 0
    changes = (values[:-1] == 0) | (negative[:-1] != negative[1:])
    return np.flatnonzero(changes).tolist()


# ---- the worked answer ------------------------------------------------------

def solve(given: Given, find: frozenset[str], work: Work) -> None:
    arrangement = given.word("arrangement", "axle_pivot")
    body = given.body
    body.require("J", "radius")
    if arrangement == "axle_pivot":
        asked = sorted(find & {"stability", "growth_rate", "upright_speed"})
        if asked:
            raise InputError(f"{asked[0]} is answered for `arrangement: free`; the pinned "
                             "axle's motion is imposed by the shaft", key=f"find.{asked[0]}")
        _axle_pivot(given, find, work)
    else:
        body.require("I_cg")
        _free(given, find, work)


def _axle_pivot(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.body
    for key in ("tilt", "speed"):
        if key in given:
            raise InputError(f"{key} belongs to `arrangement: free`; the pinned axle is "
                             "horizontal and turns at `precession`", key=f"given.{key}")
    m, g, J, r = body.m, body.g, body.J, body.radius
    Omega, R = given["precession"], given["path_radius"]
    if R <= 0:
        raise InputError(f"path_radius must be positive, got {num(R)} m: with the disk's centre "
                         "on the shaft the moments about the pin do not fix the normal force",
                         key="given.path_radius")
    work.section("Conventions (axle pinned to the shaft at the height of the disk's centre)")
    work.text("K: upward vertical, Omega positive counter-clockwise seen from above; k: along "
              "the axle, from the pin O outward to the disk; n = K x k, horizontal, the way the "
              "disk's centre moves when Omega > 0. The contact point is directly below the "
              "centre, at R from the shaft.")
    work.section("Rolling without slipping: v_contact = Omega R n + psidot r n = 0")
    spin = work.step("psidot", "-Omega R / r", f"-{qty(Omega, 'rad/s')} {qty(R, 'm')} / "
                     f"{qty(r, 'm')}", axle_pivot_spin(Omega, R, r), "rad/s")
    work.text("negative: seen from outside the disk (looking along -k toward the shaft) the "
              "disk turns clockwise when Omega is counter-clockwise from above")
    work.section("Moments about the pin O: dH_O/dt = Omega K x (J psidot k + I_O Omega K) "
                 "= J psidot Omega n (Eq. 11.29)")
    work.text("H_O = J psidot k + I_O Omega K: the angular momentum about the pin O, where I_O "
              "is the disk's moment of inertia about the vertical through O")
    dH = work.step("dH_O/dt", "J psidot Omega", f"{qty(J, 'kg*m^2')} ({qty(spin, 'rad/s')}) "
                   f"({qty(Omega, 'rad/s')})", J * spin * Omega, "N*m", note="along n")
    work.text("about n: gravity m g R (+), the plane's normal force N gives -N R; the pin force "
              "passes through O "
              "and the plane is taken to give no radial friction (the pin holds the disk on "
              "its circle)")
    work.text("m g R - N R = J psidot Omega = -J Omega^2 R / r")
    N = work.step("N", "m g + J Omega^2 / r", f"{qty(m, 'kg')} ({qty(g, 'm/s^2')}) + "
                  f"{qty(J, 'kg*m^2')} ({qty(Omega, 'rad/s')})^2 / {qty(r, 'm')}",
                  axle_pivot_normal_force(m, g, J, Omega, r), "N")
    moment = work.step("M", "(N - m g) R = J Omega^2 R / r", f"({qty(N, 'N')} - "
                       f"{qty(m * g, 'N')}) {qty(R, 'm')}", (N - m * g) * R, "N*m",
                       note="net moment of gravity and the normal force about O, positive "
                            "lifting the disk's outer side (it equals -dH_O/dt along n)")
    work.answer("normal_force", "N", [N], "force")
    work.answer("spin", "psidot", [spin], "rate")
    work.answer("moment", "M", [moment], "moment")
    if "precession_period" in find:
        _lap_time([Omega], work)
    work.check(f"moments about O along n: m g R - N R = {qty(m * g * R - N * R, 'N m')}; "
               f"dH_O/dt = {qty(dH, 'N m')}")


def _lap_time(rates: list[float], work: Work) -> None:
    """The time for one lap of the circle: the disk turns once about the vertical."""
    if any(rate == 0 for rate in rates):
        raise InputError("the precession is 0: the disk never completes a lap",
                         key="find.precession_period")
    work.section("Time for one lap of the circle")
    periods = [work.step("T", "2 pi / |Omega|", f"2 pi / {qty(abs(rate), 'rad/s')}",
                         2 * math.pi / abs(rate), "s") for rate in rates]
    work.answer("precession_period", "T", periods, "time")


def _free(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.body
    if "precession" in given:
        raise InputError("for `arrangement: free` give two of path_radius, speed and tilt",
                         key="given.precession")
    # J, I_G and m are all proportional to the mass where it is not given: the rates cancel it
    m, g, J, I, r = body.mass_for_rates, body.g, body.J, body.I_cg, body.radius
    known = [k for k in ("path_radius", "speed", "tilt") if k in given]
    if len(known) != 2:
        raise InputError(f"give exactly two of path_radius, speed and tilt (got "
                         f"{', '.join(known) or 'none'})",
                         key=f"given.{known[2] if len(known) == 3 else 'tilt'}")
    for key in known:
        if given[key] <= 0:
            raise InputError(f"{key} must be positive", key=f"given.{key}")
    if "tilt" in given and given["tilt"] >= math.pi / 2:
        raise InputError("tilt must be less than 90 deg (the disk would lie flat)",
                         key="given.tilt")
    work.section("Conventions (disk rolling by itself)")
    work.text("beta: tilt of the disk's plane from the vertical, leaning toward the centre of "
              "the circle; rho: radius of the circle of the centre G; R = rho + r sin(beta): "
              "radius of the circle traced by the contact point (path_radius); Omega: the rate at "
              "which the disk turns about the vertical; v = Omega rho: speed of G. k: the "
              "disk's axis, pointing outward and up; "
              "K: the upward vertical; H_G: the disk's angular momentum about G.")
    work.section("Steady rolling: rolling gives omega_z = -v / r; moments about G, "
                 "dH_G/dt = Omega K x H_G, with N = m g and friction m Omega^2 rho inward")
    work.text("m g r sin(beta) = Omega^2 cos(beta) [rho (m r + J / r) + I_G sin(beta)]")
    if known == ["path_radius", "tilt"] or known == ["tilt", "path_radius"]:
        states = [free_from_tilt_and_path(m, g, r, J, I, given["tilt"], given["path_radius"])]
        if states[0] is None:
            raise InputError(f"with tilt {num(math.degrees(given['tilt']))} deg the centre "
                             f"would be at rho = R - r sin(beta) = "
                             f"{num(given['path_radius'] - r * math.sin(given['tilt']))} m, not "
                             "outside the axis: no steady rolling on this circle (take a larger "
                             "path_radius or a smaller tilt)", key="given.path_radius")
        s = states[0]
        work.step("rho", "R - r sin(beta)", f"{qty(s.path_radius, 'm')} - {qty(r, 'm')} "
                  f"sin({num(math.degrees(s.tilt))} deg)", s.centre_radius, "m")
        work.step("Omega", "sqrt(m g r sin(beta) / (cos(beta) [rho (m r + J / r) + I_G "
                  "sin(beta)]))", value=s.precession, unit="rad/s")
        work.step("v", "Omega rho", value=s.speed, unit="m/s")
    elif "tilt" in given:
        s = free_from_speed_and_tilt(m, g, r, J, I, given["tilt"], given["speed"])
        states = [s]
        work.text("a quadratic in rho: m g r sin(beta) rho^2 - v^2 cos(beta) (m r + J / r) rho "
                  "- v^2 cos(beta) I_G sin(beta) = 0; one positive root")
        work.step("rho", "positive root", value=s.centre_radius, unit="m")
        work.step("R", "rho + r sin(beta)", value=s.path_radius, unit="m")
    else:
        states = free_from_speed_and_path(m, g, r, J, I, given["speed"], given["path_radius"])
        if not states:
            raise InputError(f"no tilt between 0 and 90 deg lets the disk roll steadily at "
                             f"{qty(given['speed'], 'm/s')} on a contact circle of "
                             f"{qty(given['path_radius'], 'm')} (no real root with the centre "
                             "outside the axis)", key="given.speed")
        work.text("solved for beta (every root in 0 < beta < 90 deg with rho > 0)")
        for s in states:
            work.step("beta", value=math.degrees(s.tilt), unit="deg",
                      note=f"rho = {qty(s.centre_radius, 'm')}, Omega = "
                           f"{qty(s.precession, 'rad/s')}")
    for s in states:
        work.step("omega_z", "-v / r", f"-{qty(s.speed, 'm/s')} / {qty(r, 'm')}", s.axial_rate,
                  "rad/s", note="rolling")
        work.step("psidot", "-Omega R / r", value=s.spin, unit="rad/s",
                  note="spin relative to the precessing frame")
        work.check(f"beta = {num(math.degrees(s.tilt))} deg: residual of the moment equation "
                   f"{free_residual(m, g, r, J, I, s.tilt, s.centre_radius, s.speed):.3g} "
                   "(kg m^4/s^2)")
    work.answer("tilt", "beta", [s.tilt for s in states], "angle")
    work.answer("path_radius", "R", [s.path_radius for s in states], "length")
    work.answer("speed", "v", [s.speed for s in states], "speed")
    work.answer("precession", "Omega", [s.precession for s in states], "rate")
    work.answer("spin", "psidot", [s.spin for s in states], "rate")
    if "precession_period" in find:
        _lap_time([st.precession for st in states], work)
    if body.per_kg and "normal_force" in find:
        raise InputError("the normal force depends on the mass, which the rates do not need: "
                         "give mass or weight", key="given.mass")
    if not body.per_kg:
        work.answer("normal_force", "N", [m * g for _ in states], "force")
    try:
        _stability(m, g, r, J, I, states, work)
    except ArithmeticError:
        if find & {"stability", "growth_rate", "upright_speed"}:
            raise
        work.text("stability not worked: the linearised equations overflow in double "
                  "precision for these data")


def _stability(m: float, g: float, r: float, J: float, I: float, states: list[FreeDisk],
               work: Work) -> None:
    """Each steady state's stability: tilt perturbed, linearised (physics/stability.py)."""
    from ..physics.stability import UNSTABLE, disk_critical_axial_rate, disk_rolling

    work.section("Stability: small changes of the tilt, linearised rolling equations "
                 "(betadot'' + k betadot = 0)")
    work.text("I_G (I_G + m r^2) k = J (J + m r^2) omega_z^2 - I_G (3 J + m r^2) Omega omega_z "
              "sin(beta) + I_G^2 Omega^2 (1 + 2 sin^2(beta)) + I_G m r^2 Omega^2 cos^2(beta) - "
              "I_G m g r cos(beta); k > 0 stable (the tilt wobbles at sqrt(k)), k < 0 unstable "
              "(it grows as exp(sigma t), with the growth rate sigma = sqrt(-k); sigma = 0 when "
              "stable)")
    words, rates = [], []
    for s in states:
        if not all(map(math.isfinite, (s.centre_radius, s.precession, s.spin, s.axial_rate))):
            raise OverflowError("the steady state itself overflows")
        verdict = disk_rolling(m, g, r, I, J, s.tilt, s.precession, s.axial_rate)
        detail = (f"wobbles at sqrt(k) = {qty(verdict.frequency, 'rad/s')}" if verdict.frequency
                  else f"grows at sigma = sqrt(-k) = {qty(verdict.growth_rate, '1/s')}"
                  if verdict.growth_rate else "neutral to first order")
        work.step("k", value=verdict.k, unit="1/s^2",
                  note=f"beta = {num(math.degrees(s.tilt))} deg: {verdict.word}, {detail}")
        if verdict.word == UNSTABLE:
            work.warn(f"steady rolling at beta = {num(math.degrees(s.tilt))} deg, v = "
                      f"{qty(s.speed, 'm/s')} is unstable: a small disturbance of the tilt grows "
                      f"as exp({num(verdict.growth_rate)} t / s), doubling every "
                      f"{qty(math.log(2) / verdict.growth_rate, 's')}")
        words.append(verdict.word)
        rates.append(verdict.growth_rate)
    upright = work.step("v_upright", "r sqrt(m g r I_G / (J (J + m r^2)))",
                        f"{qty(r, 'm')} sqrt(({qty(m, 'kg')}) ({qty(g, 'm/s^2')}) ({qty(r, 'm')})"
                        f" ({qty(I, 'kg*m^2')}) / (({qty(J, 'kg*m^2')}) ({qty(J + m * r * r, 'kg*m^2')})))",
                        disk_critical_axial_rate(m, g, r, I, J) * r, "m/s",
                        note="upright rolling in a straight line (beta = 0, Omega = 0) is "
                             "stable above this speed (k > 0)")
    work.answer("stability", "stability", words, None)
    work.answer("growth_rate", "sigma", rates, "rate")
    work.answer("upright_speed", "v_upright", [upright], "speed")


KIND = Kind(
    name="rolling_disk",
    summary="disk or hoop rolling without slipping on a circle (axle pinned to a shaft, or free "
            "and tilted)",
    chapter="Eqs. 11.27-11.29 with rolling; dH/dt = Omega K x H",
    params=(
        Param("arrangement", "word", "arrangement", "axle_pivot (default; problem 11/6) or free",
              choices=("axle_pivot", "free")),
        Param("precession", "rate", "Omega", "rate of the shaft about the vertical (axle_pivot)"),
        Param("path_radius", "length", "R", "radius of the circle traced by the contact point"),
        Param("speed", "speed", "v", "speed of the disk's centre (free)"),
        Param("tilt", "angle", "beta", "tilt of the disk's plane from the vertical, toward the "
              "circle's centre (free)"),
    ),
    answers=(
        AnswerSpec("normal_force", "force", "N", "normal force of the plane on the disk"),
        AnswerSpec("spin", "rate", "psidot", "spin relative to the precessing frame (axle_pivot: "
                   "about the axle, outward positive)"),
        AnswerSpec("moment", "moment", "M", "axle_pivot: net moment of gravity and the normal "
                   "force about the pin, positive lifting the disk"),
        AnswerSpec("precession_period", "time", "T", "time for one lap of the circle, "
                   "2 pi / |Omega|"),
        AnswerSpec("tilt", "angle", "beta", "free: tilt from the vertical"),
        AnswerSpec("path_radius", "length", "R", "free: radius of the contact point's circle"),
        AnswerSpec("speed", "speed", "v", "free: speed of the centre"),
        AnswerSpec("precession", "rate", "Omega", "free: rate about the vertical, v / rho"),
        AnswerSpec("stability", None, "stability", "free: stable or unstable (tilt perturbed, "
                   "linearised rolling equations)"),
        AnswerSpec("growth_rate", "rate", "sigma", "free: growth rate of the unstable mode, 1/s (0 "
                   "when stable)"),
        AnswerSpec("upright_speed", "speed", "v_upright", "free: least speed at which upright "
                   "rolling in a straight line is stable"),
    ),
    solve=solve,
    extra={"example": {
        "given": {"arrangement": "axle_pivot", "weight": "96.6 lb", "shape": "disk",
                  "radius": "1 ft", "path_radius": "2 ft", "precession": "48 rpm"},
        "find": {"normal_force": "lbf", "spin": "rpm"},
        "vary": {"precession": "[0.8, 1.2]"}}},
)
