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

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass

from ..core.errors import InputError
from ..core.expr import NAMED, PI, Let, Sym, absolute, cos, exp, sin, sqrt
from ..core.given import Given
from ..core.prose import cross, deriv, names, prime, q, rel, tup
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work, num, qty

#: the symbols the prose names (values are in the steps' trees)
K0, k0, n0, O0, R0, W0, pd0, r0, J0, IO0, HO0, N0, m0, g0 = names(
    "K k n O R Omega psidot r J I_O H_O N m g")
b0, rho0, v0, G0, wz0, IG0, HG0, sig0, t0, bd0, vc0 = names(
    "beta rho v G omega_z I_G H_G sigma t betadot v_contact")

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

    grid = _scan_grid(top)
    roots = []
    if f(0.0) < 0 < f(grid[0]):  # a tilt below the grid's finest point: a huge circle
        roots.append(_tiny_tilt(f, grid[0]))
    for k in _sign_changes(grid, f, *_scan_bounds(mgr, v2, inertia, I, path_radius, r)):
        tk, tk1 = grid[k], grid[k + 1]
        f0 = f(tk)
        if f0 == 0:
            roots.append(tk)
        elif f0 * f(tk1) < 0:
            roots.append(_bisected(f, tk, tk1, f0))
    return [free_state(m, r, t, path_radius - r * math.sin(t), speed) for t in roots]


def _bisected(f: Callable[[float], float], lo: float, hi: float, flo: float) -> float:
    """The tilt in [lo, hi] where f changes sign (f(lo) = flo), by bisection: to 1e-15 rad,
    and on to 1e-9 of itself where the tilt is below a microradian (a circle of hundreds
    of kilometres, or slow rolling), so that every digit printed holds."""
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        if (fm < 0) == (flo < 0):
            lo, flo = mid, fm
        else:
            hi = mid
        if hi - lo < 1e-15 and hi - lo <= 1e-9 * hi:
            break
    return 0.5 * (lo + hi)


def _tiny_tilt(f: Callable[[float], float], below: float) -> float:
    """The tilt under ``below``, the grid's finest point, where f changes sign, f(0) < 0 <
    f(below): a contact circle so large that tan(beta) ~ 3 v^2 / (2 g rho) is under
    1e-15. The tilt is halved until f < 0, then bisected between there and its double."""
    hi, lo = below, below / 2
    while lo > 0 and not f(lo) < 0:
        hi, lo = lo, lo / 2
    return _bisected(f, lo, hi, f(lo))


SCAN_STEPS = 4000  # the scan's even steps in tilt, from 0 to the largest tilt
#: below the first even step, the grid goes on geometrically: the first step times these
SCAN_FINE = tuple(10 ** (-k / 8) for k in range(96, 0, -1))


@functools.lru_cache(maxsize=8)
def _scan_grid(top: float) -> tuple[float, ...]:
    """The tilts the scan may evaluate, ascending: evenly in tilt, top * i / n, and
    geometrically below the first step (a nearly upright disk on a large circle tilts by
    less than 0.02 deg: tan(beta) ~ 3 v^2 / (2 g rho) for a disk), top / n * 10^(-k/8).

    The grid depends on the largest tilt alone, 90 deg unless the contact circle is smaller
    than the disk, so it is made once and kept (a tuple: nothing can change it)."""
    n = SCAN_STEPS
    step = top / n
    return tuple([step * fine for fine in SCAN_FINE] + [top * i / n for i in range(1, n)])


def _scan_bounds(mgr: float, v2: float, inertia: float, I: float, path_radius: float,
                 r: float) -> tuple[Callable[[float], float], float]:
    """(slope, slack) for `_sign_changes`: ``slope(b)`` bounds |dF/dbeta| of the residual
    F = mgr s rho^2 - v^2 c (rho K + I s), rho = R - r s, K = ``inertia``, for tilts from
    0 to b (b <= 90 deg), and ``slack`` bounds the rounding error of F as computed.

    dF/dbeta = mgr c rho (rho - 2 r s) + v^2 s (rho K + I s) - v^2 c^2 (I - r K). Up to b,
    0 <= s <= S = min(b, 1) and c <= 1; rho = R - r s and rho - 2 r s = R - 3 r s are
    linear in s, so at most their larger size at s = 0 and s = S. Hence
    |dF/dbeta| <= |mgr| max(|R|, |R - r S|) max(|R|, |R - 3 r S|)
    + v^2 S (max(|R|, |R - r S|) |K| + |I| S) + v^2 |I - r K|. The rounding error of each
    term is a few ulps of |mgr| P^2 + v^2 (P |K| + |I|), P = |R| + r, the most either term
    can be; the slack allows 4500 ulps of it. Both are taken a little larger than computed
    (and I - r K a little larger than its rounded difference), so that their own rounding
    cannot make them too small."""
    R, K, mgr, I = path_radius, abs(inertia), abs(mgr), abs(I)
    twist = v2 * (abs(I - r * inertia) + 1e-12 * (I + r * K))

    def slope(b: float) -> float:
        S = min(b, 1.0)
        rho = max(abs(R), abs(R - r * S))
        return (mgr * rho * max(abs(R), abs(R - 3 * r * S)) + v2 * S * (rho * K + I * S)
                + twist) * (1 + 1e-9)

    P = abs(R) + r
    return slope, (mgr * P * P + v2 * (P * K + I)) * 1e-12


def _sign_changes(grid: tuple[float, ...], f: Callable[[float], float],
                  slope: Callable[[float], float], slack: float) -> list[int]:
    """Every k, ascending, where f(grid[k]) is 0 or the signs of f(grid[k]) and
    f(grid[k + 1]) may differ (the caller decides each with f), with f evaluated at as few
    points of the grid as the bounds allow: the answer of evaluating every point.

    A stretch of the grid from a to b is halved until f(a) and f(b) have the same sign
    and are too far from 0 for f to reach it in between: |f(a)| + |f(b)| > L (b - a) +
    4 slack, L = slope(b), a bound on |dF/dbeta| up to b. F cannot then change sign on
    [a, b] (|F| >= (|F(a)| + |F(b)| - L (b - a)) / 2 there, more than the rounding error
    ``slack``), and neither can f, as computed, at any point between. Near a root the
    halving goes down to neighbouring points; elsewhere a stretch of hundreds of points
    costs two values. A value that is not finite never ends a halving: such a stretch is
    evaluated point by point, as the whole grid was before.
    """
    known: dict[int, float] = {}

    def value(k: int) -> float:
        v = known.get(k)
        if v is None:
            v = known[k] = f(grid[k])
        return v

    isfinite = math.isfinite
    out: list[int] = []
    todo = [(0, len(grid) - 1)]
    while todo:
        a, b = todo.pop()
        fa, fb = value(a), value(b)
        if b == a + 1:
            if fa == 0 or (fa < 0) != (fb < 0):
                out.append(a)
            continue
        if fa != 0 and fb != 0 and (fa < 0) == (fb < 0) and isfinite(fa) and isfinite(fb) \
                and abs(fa) + abs(fb) > slope(grid[b]) * (grid[b] - grid[a]) + 4 * slack:
            continue
        mid = (a + b) // 2
        todo += ((mid, b), (a, mid))  # the lower half first: k ascending
    return out


# ---- the worked answer ------------------------------------------------------

def solve(given: Given, find: frozenset[str], work: Work) -> None:
    arrangement = given.word("arrangement", "axle_pivot")
    body = given.solid_body
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


# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's time in gyro check.
_AXLE_CONVENTIONS = (
    K0, ": upward vertical, ", W0, " positive counter-clockwise seen from above; ", k0,
    ": along the axle, from the pin ", O0, " outward to the disk; ",
    rel(n0, "=", cross(K0, k0)), ", horizontal, the way the disk's centre moves when ",
    rel(W0, ">", 0), ". The contact point is directly below the centre, at ", R0,
    " from the shaft.")
_ROLLING = ("Rolling without slipping: ", rel(vc0, "=", W0 * R0 * n0 + pd0 * r0 * n0, "=", 0))
_CLOCKWISE = ("negative: seen from outside the disk (looking along ", -k0, " toward the shaft) "
              "the disk turns clockwise when ", W0, " is counter-clockwise from above")
_H_O = J0 * pd0 * k0 + IO0 * W0 * K0
_MOMENTS_TITLE = ("Moments about the pin ", O0, ": ",
                  rel(deriv(HO0), "=", cross(W0 * K0, _H_O), "=", J0 * pd0 * W0 * n0),
                  " (Eq. 11.29)")
_H_O_LINE = (rel(HO0, "=", _H_O), ": the angular momentum about the pin ", O0, ", where ", IO0,
             " is the disk's moment of inertia about the vertical through ", O0)
_ALONG_N = ("along ", n0)
_ABOUT_N = ("about ", n0, ": gravity ", m0 * g0 * R0, " (+), the plane's normal force ", N0,
            " gives ", -N0 * R0, "; the pin force passes through ", O0, " and the plane is "
            "taken to give no radial friction (the pin holds the disk on its circle)")
_NET = m0 * g0 * R0 - N0 * R0
_BALANCE = (rel(_NET, "=", J0 * pd0 * W0, "=", -J0 * W0 ** 2 * R0 / r0),)
_NET_MOMENT = ("equal to ", J0 * W0 ** 2 * R0 / r0, "; the net moment of gravity and the normal "
               "force about ", O0, ", positive lifting the disk's outer side (it equals ",
               -deriv(HO0), " along ", n0, ")")
_DH_O = deriv(HO0)


def _axle_pivot(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.solid_body
    for key in ("tilt", "speed"):
        if key in given:
            raise InputError(f"{key} belongs to `arrangement: free`; the pinned axle is "
                             "horizontal and turns at `precession`", key=f"given.{key}")
    m, g, J, r = body.m, body.g, body.needed("J"), body.needed("radius")
    Omega, R = given["precession"], given["path_radius"]
    work.section("Conventions (axle pinned to the shaft at the height of the disk's centre)")
    work.text(*_AXLE_CONVENTIONS)
    Omega_, R_, r_ = Sym("Omega", Omega, "rad/s"), Sym("R", R, "m"), Sym("r", r, "m")
    m_, g_, J_ = Sym("m", m, "kg"), Sym("g", g, "m/s^2"), Sym("J", J, "kg m^2")
    work.section(*_ROLLING)
    spin = work.step("psidot", -Omega_ * R_ / r_, unit="rad/s")  # axle_pivot_spin
    work.text(*_CLOCKWISE)
    work.section(*_MOMENTS_TITLE)
    work.text(*_H_O_LINE)
    dH = work.step(_DH_O, J_ * Sym("psidot", spin, "rad/s") * Omega_, unit="N*m",
                   note=_ALONG_N)
    work.text(*_ABOUT_N)
    work.text(*_BALANCE)
    N = work.step("N", m_ * g_ + J_ * Omega_ ** 2 / r_, unit="N")  # axle_pivot_normal_force
    weight = Let(Sym("mg", m * g, "N"), Sym("m", NAMED) * Sym("g", NAMED))  # m g, shown by value
    moment = work.step("M", (Sym("N", N, "N") - weight) * R_, unit="N*m", note=_NET_MOMENT)
    work.answer("normal_force", "N", [N], "force")
    work.answer("spin", "psidot", [spin], "rate")
    work.answer("moment", "M", [moment], "moment")
    if "precession_period" in find:
        _lap_time([Omega], work)
    work.check("moments about ", O0, " along ", n0, ": ",
               rel(_NET, "=", q(m * g * R - N * R, "N m")), "; ", rel(_DH_O, "=", q(dH, "N m")))


def _lap_time(rates: list[float], work: Work) -> None:
    """The time for one lap of the circle: the disk turns once about the vertical."""
    if any(rate == 0 for rate in rates):
        raise InputError("the precession is 0: the disk never completes a lap",
                         key="find.precession_period")
    work.section("Time for one lap of the circle")
    periods = [work.step("T", 2 * PI / Let(Sym("abs_Omega", abs(rate), "rad/s"),
                                           absolute(Sym("Omega", NAMED))), unit="s")
               for rate in rates]
    work.answer("precession_period", "T", periods, "time")


_FREE_CONVENTIONS = (
    b0, ": tilt of the disk's plane from the vertical, leaning toward the centre of "
    "the circle; ", rho0, ": radius of the circle of the centre ", G0, "; ",
    rel(R0, "=", rho0 + r0 * sin(b0)), ": radius of the circle traced by the contact "
    "point (path_radius); ", W0, ": the rate at which the disk turns about the "
    "vertical; ", rel(v0, "=", W0 * rho0), ": speed of ", G0, ". ", k0, ": the disk's "
    "axis, pointing outward and up; ", K0, ": the upward vertical; ", HG0, ": the "
    "disk's angular momentum about ", G0, ".")
_STEADY_TITLE = ("Steady rolling: rolling gives ", rel(wz0, "=", -v0 / r0), "; moments about ",
                 G0, ", ", rel(deriv(HG0), "=", cross(W0 * K0, HG0)), ", with ",
                 rel(N0, "=", m0 * g0), " and friction ", m0 * W0 ** 2 * rho0, " inward")
_MOMENT_EQUATION = (rel(m0 * g0 * r0 * sin(b0), "=", W0 ** 2 * cos(b0) * (
    rho0 * (m0 * r0 + J0 / r0) + IG0 * sin(b0))),)
_QUADRATIC = ("a quadratic in ", rho0, ": ", rel(
    m0 * g0 * r0 * sin(b0) * rho0 ** 2 - v0 ** 2 * cos(b0) * (m0 * r0 + J0 / r0) * rho0
    - v0 ** 2 * cos(b0) * IG0 * sin(b0), "=", 0), "; one positive root")
_SOLVED_FOR = ("solved for ", b0, " (every root in ",
               rel(0, "<", b0, "<", q(math.pi / 2, "deg", exact=True)), " with ",
               rel(rho0, ">", 0), ")")


def _free(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.solid_body
    if "precession" in given:
        raise InputError("for `arrangement: free` give two of path_radius, speed and tilt",
                         key="given.precession")
    # J, I_G and m are all proportional to the mass where it is not given: the rates cancel it
    m, g = body.mass_for_rates, body.g
    J, I, r = body.needed("J"), body.needed("I_cg"), body.needed("radius")
    m_, g_, J_, r_ = Sym("m", m, "kg"), Sym("g", g, "m/s^2"), Sym("J", J, "kg m^2"), Sym("r", r, "m")
    I_ = Sym("I_G", I, "kg m^2")
    known = [k for k in ("path_radius", "speed", "tilt") if k in given]
    if len(known) != 2:
        raise InputError(f"give exactly two of path_radius, speed and tilt (got "
                         f"{', '.join(known) or 'none'})",
                         key=f"given.{known[2] if len(known) == 3 else 'tilt'}")
    work.section("Conventions (disk rolling by itself)")
    work.text(*_FREE_CONVENTIONS)
    work.section(*_STEADY_TITLE)
    work.text(*_MOMENT_EQUATION)
    if known == ["path_radius", "tilt"] or known == ["tilt", "path_radius"]:
        state = free_from_tilt_and_path(m, g, r, J, I, given["tilt"], given["path_radius"])
        if state is None:
            raise InputError(f"with tilt {num(math.degrees(given['tilt']))} deg the centre "
                             f"would be at rho = R - r sin(beta) = "
                             f"{num(given['path_radius'] - r * math.sin(given['tilt']))} m, not "
                             "outside the axis: no steady rolling on this circle (take a larger "
                             "path_radius or a smaller tilt)", key="given.path_radius")
        states = [s := state]
        beta, R_ = Sym("beta", s.tilt, "deg"), Sym("R", given["path_radius"], "m")
        rho_ = Sym("rho", work.step("rho", R_ - r_ * sin(beta), unit="m"), "m")
        # the moment equation solved for Omega (free_from_tilt_and_path)
        Omega = work.step("Omega", sqrt(m_ * g_ * r_ * sin(beta) / (cos(beta) * (
            rho_ * (m_ * r_ + J_ / r_) + I_ * sin(beta)))), unit="rad/s", substitute=False)
        work.step("v", Sym("Omega", Omega, "rad/s") * rho_, unit="m/s", substitute=False)
    elif "tilt" in given:
        s = free_from_speed_and_tilt(m, g, r, J, I, given["tilt"], given["speed"])
        states = [s]
        work.text(*_QUADRATIC)
        beta, v_ = Sym("beta", s.tilt, "deg"), Sym("v", given["speed"], "m/s")
        a = m_ * g_ * r_ * sin(beta)
        b = v_ ** 2 * cos(beta) * (m_ * r_ + J_ / r_)
        c = v_ ** 2 * cos(beta) * I_ * sin(beta)
        rho = work.step("rho", (b + sqrt(b ** 2 + 4 * a * c)) / (2 * a), unit="m",
                        substitute=False)
        work.step("R", Sym("rho", rho, "m") + r_ * sin(beta), unit="m", substitute=False)
    else:
        states = free_from_speed_and_path(m, g, r, J, I, given["speed"], given["path_radius"])
        if not states:
            raise InputError(f"no tilt between 0 and 90 deg lets the disk roll steadily at "
                             f"{qty(given['speed'], 'm/s')} on a contact circle of "
                             f"{qty(given['path_radius'], 'm')} (no real root with the centre "
                             "outside the axis)", key="given.speed")
        work.text(*_SOLVED_FOR)
        for s in states:
            work.step("beta", value=math.degrees(s.tilt), unit="deg",
                      note=(rel(rho0, "=", q(s.centre_radius, "m")), ", ",
                            rel(W0, "=", q(s.precession, "rad/s"))))
    for s in states:
        work.step("omega_z", -Sym("v", s.speed, "m/s") / r_, unit="rad/s", note="rolling")
        work.step("psidot", -Sym("Omega", s.precession, "rad/s") * Sym("R", s.path_radius, "m")
                  / r_, unit="rad/s", substitute=False,
                  note="spin relative to the precessing frame")
        work.check(rel(b0, "=", q(s.tilt, "deg")), ": residual of the moment equation ",
                   q(free_residual(m, g, r, J, I, s.tilt, s.centre_radius, s.speed),
                     "kg m^4/s^2"))
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


_STABILITY_TITLE = ("Stability: small changes of the tilt, linearised rolling equations (",
                    rel(prime(bd0, 2) + k0 * bd0, "=", 0), ")")
_MR2 = m0 * r0 ** 2
_SQRT_K, _SQRT_MINUS_K, _GROWTH = sqrt(k0), sqrt(-k0), exp(sig0 * t0)
_STABILITY = (rel(IG0 * (IG0 + _MR2) * k0, "=",
                  J0 * (J0 + _MR2) * wz0 ** 2 - IG0 * (3 * J0 + _MR2) * W0 * wz0 * sin(b0)
                  + IG0 ** 2 * W0 ** 2 * (1 + 2 * sin(b0) ** 2)
                  + IG0 * _MR2 * W0 ** 2 * cos(b0) ** 2 - IG0 * m0 * g0 * r0 * cos(b0)),
              "; ", rel(k0, ">", 0), " stable (the tilt wobbles at ", _SQRT_K, "), ",
              rel(k0, "<", 0), " unstable (it grows as ", _GROWTH, ", with the growth rate ",
              rel(sig0, "=", _SQRT_MINUS_K), "; ", rel(sig0, "=", 0), " when stable)")
_UPRIGHT = ("upright rolling in a straight line ", tup(rel(b0, "=", 0), rel(W0, "=", 0)),
            " is stable above this speed (", rel(k0, ">", 0), ")")


def _stability(m: float, g: float, r: float, J: float, I: float, states: list[FreeDisk],
               work: Work) -> None:
    """Each steady state's stability: tilt perturbed, linearised (physics/stability.py)."""
    from ..physics.stability import UNSTABLE, disk_critical_axial_rate, disk_rolling

    work.section(*_STABILITY_TITLE)
    work.text(*_STABILITY)
    words, rates = [], []
    for s in states:
        if not all(map(math.isfinite, (s.centre_radius, s.precession, s.spin, s.axial_rate))):
            raise OverflowError("the steady state itself overflows")
        verdict = disk_rolling(m, g, r, I, J, s.tilt, s.precession, s.axial_rate)
        detail = (("wobbles at ", rel(_SQRT_K, "=", q(verdict.frequency, "rad/s")))
                  if verdict.frequency else
                  ("grows at ", rel(sig0, "=", _SQRT_MINUS_K, "=", q(verdict.growth_rate, "1/s")))
                  if verdict.growth_rate else ("neutral to first order",))
        work.step("k", value=verdict.k, unit="1/s^2",
                  note=(rel(b0, "=", q(s.tilt, "deg")), f": {verdict.word}, ", *detail))
        if verdict.word == UNSTABLE:
            work.warn("steady rolling at ", rel(b0, "=", q(s.tilt, "deg")), ", ",
                      rel(v0, "=", q(s.speed, "m/s")), " is unstable: a small disturbance of the "
                      "tilt grows as ", _GROWTH, " (", rel(sig0, "=", q(verdict.growth_rate,
                                                                        "1/s")),
                      "), doubling every ", q(math.log(2) / verdict.growth_rate, "s"))
        words.append(verdict.word)
        rates.append(verdict.growth_rate)
    m_, g_, r_ = Sym("m", m, "kg"), Sym("g", g, "m/s^2"), Sym("r", r, "m")
    J_, I_ = Sym("J", J, "kg m^2"), Sym("I_G", I, "kg m^2")
    upright = work.step("v_upright", r_ * disk_critical_axial_rate(m_, g_, r_, I_, J_),
                        unit="m/s", note=_UPRIGHT)
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
        Param("path_radius", "length", "R", "radius of the circle traced by the contact point",
              positive=True, reason="at 0 (axle_pivot) the disk's centre is on the shaft and "
              "the moments about the pin do not fix the normal force"),
        Param("speed", "speed", "v", "speed of the disk's centre (free)", positive=True),
        Param("tilt", "angle", "beta", "tilt of the disk's plane from the vertical, toward the "
              "circle's centre (free)", range=(0.0, math.pi / 2), bounds="()",
              reason="at 90 deg the disk would lie flat"),
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
                   "linearised rolling equations)", words=("stable", "unstable")),
        AnswerSpec("growth_rate", "rate", "sigma", "free: growth rate of the unstable mode, 1/s (0 "
                   "when stable)"),
        AnswerSpec("upright_speed", "speed", "v_upright", "free: least speed at which upright "
                   "rolling in a straight line is stable"),
    ),
    solve=solve,
    animation="rolling", physics=("gyro_cli.physics.stability",),
    example={
        "statement": ("A {shape} weighing {weight}, of radius {radius}, is mounted on an axle "
                      "pinned to a vertical shaft and rolls on a horizontal plane in a circle of "
                      "radius {path_radius} while the shaft turns at {precession}. Find the "
                      "normal force of the plane on the disk and the spin of the disk."),
        "given": {"arrangement": "axle_pivot", "weight": "96.6 lb", "shape": "disk",
                  "radius": "1 ft", "path_radius": "2 ft", "precession": "48 rpm"},
        "find": {"normal_force": "lbf", "spin": "rpm"},
        "vary": {"precession": "[0.8, 1.2]"}},
)
