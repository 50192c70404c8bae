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
from functools import cache

from ..core.errors import InputError
from ..core.expr import NAMED, PI, Expr, Let, Sym, absolute, exp, sqrt
from ..core.expr import cos as cos_
from ..core.expr import sin as sin_
from ..core.given import Given
from ..core.prose import Prose, deriv, fn, names, paren, prime, q, rel, words
from ..core.prose import text as prose_text
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work, num, qty
from ..physics import steady
from ..physics.algebra import cos_theta, quadratic_roots

RPM = 2 * math.pi / 60


def _driver_tree(D: float, driver: str) -> Expr:
    """D, the moment per unit sin(theta): printed m g l for gravity (its value in
    substitutions), D for an applied moment."""
    d = Sym("D", D, "N m")
    return Let(d, Sym("m", NAMED) * Sym("g", NAMED) * Sym("l", NAMED)) if driver == "m g l" else d


def _rate(name: str, value: float) -> Sym:
    return Sym(name, value, "rad/s")


def _abs_rate(value: float) -> Expr:
    """|phidot|, shown with its magnitude in substitutions."""
    return Let(Sym("abs_phidot", abs(value), "rad/s"), absolute(Sym("phidot", NAMED)))


def _theta(theta: float) -> Sym:
    return Sym("theta", theta, "deg")


# ---- the symbols of the sentences (known by name only) -------------------------

th, psd, phd, wz, H, I_, J_, D_ = names("theta psidot phidot omega_z H I J D")
m0, g0, l0, tdd0, V0 = names("m g l thetaddot V")

#: the moment per unit sin(theta) in a sentence: m g l (gravity) or D (applied), by driver
_MOMENT_OF = {"m g l": m0 * g0 * l0, "D": D_}


def _moment_of(driver: str) -> Expr:
    """The moment per unit sin(theta) in a sentence: m g l (gravity) or D (applied)."""
    return _MOMENT_OF[driver]


def _deg(degrees: float) -> Expr:
    """An angle of the text, 90 deg, with the digits it needs."""
    return q(math.radians(degrees), "deg", exact=True)


# The sentences that hold no values are built once, here and beside the functions that use
# them: building their trees again on every solve was a large part of the kind's own time in
# gyro check.
_AT_90 = rel(th, "=", _deg(90))  # theta = 90 deg
_COS_0 = rel(cos_(th), "=", 0)
_AXIAL_RATE = rel(wz, "=", psd + phd * cos_(th))  # omega_z = psidot + phidot cos(theta), Eq. 11.8
# The term of Eq. 11.13, m g l = phidot (J omega_z - I phidot cos theta), that the gyroscopic
# approximation drops, by how the spin is written: I phidot cos theta with omega_z; with
# psidot (omega_z = psidot + phidot cos theta) it is m g l = phidot (J psidot + (J - I)
# phidot cos theta), and (J - I) phidot cos theta drops
_DROPPED = {"omega_z": I_ * phd * cos_(th), "psidot": (J_ - I_) * phd * cos_(th)}


# Made on first use, once (functools.cache), as the sentences by driver below: a solve
# writes one case's, not both.
@cache
def _conventions(gravity: bool) -> tuple:
    """Euler angles, the rates and H; with ``gravity`` its potential V (Eq. 11.11)."""
    return ("Euler angles z-x-z; ", th, " from the upward vertical to the axis through the "
            "centre of mass",
            *((", ", rel(V0, "=", _moment_of("m g l") * cos_(th)), " (Eq. 11.11)") if gravity
              else ()),
            "; spin ", psd, " is relative to the precessing frame, which turns about the "
            "vertical at the precession rate ", phd, "; ", H, ": the angular momentum about the "
            "fixed point; ", _AXIAL_RATE, " (Eq. 11.8); ", I_, " is about the fixed point")


_I_DROPS_OUT = (_AT_90, ": ", _COS_0, ", so the transverse inertia ", I_, " drops out of Eq. "
                "11.13 and is not needed")


def _label(symbol: str | Expr, label: str) -> str | Expr:
    """A step's symbol with its root's label: ``phidot (slow)``; the symbol alone without."""
    if not label:
        return symbol
    return words(f"({label})", names(symbol)[0] if isinstance(symbol, str) else symbol)


def _percent(fraction: float, digits: int) -> Expr:
    """``5.6`` of ``5.6% apart``: a number rounded to ``digits`` figures."""
    return q(fraction * 100, label=f"{fraction * 100:.{digits}g}")


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

# Answers that follow from the precession rate(s) once known.
MOTION_ANSWERS = {"pivot_force", "precession_period", "cg_speed", "cg_acceleration"}
NEEDS_EXACT = {"precession_slow", "precession_fast", "spin_slow", "spin_fast", "min_spin"}


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.solid_body
    J = body.needed("J")
    if "theta" not in given:
        _without_theta(given, find, work)
        return
    theta = given["theta"]
    if abs(math.sin(theta)) < 1e-9:
        raise InputError("at theta = 0 or 180 deg the axis is vertical: the line of nodes, and "
                         "with it the precession rate, is undefined there (Eq. 11.13 is divided "
                         "by sin(theta)); that is the sleeping top of kind released_top",
                         key="given.theta")
    rates = [k for k in ("spin", "axial_rate", "precession") if k in given]
    if len(rates) == 3:
        raise InputError("give at most two of spin, axial_rate and precession",
                         key="given.axial_rate")
    cos = cos_theta(theta)
    approximate = False
    if body.I_pivot is not None:
        I = body.I_pivot
    elif cos == 0:
        I = 0.0  # multiplies cos(theta) = 0 in every formula below
    elif len(rates) == 1 and rates[0] in ("spin", "axial_rate") and not find & NEEDS_EXACT:
        I, approximate = 0.0, True
    else:
        wanted = sorted(find & NEEDS_EXACT) or [k for k in rates if k != "spin"] or ["precession"]
        raise InputError(f"{wanted[0]} at theta = {num(math.degrees(theta))} deg needs the "
                         "transverse inertia about the fixed point: give I_pivot, k_pivot, "
                         "I_cg or k_cg (with cg_distance) or a shape (only at theta = 90 deg "
                         "does it drop out)", key="given.I_pivot")
    work.section("Conventions (errata)")
    work.text(*_conventions("moment" not in given and bool(body.l)))
    if body.I_pivot is None and cos == 0:
        work.text(*_I_DROPS_OUT)
    D, driver = _driver(given, theta, work)
    if not rates:
        if find - {"min_spin"}:
            raise InputError("give spin, axial_rate or precession", key="given.spin")
    elif approximate:
        _approximate_only(given, rates[0], J, theta, D, driver, work)
    elif len(rates) == 2 or rates == ["precession"]:
        _from_precession_or_pair(given, rates, I, J, theta, D, driver, work)
    else:
        _precession_roots(given, rates[0], I, J, theta, D, driver, work)
        if "precession_approx" in find:
            _approximation(given, rates[0], J, theta, D, driver, work)
    if "min_spin" in find:
        _min_spin(I, J, theta, D, driver, work)
    _by_root(find, work)
    if find & MOTION_ANSWERS:
        _motion(body, theta, find, work)
    if body.per_kg:
        if "moment" in find:
            raise InputError("the moment depends on the mass, which the rates do not need: give "
                             "mass or weight", key="given.mass")
        work.answers.pop("moment", None)
    if find & {"stability", "growth_rate"}:
        _stability(given, len(rates), I, J, theta, work)
    for name in ("spin", "precession", "axial_rate"):
        fast = [v for v in work.answers[name].si_values if abs(v) > FASTEST_REAL_ROTOR] \
            if name in work.answers else []
        if fast:
            work.warn(f"{name} of ", q(max(map(abs, fast)) / RPM, "rpm"), " is more than any "
                      "real top or gyroscope reaches (about ",
                      q(FASTEST_REAL_ROTOR / RPM, "rpm", label="1e5"), "): the data describe no "
                      "practical motion")


# What the introductory books' formula Omega = m g l / (J omega) answers without an angle.
WITHOUT_THETA = {"precession", "precession_approx", "precession_period", "spin", "axial_rate"}
SPREAD_ANGLES = (30.0, 60.0, 90.0)  # deg: how far the exact slow root moves with theta


# The sentences below are made when a solve first needs them, once (functools.cache), not
# when the module is imported: most solves never write them.


@cache
def _without_theta_words() -> tuple[dict[str, tuple], dict[str, tuple], tuple, tuple]:
    """What a solve without theta writes: what the sentences name (with the spin written
    psidot or omega_z), why theta does not matter, D's note and the warning."""
    w0 = names("omega")[0]
    approximate_rate = _moment_of("m g l") / (J_ * w0)  # m g l / (J omega)
    no_angle = {symbol: (th, ", the angle of the axis from the upward vertical, is not given; ",
                         phd, ", the precession rate about the vertical; ", w0, ", the spin (here ",
                         names(symbol)[0], ")") for symbol in ("psidot", "omega_z")}
    whatever_theta = {symbol: (
        "gravity's moment ", _moment_of("m g l") * sin_(th), " turns the horizontal part ",
        J_ * w0 * sin_(th), " of the spin angular momentum at ", phd, ", so ",
        rel(phd, "=", approximate_rate), " whatever ", th, " is, once the ", term,
        " term of Eq. 11.13 is dropped (exact at ", _AT_90, ", where ", _COS_0, ")")
        for symbol, term in _DROPPED.items()}
    per_unit_sin = ("per unit ", sin_(th))
    approximation_only = ("no ", th, " given: the answers use the gyroscopic approximation ",
                          approximate_rate, ", exact only with the axis horizontal (", _AT_90,
                          "); the exact roots of Eq. 11.13 need ", th)
    return no_angle, whatever_theta, per_unit_sin, approximation_only


def _without_theta(given: Given, find: frozenset[str], work: Work) -> None:
    """No theta: the gyroscopic approximation and its period, and how far the exact roots
    would move with theta (introductory books: Omega = m g l / (J omega), no angle)."""
    body = given.solid_body
    needs = sorted(find - WITHOUT_THETA)
    if needs:
        raise InputError(f"{needs[0]} needs the angle theta of the axis from the upward vertical; "
                         "without it gyro answers only precession_approx, precession (the same "
                         "approximation) and precession_period", key="given.theta")
    if "moment" in given:
        raise InputError("an applied moment gives the precession only with the angle: "
                         "phidot = M / (J omega sin(theta)); give theta", key="given.theta")
    rates = [k for k in ("spin", "axial_rate", "precession") if k in given]
    if len(rates) != 1:
        raise InputError("without theta give exactly one of spin, axial_rate and precession "
                         f"(got {', '.join(rates) or 'none'})",
                         key=f"given.{rates[-1]}" if rates else "given.spin")
    if not body.l:
        raise InputError("no theta and no gravity moment (cg_distance 0 or absent): the "
                         "approximation m g l / (J omega) is 0; give cg_distance",
                         key="given.cg_distance")
    work.section("No angle given: the gyroscopic approximation")
    no_angle, whatever_theta, per_unit_sin, approximation_only = _without_theta_words()
    symbol = {"spin": "psidot", "axial_rate": "omega_z", "precession": "psidot"}[rates[0]]
    work.text(*no_angle[symbol])
    work.text(*whatever_theta[symbol])
    D = work.step("D", Sym("m", body.mass_for_rates, "kg") * Sym("g", body.g, "m/s^2")
                  * Sym("l", body.l, "m"), unit="N*m", ref="Eq. 11.11", note=per_unit_sin)
    J_v = Sym("J", body.needed("J"), "kg m^2")
    rate = rates[0]
    if rate == "precession":
        precession = given["precession"]
        if precession == 0:
            raise InputError("a precession of 0 needs no spin: give a non-zero precession",
                             key="given.precession")
        omega = work.step("omega_approx", _driver_tree(D, "m g l") / (
            J_v * _rate("phidot", precession)), unit="rad/s",
            note="the spin the approximation needs")
        work.answer("spin", "psidot", [omega], "rate", ["approximation"])
        work.answer("axial_rate", "omega_z", [omega], "rate", ["approximation"])
        work.answer("precession", "phidot", [precession], "rate")
    else:
        omega = given[rate]
        symbol = "psidot" if rate == "spin" else "omega_z"
        if omega == 0:
            raise InputError(f"the approximation m g l / (J {symbol}) needs a non-zero {rate}",
                             key=f"given.{rate}")
        precession = work.step("phidot_approx", steady.precession_approx(
            _driver_tree(D, "m g l"), J_v, _rate(symbol, omega)), unit="rad/s")
        for name, symbol_ in (("precession_approx", "phidot_approx"), ("precession", "phidot")):
            work.answer(name, symbol_, [precession], "rate", ["approximation"])
        work.answer(rate, symbol, [omega], "rate")
    if "precession_period" in find:
        work.answer("precession_period", "T", [work.step(
            "T", 2 * PI / _abs_rate(precession), unit="s")], "time", ["approximation"])
    missing = sorted(name for name in find if name not in work.answers)
    if missing:
        raise InputError(f"{missing[0]} needs the angle theta of the axis from the upward "
                         "vertical (omega_z = psidot + phidot cos(theta))", key="given.theta")
    work.warn(*approximation_only, *_spread(body, rate, given[rate], D, work))


_NEITHER_GIVEN = ("the exact roots need ", th, " and the transverse inertia about the pivot "
                  "(I_pivot, k_pivot, I_cg or k_cg, or a shape), neither given")
_AND_I = (" and the transverse inertia ", I_)


@cache
def _angle(degrees: float) -> Expr:
    """30 deg, 60 deg, 90 deg: the angles of the spread."""
    return _deg(degrees)


@cache
def _at_angle(root: str, degrees: float) -> Expr:
    """``phidot_slow at 30 deg``: the exact root at an angle, by its symbol and the angle."""
    return words("at", names(root)[0], _angle(degrees))


def _spread(body, rate: str, value: float, D: float, work: Work) -> tuple:
    """How far the exact slow root moves between 30 and 90 deg, as a clause for the warning."""
    if body.I_pivot is None:
        work.text(*_NEITHER_GIVEN)
        return _AND_I
    I, J = body.I_pivot, body.J
    slow: dict[float, float | None] = {}
    for degrees in SPREAD_ANGLES:
        theta = math.radians(degrees)
        if rate == "precession":
            slow[degrees] = spin_for_precession(I, J, theta, value, D)
            continue
        roots = precession_from_spin(I, J, theta, value, D) if rate == "spin" else \
            precession_from_axial_rate(I, J, theta, value, D)
        slow[degrees] = min(roots, key=abs) if roots else None
    name = "spin" if rate == "precession" else "slow precession root"
    work.text("for comparison, the exact " + name + " of Eq. 11.13 (", _THETA_STEADY,
              ") with the transverse inertia ", rel(I_, "=", q(I, "kg m^2")), " at three angles:")
    exact_root = "psidot" if rate == "precession" else "phidot_slow"
    for degrees, root in slow.items():
        work.step(_at_angle(exact_root, degrees), value=root, unit="rad/s",
                  note="exact, Eq. 11.13" if root is not None else
                  "no steady precession: below the least spin (the discriminant of Eq. 11.13)")
    exact, at_30 = slow[90.0], slow[30.0]
    assert exact is not None, "at 90 deg Eq. 11.13 is linear: one root for a non-zero rate"
    if at_30 is None:
        return ("; for these data the exact " + name + " is ", q(exact, "rad/s"), " at ",
                _angle(90.0), " and there is none at ", _angle(30.0), " (the spin is below the "
                "least: the discriminant of Eq. 11.13)")
    apart = abs(at_30 - exact) / abs(exact)
    return ("; for these data the exact " + name + " is ", q(at_30, "rad/s"), " at ",
            _angle(30.0), " and ", q(exact, "rad/s"), " at ", _angle(90.0), ", ",
            _percent(apart, 2), "% apart")


_TORQUE_FREE = (rel(l0, "=", 0), " and no applied moment: a torque-free body, ", rel(D_, "=", 0),
                ", where ", D_, " is the moment per unit ", sin_(th))


def _driver(given: Given, theta: float, work: Work) -> tuple[float, str]:
    """D = M / sin(theta): from an applied moment, or gravity's m g l."""
    body = given.solid_body
    work.section("Moment about the line of nodes")
    if "moment" in given:
        if body.l:
            raise InputError("give an applied moment or gravity (cg_distance), not both: the "
                             "applied moment replaces gravity's", key="given.moment")
        M = given["moment"]
        D = work.step("D", Sym("M", M, "N m") / sin_(_theta(theta)), unit="N*m")
        return D, "D"
    if body.l == 0:
        work.text(*_TORQUE_FREE)
        return 0.0, "D"
    work.step("M", Sym("m", body.mass_for_rates, "kg") * Sym("g", body.g, "m/s^2")
              * Sym("l", body.l, "m") * sin_(_theta(theta)), unit="N*m",
              ref="Eq. 11.11, gravity")
    return body.mgl, "m g l"


_THETA_STEADY = rel(tdd0, "=", 0)  # thetaddot = 0
_STEADY_TITLE = ("Steady precession, Eq. 11.13 with ", _THETA_STEADY, " and ", _AXIAL_RATE)
_PHIDOT_SQUARED = phd ** 2


@cache
def _spin_quadratic(driver: str) -> tuple:
    """(J - I) cos(theta) phidot^2 + J psidot phidot - m g l = 0 (Eq. 11.13, thetaddot = 0)."""
    return (rel((J_ - I_) * cos_(th) * _PHIDOT_SQUARED + J_ * psd * phd - _moment_of(driver), "=",
                0),)


@cache
def _axial_quadratic(driver: str) -> tuple:
    """phidot^2 cos(theta) - gamma phidot + a / 2 = 0 with its gamma and a (Eq. 11.20)."""
    gamma, a_ = names("gamma a")
    return (rel(_PHIDOT_SQUARED * cos_(th) - gamma * phd + a_ / 2, "=", 0), ", ",
            rel(gamma, "=", J_ * wz / I_), ", ", rel(a_, "=", 2 * _moment_of(driver) / I_),
            "    (Eq. 11.20)")


#: where each least rate comes from: Eq. 11.21 (corrected) bounds omega_z; the least psidot
#: is the discriminant of Eq. 11.13 at a given psidot, another number (965.4 rpm for 11/3,
#: where the least omega_z is 1091 rpm)
_LEAST_REF: dict[str, tuple[str | Expr, ...]] = {
    "psidot": ("the discriminant of Eq. 11.13; Eq. 11.21 is its ", wz, " form"),
    "omega_z": ("Eq. 11.21",)}


@cache
def _least_spin(driver: str) -> Expr:
    """The least psidot with a real root: the discriminant of Eq. 11.13 at a given psidot
    (Eq. 11.21, corrected, is the bound on omega_z)."""
    return 2 * sqrt((I_ - J_) * _moment_of(driver) * cos_(th)) / J_


@cache
def _least_axial_rate(driver: str) -> Expr:
    """The least omega_z with a real root (Eq. 11.21 corrected)."""
    return 2 * sqrt(I_ * _moment_of(driver) * cos_(th)) / J_



_NO_PRECESSION = ("no moment: ", rel(phd, "=", 0), " (the body spinning about a fixed axis) also "
                  "solves the equation; it is no precession and is left out")


@cache
def _one_root(at_90: bool) -> tuple:
    """One root: the phidot^2 term vanishes, at theta = 90 deg or with I = J."""
    return ("one root: the ", _PHIDOT_SQUARED, " term vanishes (",
            _AT_90 if at_90 else rel(I_, "=", J_), ")")



_EXACT_AT_90 = ("at ", _AT_90, ", exact")


def _precession_roots(given: Given, rate: str, I: float, J: float, theta: float, D: float,
                      driver: str, work: Work) -> None:
    cos = cos_theta(theta)
    work.section(*_STEADY_TITLE)
    if rate == "spin":
        spin = given["spin"]
        a, b = (J - I) * cos, J * spin
        work.text(*_spin_quadratic(driver))
        work.text(rel(paren(q(a, "kg m^2")) * _PHIDOT_SQUARED + paren(q(b, "kg m^2/s")) * phd
                      - q(D, "N m"), "=", 0))
        roots = precession_from_spin(I, J, theta, spin, D)
        least, formula = min_spin(I, J, theta, D), _least_spin(driver)
        symbol = "psidot"
    else:
        axial = given["axial_rate"]
        work.text(*_axial_quadratic(driver))
        J_v, I_v = Sym("J", J, "kg m^2"), Sym("I", I, "kg m^2")
        work.step("gamma", J_v * _rate("omega_z", axial) / I_v, unit="rad/s")
        work.step("a", 2 * _driver_tree(D, driver) / I_v, unit="1/s^2")
        roots = precession_from_axial_rate(I, J, theta, axial, D)
        least, formula = min_axial_rate(I, J, theta, D), _least_axial_rate(driver)
        symbol, spin = "omega_z", None
    if D == 0 and 0.0 in roots:
        roots = [r for r in roots if r != 0.0]
        work.text(*_NO_PRECESSION)
        if not roots:
            raise InputError(f"with no moment there is no steady precession at theta = "
                             f"{num(math.degrees(theta))} deg other than phidot = 0 (a "
                             "torque-free body precesses only where (J - I) cos(theta) is not "
                             "0)", key="given.moment" if "moment" in given
                             else "given.cg_distance")
    if not roots and given[rate] == 0:
        raise InputError(f"a {rate} of 0 is too low for steady precession at theta = "
                         f"{num(math.degrees(theta))} deg: without spin the moment "
                         f"{driver} sin(theta) has no angular momentum to turn; give a spin",
                         key=f"given.{rate}")
    if not roots:
        raise InputError(
            f"{rate} {qty(given[rate], 'rad/s')} ({num(given[rate] / RPM)} rpm) is too low for "
            f"steady precession at theta = {num(math.degrees(theta))} deg: the least is "
            f"{_least(symbol)} = {prose_text(formula)} = {qty(least, 'rad/s')} "
            f"({num(least / RPM)} rpm), {Prose(_LEAST_REF[symbol]).text}", key=f"given.{rate}")
    if least > 0:
        work.text("real roots exist because ", rel(names(symbol)[0], ">=",
                                                   names(_least(symbol))[0], "=", formula, "=",
                                                   q(least, "rad/s")),
                  "    (", *_LEAST_REF[symbol], ")")
    if len(roots) == 1:
        work.text(*_one_root(abs(cos) < 1e-12))
    labels = _labels(roots)
    if abs(cos) == 0 and len(roots) == 1 and D:
        omega = given["spin"] if rate == "spin" else given["axial_rate"]
        M = D * math.sin(theta)
        roots = [work.step("phidot", Sym("M", M, "N m") / (Sym("J", J, "kg m^2") * _rate(
            "psidot", omega)), unit="rad/s", ref="Eq. 11.13",
            note=_EXACT_AT_90)]
    else:
        for root, label in zip(roots, labels):
            work.step(_label("phidot", label), value=root, unit="rad/s")
    work.answer("precession", "phidot", roots, "rate", labels)
    spins = [spin] * len(roots) if spin is not None else \
        [given["axial_rate"] - p * cos for p in roots]
    if spin is None:  # the spin at each root, from the given axial rate (Eq. 11.8)
        for p, _s, label in zip(roots, spins, labels or [""] * len(roots)):
            work.step(_label("psidot", label),
                      _rate("omega_z", given["axial_rate"]) - _rate("phidot", p)
                      * cos_(_theta(theta)), unit="rad/s", ref="Eq. 11.8")
    axials = [s + p * cos for s, p in zip(spins, roots)]
    work.answer("spin", "psidot", spins, "rate", labels)
    work.answer("axial_rate", "omega_z", axials, "rate", labels)
    work.answer("moment", "M", [D * math.sin(theta)] * len(roots), "moment", labels)
    _check(I, J, theta, spins, roots, D, work, driver)




@cache
def _spin_words(driver: str) -> tuple[tuple, tuple, tuple]:
    """The title, the equation J psidot phidot + (J - I) cos(theta) phidot^2 = m g l (or
    D), by driver, and the note on a negative spin."""
    title = ("Spin for the given precession, Eq. 11.13 with ", _THETA_STEADY, " solved for ", psd)
    equation = (rel(J_ * psd * phd + (J_ - I_) * cos_(th) * _PHIDOT_SQUARED, "=",
                    _moment_of(driver)),)
    against = (rel(psd, "<", 0), ": the body spins against the sense that precession alone "
               "would need; the sign is the answer, not an error")
    return title, equation, against


def _from_precession_or_pair(given: Given, rates: list[str], I: float, J: float, theta: float,
                             D: float, driver: str, work: Work) -> None:
    cos = cos_theta(theta)
    if "precession" in rates:
        precession = given["precession"]
    else:
        work.section("Precession from the two rates, ", _AXIAL_RATE)
        if abs(cos) < 1e-12:
            raise InputError("at theta = 90 deg omega_z = psidot whatever the precession: give "
                             "the precession itself", key="given.axial_rate")
        precession = work.step("phidot", (_rate("omega_z", given["axial_rate"])
                                          - _rate("psidot", given["spin"]))
                               / cos_(_theta(theta)), unit="rad/s")
    if len(rates) == 2:
        spin = given["spin"] if "spin" in given else given["axial_rate"] - precession * cos
        _moment(I, J, theta, spin, precession, D, driver, work)
        work.answer("precession", "phidot", [precession], "rate")
        return
    if precession == 0:
        raise InputError("a steady precession of zero needs no spin and no moment: give a "
                         "non-zero precession", key="given.precession")
    title, equation, against = _spin_words(driver)
    work.section(*title)
    work.text(*equation)
    J_v, I_v, phidot = Sym("J", J, "kg m^2"), Sym("I", I, "kg m^2"), _rate("phidot", precession)
    if cos_theta(theta) == 0:  # the (J - I) term is 0: I, perhaps not given, is not shown
        spin = work.step("psidot", _driver_tree(D, driver) / (J_v * phidot), unit="rad/s",
                         note=(_COS_0,))
    else:
        spin = work.step("psidot", (_driver_tree(D, driver) - (J_v - I_v) * cos_(_theta(theta))
                                    * phidot ** 2) / (J_v * phidot), unit="rad/s")
    axial = work.step("omega_z", _rate("psidot", spin) + phidot * cos_(_theta(theta)),
                      unit="rad/s", ref="Eq. 11.8")
    if spin < 0:
        work.text(*against)
    work.answer("precession", "phidot", [precession], "rate")
    work.answer("spin", "psidot", [spin], "rate")
    work.answer("axial_rate", "omega_z", [axial], "rate")
    work.answer("moment", "M", [D * math.sin(theta)], "moment")
    _check(I, J, theta, [spin], [precession], D, work, driver)


_DH = deriv(H)  # dH/dt


@cache
def _moment_title() -> tuple:
    return ("Moment for the motion, Eq. 11.13 with ", _THETA_STEADY, " (",
            rel(_DH, "=", names("M")[0]), ")")


@cache
def _applied(driver: str) -> Expr:
    """The applied moment about the line of nodes, m g l sin(theta) (or D sin(theta))."""
    return _moment_of(driver) * sin_(th)


def _moment(I: float, J: float, theta: float, spin: float, precession: float, D: float,
            driver: str, work: Work) -> None:
    sin = math.sin(theta)
    work.section(*_moment_title())
    phidot, th_v = _rate("phidot", precession), _theta(theta)
    axial = work.step("omega_z", _rate("psidot", spin) + phidot * cos_(th_v), unit="rad/s",
                      ref="Eq. 11.8")
    J_v, I_v = Sym("J", J, "kg m^2"), Sym("I", I, "kg m^2")
    M = work.step("M", phidot * sin_(th_v) * (J_v * _rate("omega_z", axial) - I_v * phidot
                                              * cos_(th_v)), unit="N*m")  # moment_required
    if D:
        work.text("of which ", rel(_applied(driver), "=", q(D * sin, "N m")),
                  " is supplied; the rest, ", q(M - D * sin, "N m"), ", must be applied")
    work.answer("spin", "psidot", [spin], "rate")
    work.answer("axial_rate", "omega_z", [axial], "rate")
    work.answer("moment", "M", [M], "moment")


@cache
def _no_least_spin(driver: str) -> tuple:
    """(I - J) m g l cos(theta) <= 0: no least spin (Eq. 11.21)."""
    return (rel((I_ - J_) * _moment_of(driver) * cos_(th), "<=", 0),
            ": real roots for every spin, no least spin (", rel(names("psidot_min")[0], "=", 0),
            ")")


def _min_spin(I: float, J: float, theta: float, D: float, driver: str, work: Work) -> None:
    work.section("Least spin for steady precession (discriminant of Eq. 11.13)")
    least = min_spin(I, J, theta, D)
    if least > 0:
        J_v, I_v = Sym("J", J, "kg m^2"), Sym("I", I, "kg m^2")
        # (I - J) and cos(theta) shown by value, as the chapter's Eq. 11.21 is worked
        difference = Let(Sym("I_minus_J", I - J, "kg m^2"), I_v - J_v)
        cos_value = Let(Sym("cos_theta", cos_theta(theta)), cos_(_theta(theta)))
        work.step("psidot_min", 2 * sqrt(difference * _driver_tree(D, driver) * cos_value)
                  / J_v, unit="rad/s")
    else:
        work.text(*_no_least_spin(driver))
    work.answer("min_spin", "psidot_min", [least], "rate")


#: dH/dt = phidot sin(theta) (J omega_z - I phidot cos(theta)), Eq. 11.13 with thetaddot = 0
_RATE_OF_H = phd * sin_(th) * (J_ * wz - I_ * phd * cos_(th))


def _check(I: float, J: float, theta: float, spins: list[float], precessions: list[float],
           D: float, work: Work, driver: str = "D") -> None:
    """Each root in the vector form dH/dt = M, beside gravity's (or the applied) moment,
    written with the symbols of the steps (m g l, or D = M / sin(theta) when applied)."""
    for spin, precession in zip(spins, precessions):
        rate = moment_required(I, J, theta, spin, precession)
        work.check(rel(phd, "=", q(precession, "rad/s")), ": ",
                   rel(_DH, "=", _RATE_OF_H, "=", q(rate, "N m")), "; applied ",
                   rel(_applied(driver), "=", q(D * math.sin(theta), "N m")))


def _least(symbol: str) -> str:
    """The least value's symbol: psidot_min, omega_z,min (one subscript)."""
    return f"{symbol},min" if "_" in symbol else f"{symbol}_min"


@cache
def _stability_words() -> tuple[tuple, tuple, Expr, Expr, Expr]:
    """The title, the account, the frequency sqrt(k), the growth of an unstable root and
    its rate sigma."""
    k0, U0, p_phi0, p_psi0, sigma0, t0 = names("k U_eff p_phi p_psi sigma t")
    title = ("Stability: small changes of ", th, " with ", p_phi0, " and ", p_psi0,
             " fixed, ", rel(prime(th, 2) + k0 * th, "=", 0))
    growth = exp(sigma0 * t0)
    account = (
        rel(k0, "=", fn("U_eff''", th) / I_, "=",
            ((J_ * wz - 2 * I_ * phd * cos_(th)) / I_)**2 + _PHIDOT_SQUARED * sin_(th)**2, ">=",
            0),
        " (Eqs. 11.13-11.16; Goldstein Sec. 5.7): every steady precession of a heavy top about "
        "a fixed point is a minimum of ", U0, ", stable; a change of ", p_phi0, " or ", p_psi0,
        " only moves it to a neighbouring steady precession; an unstable root (",
        rel(k0, "<", 0), ") would grow as ", growth, " with the growth rate ",
        rel(sigma0, "=", sqrt(-k0)), ", and ", rel(sigma0, "=", 0), " for a stable one")
    return title, account, sqrt(k0), growth, sigma0


def _stability(given: Given, n_rates: int, I: float, J: float, theta: float,
               work: Work) -> None:
    """Each root's stability in theta (physics/stability.py: theta'' + k theta = 0)."""
    from ..physics.stability import UNSTABLE, top_steady_precession

    if "moment" in given or n_rates == 2:
        raise InputError("stability is worked for a top held by gravity alone (cg_distance, "
                         "one of spin, axial_rate, precession): how an applied moment changes "
                         "with theta is not given", key="find.stability")
    answer = work.answers["precession"]
    title, account, sqrt_k, growth, sigma0 = _stability_words()
    work.section(*title)
    work.text(*account)
    words, rates = [], []
    for phidot, axial, label in zip(answer.si_values, work.answers["axial_rate"].si_values,
                                    answer.labels or [""] * len(answer.si_values)):
        verdict = top_steady_precession(I, J, theta, phidot, axial)
        work.step(_label("k", label), value=verdict.k, unit="1/s^2", note=(
            verdict.word, ", ", th, " oscillates at ",
            rel(sqrt_k, "=", q(verdict.frequency, "rad/s"))) if verdict.frequency else
            verdict.word)
        if verdict.word == UNSTABLE:
            work.warn("the steady precession ", rel(phd, "=", q(phidot, "rad/s")), " is "
                      "unstable: a small disturbance grows as ", growth, " with ",
                      rel(sigma0, "=", q(verdict.growth_rate, "1/s")))
        words.append(verdict.word)
        rates.append(verdict.growth_rate)
    work.answer("stability", "stability", words, None, answer.labels)
    work.answer("growth_rate", "sigma", rates, "rate", answer.labels)


def _approximation(given: Given, rate: str, J: float, theta: float, D: float, driver: str,
                   work: Work) -> float:
    """The gyroscopic approximation beside the exact roots, and how far apart they are."""
    omega = given[rate]
    symbol = "psidot" if rate == "spin" else "omega_z"
    work.section("Gyroscopic approximation (the ", _DROPPED[symbol], " term dropped)")
    if omega == 0:
        raise InputError(f"the approximation {driver} / (J {symbol}) needs a non-zero {rate}",
                         key=f"given.{rate}")
    value = work.step("phidot_approx", steady.precession_approx(
        _driver_tree(D, driver), Sym("J", J, "kg m^2"), _rate(symbol, omega)), unit="rad/s")
    exact = work.answers.get("precession")
    if exact and exact.si_values and exact.labels != ["approximation"]:
        slow = min(exact.si_values, key=abs)
        if slow:
            apart = abs(value - slow) / abs(slow)
            if apart < 1e-12:
                work.text("at ", _AT_90, " the approximation is exact: it equals the root ",
                          q(slow, "rad/s"))
            else:
                work.text("the approximation is ", _percent(apart, 3), "% from the slow root ",
                          q(slow, "rad/s"))
    work.answer("precession_approx", "phidot_approx", [value], "rate", ["approximation"])
    return value


def _approximate_only(given: Given, rate: str, J: float, theta: float, D: float, driver: str,
                      work: Work) -> None:
    """No transverse inertia away from 90 deg: the approximation, labelled, and a warning."""
    value = _approximation(given, rate, J, theta, D, driver, work)
    work.warn("no transverse inertia (I_pivot, k_pivot, I_cg or k_cg, or a shape) was given: "
              "`precession` is the gyroscopic approximation ", names("phidot_approx")[0],
              ", not an exact root of Eq. 11.13; the exact roots need ", I_)
    cos = cos_theta(theta)
    spin = given["spin"] if rate == "spin" else given["axial_rate"] - value * cos
    work.answer("precession", "phidot", [value], "rate", ["approximation"])
    work.answer("spin", "psidot", [spin], "rate", ["approximation"])
    work.answer("axial_rate", "omega_z", [spin + value * cos], "rate", ["approximation"])
    work.answer("moment", "M", [D * math.sin(theta)], "moment")


def _by_root(find: frozenset[str], work: Work) -> None:
    """precession_slow/_fast and spin_slow/_fast: one root named, for keys that quote one."""
    for name in ("precession", "spin"):
        answer = work.answers.get(name)
        for which in ("slow", "fast"):
            key = f"{name}_{which}"
            if answer is None or key not in find:
                continue
            if which in answer.labels:
                value = answer.si_values[answer.labels.index(which)]
            elif which == "slow" and len(answer.si_values) == 1 and not answer.labels:
                value = answer.si_values[0]  # one root (theta = 90 deg, I = J, torque-free)
            else:
                raise InputError(f"there is no {which} root here (one steady precession "
                                 f"only{', and it is the approximation' if answer.labels == ['approximation'] else ''}); "
                                 f"ask for {name}", key=f"find.{key}")
            work.answer(key, f"{answer.symbol}_{which}", [value], "rate")


@cache
def _cg_circle() -> tuple:
    return ("the centre of mass runs round a horizontal circle of radius ", l0 * sin_(th),
            " at the rate ", phd, " (", th, " constant)")


@cache
def _pivot_words() -> tuple[tuple, Expr, tuple]:
    """Newton's law for the centre of mass, |F|, and the check of the pivot force: its
    moment about G against dH_G/dt (Eq. 11.13 about G), after the numbers."""
    F0, a_G0, G0, I_G0, H_G0, F_v0, F_h0 = names("F a_G G I_G H_G F_vertical F_horizontal")
    newton = ("Newton's second law for the centre of mass, ", rel(F0 + m0 * g0, "=", m0 * a_G0),
              ", where ", F0, " is the force of the support: it carries the weight and supplies "
              "the centripetal force")
    about_g = (" the transverse moment about ", G0, " and ", H_G0, " the angular momentum "
               "about ", G0, ", ")
    pivot_moment = l0 * (F_v0 * sin_(th) + F_h0 * cos_(th))
    rate_of_h_g = phd * sin_(th) * (J_ * wz - I_G0 * phd * cos_(th))
    check = (G0, I_G0, I_ - m0 * l0**2, about_g, pivot_moment, deriv(H_G0), rate_of_h_g)
    return newton, absolute(F0), check


def _motion(body, theta: float, find: frozenset[str], work: Work) -> None:
    """Period, centre-of-mass speed and acceleration and the pivot force, root by root."""
    answer = work.answers.get("precession")
    if answer is None:
        raise InputError("these answers need the precession: give spin, axial_rate or "
                         "precession", key="given.spin")
    rates, labels = answer.si_values, answer.labels or [""] * len(answer.si_values)
    l = body.l
    work.section("Motion of the centre of mass and the force at the pivot")
    work.text(*_cg_circle())
    if "precession_period" in find:
        if any(p == 0 for p in rates):
            raise InputError("the precession rate is 0: it never completes a turn",
                             key="find.precession_period")
        for p, tag in zip(rates, labels):
            work.step(_label("T", tag), 2 * PI / _abs_rate(p), unit="s")
        work.answer("precession_period", "T", [steady.precession_period(p) for p in rates],
                    "time", answer.labels)
    if "cg_speed" in find:
        for p, tag in zip(rates, labels):
            work.step(_label("v_G", tag), Sym("l", l, "m") * sin_(_theta(theta)) * _abs_rate(p),
                      unit="m/s")
        work.answer("cg_speed", "v_G", [steady.cg_speed(l, theta, p) for p in rates], "speed",
                    answer.labels)
    if "cg_acceleration" in find or "pivot_force" in find:
        for p, tag in zip(rates, labels):
            work.step(_label("a_G", tag), Sym("l", l, "m") * sin_(_theta(theta))
                      * _rate("phidot", p) ** 2, unit="m/s^2", note="toward the precession axis")
        work.answer("cg_acceleration", "a_G", [steady.cg_acceleration(l, theta, p)
                                                for p in rates], "acceleration", answer.labels)
    if "pivot_force" in find:
        m, g = body.m, body.g
        newton, size_of_f, (G0, I_G0, I_G_tree, about_g, pivot_moment, dh_g, rate_of_h_g) = \
            _pivot_words()
        work.text(*newton)
        values, parts = [], []
        forces = [steady.pivot_force(m, g, l, theta, p) for p in rates]  # for the steps and check
        for i, (p, tag, (up, toward, size)) in enumerate(zip(rates, labels, forces)):
            if i == 0:
                work.step("F_vertical", Sym("m", m, "kg") * Sym("g", g, "m/s^2"), unit="N",
                          note="upward")
                values.append(up)
                parts.append("vertical")
            a_G = Let(Sym("a_G", steady.cg_acceleration(l, theta, p), "m/s^2"),
                      Sym("l", l, "m") * sin_(_theta(theta)) * _rate("phidot", p) ** 2)
            work.step(_label("F_horizontal", tag), Sym("m", m, "kg") * a_G, unit="N",
                      note="toward the precession axis")
            size = work.step(_label(size_of_f, tag), sqrt(Sym("F_vertical", up, "N") ** 2 + Sym(
                "F_horizontal", toward, "N") ** 2), unit="N", substitute=False)
            values += [toward, size]
            parts += [f"horizontal{_tag(tag)}", f"magnitude{_tag(tag)}"]
        work.answer("pivot_force", "F", values, "force", parts)
        if body.I_pivot is not None and "moment" not in given_keys(work):
            I_G = body.I_pivot - m * l * l
            for p, (up, toward, _) in zip(rates, forces):
                spin = _spin_for(work, p)
                axial = spin + p * cos_theta(theta)
                rate = p * math.sin(theta) * (body.J * axial - I_G * p * cos_theta(theta))
                work.check(rel(phd, "=", q(p, "rad/s")), ": moment of the pivot force about ",
                           G0, ", with ", rel(I_G0, "=", I_G_tree, "=", q(I_G, "kg m^2")),
                           *about_g,
                           rel(pivot_moment, "=",
                               q(l * (up * math.sin(theta) + toward * cos_theta(theta)), "N m")),
                           "; ", rel(dh_g, "=", rate_of_h_g, "=", q(rate, "N m")))


def _tag(label: str) -> str:
    return f" ({label})" if label else ""


def given_keys(work: Work) -> set[str]:
    return {line.key for line in work.given}


def _spin_for(work: Work, precession: float) -> float:
    spin = work.answers["spin"]
    values = work.answers["precession"].si_values
    return spin.si_values[values.index(precession)] if len(spin.si_values) == len(values) \
        else spin.si_values[0]


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
        Param("theta", "angle", "theta", "angle of the symmetry axis from the upward vertical",
              range=(0.0, math.pi)),  # the ends (the axis vertical) are refused by the kind
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
                   "perturbed, gravity alone)", words=("stable", "unstable")),
        AnswerSpec("growth_rate", "rate", "sigma", "growth rate of the unstable mode, 1/s (0 when "
                   "stable)"),
        AnswerSpec("precession_slow", "rate", "phidot_slow", "the slow root alone (the one "
                   "books quote)"),
        AnswerSpec("precession_fast", "rate", "phidot_fast", "the fast root alone"),
        AnswerSpec("spin_slow", "rate", "psidot_slow", "spin at the slow root (given axial_rate)"),
        AnswerSpec("spin_fast", "rate", "psidot_fast", "spin at the fast root (given axial_rate)"),
        AnswerSpec("precession_approx", "rate", "phidot_approx", "gyroscopic approximation m g l "
                   "/ (J omega), beside the exact roots"),
        AnswerSpec("precession_period", "time", "T", "time for one turn of the precession, "
                   "2 pi / |phidot|"),
        AnswerSpec("cg_speed", "speed", "v_G", "speed of the centre of mass, l sin(theta) "
                   "|phidot|"),
        AnswerSpec("cg_acceleration", "acceleration", "a_G", "centripetal acceleration of the "
                   "centre of mass, l sin(theta) phidot^2"),
        AnswerSpec("pivot_force", "force", "F", "force of the support on the body: [vertical "
                   "(up), horizontal (toward the axis), magnitude] per root"),
    ),
    solve=solve,
    animation="steady_top", simulation="steady", physics=("gyro_cli.physics.stability",),
    size_free=True, example={
        "statement": ("A top weighing {weight} has radii of gyration of {k_axial} about its axis "
                      "and {k_pivot} about its point of support, and its centre of mass is "
                      "{cg_distance} from that point. It spins at {spin} with its axis at {theta} "
                      "from the upward vertical. Find the two possible rates of steady precession and the "
                      "least spin at which steady precession is possible at this angle."),
        "given": {"weight": "3 oz", "k_axial": "0.84 in", "k_pivot": "1.80 in",
                  "cg_distance": "1.5 in", "spin": "1800 rpm", "theta": "30 deg"},
        "find": {"precession": "rpm", "min_spin": "rpm"},
        "vary": {"spin": "[0.8, 1.2]", "theta": "[20 deg, 40 deg]"}},
)
