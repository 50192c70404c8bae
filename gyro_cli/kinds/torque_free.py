"""Torque-free motion of an axisymmetric body: space capsule, satellite, football, the Earth.

No moment acts about the centre of mass, so H is fixed in space. The motion is
fixed by J, I (about the centre of mass) and any two of omega, omega_angle
(beta), nutation_angle (theta), axial_rate (omega_z), precession (phidot),
spin (psidot) and angular_momentum (H). The relations, their derivation and the sign conventions are in
``gyro_cli.physics.torque_free``:

    tan(theta) = (I / J) tan(beta),  phidot = H / I,  psidot = (I - J) / I * omega_z.
"""

from __future__ import annotations

import math
from typing import Any

from ..core.errors import InputError
from ..core.expr import PI, Expr, Num, Sym, absolute, acos, asin, atan, cos, sin, sqrt, tan
from ..core.given import Given
from ..core.prose import Prose, names, q, rel, tup, words
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work
from ..physics.torque_free import MOTION_KEYS, FreeMotion, TorqueFreeError, solve_motion

WORDS = {"omega": "omega", "omega_angle": "beta", "nutation_angle": "theta",
         "axial_rate": "omega_z", "precession": "phidot", "spin": "psidot",
         "angular_momentum": "H"}


#: the symbols of the kind's steps, beside its Params: name -> the unit each is shown in
UNITS = {"J": "kg*m^2", "I": "kg*m^2", "theta": "deg", "beta": "deg", "omega": "rad/s",
         "omega_z": "rad/s", "omega_e": "rad/s", "phidot": "rad/s", "psidot": "rad/s",
         "H": "kg m^2/s", "T": "J", "T_f": "J", "omega_f": "rad/s", "I_max": "kg*m^2"}


HALF = Num(0.5, "1/2")


def _sym(name: str, value: float) -> Sym:
    """The kind's symbol ``name`` holding ``value`` (SI: an angle in rad)."""
    return Sym(name, value, UNITS[name])


# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's time in gyro check.
def _conventions() -> tuple[tuple, ...]:
    G, H, Z, k, phi, theta, psi, phidot, psidot, omega, omega_z, omega_e, beta, I_, I_G, J_ = \
        names("G H Z k phi theta psi phidot psidot omega omega_z omega_e beta I I_G J")
    frame = ("No moment about the centre of mass ", G, ": ", H, ", the angular momentum "
             "about ", G, ", is fixed in space. ", Z, ": along ", H, "; ", k, ": the symmetry "
             "axis, taken on the side of ", H, ", so that ", H, " has a positive component "
             "along ", k, ". z-x-z Euler angles as in the chapter (Eqs. 11.5-11.8): ", phi,
             " about ", Z, ", ", theta, " from ", Z, " to ", k, ", ", psi, " about ", k,
             ", with the rates ", phidot, " (precession) and ", psidot, " (spin); ",
             rel(omega, "=", phidot * Z + psidot * k), ", ",
             rel(omega_z, "=", psidot + phidot * cos(theta)), "; ", beta, ": the angle from ",
             k, " to ", omega, ". Then ", rel(omega_z, ">", 0), " and ", theta, ", ",
             rel(beta, "<", q(math.pi / 2, "deg", exact=True)), ".")
    inertia = (rel(I_, "=", I_G), ": the transverse moment of inertia about ", G, ", the centre of "
               "mass (H is taken about it: no moment acts); ", omega_e, ": the component of ", omega, " across ", k)
    relations = ("Along ", k, ": ", rel(J_ * omega_z, "=", H * cos(theta)), "; across ", k,
                 ": ", rel(I_ * omega_e, "=", H * sin(theta)), " with ",
                 rel(omega_e, "=", phidot * sin(theta)), ". Hence ", rel(phidot, "=", H / I_),
                 ", ", rel(tan(theta), "=", I_ / J_ * tan(beta)), " and ",
                 rel(psidot, "=", omega_z - phidot * cos(theta), "=",
                     (I_ - J_) / I_ * omega_z), ".")
    I_, I_G = names("I I_G")
    apex = (I_, " about the apex is not used: a free body turns about its centre of mass, "
            "so ", rel(I_, "=", I_G))
    return frame, inertia, relations, apex


_FRAME, _INERTIA, _RELATIONS, _APEX = _conventions()


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.solid_body
    for key in ("I_pivot", "k_pivot", "cg_distance"):
        if key in given:
            raise InputError(f"{key} does not apply: a torque-free body turns about its centre "
                             "of mass, so give the transverse inertia about it (I_cg, k_cg or a "
                             "shape)", key=f"given.{key}")
    J, I = body.needed("J"), body.needed("I_cg")
    if body.I_pivot is not None:  # a cone's I about its apex, worked out with the body
        work.text(*_APEX)
    known = {k: given[k] for k in MOTION_KEYS if k in given}
    sense = given.word("precession_sense")
    books = _books_sense(J, I, sense, known) if sense is not None else ""
    if sense is None and known.get("spin", 0.0) > 0 and J > I:
        raise InputError("spin must be negative for this oblate (J > I) body in gyro's "
                         "convention (psidot = (I - J) / I omega_z, retrograde precession); "
                         "books (Meriam, Beer and Johnston) quote it positive with the sense "
                         "in words: add `precession_sense: retrograde`", key="given.spin")
    try:
        state = solve_motion(J, I, known)
    except TorqueFreeError as err:
        key = {"I_cg": "I_cg" if "I_cg" in given else "k_cg" if "k_cg" in given else "shape",
               "J": "J" if "J" in given else "k_axial" if "k_axial" in given else "shape"
               }.get(err.key, err.key)
        raise InputError(err.message, key=f"given.{key}") from None
    if state.omega_angle == 0:
        _representable(state, known, steady=True)
        _steady(J, known, state, find, work)
        if find & ENERGY_ANSWERS:
            _energy(J, I, state, work)
        return
    _representable(state, known)

    work.section("Conventions")
    work.text(*_FRAME)
    work.text(*_INERTIA)
    work.text(*_RELATIONS)
    if books:
        work.text(*books)
        for line in work.given:
            if line.key == "spin":
                note = Prose(("a magnitude: ", rel(*names("psidot"), "=",
                                                    q(known["spin"], "rad/s")), f" ({sense})"))
                line.note, line.note_prose = note.text, note
    _route(J, I, known, state, work)
    _results(J, I, state, work, magnitude=sense is not None)
    if find & ENERGY_ANSWERS:
        _energy(J, I, state, work)


def _books_sense(J: float, I: float, sense: str, known: dict[str, float]) -> tuple:
    """The books' convention: the spin p as a magnitude, the sense of the precession in words
    (direct: the spin and the precession turn the same way; retrograde: opposite ways)."""
    body = "prolate (I > J)" if I > J else "oblate (J > I)"
    if (sense == "direct") != (I > J):
        raise InputError(f"{sense} precession needs {'a prolate (I > J)' if sense == 'direct' else 'an oblate (J > I)'} "
                         f"body; this one is {body}, so its precession is "
                         f"{'direct' if I > J else 'retrograde'}", key="given.precession_sense")
    if "spin" not in known:
        return (f"the precession is {sense}, as the books say",)
    p = abs(known["spin"])
    known["spin"] = p if sense == "direct" else -p
    p_, psidot, k, H = names("p psidot k H")
    return (p_, ", the spin as the books quote it: ", q(p, "rad/s"), ", a magnitude, with the "
            f"precession {sense}; here ", psidot, " carries the sense (", k, " on the side of ",
            H, "): ", rel(psidot, "=", p_ if sense == "direct" else -p_, "=",
                          q(known["spin"], "rad/s")))


def _representable(s: FreeMotion, known: dict[str, float], steady: bool = False) -> None:
    """Refuse data whose rates or periods overflow or underflow double precision."""
    values: tuple[float, ...]
    try:
        values = ((s.omega, s.angular_momentum, s.kinetic_energy) if steady else
                  (s.omega, s.transverse_rate, s.angular_momentum, s.precession, s.spin,
                   s.precession_period, s.body_wobble_period))
    except ArithmeticError:
        values = (math.nan,)
    if not all(math.isfinite(v) and v != 0 for v in values):
        raise InputError("these rates and inertias overflow or underflow double precision (a "
                         "rate, H or a period is not a finite non-zero number): check the "
                         "magnitudes and units", key=f"given.{next(iter(known))}")


#: the answers that describe the wobble: none exists in a steady spin about the axis
WOBBLE_ANSWERS = frozenset({"precession", "spin", "precession_period", "body_wobble_period",
                            "motion", "spin_ratio"})
def _steady_words() -> tuple:
    G, H, k, w, wz, J = names("G H k omega omega_z J")
    return ("No moment about the centre of mass ", G, ": ", H, " is fixed in space. With no "
            "angle between ", k, " and ", w, ", the body spins steadily about its symmetry "
            "axis: ", rel(w, "=", wz), ", ", rel(H, "=", J * wz), " along ", k, ", and nothing "
            "wobbles or precesses.")


_STEADY = _steady_words()


def _steady(J: float, known: dict[str, float], s: FreeMotion, find: frozenset[str],
            work: Work) -> None:
    """A spin about the symmetry axis with no wobble (an angle of 0): the rates and H only."""
    angle = next(k for k in ("omega_angle", "nutation_angle") if k in known)
    asked = sorted(find & WOBBLE_ANSWERS)
    if asked:
        raise InputError(f"{asked[0]} is not defined: with {angle} = 0 the body spins steadily "
                         "about its axis and does not wobble; ask omega, axial_rate, "
                         "angular_momentum, kinetic_energy or the energy-dissipation answers "
                         "(final_rate, final_kinetic_energy, energy_lost, spin_stability)",
                         key=f"given.{angle}")
    work.section("Conventions")
    work.text(*_STEADY)
    work.text(*_INERTIA)
    work.section("The steady spin")
    work.text(rel(_be, "=", _th, "=", q(0.0, "deg", exact=True)), ": ", _k, ", ", _omega,
              " and ", _H, " lie along one line")
    J_ = _sym("J", J)
    if "angular_momentum" in known:
        work.step("omega_z", _sym("H", known["angular_momentum"]) / J_, unit="rad/s")
    else:
        if "omega" in known:
            work.step("omega_z", _sym("omega", known["omega"]), unit="rad/s", substitute=False)
        work.step("H", J_ * _sym("omega_z", s.axial_rate), unit="kg m^2/s")
    for name, symbol, value, dimension in (
            ("axial_rate", "omega_z", s.axial_rate, "rate"), ("omega", "omega", s.omega, "rate"),
            ("nutation_angle", "theta", 0.0, "angle"), ("omega_angle", "beta", 0.0, "angle"),
            ("angular_momentum", "H", s.angular_momentum, "angular_momentum"),
            ("body_cone_angle", "beta", 0.0, "angle")):
        work.answer(name, symbol, [value], dimension)
    work.answer("space_cone_angle", _SPACE_CONE_ANGLE, [0.0], "angle")


_GIVEN_SYMS = {key: names(word)[0] for key, word in WORDS.items()}
_FIX_THE_MOTION: tuple[str | Expr, ...] = (*names("beta"), " and ", *names("omega_z"), " are given: together with ",
                   *names("J"), " and ", *names("I"), " they fix the motion")


def _route(J: float, I: float, known: dict[str, float], s: FreeMotion, work: Work) -> None:
    """The steps that turn the two given quantities into omega_z and beta."""
    given_syms = [piece for k in known for piece in (" and ", _GIVEN_SYMS[k])][1:]
    work.section("The motion from ", *given_syms)
    J_, I_ = _sym("J", J), _sym("I", I)
    beta, theta, wz = _sym("beta", s.omega_angle), _sym("theta", s.nutation_angle), \
        _sym("omega_z", s.axial_rate)
    if "nutation_angle" in known:  # omega_angle_from_nutation
        work.step("beta", atan(J_ / I_ * tan(_sym("theta", known["nutation_angle"]))),
                  unit="deg")
    if "spin" in known:  # axial_rate_from_spin
        work.step("omega_z", I_ * _sym("psidot", known["spin"]) / (I_ - J_), unit="rad/s")
    angle = "omega_angle" in known or "nutation_angle" in known
    axial = "axial_rate" in known or "spin" in known
    if angle and axial:
        if "omega_angle" in known and "axial_rate" in known:
            work.text(*_FIX_THE_MOTION)
    elif angle and "omega" in known:
        work.step("omega_z", _sym("omega", known["omega"]) * cos(beta), unit="rad/s")
    elif angle and "precession" in known:
        if "nutation_angle" not in known:
            work.step("theta", atan(I_ / J_ * tan(beta)), unit="deg")
        H, phidot = names("H phidot")
        work.step("omega_z", I_ * _sym("phidot", known["precession"]) * cos(theta) / J_,
                  unit="rad/s", note=(tup(rel(H, "=", I_ * phidot),
                                          rel(H * cos(theta), "=", J_ * wz)),))
    elif angle and "angular_momentum" in known:
        if "nutation_angle" not in known:
            work.step("theta", atan(I_ / J_ * tan(beta)), unit="deg")
        H = names("H")[0]
        work.step("omega_z", _sym("H", known["angular_momentum"]) * cos(theta) / J_,
                  unit="rad/s", note=(tup(rel(H * cos(theta), "=", J_ * wz)),))
    elif axial and "omega" in known:
        work.step("beta", acos(wz / _sym("omega", known["omega"])), unit="deg")
    elif "omega" in known:  # with precession or H
        w = _sym("omega", known["omega"])
        H, omega_z, omega_e, omega, phidot = names("H omega_z omega_e omega phidot")
        law = (rel(H**2, "=", (J_ * omega_z)**2 + (I_ * omega_e)**2, "=",
                   J_**2 * omega**2 + (I_**2 - J_**2) * omega**2 * sin(beta)**2),)
        if "angular_momentum" in known:
            work.text(*law)
            Hg: Expr = _sym("H", known["angular_momentum"])
        else:
            work.text(*law, ", with ", rel(H, "=", I_ * phidot))
            Hg = I_ * _sym("phidot", known["precession"])
        work.step("beta", asin(sqrt((Hg ** 2 - (J_ * w) ** 2) / ((I_ ** 2 - J_ ** 2)
                                                                 * w ** 2))), unit="deg")
        work.step("omega_z", w * cos(beta), unit="rad/s", substitute=False)
    elif axial:  # with precession or H
        H = names("H")[0]
        Hg = (_sym("H", known["angular_momentum"]) if "angular_momentum" in known
              else I_ * _sym("phidot", known["precession"]))
        work.step("theta", acos(J_ * wz / Hg), unit="deg",
                  note=(tup(rel(H * cos(theta), "=", J_ * wz)),))
        work.step("beta", atan(J_ / I_ * tan(theta)), unit="deg", substitute=False)


_H, _k, _omega = names("H k omega")
_I0, _J0, _th, _be, _ps, _ph, _wz0, _we0 = names("I J theta beta psidot phidot omega_z omega_e")
_BETA_NOTE = ("angle from ", _k, " to ", _omega)
_THETA_NOTE = ("angle from ", _H, " to ", _k)
_PRECESSION_NOTE = ("precession of ", _k, " about ", _H)
_T_P_NOTE = ("period of the axis about ", _H)
_T_W_NOTE = ("period of ", _omega, " and ", _H, " about ", _k, ", seen in the body")
_BODY_CONE, _SPACE_CONE = words("body cone"), words("space cone")
_BODY_NOTE = ("semi-angle of the cone ", _omega, " traces about ", _k, " in the body")
_SPACE_NOTE = ("semi-angle of the cone ", _omega, " traces about ", _H, " in space")
_MOTION = {
    "direct": (rel(_I0, ">", _J0), " (prolate): ", rel(_th, ">", _be), ", ", _ps, " has the "
               "sense of ", _ph, "; the body cone rolls on the outside of the space cone: "
               "direct precession."),
    "retrograde": (rel(_J0, ">", _I0), " (oblate): ", rel(_be, ">", _th), ", ", _ps, " is "
                   "against ", _ph, "; the body cone rolls with the space cone inside it: "
                   "retrograde precession.")}
_EQ_11_8 = rel(_wz0, "=", _ps + _ph * cos(_th))
_ACROSS = rel(_we0, "=", _ph * sin(_th))
_ALONG = (_H, " along ", _k, ": ")
_J_OMEGA_Z, _H_COS = (_J0 * _wz0, "="), (_H * cos(_th), "=")
_SPACE_CONE_ANGLE = absolute(_th - _be)
_MERIAM: tuple[str | Expr, ...] = ("the ratio of the spin to the precession (Meriam's ", *names("n"))
_RATIO, _SPIN_OVER_PRECESSION = ((_I0 - _J0) * cos(_th) / _J0, "="), (_ps / _ph, "=")


def _results(J: float, I: float, s: FreeMotion, work: Work, magnitude: bool = False) -> None:
    work.section("Rates, angles and periods")
    beta, theta, wz, we = s.omega_angle, s.nutation_angle, s.axial_rate, s.transverse_rate
    J_, I_, beta_, theta_ = _sym("J", J), _sym("I", I), _sym("beta", beta), _sym("theta", theta)
    wz_, we_ = _sym("omega_z", wz), _sym("omega_e", we)
    phidot_, psidot_ = _sym("phidot", s.precession), _sym("psidot", s.spin)
    stated = {step.symbol for section in work.sections for step in section.steps}
    if "beta" not in stated:  # worked out above from the data: not repeated
        work.step("beta", value=math.degrees(beta), unit="deg", note=_BETA_NOTE)
    if "theta" not in stated:
        work.step("theta", atan(I_ / J_ * tan(beta_)), unit="deg", note=_THETA_NOTE)
    if "omega_z" not in stated:
        work.step("omega_z", value=wz, unit="rad/s", note="axial rate")
    work.step("omega_e", wz_ * tan(beta_), unit="rad/s", note="across the axis")
    work.step("omega", sqrt(wz_ ** 2 + we_ ** 2), unit="rad/s", substitute=False)
    work.step("H", sqrt((J_ * wz_) ** 2 + (I_ * we_) ** 2), unit="kg m^2/s")
    H = s.angular_momentum
    work.step("phidot", _sym("H", H) / I_, unit="rad/s", note=_PRECESSION_NOTE)
    work.step("psidot", (I_ - J_) / I_ * wz_, unit="rad/s",
              note="spin relative to the precessing frame")
    work.step("T_p", 2 * PI / phidot_, unit="s", substitute=False, note=_T_P_NOTE)
    work.step("T_w", 2 * PI / absolute(psidot_), unit="s", substitute=False,
              note=_T_W_NOTE)
    work.step(_BODY_CONE, beta_, unit="deg", substitute=False, note=_BODY_NOTE)
    work.step(_SPACE_CONE, absolute(theta_ - beta_), unit="deg", substitute=False,
              note=_SPACE_NOTE)
    work.text(*_MOTION[s.motion])
    work.check(_EQ_11_8, ": ",
               rel(q(wz), "=", q(s.spin) + q(s.precession) * tup(q(math.cos(theta))), "=",
                   q(s.spin + s.precession * math.cos(theta), "rad/s")), " (Eq. 11.8)")
    work.check(_ACROSS, ": ",
               rel(q(we), "=", q(s.precession * math.sin(theta), "rad/s")))
    work.check(*_ALONG, rel(*_J_OMEGA_Z, q(J * wz, "kg m^2/s")), ", ",
               rel(*_H_COS, q(H * math.cos(theta), "kg m^2/s")))

    work.answer("precession", "phidot", [s.precession], "rate")
    work.answer("spin", "psidot", [s.spin], "rate")
    work.answer("axial_rate", "omega_z", [wz], "rate")
    work.answer("omega", "omega", [s.omega], "rate")
    work.answer("nutation_angle", "theta", [theta], "angle")
    work.answer("omega_angle", "beta", [beta], "angle")
    work.answer("angular_momentum", "H", [H], "angular_momentum")
    work.answer("precession_period", "T_p", [s.precession_period], "time")
    work.answer("body_wobble_period", "T_w", [s.body_wobble_period], "time")
    work.answer("body_cone_angle", "beta", [s.body_cone_angle], "angle")
    work.answer("space_cone_angle", _SPACE_CONE_ANGLE, [s.space_cone_angle], "angle")
    work.answer("motion", "motion", [s.motion], None)
    n = s.spin / s.precession
    if magnitude:  # the books' convention: a ratio of magnitudes, the sense in words
        n = work.step("n", absolute(psidot_) / phidot_, unit="", note=(
            *_MERIAM, f"), the precession {s.motion}"))
    else:
        work.step("n", psidot_ / phidot_, unit="", note=(
            *_MERIAM, f"); {'negative' if n < 0 else 'positive' if n > 0 else 'zero'}: the "
            f"precession {s.motion}"))
    work.answer("spin_ratio", "n", [n], "dimensionless")
    work.check(rel(*_RATIO, q((I - J) * math.cos(theta) / J)), "; ",
               rel(*_SPIN_OVER_PRECESSION, q(s.spin / s.precession)))


ENERGY_ANSWERS = frozenset({"kinetic_energy", "final_rate", "final_kinetic_energy",
                            "energy_lost", "spin_stability"})
_T, _Tf, _Imax, _wf, _Hs = names("T T_f I_max omega_f H")
_DISSIPATION = ("Energy dissipation (flexing parts, sloshing fuel) with no external moment: ",
                _Hs, " is kept and ", _T, " falls to the least energy a body with this ", _Hs,
                " can have, ", rel(_Tf, "=", _Hs ** 2 / (2 * _Imax)), ", turning about its axis "
                "of largest moment at ", rel(_wf, "=", _Hs / _Imax),
                " (the major-axis rule; Curtis, Orbital Mechanics, Sec. 10.5).")
_FINAL = {"stable": (rel(_J0, ">", _I0), ": the symmetry axis is the major axis; any wobble "
                     "dies out and the body ends (or stays) spinning about ", _k, ": its spin is stable."),
          "unstable": (rel(_I0, ">", _J0), ": the symmetry axis is the minor axis; any wobble "
                       "grows and the body ends in a flat spin about a transverse axis: its "
                       "spin about ", _k, " is unstable.")}


def _energy(J: float, I: float, s: FreeMotion, work: Work) -> None:
    """Kinetic energy (Eq. 11.2), and where energy dissipation takes the motion (H kept)."""
    work.section("Kinetic energy and energy dissipation")
    J_, I_ = _sym("J", J), _sym("I", I)
    wz_, we_ = _sym("omega_z", s.axial_rate), _sym("omega_e", s.transverse_rate)
    H_, T_ = _sym("H", s.angular_momentum), _sym("T", s.kinetic_energy)
    if s.omega_angle == 0:  # a steady spin: omega_e = 0
        work.step("T", HALF * J_ * wz_ ** 2, unit="J", ref="Eq. 11.2")
    else:
        work.step("T", HALF * (J_ * wz_ ** 2 + I_ * we_ ** 2), unit="J", ref="Eq. 11.2")
    Imax = _sym("I_max", s.major_moment)
    work.step("I_max", J_ if J > I else I_, unit="kg*m^2",
              substitute=False, note=("the larger of ", _J0, " and ", _I0))
    work.text(*_DISSIPATION)
    work.step("omega_f", H_ / Imax, unit="rad/s", note="about the major axis, at the end")
    Tf = work.step("T_f", H_ ** 2 / (2 * Imax), unit="J")
    lost = (HALF * I_ * we_ ** 2 * (J_ - I_) / J_ if J > I
            else HALF * J_ * wz_ ** 2 * (I_ - J_) / I_)
    work.step(_T - _Tf, lost, unit="J", note="energy dissipated")
    work.text(*_FINAL[s.spin_stability])
    work.check(rel(_T - _Tf, "=", q(s.kinetic_energy - (Tf or 0.0), "J")), " from ", T_,
               " and ", _Tf)
    work.answer("kinetic_energy", "T", [s.kinetic_energy], "energy")
    work.answer("final_rate", "omega_f", [s.final_rate], "rate")
    work.answer("final_kinetic_energy", "T_f", [s.final_kinetic_energy], "energy")
    work.answer("energy_lost", _T - _Tf, [s.energy_lost], "energy")
    work.answer("spin_stability", "stability", [s.spin_stability], None)


# why a key's limit is what it is (the loader adds it to the refusal); physics.torque_free
# keeps the same checks for its own callers
_SIDE = "H is taken along +Z and k on the side of H"
_WOBBLE: dict[str, Any] = dict(range=(0.0, math.pi / 2), bounds="[)", reason="at 90 deg the body turns about "
               "a transverse axis and does not wobble; above 90 deg take the axis k the other "
               "way (180 deg minus the angle); 0 is a steady spin about the axis, which has "
               "rates, H and energy but no precession")

KIND = Kind(
    name="torque_free",
    summary="axisymmetric body with no applied moment (space capsule, satellite, football, the "
            "Earth's free wobble): precession, spin, cones and periods",
    chapter="Eqs. 11.5-11.8 with H fixed; Euler's equations with no moment",
    params=(
        Param("omega", "rate", "omega", "magnitude of the angular velocity", positive=True,
              reason=_SIDE),
        Param("omega_angle", "angle", "beta", "angle between omega and the symmetry axis "
              "(0 to 90 deg)", **_WOBBLE),
        Param("nutation_angle", "angle", "theta", "angle between H and the symmetry axis "
              "(0 to 90 deg)", **_WOBBLE),
        Param("axial_rate", "rate", "omega_z", "component of omega along the symmetry axis "
              "(positive)", positive=True, reason=_SIDE),
        Param("precession", "rate", "phidot", "rate of the symmetry axis about H (positive)",
              positive=True, reason=_SIDE),
        Param("spin", "rate", "psidot", "spin relative to the precessing frame: positive for "
              "I > J, negative for J > I (or a magnitude, with precession_sense)", nonzero=True,
              reason="with J != I the body always spins relative to its precessing frame, "
              "psidot = (I - J) / I omega_z"),
        Param("angular_momentum", "angular_momentum", "H", "magnitude of H about the centre "
              "of mass (Hibbeler's H_G), given instead of a rate", positive=True, reason=_SIDE),
        Param("precession_sense", "word", "sense", "the books' words: direct (spin and "
              "precession the same way, I > J) or retrograde (opposite, J > I); spin is then "
              "a magnitude", choices=("direct", "retrograde"),
              words=(("same", "direct"), ("same_sense", "direct"), ("prograde", "direct"),
                     ("direct_precession", "direct"), ("opposite", "retrograde"),
                     ("opposite_sense", "retrograde"), ("retrograde_precession",
                                                        "retrograde"))),
    ),
    answers=(
        AnswerSpec("precession", "rate", "phidot", "precession of the axis about H, H / I"),
        AnswerSpec("spin", "rate", "psidot", "spin relative to the precessing frame, "
                   "(I - J) / I omega_z"),
        AnswerSpec("axial_rate", "rate", "omega_z", "component of omega along the axis"),
        AnswerSpec("omega", "rate", "omega", "magnitude of the angular velocity"),
        AnswerSpec("nutation_angle", "angle", "theta", "angle between H and the axis"),
        AnswerSpec("omega_angle", "angle", "beta", "angle between omega and the axis"),
        AnswerSpec("angular_momentum", "angular_momentum", "H", "magnitude of H about the "
                   "centre of mass"),
        AnswerSpec("precession_period", "time", "T_p", "2 pi / phidot: one turn of the axis "
                   "about H"),
        AnswerSpec("body_wobble_period", "time", "T_w", "2 pi / |psidot|: one turn of omega "
                   "about the axis, seen in the body (Euler's period for the Earth)"),
        AnswerSpec("body_cone_angle", "angle", "beta", "semi-angle of the body cone (omega "
                   "about the axis)"),
        AnswerSpec("space_cone_angle", "angle", "|theta - beta|", "semi-angle of the space "
                   "cone (omega about H)"),
        AnswerSpec("motion", None, "motion", "direct (prolate, I > J) or retrograde (oblate, "
                   "J > I)", words=tuple(_MOTION)),
        AnswerSpec("kinetic_energy", "energy", "T", "kinetic energy, (1/2) (J omega_z^2 + "
                   "I omega_e^2) (Eq. 11.2)"),
        AnswerSpec("final_rate", "rate", "omega_f", "energy dissipation, H kept: the rate at "
                   "the end, about the axis of largest moment, H / I_max"),
        AnswerSpec("final_kinetic_energy", "energy", "T_f", "energy dissipation: the least "
                   "energy for this H, H^2 / (2 I_max)"),
        AnswerSpec("energy_lost", "energy", "T - T_f", "energy dissipation: the kinetic "
                   "energy lost on the way to the major axis"),
        AnswerSpec("spin_stability", None, "stability", "stable (J > I: the symmetry axis is "
                   "the major axis) or unstable (I > J: a flat spin at the end); the "
                   "major-axis rule", words=tuple(_FINAL)),
        AnswerSpec("spin_ratio", "dimensionless", "n", "psidot / phidot, the ratio of the spin "
                   "to the precession (Meriam's n), (I - J) cos(theta) / J; negative when "
                   "retrograde"),
    ),
    solve=solve,
    animation="free_body",
    size_free=True, gravity=False, example={
        "statement": ("A free symmetric body has moments of inertia of {J} about its symmetry "
                      "axis and {I_cg} about a transverse axis through its centre of mass. Its "
                      "axis makes an angle of {nutation_angle} with its angular momentum, and it "
                      "spins at {spin} relative to the precessing frame. Find the rate and the "
                      "period of its precession, the magnitude of its angular velocity, and "
                      "whether the precession is direct or retrograde."),
        "given": {"J": "100 kg m^2", "I_cg": "125 kg m^2", "nutation_angle": "20 deg",
                  "spin": "1 rpm"},
        "find": {"precession": "rpm", "precession_period": "s", "omega": "rad/s",
                 "motion": None, "kinetic_energy": "J", "spin_stability": None},
        "vary": {"nutation_angle": "[10 deg, 40 deg]"}},
)
