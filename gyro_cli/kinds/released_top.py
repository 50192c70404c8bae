"""The heavy top released at theta0 with spin: nutation limits, period, precession.

Chapter 11, Eqs. 11.14-11.26 (Eq. 11.24 corrected: gamma^2/a), solved exactly by
gyro_cli.physics.nutation: the roots of the cubic f(u) of Eq. 11.19 give the nutation
limits, complete elliptic integrals the period and the mean precession.
"""

from __future__ import annotations

import math

from ..core.errors import InputError
from ..core.expr import NAMED, PI, Expr, Let, Num, Sym, absolute, acos, asin, cos, ellipk, sin, sqrt
from ..core.given import Given
from ..core.prose import bracket, fn, integral, names, pm, q, rel
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work, num

RPM = 2 * math.pi / 60
DEG = math.pi / 180


def _deg(x: float) -> str:
    return f"{num(x / DEG)} deg"


def _rel(approx: float, exact: float) -> tuple:
    """The relative error as pieces: ``-18%``, or ``n/a``."""
    return (q(100 * (approx - exact) / exact, sig=2), "%") if exact else ("n/a",)


# the names of the sentences (no values): Eq. 11.19's u and its roots, the chapter's symbols
(u, u0, u1, u2, u3, u_i, f, udot, s_, m_, K_, T_, phi, theta, theta0, theta_min, theta_max,
 phidot, psidot, thetadot0, omega_z, I_, J_, a_, alpha_, beta_, gamma_, n1, n2, n_, m, g, l,
 t_) = names("u u0 u1 u2 u3 u_i f udot s m K T phi theta theta0 theta_min theta_max phidot "
             "psidot thetadot0 omega_z I J a alpha beta gamma n1 n2 n m g l t")


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    from ..physics.nutation import Start, Top, analyse, constants

    body = given.solid_body
    body.require("J", "I_pivot")
    if not body.l or body.l <= 0:
        raise InputError("a released top needs its centre of mass off the fixed point: give "
                         "cg_distance > 0 (with l = 0 there is no gravity moment and no "
                         "nutation of this kind)", key="given.cg_distance")
    theta0, spin = given["theta0"], given["spin"]
    precession0 = given.get("precession0", 0.0) or 0.0
    theta_rate0 = given.get("theta_rate0", 0.0) or 0.0
    theta0 = min(theta0, math.pi)
    vertical = abs(math.sin(theta0)) < 1e-15
    top = Top(I=body.needed("I_pivot"), J=body.needed("J"), mgl=body.mgl)
    start = Start(theta0=theta0, spin=spin, precession0=precession0, theta_rate0=theta_rate0)
    omega_z = constants(top, start)["omega_z"]
    if vertical and omega_z == 0 and theta_rate0 == 0:
        raise InputError(f"theta0 = {_deg(theta0)} with no spin about the axis: the top stands "
                         "(or hangs) on the vertical and does not move", key="given.theta0")
    nut = analyse(top, start)
    t = _syms(top, start, nut, omega_z)
    _constants(t, nut, work)
    _roots(nut, work)
    if nut.motion == "sleeping":
        _sleeping(top, start, nut, omega_z, t, find, work)
        return
    released = precession0 == 0 and theta_rate0 == 0
    if released:
        _released(nut, t, work)
    _period(nut, work)
    _precession(start, nut, work)
    _fast_top(nut, t, released, work)
    _answers(nut, work)
    if find & {"spin_at_limits", "reversal_theta"}:
        _spin_and_reversal(nut, omega_z, find, work)
    pole = "0" if nut.theta_min == 0 else "180" if nut.theta_max == math.pi else ""
    if pole:
        work.warn("the axis passes through the vertical (",
                  rel(theta, "=", q(math.radians(float(pole)), "deg", exact=True)),
                  ") once a period: there ", phi, " jumps by ",
                  pm(None, q(math.pi, "deg", exact=True)), " (which sign is undefined); "
                  "mean_precession counts only the continuous advance, the integral of Eq. "
                  "11.16 (the two one-sided limits are mean_precession ",
                  rel(pm(None, PI / T_), "=", pm(None, q(math.pi / nut.nutation_period,
                                                         "rad/s"))), ")")
    if nut.theta_max > math.pi / 2 + 1e-12:
        work.warn(rel(theta_max, "=", q(nut.theta_max, "deg")), " passes ",
                  q(math.pi / 2, "deg", exact=True), ": the centre of mass goes below the "
                  "fixed point; a top standing on a floor would touch it (the analysis assumes "
                  "a fixed point free to swing, as in a ball joint)")


# The sentences that hold no values are built once, here, and only their values' steps
# each time: building a sentence's trees cost as much as a third of the kind's time.
_CONSTANTS_TITLE = ("Constants of the motion at ", rel(t_, "=", 0),
                    " (Eqs. 11.8, 11.14, 11.17, 11.18)")
_CONVENTIONS: tuple[str | Expr, ...] = ("Euler angles z-x-z; ", phi, ": the azimuth of the axis about the vertical; ",
                theta, " from the upward vertical to the axis through the centre of mass, ",
                rel(*names("V"), "=", m * g * l * cos(theta)), " (Eq. 11.11); spin ", psidot,
                " is relative to the precessing frame, which turns about the vertical at the "
                "precession rate ", phidot, "; ", *names("thetadot"), ": the rate of ", theta,
                "; the suffix ", Num(0), " marks a value at ", rel(t_, "=", 0))


def _constants(t: dict[str, Expr], nut, work: Work) -> None:
    work.section(*_CONSTANTS_TITLE)
    work.text(*_CONVENTIONS)
    th0 = cos(t["theta0"])
    work.step("omega_z", t["psidot"] + t["phidot0"] * th0, unit="rad/s", ref="Eq. 11.8")
    work.step("P2", t["J"] * t["omega_z"], unit="kg m^2/s", ref="Eq. 11.14")
    work.step("P1", t["I"] * t["phidot0"] * sin(t["theta0"]) ** 2 + t["P2"] * th0,
              unit="kg m^2/s", ref="Eq. 11.14")
    work.step("h", (t["I"] * (t["thetadot0"] ** 2 + t["phidot0"] ** 2 * sin(t["theta0"]) ** 2)
                    + t["J"] * t["omega_z"] ** 2) / 2 + t["mgl"] * th0, unit="J", ref="Eq. 11.17")
    work.step("a", 2 * t["mgl"] / t["I"], unit="1/s^2", ref="Eq. 11.18")
    work.step("alpha", 2 * Sym("h", nut.energy, "J") / t["I"] - t["P2"] ** 2 / (t["I"] * t["J"]),
              unit="1/s^2", ref="Eq. 11.18")
    work.step("beta", Sym("P1", nut.P1, "kg m^2/s") / t["I"], unit="rad/s", ref="Eq. 11.18")
    work.step("gamma", t["P2"] / t["I"], unit="rad/s", ref="Eq. 11.18")


def _syms(top, start, nut, omega_z: float) -> dict[str, Expr]:
    """The symbols of the worked answer, SI values (m g l is one product, N m)."""
    mgl = Let(Sym("mgl", top.mgl, "N m"), Sym("m", NAMED) * Sym("g", NAMED) * Sym("l", NAMED))
    return {"J": Sym("J", top.J, "kg m^2"), "I": Sym("I", top.I, "kg m^2"), "mgl": mgl,
            "theta0": Sym("theta0", start.theta0, "deg"),
            "psidot": Sym("psidot", start.spin, "rad/s"),
            "phidot0": Sym("phidot0", start.precession0, "rad/s"),
            "thetadot0": Sym("thetadot0", start.theta_rate0, "rad/s"),
            "omega_z": Sym("omega_z", omega_z, "rad/s"), "P2": Sym("P2", nut.P2, "kg m^2/s"),
            "a": Sym("a", nut.a, "1/s^2"), "gamma": Sym("gamma", nut.gamma, "rad/s"),
            "beta": Sym("beta", nut.beta, "rad/s")}


_U = names("u")[0]  # u: a root below
_ROOTS_TITLE = ("Energy integral in ", rel(_U, "=", cos(theta)), ", Eq. 11.19")
_EQ_11_19 = (rel(udot ** 2, "=", fn("f", _U), "=", (1 - _U ** 2) * (alpha_ - a_ * _U)
                 - (beta_ - gamma_ * _U) ** 2), "    (Eq. 11.19)")
_EQ_11_19_EXPANDED = ("       ", rel(None, "=", a_ * _U ** 3 - (alpha_ + gamma_ ** 2) * _U ** 2
                                   + (2 * beta_ * gamma_ - a_) * _U
                                   + bracket(alpha_ - beta_ ** 2, open="(")))
_ROOTS_LIE = (rel(fn("f", pm(None, 1)), "=", -pm(beta_, gamma_, "-+") ** 2, "<=", 0), " and ",
              rel(fn("f", u0), "=", sin(theta0) ** 2 * thetadot0 ** 2, ">=", 0), ", where ",
              rel(u0, "=", cos(theta0)), ": so the roots ", u1, ", ", u2, ", ", u3, " of ", f,
              " lie ", rel(u1, "<=", u0, "<=", u2), " in ", bracket(-1, 1), ", ",
              rel(u3, ">=", 1))
_RESIDUAL = ("at each root ", u_i, ", ", fn("f", u_i), " from Eq. 11.19 itself, largest ",
             absolute(fn("f", u_i)), " / (largest coefficient) ")


def _roots(nut, work: Work) -> None:
    a, al, b, g = nut.a, nut.alpha, nut.beta, nut.gamma
    U = _U
    work.section(*_ROOTS_TITLE)
    work.text(*_EQ_11_19)
    work.text(*_EQ_11_19_EXPANDED)
    c0 = al - b * b
    per_s2 = "1/s^2"  # the coefficients' unit (u is a number)
    cubic = (bracket(q(a, per_s2), open="(") * U ** 3
             - bracket(q(al + g * g, per_s2), open="(") * U ** 2
             + bracket(q(2 * b * g - a, per_s2), open="(") * U)
    work.text("       ", rel(None, "=", cubic - q(-c0, per_s2) if c0 < 0 else
                             cubic + q(c0, per_s2)))
    work.text(*_ROOTS_LIE)
    for i, u in enumerate(nut.u_roots, 1):
        work.step(f"u{i}", value=u)
    if nut.motion == "sleeping":
        return
    one_minus, one_plus = nut.one_minus_u0, nut.one_plus_u0
    for symbol, u, d in (("theta_max", "u1", nut.d_roots[0]), ("theta_min", "u2", nut.d_roots[1])):
        work.step(symbol, _theta(u, one_minus - d, one_plus + d), unit="deg", substitute=False)
    from ..physics.nutation import f_of_u

    scale = max(abs(a), abs(al + g * g), abs(2 * b * g - a), abs(al - b * b))
    residual = max(abs(f_of_u(nut, u)) for u in nut.u_roots) / scale
    work.check(*_RESIDUAL, rel(None, "=", q(residual, sig=2)))


def _theta(u: str, one_minus: float, one_plus: float) -> Expr:
    """theta = acos(u) as physics/nutation.py computes it, from 1 - u and 1 + u (the roots'
    offsets, no cancellation): 2 asin(sqrt((1 - u) / 2)) for u >= 0, pi - 2 asin(sqrt((1 + u)
    / 2)) below; acos(u) of a rounded u loses the digits of a small angle."""
    one_minus, one_plus = min(max(one_minus, 0.0), 2.0), min(max(one_plus, 0.0), 2.0)
    if one_minus <= one_plus:
        return 2 * asin(sqrt(Let(Sym(f"one_minus_{u}", one_minus), 1 - Sym(u, NAMED)) / 2))
    return PI - 2 * asin(sqrt(Let(Sym(f"one_plus_{u}", one_plus), 1 + Sym(u, NAMED)) / 2))


_RELEASED_TITLE = ("Released from rest (", rel(*names("phidot0"), "=", thetadot0, "=", 0),
                   "): Eqs. 11.22-11.25")
_P1, _P2 = names("P1 P2")
_EQ_11_23 = (rel(_P1, "=", _P2 * u2), " (Eq. 11.22), ", rel(alpha_, "=", a_ * u2), ", ",
             rel(fn("f", u), "=", (u2 - u) * bracket(a_ * (1 - u ** 2) - gamma_ ** 2
                                                      * (u2 - u))), " (Eq. 11.23)")
_ERRATA = ("Eq. 11.24 as corrected in the errata: ", gamma_ ** 2 / a_ * u2, " under the root, "
           "not ", gamma_ ** 2 / 2)
_FALLS: tuple[str | Expr, ...] = ("the axis falls from ", rel(*names("theta_2"), "=", theta0), " to ",
          *names("theta_1"), " and back")


def _released(nut, t: dict[str, Expr], work: Work) -> None:
    work.section(*_RELEASED_TITLE)
    work.text(*_EQ_11_23)
    work.text(*_ERRATA)
    g, a = t["gamma"], t["a"]
    u1_ = names("u1")[0]
    # as printed; the check below holds it against the root of Eq. 11.19 (no cancellation)
    u1 = work.step("u1", g ** 2 / (2 * a) - sqrt(g ** 4 / (4 * a ** 2) - g ** 2 / a
                                                  * cos(t["theta0"]) + 1), ref="Eq. 11.25")
    assert u1 is not None
    work.step("theta_1", acos(Sym("u1", max(-1.0, min(1.0, u1)))), unit="deg", substitute=False,
              note=_FALLS)
    work.check("Eq. 11.25 ", rel(u1_, "=", q(u1, sig=10)), " against the root of Eq. 11.19 ",
               rel(u1_, "=", q(nut.u_roots[0], sig=10)))


def _differences(nut) -> tuple[Expr, Expr]:
    """u2 - u1 and u3 - u1 as the differences of the roots' offsets d_i = u_i - u0, which
    physics/nutation.py computes without cancellation (u1 and u2 agree to many digits in a
    fast or nearly steady top)."""
    d1, d2, d3 = nut.d_roots
    u1, u2, u3 = (Sym(f"u{i}", NAMED) for i in (1, 2, 3))
    return (Let(Sym("u2_minus_u1", d2 - d1), u2 - u1), Let(Sym("u3_minus_u1", d3 - d1), u3 - u1))


_PERIOD_TITLE = ("Nutation period: ", rel(fn("f", u), "=", a_ * (u - u1) * (u - u2) * (u - u3)),
                 ", ", rel(u, "=", u1 + (u2 - u1) * sin(s_) ** 2))
_PERIOD = (rel(T_, "=", 2 * integral(u1, u2, names("du")[0] / sqrt(fn("f", u))), "=",
               4 * fn("K", m_) / sqrt(a_ * (u3 - u1))), ", where ", K_, " is the complete "
           "elliptic integral of the first kind and ", m_, ", below, its parameter; the "
           "substitution is ", rel(u, "=", u1 + (u2 - u1) * sin(s_) ** 2), " for ", s_,
           " from ", Num(0), " to ", PI / 2)
_K_OF_M = fn("K", m_)
_NUTATES = (rel(theta_max, "->", theta_min, "->", theta_max),)
_STEADY = (rel(u1, "=", u2), " (to rounding): no nutation; ", T_, " is the period of "
           "small oscillations about ", theta0, ", the ", rel(m_, "->", 0), " limit ",
           2 * PI / sqrt(a_ * (u3 - u1)))


def _period(nut, work: Work) -> None:
    K = nut.K  # K(m) as analyse computed it for the period
    width, span = _differences(nut)
    work.section(*_PERIOD_TITLE)
    work.text(*_PERIOD)
    m = work.step("m", width / span)
    work.step(_K_OF_M, value=K)
    # K(m) from R_F with 1 - m = (u3 - u2) / (u3 - u1) exact; ellipk(m) would lose it as m -> 1
    K_m = Let(Sym("K", K), ellipk(Sym("m", m if m is not None else NAMED)))
    work.step("T", 4 * K_m / sqrt(Sym("a", nut.a, "1/s^2") * span), unit="s", note=_NUTATES)
    if nut.motion == "steady":
        work.text(*_STEADY)


def _limit_precession(nut, u: str, terms: tuple[float, float, float]) -> Expr:
    """phidot = (beta - gamma u) / (1 - u^2) at a nutation limit (Eq. 11.16), numerator and
    denominator from the roots' offsets (physics/nutation.limit_precession_terms: beta -
    gamma u vanishes exactly at a cusp). On a pole, where both vanish, the limit gamma / 2
    (u = 1) or -gamma / 2 (u = -1)."""
    numerator, one_minus, one_plus = terms
    U = Sym(u, NAMED)
    gamma = Sym("gamma", nut.gamma, "rad/s")
    if one_minus <= 0:
        return gamma / 2
    if one_plus <= 0:
        return -gamma / 2
    return (Let(Sym(f"beta_minus_gamma_{u}", numerator),
                Sym("beta", NAMED) - Sym("gamma", NAMED) * U)
            / Let(Sym(f"one_minus_{u}_squared", one_minus * one_plus), 1 - U ** 2))


_PHIDOT_OF_U = (beta_ - gamma_ * _U) / (1 - _U ** 2)
_PRECESSION_TITLE = ("Precession: ", rel(phidot, "=", _PHIDOT_OF_U), " (Eqs. 11.16, 11.26)")
_ON_POLE = ("; the limit of ", _PHIDOT_OF_U, " on the pole")
#: each nutation limit: its root's name, phidot there (the step's symbol), the limit's name
_LIMITS = tuple((u_, fn("phidot", *names(u_)), names(where)[0])
                for u_, where in (("u1", "theta_max"), ("u2", "theta_min")))
_N1 = (n1, (u2 - u1) / (1 - u1))
_N2 = (n2, (u2 - u1) / (1 + u1))
_HALVES = (rel(phidot, "=", Num(0.5, "1/2") * bracket((beta_ - gamma_) / (1 - _U)
                                                      + (beta_ + gamma_) / (1 + _U))),
           "; with ", rel(1 - _U, "=", (1 - u1) * (1 - n1 * sin(s_) ** 2)), ", ",
           rel(1 + _U, "=", (1 + u1) * (1 + n2 * sin(s_) ** 2)), ":")
_Pi, _R_F, _R_J = names("Pi R_F R_J")
_MEAN = ("mean ", rel(phidot, "=", bracket(
    (beta_ - gamma_) * fn("Pi", n1, m_, sep="|") / (1 - u1)
    + (beta_ + gamma_) * fn("Pi", -n2, m_, sep="|") / (1 + u1)) / (2 * fn("K", m_))),
    ", where ", _Pi, " is the complete elliptic integral of the third kind, ",
    rel(fn("Pi", n_, m_, sep="|"), "=", fn("R_F", 0, 1 - m_, 1)
        + n_ / 3 * fn("R_J", 0, 1 - m_, 1, 1 - n_)),
    ", with Carlson's symmetric integrals ", _R_F, " and ", _R_J)
_ADVANCE = ("; ", phi, " advance over one period / ", T_, ")")
#: the closing sentence for each motion (Figs. 11-7, 11-9, 11-10)
_MOTION = {motion: (f"motion: {motion}. The numerator ", beta_ - gamma_ * _U, " is linear in ",
                    _U, ", so ", phidot, "'s signs over the nutation are those at ", u1, " and ",
                    u2, ": ", *reason) for motion, reason in {
    "cusps": (rel(phidot, "=", 0), " at a limit of the nutation: the axis stops there, the "
              "path has cusps (Fig. 11-9)"),
    "loops": (phidot, " changes sign between the limits: the path loops back (Fig. 11-10)"),
    "waves": (phidot, " keeps one sign between the limits: the path waves (Fig. 11-10)"),
    "steady": ("no nutation: steady precession at ", theta0, " (Fig. 11-7)"),
}.items()}


def _precession(start, nut, work: Work) -> None:
    from ..physics.nutation import limit_precession_terms

    d1, d2, d3 = nut.d_roots
    u1_, u2_, _ = nut.u_roots
    work.section(*_PRECESSION_TITLE)
    for (u, symbol, where), terms in zip(_LIMITS, limit_precession_terms(nut, start)):
        tree = _limit_precession(nut, u, terms)
        pole = _ON_POLE if min(terms[1:]) <= 0 else ()
        work.step(symbol, tree, unit="rad/s", substitute=False,
                  note=("at ", where, " (", q(tree.value / RPM, "rpm"), ")", *pole))
    if nut.motion != "steady":
        m = (d2 - d1) / (d3 - d1)
        n1_ = (u2_ - u1_) / (1 - u1_) if u1_ < 1 else math.inf
        n2_ = (u2_ - u1_) / (1 + u1_) if u1_ > -1 else math.inf
        def shown(name: Expr, formula: Expr, n: float, pole: int) -> tuple:
            # On a pole (u1 = +-1) that term's coefficient beta -+ gamma is zero: no term.
            if math.isfinite(n):
                return (rel(name, "=", formula, "=", q(n)),)
            return (rel(name, "=", formula), " = unbounded (", rel(u1, "=", pole),
                    ": the term drops)")

        work.text(*shown(*_N1, n1_, 1), ", ", *shown(*_N2, n2_, -1), ", ", rel(m_, "=", q(m)))
        work.text(*_HALVES)
        work.text(*_MEAN)
    work.step("phidot_mean", value=nut.mean_precession, unit="rad/s",
              note=("(", q(nut.mean_precession / RPM, "rpm"), *_ADVANCE))
    work.text(*_MOTION[nut.motion])


_FAST_TITLE = ("Fast-top approximation (", rel(gamma_ ** 2, ">>", a_), ")")
_GAMMA2_A = gamma_ ** 2 / a_
_NEEDS = ("(the approximation needs this ", rel(None, ">>", 1), ")")
_W_Z = names("omega_z")[0]
_FAST = (rel(u3, "~", gamma_ ** 2 / a_), ", so ", rel(sqrt(a_ * (u3 - u1)), "~", gamma_),
         ": nutation at ", J_ * _W_Z / I_, "; the slow root of Eq. 11.20 gives the mean "
         "precession ", rel(a_ / (2 * gamma_), "=", m * g * l / (J_ * _W_Z)))
_U_, _DU, _DTHETA = names("u du dtheta")
_FAST_RELEASED = ("Released from rest: ", rel(a_ * (1 - _U_ ** 2), "=", gamma_ ** 2 * (u2 - _U_)),
                  " at ", u1, " (Eq. 11.23); for ", rel(gamma_ ** 2, ">>", a_), ", ",
                  rel(u2 - u1, "~", a_ * sin(theta0) ** 2 / gamma_ ** 2), " and ",
                  rel(_DTHETA, "~", _DU / sin(theta0)), ":")
_AMPLITUDE = theta_max - theta_min


def _fast_top(nut, t: dict[str, Expr], released: bool, work: Work) -> None:
    from ..physics.nutation import (
        fast_mean_precession,
        fast_nutation_amplitude,
        fast_nutation_period,
    )

    work.section(*_FAST_TITLE)
    ratio = nut.gamma ** 2 / nut.a
    work.step(_GAMMA2_A, value=ratio, note=_NEEDS)
    work.text(*_FAST)
    period = fast_nutation_period(t["I"], t["J"], t["omega_z"])
    T = period.value
    work.step("T_fast", period, unit="s",
              note=("exact ", q(nut.nutation_period, "s"), ", error ",
                    *_rel(T, nut.nutation_period)))
    precession = fast_mean_precession(t["mgl"], t["J"], t["omega_z"])
    mean = precession.value
    work.step("phidot_fast", precession, unit="rad/s",
              note=("exact ", q(nut.mean_precession, "rad/s"), ", error ",
                    *_rel(mean, nut.mean_precession)))
    if released:
        work.text(*_FAST_RELEASED)
        tree = fast_nutation_amplitude(t["I"], t["mgl"], t["theta0"], t["J"], t["omega_z"])
        amp, exact = tree.value, nut.theta_max - nut.theta_min
        work.step("dtheta_fast", tree, unit="deg",
                  note=("exact ", rel(_AMPLITUDE, "=", q(exact, "deg")), ", error ",
                        *_rel(amp, exact)))


#: upright (True) or hanging: the section's title and its first line
_SLEEPING = {upright: (
    ("Sleeping top: the axis on the vertical (",
     rel(theta0, "=", q(0.0 if upright else math.pi, "deg", exact=True)), ", ",
     rel(thetadot0, "=", 0), ")"),
    (rel(u, "=", Num(1 if upright else -1)), " is a double root of ", fn("f", u), "; ",
     phi, " is undefined on the vertical (", phidot, " and ", psidot, " only add up to ",
     omega_z, "); ", rel(theta_max, "=", theta_min, "=", theta0), ": the axis stays "
     "there")) for upright in (True, False)}
_SPIN2, _WEIGHT4 = J_ ** 2 * omega_z ** 2, 4 * I_ * m * g * l
_STABLE = (rel(_SPIN2, ">", _WEIGHT4), " (Eq. 11.21 with ", rel(theta0, "=", 0),
           ", i.e. ", rel(gamma_ ** 2, ">", 2 * a_), "): stable; ",
           rel(u3, "=", gamma_ ** 2 / a_ - 1, ">", 1))
_DISTURBED = ("nutation period of a slightly disturbed sleeping top (",
              2 * PI / sqrt(a_ * (u3 - u1)), ")")


def _sleeping(top, start, nut, omega_z_: float, t: dict[str, Expr], find: frozenset[str],
              work: Work) -> None:
    upright = start.theta0 < 1
    title, line = _SLEEPING[upright]
    work.section(*title)
    work.text(*line)
    spin2, weight4 = _SPIN2, _WEIGHT4
    if upright:
        work.step(spin2, (t["J"] * t["omega_z"]) ** 2, unit="kg^2 m^4/s^2", state=False)
        work.step(weight4, 4 * t["I"] * t["mgl"], unit="kg^2 m^4/s^2", state=False)
        if nut.stable:
            work.text(*_STABLE)
        else:
            root = nut.u_roots[0]
            work.text(rel(spin2, "<=", weight4), ": not stable; the least disturbance lets the "
                      "axis fall to ", rel(u1, "=", gamma_ ** 2 / a_ - 1, "=", q(root)), ", ",
                      rel(theta, "=", q(math.acos(max(-1, root)), "deg")))
            least = 2 * math.sqrt(top.I * top.mgl) / top.J
            work.warn("the sleeping top is unstable: ", rel(omega_z, "=", q(omega_z_ / RPM, "rpm")),
                      " is below ", rel(2 * sqrt(I_ * m * g * l) / J_, "=", q(least / RPM, "rpm")),
                      " (Eq. 11.21 at ", rel(theta0, "=", 0), ")")
    else:
        work.text("hanging: always stable (gravity restores the axis)")
    if nut.stable:
        beat = t["gamma"] ** 2 - 2 * t["a"] if upright else t["gamma"] ** 2 + 2 * t["a"]
        work.step("T", 2 * PI / sqrt(beat), unit="s", note=_DISTURBED)
    undefined = {"mean_precession", "max_precession", "min_precession"} & find
    if undefined:
        raise InputError(f"{sorted(undefined)[0]} is undefined for a sleeping top: the axis "
                         "stays on the vertical, where phi has no meaning; drop it from `find`",
                         key=f"find.{sorted(undefined)[0]}")
    if "nutation_period" in find and not nut.stable:
        raise InputError("nutation_period: the sleeping top is unstable (J^2 omega_z^2 <= "
                         "4 I m g l), it does not nutate about the vertical; drop it from `find`",
                         key="find.nutation_period")
    work.answer("theta_min", "theta_min", [nut.theta_min], "angle")
    work.answer("theta_max", "theta_max", [nut.theta_max], "angle")
    if nut.stable:
        work.answer("nutation_period", "T", [nut.nutation_period], "time")
    work.answer("motion", "motion", ["sleeping"], None,
                labels=["stable" if nut.stable else "unstable"])
    work.answer("u_roots", "u", list(nut.u_roots), "dimensionless")


def _spin_and_reversal(nut, omega_z: float, find: frozenset[str], work: Work) -> None:
    """psidot at the nutation limits and the theta where phidot passes through zero.

    omega_z = psidot + phidot cos(theta) is constant (Eq. 11.14, P2 = J omega_z),
    so psidot = omega_z - phidot u at u = cos(theta); phidot = (beta - gamma u) /
    (1 - u^2) (Eq. 11.16) vanishes at u = beta / gamma.
    """
    u1, u2, _ = nut.u_roots
    omega_z_ = names("omega_z")[0]
    work.section("Spin at the nutation limits and where the precession reverses")
    work.text(rel(omega_z_, "=", psidot + phidot * cos(names("theta")[0])), " is constant (Eq. 11.14): ",
              rel(psidot, "=", omega_z_ - phidot * names("u")[0]))
    if "spin_at_limits" in find:
        spins = []
        for u, rate, where in ((u1, nut.limit_precession[0], "theta_max"),
                               (u2, nut.limit_precession[1], "theta_min")):
            if not math.isfinite(rate):
                raise InputError(f"at {where} the axis is on the vertical, where phidot and "
                                 "psidot are undefined (only omega_z is)",
                                 key="find.spin_at_limits")
            spins.append(work.step(fn("psidot", *names(where)), Sym("omega_z", omega_z, "rad/s")
                                   - Sym("phidot", rate, "rad/s") * Sym("u", u), unit="rad/s"))
        work.answer("spin_at_limits", "psidot", spins, "rate", ["at theta_max", "at theta_min"])
    if "reversal_theta" in find:
        u_star = nut.beta / nut.gamma if nut.gamma else math.inf
        tol = 1e-9 * max(1.0, abs(u_star)) if math.isfinite(u_star) else 0.0
        if not (u1 - tol <= u_star <= u2 + tol):
            raise InputError(f"the precession does not reverse in this motion ({nut.motion}): "
                             "phidot = (beta - gamma u) / (1 - u^2) keeps one sign between the "
                             "nutation limits (it changes sign only in loops, and touches 0 at "
                             "the cusps)", key="find.reversal_theta")
        u_star = min(max(u_star, -1.0), 1.0)
        ratio = Sym("beta", nut.beta, "rad/s") / Sym("gamma", nut.gamma, "rad/s")
        if abs(ratio.value) > 1:  # beta / gamma beyond +-1 by rounding, at a pole
            ratio = Let(Sym("u*", u_star), ratio)
        cusp = (" (a cusp: ", phidot, " touches ", Num(0), " and keeps its sign)") \
            if nut.motion == "cusps" else ()
        theta = work.step("theta_rev", acos(ratio), unit="deg",
                          note=(rel(phidot, "=", 0), " there", *cusp))
        work.answer("reversal_theta", "theta_rev", [theta * DEG], "angle")  # theta in deg


def _answers(nut, work: Work) -> None:
    work.answer("theta_min", "theta_min", [nut.theta_min], "angle")
    work.answer("theta_max", "theta_max", [nut.theta_max], "angle")
    work.answer("nutation_period", "T", [nut.nutation_period], "time")
    work.answer("mean_precession", "phidot_mean", [nut.mean_precession], "rate")
    work.answer("max_precession", "phidot_max", [nut.max_precession], "rate")
    work.answer("min_precession", "phidot_min", [nut.min_precession], "rate")
    work.answer("motion", "motion", [nut.motion], None)
    work.answer("u_roots", "u", list(nut.u_roots), "dimensionless")


KIND = Kind(
    name="released_top",
    summary="heavy symmetric top released at theta0 with spin: nutation and precession",
    chapter="Eqs. 11.14-11.26 (11.24 corrected), exact by elliptic integrals",
    params=(
        Param("theta0", "angle", "theta0", "angle of the axis from the upward vertical at t = 0 "
              "(the chapter's theta_2)", range=(0.0, math.pi * (1 + 1e-15)),
              limits=("0 deg", "180 deg"), required=True),  # 180 deg read from grad or arcmin may be 1 ulp over
        Param("spin", "rate", "psidot", "spin relative to the precessing frame (> 0)",
              positive=True, reason="the chapter takes psidot > 0 about the axis from the fixed "
              "point to the centre of mass: for a negative spin reverse the sense of the axis "
              "instead (give the spin as positive and change the sign of precession0); at 0 a "
              "top released without spin is a pendulum, not a top", required=True),
        Param("precession0", "rate", "phidot0", "precession rate at t = 0", default="0 rad/s"),
        Param("theta_rate0", "rate", "thetadot0", "rate of change of theta at t = 0",
              default="0 rad/s"),
    ),
    answers=(
        AnswerSpec("theta_min", "angle", "theta_min", "least angle of the axis from the vertical"),
        AnswerSpec("theta_max", "angle", "theta_max", "largest angle of the axis from the "
                   "vertical"),
        AnswerSpec("nutation_period", "time", "T", "time from theta_max to theta_min and back"),
        AnswerSpec("mean_precession", "rate", "phidot_mean", "phi advance over one nutation "
                   "period, divided by the period"),
        AnswerSpec("max_precession", "rate", "phidot_max", "precession rate of largest "
                   "magnitude (at a nutation limit), signed"),
        AnswerSpec("min_precession", "rate", "phidot_min", "precession rate at the other "
                   "nutation limit, signed"),
        AnswerSpec("motion", None, "motion", "cusps, loops, waves, steady or sleeping",
                   words=(*_MOTION, "sleeping")),
        AnswerSpec("spin_at_limits", "rate", "psidot", "[at theta_max, at theta_min]: spin "
                   "relative to the precessing frame at the nutation limits"),
        AnswerSpec("reversal_theta", "angle", "theta_rev", "theta where the precession passes "
                   "through zero (loops; a cusp touches zero at theta_min)"),
        AnswerSpec("u_roots", "dimensionless", "u", "the three roots of f(u), Eq. 11.19, "
                   "ascending"),
    ),
    solve=solve,
    picture="axis_path", animation="nutating_top", simulation="released",
    physics=("gyro_cli.physics.nutation", "gyro_cli.physics.elliptic"),
    example={
        "statement": ("A top weighing {weight} has radii of gyration of {k_axial} about its axis "
                      "and {k_pivot} about its point of support, and its centre of mass is "
                      "{cg_distance} from that point. It is released with its axis at {theta0} "
                      "from the upward vertical and a spin of {spin}. Find the largest angle of "
                      "its axis from the vertical, the period of nutation, the mean rate of "
                      "precession, and the kind of motion."),
        "given": {"weight": "3 oz", "k_axial": "0.84 in", "k_pivot": "1.80 in",
                  "cg_distance": "1.5 in", "theta0": "30 deg", "spin": "1800 rpm"},
        "find": {"theta_max": "deg", "nutation_period": "s", "mean_precession": "rpm",
                 "motion": None},
        "vary": {"spin": "[0.8, 1.2]", "theta0": "[20 deg, 40 deg]"}},
)
