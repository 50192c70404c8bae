"""Steady precession of a symmetric body about a fixed point (theta constant).

With thetaddot = 0 the first of Eqs. 11.13, divided by sin(theta), reads

    J omega_z phidot - I phidot^2 cos(theta) = D,   omega_z = psidot + phidot cos(theta)

where D = M / sin(theta) and M is the moment about the line of nodes: gravity's
m g l sin(theta) (D = m g l, Eq. 11.11) or a given applied moment. Written with
the spin psidot it is the quadratic

    (J - I) cos(theta) phidot^2 + J psidot phidot - D = 0;

written with omega_z it is Eq. 11.20, real when J^2 omega_z^2 >= 4 I D cos(theta)
(Eq. 11.21 as corrected in the errata).
"""

from __future__ import annotations

import math

from ..core.errors import InputError
from ..core.given import Given
from ..core.spec import AnswerSpec, Kind, Param
from ..physics.algebra import cos_theta, quadratic_roots
from ..core.work import Work, num, qty

RPM = 2 * math.pi / 60
FASTEST_REAL_ROTOR = 1e5 * RPM  # beyond this no real top or gyroscope spins


# ---- physics on floats ------------------------------------------------------

def precession_from_spin(I: float, J: float, theta: float, spin: float, D: float) -> list[float]:
    """Steady precession rates for a given spin psidot (Eq. 11.13, thetaddot = 0)."""
    return quadratic_roots((J - I) * cos_theta(theta), J * spin, -D)


def precession_from_axial_rate(I: float, J: float, theta: float, axial_rate: float,
                               D: float) -> list[float]:
    """Steady precession rates for a given omega_z (Eq. 11.20)."""
    return quadratic_roots(I * cos_theta(theta), -J * axial_rate, D)


def spin_for_precession(I: float, J: float, theta: float, precession: float, D: float) -> float:
    """psidot that gives steady precession at phidot (Eq. 11.13 solved for psidot)."""
    return (D - (J - I) * cos_theta(theta) * precession ** 2) / (J * precession)


def moment_required(I: float, J: float, theta: float, spin: float, precession: float) -> float:
    """Moment about the line of nodes for the motion: phidot sin(th) (J w_z - I phidot cos(th))."""
    axial = spin + precession * cos_theta(theta)
    return precession * math.sin(theta) * (J * axial - I * precession * cos_theta(theta))


def min_spin(I: float, J: float, theta: float, D: float) -> float:
    """Least psidot with a real steady precession: 2 sqrt((I - J) D cos(theta)) / J; 0 if none."""
    radicand = (I - J) * D * cos_theta(theta)
    return 2 * math.sqrt(radicand) / J if radicand > 0 else 0.0


def min_axial_rate(I: float, J: float, theta: float, D: float) -> float:
    """Least omega_z with a real steady precession (Eq. 11.21 corrected): 2 sqrt(I D cos th)/J."""
    radicand = I * D * cos_theta(theta)
    return 2 * math.sqrt(radicand) / J if radicand > 0 else 0.0


# ---- the worked answer ------------------------------------------------------

def solve(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.body
    body.require("J", "I_pivot")
    I, J = body.I_pivot, body.J
    theta = given["theta"]
    if abs(math.sin(theta)) < 1e-9:
        raise InputError("at theta = 0 or 180 deg the axis is vertical: the line of nodes, and "
                         "with it the precession rate, is undefined there (Eq. 11.13 is divided "
                         "by sin(theta)); that is the sleeping top of kind released_top",
                         key="given.theta")
    if not 0 < theta < math.pi:
        raise InputError(f"theta must lie between 0 and 180 deg, got {num(math.degrees(theta))} "
                         "deg", key="given.theta")
    rates = [k for k in ("spin", "axial_rate", "precession") if k in given]
    if len(rates) == 3:
        raise InputError("give at most two of spin, axial_rate and precession",
                         key="given.axial_rate")
    work.section("Conventions (errata)")
    work.text("Euler angles z-x-z; theta from the upward vertical to the axis through the centre "
              "of mass, V = m g l cos(theta) (Eq. 11.11); spin psidot is relative to the "
              "precessing frame, omega_z = psidot + phidot cos(theta) (Eq. 11.8); I is about "
              "the fixed point")
    D, driver = _driver(given, theta, work)
    if not rates:
        if find - {"min_spin"}:
            raise InputError("give spin, axial_rate or precession", key="given.spin")
    elif len(rates) == 2 or rates == ["precession"]:
        _from_precession_or_pair(given, rates, I, J, theta, D, driver, work)
    else:
        _precession_roots(given, rates[0], I, J, theta, D, driver, work)
    if "min_spin" in find:
        _min_spin(I, J, theta, D, driver, work)
    if find & {"stability", "growth_rate"}:
        _stability(given, len(rates), I, J, theta, work)
    for name in ("spin", "precession", "axial_rate"):
        fast = [v for v in work.answers[name].si_values if abs(v) > FASTEST_REAL_ROTOR] \
            if name in work.answers else []
        if fast:
            work.warn(f"{name} of {num(max(map(abs, fast)) / RPM)} rpm is more than any real top "
                      "or gyroscope reaches (about 1e5 rpm): the data describe no practical "
                      "motion")


def _driver(given: Given, theta: float, work: Work) -> tuple[float, str]:
    """D = M / sin(theta): from an applied moment, or gravity's m g l."""
    body = given.body
    work.section("Moment about the line of nodes")
    if "moment" in given:
        if body.l:
            raise InputError("give an applied moment or gravity (cg_distance), not both: the "
                             "applied moment replaces gravity's", key="given.moment")
        M = given["moment"]
        D = work.step("D", "M / sin(theta)", f"{qty(M, 'N*m')} / sin({num(math.degrees(theta))}"
                      " deg)", M / math.sin(theta), "N*m")
        return D, "D"
    if body.l == 0:
        work.text("l = 0 and no applied moment: a torque-free body (D = 0)")
        return 0.0, "m g l"
    work.step("M", "m g l sin(theta)", f"{qty(body.m, 'kg')} ({qty(body.g, 'm/s^2')}) "
              f"({qty(body.l, 'm')}) sin({num(math.degrees(theta))} deg)",
              body.mgl * math.sin(theta), "N*m", ref="Eq. 11.11, gravity")
    return body.mgl, "m g l"


def _precession_roots(given: Given, rate: str, I: float, J: float, theta: float, D: float,
                      driver: str, work: Work) -> None:
    cos = cos_theta(theta)
    work.section("Steady precession, Eq. 11.13 with thetaddot = 0 and "
                 "omega_z = psidot + phidot cos(theta)")
    if rate == "spin":
        spin = given["spin"]
        a, b, c = (J - I) * cos, J * spin, -D
        work.text(f"(J - I) cos(theta) phidot^2 + J psidot phidot - {driver} = 0")
        work.text(f"({qty(a, 'kg m^2')}) phidot^2 + ({qty(b, 'kg m^2/s')}) phidot "
                  f"- {qty(D, 'N m')} = 0")
        roots = precession_from_spin(I, J, theta, spin, D)
        least, formula = min_spin(I, J, theta, D), f"2 sqrt((I - J) {driver} cos(theta)) / J"
        symbol = "psidot"
    else:
        axial = given["axial_rate"]
        work.text(f"phidot^2 cos(theta) - gamma phidot + a / 2 = 0, gamma = J omega_z / I, "
                  f"a = 2 {driver} / I    (Eq. 11.20)")
        work.step("gamma", "J omega_z / I", f"{qty(J, 'kg*m^2')} ({qty(axial, 'rad/s')})"
                          f" / {qty(I, 'kg*m^2')}", J * axial / I, "rad/s")
        work.step("a", f"2 {driver} / I", f"2 ({qty(D, 'N*m')}) / {qty(I, 'kg*m^2')}",
                  2 * D / I, "1/s^2")
        roots = precession_from_axial_rate(I, J, theta, axial, D)
        least, formula = min_axial_rate(I, J, theta, D), f"2 sqrt(I {driver} cos(theta)) / J"
        symbol, spin = "omega_z", None
    if not roots:
        raise InputError(
            f"{rate} {qty(given[rate], 'rad/s')} ({num(given[rate] / RPM)} rpm) is too low for "
            f"steady precession at theta = {num(math.degrees(theta))} deg: the least is "
            f"{symbol}_min = {formula} = {qty(least, 'rad/s')} ({num(least / RPM)} rpm), "
            "Eq. 11.21", key=f"given.{rate}")
    if least > 0:
        work.text(f"real roots exist because {symbol} >= {symbol}_min = {formula} = "
                  f"{qty(least, 'rad/s')}    (Eq. 11.21)")
    if len(roots) == 1:
        work.text("one root: the phidot^2 term vanishes" + (" (theta = 90 deg)"
                                                             if abs(cos) < 1e-12 else " (I = J)"))
    labels = _labels(roots)
    for root, label in zip(roots, labels):
        work.step(f"phidot ({label})" if label else "phidot", value=root, unit="rad/s")
    work.answer("precession", "phidot", roots, "rate", labels)
    spins = [spin] * len(roots) if spin is not None else \
        [given["axial_rate"] - p * cos for p in roots]
    axials = [s + p * cos for s, p in zip(spins, roots)]
    work.answer("spin", "psidot", spins, "rate", labels)
    work.answer("axial_rate", "omega_z", axials, "rate", labels)
    work.answer("moment", "M", [D * math.sin(theta)] * len(roots), "moment", labels)
    _check(I, J, theta, spins, roots, D, work, driver)


def _from_precession_or_pair(given: Given, rates: list[str], I: float, J: float, theta: float,
                             D: float, driver: str, work: Work) -> None:
    cos = cos_theta(theta)
    if "precession" in rates:
        precession = given["precession"]
    else:
        work.section("Precession from the two rates, omega_z = psidot + phidot cos(theta)")
        if abs(cos) < 1e-12:
            raise InputError("at theta = 90 deg omega_z = psidot whatever the precession: give "
                             "the precession itself", key="given.axial_rate")
        precession = work.step("phidot", "(omega_z - psidot) / cos(theta)",
                               f"({qty(given['axial_rate'], 'rad/s')} - "
                               f"{qty(given['spin'], 'rad/s')}) / {num(cos)}",
                               (given["axial_rate"] - given["spin"]) / cos, "rad/s")
    if len(rates) == 2:
        spin = given["spin"] if "spin" in given else given["axial_rate"] - precession * cos
        _moment(I, J, theta, spin, precession, D, driver, work)
        work.answer("precession", "phidot", [precession], "rate")
        return
    if precession == 0:
        raise InputError("a steady precession of zero needs no spin and no moment: give a "
                         "non-zero precession", key="given.precession")
    work.section("Spin for the given precession, Eq. 11.13 with thetaddot = 0 solved for psidot")
    work.text(f"J psidot phidot + (J - I) cos(theta) phidot^2 = {driver}")
    spin = work.step("psidot", f"({driver} - (J - I) cos(theta) phidot^2) / (J phidot)",
                     f"({qty(D, 'N*m')} - ({qty((J - I) * cos, 'kg*m^2')}) "
                     f"({qty(precession, 'rad/s')})^2) / ({qty(J, 'kg*m^2')} "
                     f"{qty(precession, 'rad/s')})",
                     spin_for_precession(I, J, theta, precession, D), "rad/s")
    axial = work.step("omega_z", "psidot + phidot cos(theta)",
                      f"{qty(spin, 'rad/s')} + {qty(precession, 'rad/s')} ({num(cos)})",
                      spin + precession * cos, "rad/s", ref="Eq. 11.8")
    if spin < 0:
        work.text("psidot < 0: the body spins against the sense that precession alone would "
                  "need; the sign is the answer, not an error")
    work.answer("precession", "phidot", [precession], "rate")
    work.answer("spin", "psidot", [spin], "rate")
    work.answer("axial_rate", "omega_z", [axial], "rate")
    work.answer("moment", "M", [D * math.sin(theta)], "moment")
    _check(I, J, theta, [spin], [precession], D, work, driver)


def _moment(I: float, J: float, theta: float, spin: float, precession: float, D: float,
            driver: str, work: Work) -> None:
    cos, sin = cos_theta(theta), math.sin(theta)
    work.section("Moment for the motion, Eq. 11.13 with thetaddot = 0 (dH/dt = M)")
    axial = work.step("omega_z", "psidot + phidot cos(theta)", f"{qty(spin, 'rad/s')} + "
                      f"{qty(precession, 'rad/s')} ({num(cos)})", spin + precession * cos,
                      "rad/s", ref="Eq. 11.8")
    M = work.step("M", "phidot sin(theta) (J omega_z - I phidot cos(theta))",
                  f"{qty(precession, 'rad/s')} ({num(sin)}) ({qty(J, 'kg*m^2')} "
                  f"{qty(axial, 'rad/s')} - {qty(I, 'kg*m^2')} {qty(precession, 'rad/s')} "
                  f"({num(cos)}))", moment_required(I, J, theta, spin, precession), "N*m")
    if D:
        work.text(f"of which {driver} sin(theta) = {qty(D * sin, 'N m')} is supplied; the rest, "
                  f"{qty(M - D * sin, 'N m')}, must be applied")
    work.answer("spin", "psidot", [spin], "rate")
    work.answer("axial_rate", "omega_z", [axial], "rate")
    work.answer("moment", "M", [M], "moment")


def _min_spin(I: float, J: float, theta: float, D: float, driver: str, work: Work) -> None:
    work.section("Least spin for steady precession (discriminant of Eq. 11.13; Eq. 11.21)")
    least = min_spin(I, J, theta, D)
    if least > 0:
        work.step("psidot_min", f"2 sqrt((I - J) {driver} cos(theta)) / J", f"2 sqrt(({qty(I - J, 'kg*m^2')}"
                  f") ({qty(D, 'N*m')}) ({num(cos_theta(theta))})) / {qty(J, 'kg*m^2')}", least,
                  "rad/s")
    else:
        work.text(f"(I - J) {driver} cos(theta) <= 0: real roots for every spin, no least spin "
                  "(psidot_min = 0)")
    work.answer("min_spin", "psidot_min", [least], "rate")


def _check(I: float, J: float, theta: float, spins: list[float], precessions: list[float],
           D: float, work: Work, driver: str = "D") -> None:
    """Each root in the vector form dH/dt = M, beside gravity's (or the applied) moment,
    written with the symbols of the steps (m g l, or D = M / sin(theta) when applied)."""
    for spin, precession in zip(spins, precessions):
        rate = moment_required(I, J, theta, spin, precession)
        work.check(f"phidot = {qty(precession, 'rad/s')}: dH/dt = phidot sin(theta) (J omega_z - "
                   f"I phidot cos(theta)) = {qty(rate, 'N m')}; applied {driver} sin(theta) = "
                   f"{qty(D * math.sin(theta), 'N m')}")


def _stability(given: Given, n_rates: int, I: float, J: float, theta: float,
               work: Work) -> None:
    """Each root's stability in theta (physics/stability.py: theta'' + k theta = 0)."""
    from ..physics.stability import UNSTABLE, top_steady_precession

    if "moment" in given or n_rates == 2:
        raise InputError("stability is worked for a top held by gravity alone (cg_distance, "
                         "one of spin, axial_rate, precession): how an applied moment changes "
                         "with theta is not given", key="find.stability")
    answer = work.answers["precession"]
    work.section("Stability: small changes of theta with p_phi and p_psi fixed, "
                 "theta'' + k theta = 0")
    work.text("k = U_eff''(theta) / I = ((J omega_z - 2 I phidot cos(theta)) / I)^2 + "
              "phidot^2 sin^2(theta) >= 0 (Eqs. 11.13-11.16; Goldstein Sec. 5.7): every steady "
              "precession of a heavy top about a fixed point is a minimum of U_eff, stable; a "
              "change of p_phi or p_psi only moves it to a neighbouring steady precession")
    words, rates = [], []
    for phidot, axial, label in zip(answer.si_values, work.answers["axial_rate"].si_values,
                                    answer.labels or [""] * len(answer.si_values)):
        verdict = top_steady_precession(I, J, theta, phidot, axial)
        tag = f" ({label})" if label else ""
        work.step(f"k{tag}", value=verdict.k, unit="1/s^2", note=verdict.word + (
            f", theta oscillates at sqrt(k) = {qty(verdict.frequency, 'rad/s')}"
            if verdict.frequency else ""))
        if verdict.word == UNSTABLE:
            work.warn(f"the steady precession phidot = {qty(phidot, 'rad/s')} is unstable: a "
                      f"small disturbance grows as exp({num(verdict.growth_rate)} t / s)")
        words.append(verdict.word)
        rates.append(verdict.growth_rate)
    work.answer("stability", "stability", words, None, answer.labels)
    work.answer("growth_rate", "s", rates, "rate", answer.labels)


def _labels(roots: list[float]) -> list[str]:
    if len(roots) != 2:
        return []
    slow = 0 if abs(roots[0]) <= abs(roots[1]) else 1
    return ["slow", "fast"] if slow == 0 else ["fast", "slow"]


KIND = Kind(
    name="steady_precession",
    summary="symmetric body about a fixed point precessing steadily at constant theta",
    chapter="Eqs. 11.13-11.14 with theta constant, 11.20, 11.21 (corrected)",
    params=(
        Param("theta", "angle", "theta", "angle of the symmetry axis from the upward vertical"),
        Param("spin", "rate", "psidot", "spin relative to the precessing frame"),
        Param("axial_rate", "rate", "omega_z", "axial angular velocity psidot + phidot cos(theta)"),
        Param("precession", "rate", "phidot", "precession rate about the vertical"),
        Param("moment", "moment", "M", "applied moment about the line of nodes, instead of "
              "gravity"),
    ),
    answers=(
        AnswerSpec("precession", "rate", "phidot", "steady precession rate(s), ascending"),
        AnswerSpec("spin", "rate", "psidot", "spin relative to the precessing frame"),
        AnswerSpec("axial_rate", "rate", "omega_z", "axial angular velocity"),
        AnswerSpec("moment", "moment", "M", "moment about the line of nodes for the motion"),
        AnswerSpec("min_spin", "rate", "psidot_min", "least spin for steady precession at theta"),
        AnswerSpec("stability", None, "stability", "stable or unstable, for each root (theta "
                   "perturbed, gravity alone)"),
        AnswerSpec("growth_rate", "rate", "s", "growth rate of the unstable mode, 1/s (0 when "
                   "stable)"),
    ),
    solve=solve,
    extra={"example": {
        "given": {"weight": "3 oz", "k_axial": "0.84 in", "k_pivot": "1.80 in",
                  "cg_distance": "1.5 in", "spin": "1800 rpm", "theta": "30 deg"},
        "find": {"precession": "rpm", "min_spin": "rpm"},
        "vary": {"spin": "[0.8, 1.2]", "theta": "[20 deg, 40 deg]"}}},
)
