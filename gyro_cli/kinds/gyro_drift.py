"""Drift and nutation of a gimballed gyroscope under a small disturbing moment.

Section 11.3 (Fig. 11-13): the gyroscope in gimbals is an inertial reference;
bearing friction, drag and imbalance give a small moment M about an axis at
right angles to the spin, and the spin axis precesses ("drifts") at M / H,
H = J psidot (Eq. 11.29 read for phidot). Switched on with the gyro at rest it
also nutates at w_n = H / sqrt(I_x I_y). The derivation and the closed forms
are in gyro_cli/physics/gyro_drift.py; a drift budget gives the largest moment.
"""

from __future__ import annotations

import math

from ..core.body import spin_angular_momentum
from ..core.errors import InputError
from ..core.expr import PI, Let, Sym, cos, sin, sqrt
from ..core.given import Given
from ..core.prose import fn, names, prime, q, rel, words
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work, qty
from ..physics import gyro_drift as gd

LINEAR_LIMIT = 0.1  # rad: beyond this the small-angle gimbal equations are doubtful


#: the symbols the sentences name (values are in the steps' trees)
k0, H0, x0, y0, M0, a0, b0, I_x0, I_y0, I0 = names("k H x y M alpha beta I_x I_y I")
t0, w_n0, T_n0, W_d0 = names("t w_n T_n Omega_d")

# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's own time in gyro check.
#: I_x alpha'' + H beta' = M, the gimbal equation about the moment's axis
_FIRST_EQUATION = rel(I_x0 * prime(a0, 2) + H0 * prime(b0), "=", M0)
_AXES = (k0, ": the spin axis; ", H0, ": the rotor's angular momentum along it; ", x0, ": the "
         "gimbal axis about which the disturbing moment ", M0, " acts; ", y0, ": the other "
         "gimbal axis, at right angles to both. ", a0, ", ", b0, ": small rotations of the spin "
         "axis about ", x0, " and ", y0, "; ", I_x0, ", ", I_y0, ": inertias of rotor and "
         "gimbals about ", x0, " and ", y0, ".")
_GIMBAL_EQUATIONS = ("Linearised gimbal equations: ", _FIRST_EQUATION, ",  ",
                     rel(I_y0 * prime(b0, 2) - H0 * prime(a0), "=", 0), ". The moment does not "
                     "turn the rotor about ", x0, ": the spin axis drifts about ", y0, ".")
_DRIFT_ANGLE, _DRIFT_ANGLE_SYMBOL = words("drift angle"), M0 / H0 * t0


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    work.sections[:] = [s for s in work.sections if s.steps or s.title != "Body"]
    work.section("Conventions")
    work.text(*_AXES)
    work.text(*_GIMBAL_EQUATIONS)
    H = _momentum(given, work)
    M, rate = _moment_and_rate(given, H, work)
    work.answer("angular_momentum", "H", [H], "angular_momentum")
    work.answer("moment", "M", [M], "moment")
    work.answer("drift_rate", "Omega_d", [rate], "rate")
    if "duration" in given:
        t = given["duration"]
        drift = Let(Sym("Omega_d", rate, "rad/s"), Sym("M", M, "N m") / Sym("H", H, "kg m^2/s"))
        angle = work.step(_DRIFT_ANGLE, drift * Sym("t", t, "s"), unit="rad",
                          note=_equals(rate * t, "deg"))
        work.answer("drift_angle", _DRIFT_ANGLE_SYMBOL, [angle], "angle")
    elif "drift_angle" in find:
        raise InputError("drift_angle needs the time the moment acts: give duration",
                         key="given.duration")
    _nutation(given, find, H, M, work)


def _momentum(given: Given, work: Work) -> float:
    work.section("Spin angular momentum")
    H = spin_angular_momentum(given, work)
    if H == 0:
        raise InputError("the rotor must spin: with H = 0 there is no gyroscopic stiffness and "
                         "any moment simply turns it", key="given.spin"
                         if "spin" in given else "given.angular_momentum")
    return H


_DRIFT_TITLE = ("Drift: steady precession of the spin axis about ", y0, " (Eq. 11.29)")
_BUDGET_TITLE = ("Largest disturbing moment for the drift budget: ", rel(M0, "=", H0 * W_d0))
_FASTER_THAN_BUDGET = ("any larger moment about ", x0, " makes the spin axis drift faster than "
                       "the budget")


def _moment_and_rate(given: Given, H: float, work: Work) -> tuple[float, float]:
    ways = [k for k in ("moment", "drift_rate", "drift_period") if k in given]
    if len(ways) > 1:
        raise InputError(f"give one of moment, drift_rate (a budget) or drift_period, not "
                         f"{ways[0]} and {ways[1]}", key=f"given.{ways[1]}")
    if not ways:
        raise InputError("give the disturbing moment, or a drift budget (drift_rate or "
                         "drift_period) to find the largest moment", key="given.moment")
    if ways == ["moment"]:
        M = given["moment"]
        work.section(*_DRIFT_TITLE)
        rate = work.step("Omega_d", gd.drift_rate(Sym("M", M, "N m"), Sym("H", H, "kg m^2/s")),
                         unit="rad/s",
                         note=_equals(gd.drift_rate(M, H), "deg/h"))
        return M, rate
    if ways == ["drift_period"]:
        T = given["drift_period"]
        work.section("Drift rate from the period of one full turn")
        rate = work.step("Omega_d", 2 * PI / Sym("T_d", T, "s"), unit="rad/s",
                         note=_equals(2 * math.pi / T, "deg/h"))
    else:
        rate = given["drift_rate"]
    work.section(*_BUDGET_TITLE)
    M = work.step("M", Sym("H", abs(H), "kg m^2/s") * Sym("Omega_d", rate, "rad/s"), unit="N*m")
    work.text(*_FASTER_THAN_BUDGET)
    return M, math.copysign(rate, H) if rate else 0.0


def _transverse(given: Given, find: frozenset[str]) -> tuple[float, float] | None:
    body = given.solid_body
    if "I" in given and ("I_x" in given or "I_y" in given):
        raise InputError("give I (equal inertias) or I_x and I_y, not both",
                         key="given.I_x" if "I_x" in given else "given.I_y")
    if "I" in given:
        Ix = Iy = given["I"]
    elif "I_x" in given or "I_y" in given:
        if "I_x" not in given or "I_y" not in given:
            missing = "I_x" if "I_x" not in given else "I_y"
            raise InputError("give both I_x and I_y (or one I for both)", key=f"given.{missing}")
        Ix, Iy = given["I_x"], given["I_y"]
    elif body.I_pivot is not None or body.I_cg is not None:  # I, I_x, I_y declare > 0
        Ix = Iy = body.I_pivot if body.I_pivot is not None else body.needed("I_cg")
        if Ix <= 0:
            raise InputError(f"a moment of inertia must be positive, got the rotor's "
                             f"{qty(Ix, 'kg*m^2')}", key="given.I_pivot")
    else:
        return None
    return Ix, Iy


_ROTOR_ALONE = ("transverse inertias: ", "the rotor alone (gimbals' inertia neglected)")
_EQUAL_INERTIAS = ("transverse inertias: ", rel(I_x0, "=", I_y0, "=", I0))
_TWO_INERTIAS = ("transverse inertias: ", I_x0, ", ", I_y0)
_FROM_REST = ("solution from rest: ",
              rel(fn("alpha", t0), "=", M0 * I_y0 / H0**2 * (1 - cos(w_n0 * t0))), ",  ",
              rel(fn("beta", t0), "=", M0 / H0 * t0 - M0 / (H0 * w_n0) * sin(w_n0 * t0)))
_ABOUT_X = ("about ", x0, ", the moment's axis (", M0 * I0 / H0**2, " for equal inertias ", I0,
            ")")
_ABOUT_Y = ("about ", y0, ", the drift axis: the ripple on the drift")
# alpha = A (1 - cos(w_n t)): largest at t = T_n / 2, then once every period
_LARGEST = ("largest deflection about ", x0, ", reached half a period from rest and once "
            "every period after")
_AT_A_QUARTER_PERIOD = ("the solution in the first gimbal equation at ", rel(t0, "=", T_n0 / 4),
                        ": ")


def _nutation(given: Given, find: frozenset[str], H: float, M: float, work: Work) -> None:
    nutation_answers = {"nutation_frequency", "nutation_period", "nutation_amplitude",
                        "nutation_amplitude_drift", "max_deflection"}
    inertias = _transverse(given, find)
    if inertias is None:
        asked = sorted(nutation_answers & find)
        if asked:
            raise InputError(f"{asked[0]} needs the transverse inertia of rotor and gimbals: "
                             "give I (or I_x and I_y, or the rotor's I_pivot / I_cg / shape)",
                             key="given.I")
        return
    Ix, Iy = inertias
    source = _ROTOR_ALONE if "I" not in given and "I_x" not in given else \
        _EQUAL_INERTIAS if Ix == Iy else _TWO_INERTIAS
    work.section("Nutation, the moment switched on with the gyro at rest")
    work.text(*source)
    H_, I_x, I_y = Sym("H", abs(H), "kg m^2/s"), Sym("I_x", Ix, "kg m^2"), Sym("I_y", Iy, "kg m^2")
    w = gd.nutation_frequency(abs(H), Ix, Iy)
    wn = work.step("w_n", gd.nutation_frequency(H_, I_x, I_y), unit="rad/s", note=_equals(w / (2 * math.pi), "Hz"))
    period = work.step("T_n", 2 * PI / Sym("w_n", wn, "rad/s"), unit="s")
    work.text(*_FROM_REST)
    M_, H_ = Sym("M", M, "N m"), Sym("H", H, "kg m^2/s")
    ax = work.step("A_x", M_ * I_y / H_ ** 2, unit="rad", note=_ABOUT_X)
    ay = work.step("A_y", M_ * sqrt(I_x * I_y) / H_ ** 2, unit="rad", substitute=False,
                   note=_ABOUT_Y)
    work.step("alpha_max", 2 * M_ * I_y / H_ ** 2, unit="rad", substitute=False,
              note=_LARGEST)
    quarter = period / 4
    residual = Ix * _a_dd(M, H, Iy, w, quarter) + H * _b_d(M, H, w, quarter)
    work.check(*_AT_A_QUARTER_PERIOD, rel(_FIRST_EQUATION.first, "=", q(residual, "N m")), ", ",
               rel(M0, "=", q(M, "N m")))
    if abs(2 * ax) > LINEAR_LIMIT or abs(ay) > LINEAR_LIMIT:
        work.warn("the nutation reaches ", q(max(abs(2 * ax), abs(ay)), "deg"), ": the "
                  "linearised gimbal equations assume small angles")
    work.answer("nutation_frequency", "w_n", [wn], "rate")
    work.answer("nutation_period", "T_n", [period], "time")
    work.answer("nutation_amplitude", "A_x", [abs(ax)], "angle")
    work.answer("nutation_amplitude_drift", "A_y", [abs(ay)], "angle")
    work.answer("max_deflection", "alpha_max", [abs(2 * ax)], "angle")


def _equals(si: float, unit: str) -> tuple:
    """A step's note ``= 0.03283 deg/h``: its SI value ``si`` in another unit (``q``
    converts: a value already in the unit was converted twice, 1e-6 rad/s printed as
    42,550 deg/h)."""
    return (rel(None, "=", q(si, unit)),)


def _a_dd(M: float, H: float, Iy: float, wn: float, t: float) -> float:
    """alpha''(t) of the motion from rest, (M I_y / H^2) w_n^2 cos(w_n t), at the nutation
    frequency ``wn`` the caller has found."""
    return M * Iy / (H * H) * wn * wn * math.cos(wn * t)


def _b_d(M: float, H: float, wn: float, t: float) -> float:
    """beta'(t) of the motion from rest, (M / H) (1 - cos(w_n t))."""
    return M / H * (1 - math.cos(wn * t))


KIND = Kind(
    name="gyro_drift",
    summary="gimballed gyroscope as an inertial reference: drift under a small disturbing "
            "moment, nutation, and the largest moment a drift budget allows",
    chapter="section 11.3, Fig. 11-13; drift M / H from Eq. 11.29",
    params=(
        Param("spin", "rate", "psidot", "rotor spin (H = J psidot)"),
        Param("angular_momentum", "angular_momentum", "H", "the rotor's spin angular momentum "
              "(instead of J and spin)"),
        Param("moment", "moment", "M", "disturbing moment about a gimbal axis at right angles "
              "to the spin (friction, drag, imbalance)"),
        Param("drift_rate", "rate", "Omega_d", "drift budget (instead of moment), e.g. "
              "'0.1 deg/h'", nonnegative=True, reason="a drift budget is a magnitude"),
        Param("drift_period", "time", "T_d", "time for one full turn of drift (instead of "
              "drift_rate)", positive=True),
        Param("duration", "time", "t", "time the moment acts, for drift_angle",
              nonnegative=True),
        Param("I", "inertia", "I", "transverse inertia of rotor and gimbals about each gimbal "
              "axis", positive=True),
        Param("I_x", "inertia", "I_x", "about the axis of the moment (where the outer gimbal "
              "adds inertia)", positive=True),
        Param("I_y", "inertia", "I_y", "about the drift axis", positive=True),
    ),
    answers=(
        AnswerSpec("angular_momentum", "angular_momentum", "H", "spin angular momentum J psidot"),
        AnswerSpec("drift_rate", "rate", "Omega_d", "drift (precession) rate of the spin axis"),
        AnswerSpec("drift_angle", "angle", "(M / H) t", "drift after duration (the nutation "
                   "ripple of at most nutation_amplitude_drift aside)"),
        AnswerSpec("moment", "moment", "M", "the moment (given, or the largest the drift "
                   "budget allows, H times the rate)"),
        AnswerSpec("nutation_frequency", "rate", "w_n", "H / sqrt(I_x I_y)"),
        AnswerSpec("nutation_period", "time", "T_n", "2 pi / w_n"),
        AnswerSpec("nutation_amplitude", "angle", "A_x", "moment applied at rest: M I_y / H^2 "
                   "about the moment's axis (M I / H^2 for equal inertias)"),
        AnswerSpec("nutation_amplitude_drift", "angle", "A_y", "M sqrt(I_x I_y) / H^2 about "
                   "the drift axis"),
        AnswerSpec("max_deflection", "angle", "alpha_max", "2 M I_y / H^2, the largest deflection "
                   "about the moment's axis"),
    ),
    solve=solve,
    gravity=False, body_keys=("mass", "weight", "J", "k_axial", "I_pivot", "k_pivot", "I_cg", "k_cg", "shape", "radius", "diameter", "inner_radius", "width", "length"), example={
        "statement": ("A gyro rotor with a moment of inertia of {J} spins at {spin} in gimbals; "
                      "rotor and gimbals have a moment of inertia of {I} about each gimbal axis. "
                      "A disturbing moment of {moment} acts about one gimbal axis for {duration}. "
                      "Find the rate at which the spin axis drifts, the angle it drifts through, "
                      "and the frequency and amplitude of its nutation."),
        "given": {"J": "2.5e-4 kg m^2", "spin": "24000 rpm", "moment": "1e-7 N m",
                  "I": "2e-4 kg m^2", "duration": "1 h"},
        "find": {"drift_rate": "deg/h", "drift_angle": "deg", "nutation_frequency": "Hz",
                 "nutation_amplitude": "arcsec"},
        "vary": {"moment": "[0.5, 2]"}},
)
