"""A ship's turbine rotor: the gyroscopic couple in steering, pitching and rolling.

The rotor's axis lies fore and aft. Its angular momentum H = J omega s points
forward or aft (``rotor_sense``, seen from the stern or the bow). The ship's
motion turns H at omega_p, so the rotor needs the couple C = omega_p x H
(Eq. 11.29 in vector form) and the ship feels the reactive couple -C:

- steering on a circle of radius R at speed v: omega_p = v / R about the
  vertical, C = J omega v / R, which pitches the ship;
- pitching in simple harmonic motion, theta = phi sin(2 pi t / T):
  omega_p,max = phi 2 pi / T, C_max = J omega omega_p,max, which turns (yaws)
  the ship; alpha_max = phi (2 pi / T)^2;
- rolling about the fore-and-aft axis: omega_p is parallel to H, so C = 0.

Reference: R.S. Khurmi and J.K. Gupta, "Theory of Machines", ch. 14 (naval
ship: steering, pitching, rolling); S.S. Rattan, "Theory of Machines", ch. 14.
"""

from __future__ import annotations

import math
from typing import Any

from ..core.errors import InputError, refuse_overflow
from ..core.expr import Num, Sym, absolute, cos, sin
from ..core.given import Given
from ..core.prose import deriv, names, plus, q, qvec, rel
from ..core.spec import AnswerSpec, Kind, OneOf, Param
from ..core.vehicle_words import COUPLE, reactive_couple, rotor_steps, turn_of
from ..core.work import Work
from ..physics import vehicles as V

#: the ship's axes and the symbols its prose names (values are in the steps' trees)
x, y, z = names("x y z")
H0, C0, wp0, phi0, w10, t0, theta0, alpha0 = names("H C omega_p phi omega_1 t theta alpha")

# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's own time in gyro check.
_AXES = ("ship axes: ", x, " forward (toward the bow), ", y, " to port (left, looking forward), ",
         z, " up. The rotor's axis lies fore and aft. A rotation that looks clockwise to an "
         "observer has its vector pointing away from the observer (right-hand rule).")
#: the axes' senses as the sentences write them: +x forward, -x aft, +z up, ...
_PLUS_X, _MINUS_X, _PLUS_Y, _MINUS_Y, _PLUS_Z, _MINUS_Z = plus(x), -x, plus(y), -y, plus(z), -z
_TURNS = "the ship's angular velocity: about the vertical as it steers, athwartships as it " \
    "pitches, fore and aft as it rolls"
_REACTIVE = (*reactive_couple("ship", precession=_TURNS), ". About ", _MINUS_Y, " it raises the "
             "bow; about ", _PLUS_Z, " it turns the ship to port.")
_COUPLE_TITLE = ("Gyroscopic couple, ", rel(C0, "=", COUPLE))
_NO_ROLLING_COUPLE = (wp0, " lies along ", x, ", parallel to ", H0, ": ", rel(COUPLE, "=", 0),
                      ". Rolling gives no gyroscopic couple.")
_REACTION, _SIZE = -COUPLE, absolute(COUPLE)


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.solid_body
    J = body.needed("J")
    spin = given["spin"]
    motion = given.word("motion", "steering")
    sense = given.word("rotor_sense")
    _refuse_foreign(given, motion)
    if motion == "stabilising":
        _stabilising(given, find, work, J, spin)
        return

    work.section("Conventions (Khurmi, Theory of Machines, ch. 14)")
    work.text(*_AXES)
    work.text(*_REACTIVE)

    if sense is None:
        if "effect" in find:
            raise InputError("the effect needs the rotor's sense: rotor_sense, one of "
                             f"{', '.join(V.SHIP_SENSES)}", key="given.rotor_sense")
        direction = 1.0
        work.text("rotor_sense not given: the couple's size is found; its effect needs the sense")
    else:
        direction = V.spin_direction(sense)
    work.section("Rotor")
    H = V.spin_vector(J, spin, direction)
    J_, omega, Hmag = rotor_steps(work, J, spin, "axial moment of inertia of the rotor",
                                  "rotor speed")
    if sense:
        way = "forward (toward the bow), " if direction > 0 else "aft (toward the stern), "
        work.text(f"{sense.replace('_', ' ')}: the spin vector points {way}",
                  _PLUS_X if direction > 0 else _MINUS_X, "; ", rel(H0, "=", qvec(H, "kg m^2/s")))

    if motion == "steering":
        wp = _steering(given, work)
    elif motion == "pitching":
        wp = _pitching(given, find, work)
    else:
        wp = _rolling(given, work)

    rate: float | None = V.norm(wp)
    if motion == "rolling":
        rate = abs(given["roll_rate"]) if "roll_rate" in given else None
    work.section(*_COUPLE_TITLE)
    if motion == "rolling":
        work.text(*_NO_ROLLING_COUPLE)
        # with no roll_rate any rate will do (V.rolling_precession takes 1 rad/s)
        omega_p = Sym("omega_p", 1.0 if rate is None else rate, "rad/s")
        C = work.step("C", J_ * omega * omega_p * sin(Num(0)), unit="N*m", substitute=False)
    else:
        assert rate is not None, "only a roll leaves the rate unknown"
        C = work.step("C", V.gyroscopic_couple(J_, omega, Sym("omega_p", rate, "rad/s")), unit="N*m",
                      ref="Eq. 11.29", note=_PITCH_NOTE.get(motion, "") if "pitch_rate"
                      not in given else "at the instant")
    refuse_overflow(C, Hmag)
    work.answer("couple", "C", [C], "moment")
    if rate is not None:
        work.answer("precession", "omega_p", [rate], "rate")
    if sense:
        active = V.couple_on_rotor(wp, H)
        reactive = V.reactive_couple(wp, H)
        work.text("couple on the rotor ", rel(COUPLE, "=", qvec(active, "N m")))
        work.text("reactive couple on the ship ", rel(_REACTION, "=", qvec(reactive, "N m")))
        words = V.effect_of(wp, H, "ship")
        work.text(f"effect on the ship: {words}")
        work.answer("effect", "effect", [words], None)
        work.check(rel(_SIZE, "=", q(V.norm(active), "N m"), "=", C0, "=", q(C, "N m")))


def _refuse_foreign(given: Given, motion: str) -> None:
    """Keys of another motion are refused rather than silently ignored."""
    for key, owner in _MOTION_OF_KEY.items():
        if key in given and owner != motion:
            raise InputError(f"{key} belongs to `motion: {owner}`, but motion is {motion}",
                             key=f"given.{key}")


def _steering(given: Given, work: Work) -> V.Vector:
    if "turn_rate" in given:
        for key in ("speed", "turn_radius"):
            if key in given:
                raise InputError("give turn_rate, or speed and turn_radius (omega_p = v / R), "
                                 "not both", key=f"given.{key}")
        rate = given["turn_rate"]
        turn, taken = turn_of(given)
        work.section("Steering: precession about the vertical")
        work.step("omega_p", value=rate, unit="rad/s", note="the ship's rate of turn, as given")
        wp = V.steering_precession(rate, 1.0, turn)
        _steering_line(turn, taken, wp, work)
        return wp
    for key in ("speed", "turn_radius"):
        if key not in given:
            raise InputError("steering needs speed and turn_radius (omega_p = v / R), or "
                             "turn_rate",
                             key=f"given.{key}")
    v, R = given["speed"], given["turn_radius"]
    turn, taken = turn_of(given)
    work.section("Steering: precession about the vertical")
    work.step("omega_p", V.turn_rate(Sym("v", v, "m/s"), Sym("R", R, "m")), unit="rad/s")
    wp = V.steering_precession(v, R, turn)
    _steering_line(turn, taken, wp, work)
    return wp


# a pitch of amplitude and period: the couple at its greatest (a pitch_rate: at the instant)
_PITCH_NOTE = {"pitching": "the maximum, in pitching"}


def _steering_line(turn: str, taken: str, wp: V.Vector, work: Work) -> None:
    work.text(f"steering to the {turn} ({'counter-clockwise' if turn == 'left' else 'clockwise'} "
              "seen from above)" + taken + ": ", rel(wp0, "=", qvec(wp, "rad/s")), ", along ",
              _PLUS_Z if turn == "left" else _MINUS_Z)


_FROM_FREQUENCY = ("from the frequency (", q(1.0, "Hz", exact=True), " = one oscillation per "
                   "second = ", q(2 * math.pi, "rad/s"), ")")
_PITCH_ANGLE = (rel(theta0, "=", phi0 * sin(w10 * t0)), ": the pitch angle at the time ", t0)
_PITCH_RATE = (rel(wp0, "=", deriv(theta0), "=", phi0 * w10 * cos(w10 * t0)),
               ": largest at the mean position (cos = 1)")
_PITCH_ACCELERATION = (rel(alpha0, "=", -phi0 * w10 ** 2 * sin(w10 * t0)),
                       ": largest at the extremes")


def _pitching(given: Given, find: frozenset[str], work: Work) -> V.Vector:
    bow = given.word("bow")
    if "pitch_rate" in given:
        if any(k in given for k in AMPLITUDE_KEYS + PERIOD_KEYS):
            raise InputError("give either pitch_rate (the rate at the instant) or amplitude and "
                             "period (simple harmonic pitching), not both", key="given.pitch_rate")
        for name in ("max_precession", "max_angular_acceleration"):
            if name in find:
                raise InputError(f"{name} needs amplitude and period of the pitching",
                                 key=f"find.{name}")
        rate = abs(given["pitch_rate"])
        work.section("Pitching at a given rate")
        work.step("omega_p", value=rate, unit="rad/s", note="pitching rate at the instant")
    else:
        amplitude_key = _one_of(given, AMPLITUDE_KEYS, "pitching needs its amplitude (the "
                                "largest angle from the mean position: amplitude or "
                                "pitch_amplitude) or the swing between the extremes "
                                "(pitch_total or between_extremes, twice the amplitude), or "
                                "pitch_rate")
        period_key = _one_of(given, PERIOD_KEYS, "pitching needs its period (or frequency), "
                             "or pitch_rate")
        work.section("Pitching: simple harmonic motion")
        if amplitude_key in ("pitch_total", "between_extremes"):
            total = given[amplitude_key]
            work.step("phi_total", value=math.degrees(total), unit="deg",
                      note="the swing from one extreme to the other")
            phi = total / 2
            work.step("phi", Sym("phi_total", total, "deg") / 2, unit="deg",
                      note=(rel(None, "=", q(phi, "rad")), ", the amplitude, from the mean "
                            "position"))
        else:
            phi = given[amplitude_key]
            work.step("phi", value=math.degrees(phi), unit="deg", note=(
                rel(None, "=", q(phi, "rad")),))
        if period_key == "frequency":
            f_rate = given["frequency"]  # rad/s: a frequency in Hz is read as 2 pi f
            T = work.step("T", V.circular_frequency(Sym("omega_1", f_rate, "rad/s")), unit="s",
                          note=_FROM_FREQUENCY)
        else:
            T = given["period"]
        p = V.pitching(phi, T)
        if period_key == "frequency":
            work.step("omega_1", value=p.frequency, unit="rad/s", note="the circular "
                      "frequency of the pitching")
        else:
            work.step("omega_1", V.circular_frequency(Sym("T", T, "s")), unit="rad/s")
        work.text(*_PITCH_ANGLE)
        work.text(*_PITCH_RATE)
        phi_, omega_1 = Sym("phi", phi), Sym("omega_1", p.frequency, "rad/s")  # phi in rad
        rate = work.step("omega_p,max", V.max_pitching_rate(phi_, omega_1), unit="rad/s")
        work.text(*_PITCH_ACCELERATION)
        work.step("alpha_max", phi_ * omega_1 ** 2, unit="rad/s^2")
        work.answer("max_precession", "omega_p,max", [p.max_precession], "rate")
        work.answer("max_angular_acceleration", "alpha_max", [p.max_acceleration],
                    "angular_acceleration")
        work.text("at the extremes the pitching rate, and so the gyroscopic couple, is zero")
    if bow is None:
        if "effect" in find:
            raise InputError("the effect needs bow: rising or falling at the instant",
                             key="given.bow")
        bow = "rising"
        work.text("bow not given: the couple's size is the same rising or falling")
    wp = V.pitching_precession(rate, bow)
    rising = bow == "rising"
    work.text(f"bow {bow}: the rotation carries ", x, " toward ", _PLUS_Z if rising else _MINUS_Z,
              ", a rotation about ", _MINUS_Y if rising else _PLUS_Y, ": ",
              rel(wp0, "=", qvec(wp, "rad/s")))
    return wp


AMPLITUDE_KEYS = ("amplitude", "pitch_amplitude", "pitch_total", "between_extremes")
STABILISER_KEYS = ("gyro_sense", "precession", "rolling_couple", "axle_top", "roll")
# the amplitude's limits (the total swing is twice it): the loader refuses a value outside
_AMPLITUDE: dict[str, Any] = dict(range=(0.0, math.pi / 2), bounds="()",
                  reason="a ship cannot pitch through 90 deg")
_TOTAL: dict[str, Any] = dict(range=(0.0, math.pi), bounds="()", reason="twice the amplitude, and a ship "
              "cannot pitch through 90 deg")
PERIOD_KEYS = ("period", "frequency")
#: the motion each motion's own key belongs to (_refuse_foreign)
_MOTION_OF_KEY = {"speed": "steering", "turn_radius": "steering", "turn": "steering",
                  "turn_rate": "steering",
                  "bow": "pitching", "pitch_rate": "pitching", "roll_rate": "rolling",
                  **{key: "pitching" for key in AMPLITUDE_KEYS + PERIOD_KEYS},
                  **{key: "stabilising" for key in STABILISER_KEYS}}


def _one_of(given: Given, keys: tuple[str, ...], missing: str) -> str:
    """The one key of ``keys`` the file gives (refusing none or two): for pitching only, so
    checked here rather than declared by the kind."""
    present = [k for k in keys if k in given]
    refused = OneOf(keys, missing).refusal(present)
    if refused is not None:
        raise InputError(refused[0], key=f"given.{refused[1]}")
    return present[0]


def _rolling(given: Given, work: Work) -> V.Vector:
    rate = abs(given["roll_rate"]) if "roll_rate" in given else 0.0
    work.section("Rolling: precession about the fore-and-aft axis")
    if rate:
        work.step("omega_p", Sym("omega_r", rate, "rad/s"), unit="rad/s", substitute=False,
                  note="rolling rate")
    else:
        work.text("no roll_rate given: any rate will do, only its direction matters")
    wp = V.rolling_precession(rate or 1.0)
    # the roll's sense is not among the data (+x is either): it does not matter, as the
    # couple is 0 whichever way the ship rolls
    work.text(wp0, " along ", x, " (the roll's sense does not matter here): ", qvec(wp, "rad/s"),
              " or its opposite")
    return wp


_STABILISER_AXES = ("ship axes: ", x, " forward (toward the bow), ", y, " to port, ", z,
                    " up. The stabiliser's rotor spins about the vertical; its frame is turned "
                    "(precessed) about the athwartship axis ", y, ", the top of the axle moving "
                    "forward (about ", _PLUS_Y, ") or aft (about ", _MINUS_Y, ").")
_STABILISER_REACTIVE = (*reactive_couple("ship", precession="the rate at which the "
                                         "stabiliser's frame is turned, athwartships"),
                        ", here about the fore-and-aft axis: about ", _PLUS_X, " it lifts the "
                        "port side, about ", _MINUS_X, " the starboard side.")


def _stabilising(given: Given, find: frozenset[str], work: Work, J: float, spin: float) -> None:
    """A ship's stabiliser gyro (Schlick, Sperry): a rotor spinning about the vertical whose
    frame is precessed about the athwartship axis; the reactive couple rolls the ship."""
    if "rotor_sense" in given:
        raise InputError("a stabiliser's rotor spins about the vertical: give its sense as "
                         f"gyro_sense ({', '.join(V.GYRO_SENSES)}), not rotor_sense",
                         key="given.rotor_sense")
    sense, roll, top = given.word("gyro_sense"), given.word("roll"), given.word("axle_top")
    if sense is None and ({"effect", "axle_top"} & find):
        raise InputError("the effect and the way to precess need the rotor's sense: "
                         f"gyro_sense, one of {', '.join(V.GYRO_SENSES)}", key="given.gyro_sense")
    if "axle_top" in find and roll is None:
        raise InputError("axle_top as an answer needs `roll`: the roll (to port or to "
                         "starboard) the stabiliser is to counteract", key="given.roll")
    work.section("Conventions (Khurmi, Theory of Machines, ch. 14; Meriam, Dynamics, ch. 7)")
    work.text(*_STABILISER_AXES)
    work.text(*_STABILISER_REACTIVE)
    up = V.vertical_spin_direction(sense) if sense else 1.0
    work.section("Rotor")
    J_, omega, Hmag = rotor_steps(work, J, spin, "the rotor's moment of inertia about its axle",
                                  "rotor speed")
    H = (0.0, 0.0, up * Hmag)
    if sense:
        work.text(f"{sense.replace('_', ' ')}: the spin vector points "
                  f"{'up, ' if up > 0 else 'down, '}", _PLUS_Z if up > 0 else _MINUS_Z, "; ",
                  rel(H0, "=", qvec(H, "kg m^2/s")))
    rate = _stabiliser_rate(given, work, J_, omega)
    if top is None and roll is not None and sense is not None:
        top = V.axle_top_against(roll, up)
        work.text(f"to counteract a roll to {roll} the ship needs a couple lifting its {roll} "
                  "side, about ", _PLUS_X if roll == "port" else _MINUS_X, ": the top of the "
                  f"axle must move {top}")
        work.answer("axle_top", "axle_top", [top], None)
    wp = V.stabiliser_precession(rate, top or "forward")
    if top:
        work.text(f"top of the axle moving {top}: ", rel(wp0, "=", qvec(wp, "rad/s")))
    elif "effect" in find:
        raise InputError("the effect needs axle_top (forward or aft: which way the top of the "
                         "rotor's axle moves) or the roll to counteract", key="given.axle_top")
    work.section(*_COUPLE_TITLE)
    C = work.step("C", V.gyroscopic_couple(J_, omega, Sym("omega_p", rate, "rad/s")), unit="N*m", ref="Eq. 11.29",
                  note="with the axle vertical")
    refuse_overflow(C, Hmag)
    work.answer("couple", "C", [C], "moment")
    work.answer("precession", "omega_p", [rate], "rate")
    if sense and top:
        _stabiliser_effect(wp, H, C, roll, top, work)


def _stabiliser_rate(given: Given, work: Work, J_: Sym, omega: Sym) -> float:
    """The precession of the stabiliser's frame: given, or the one that gives a rolling
    couple to resist, omega_p = M / (J omega)."""
    work.section("Precession of the stabiliser's frame")
    if "precession" in given:
        if "rolling_couple" in given:
            raise InputError("give precession, or rolling_couple (the couple to resist, "
                             "omega_p = M / (J omega)), not both", key="given.rolling_couple")
        rate: float = given["precession"]
        work.step("omega_p", value=rate, unit="rad/s", note="the frame's rate of precession")
        return rate
    if "rolling_couple" in given:
        return work.step("omega_p", V.precession_for_couple(Sym("M", given["rolling_couple"], "N m"), J_, omega),
                         unit="rad/s", note="the precession that gives the couple to resist")
    raise InputError("the stabiliser needs its precession (the frame's rate about the "
                     "athwartship axis), or the rolling_couple it must resist",
                     key="given.precession")


def _stabiliser_effect(wp: V.Vector, H: V.Vector, C: float, roll: str | None, top: str,
                       work: Work) -> None:
    """The reactive couple on the hull in words, with a warning where it adds to the roll."""
    active, reactive = V.couple_on_rotor(wp, H), V.reactive_couple(wp, H)
    work.text("couple on the rotor ", rel(COUPLE, "=", qvec(active, "N m")))
    work.text("reactive couple on the ship ", rel(_REACTION, "=", qvec(reactive, "N m")))
    words = V.effect_of(wp, H, "ship")
    work.text(f"effect on the ship: {words}")
    work.answer("effect", "effect", [words], None)
    if roll is not None and (reactive[0] > 0) != (roll == "port"):
        work.warn(f"with the top of the axle moving {top} the couple adds to the roll to "
                  f"{roll} instead of counteracting it")
    work.check(rel(_SIZE, "=", q(V.norm(active), "N m"), "=", C0, "=", q(C, "N m")))


# The books' own words (Khurmi, Rattan): other spellings of each choice.
_ENDS = {"stern": "stern", "aft": "stern", "rear": "stern", "back": "stern", "behind": "stern",
         "astern": "stern", "bow": "bow", "front": "bow", "fore": "bow", "ahead": "bow"}
SENSE_WORDS = tuple((f"{turn}_from_{end}", f"{turn}_from_{choice}")
                    for turn in ("clockwise", "counterclockwise")
                    for end, choice in _ENDS.items() if end != choice)
TURN_WORDS = (("port", "left"), ("to_port", "left"), ("to_the_left", "left"),
              ("starboard", "right"), ("to_starboard", "right"), ("to_the_right", "right"))
BOW_WORDS = (("descending", "falling"), ("going_down", "falling"), ("dipping", "falling"),
             ("ascending", "rising"), ("going_up", "rising"), ("lifting", "rising"),
             ("bow_descending", "falling"), ("bow_falling", "falling"),
             ("bow_ascending", "rising"), ("bow_rising", "rising"))

MOTION_WORDS = (("stabiliser", "stabilising"), ("stabilizer", "stabilising"),
                ("stabilizing", "stabilising"), ("anti_rolling", "stabilising"))
GYRO_SENSE_WORDS = tuple((f"{turn}_from_{end}", f"{turn}_from_{choice}")
                         for turn in ("clockwise", "counterclockwise")
                         for end, choice in (("top", "above"), ("bottom", "below"),
                                             ("underneath", "below")))
AXLE_TOP_WORDS = (("toward_the_bow", "forward"), ("towards_the_bow", "forward"),
                  ("to_the_bow", "forward"), ("bow", "forward"), ("fore", "forward"),
                  ("toward_the_stern", "aft"), ("towards_the_stern", "aft"),
                  ("to_the_stern", "aft"), ("stern", "aft"), ("astern", "aft"),
                  ("backward", "aft"))
ROLL_WORDS = (("to_port", "port"), ("to_the_left", "port"), ("left", "port"),
              ("to_starboard", "starboard"), ("to_the_right", "starboard"),
              ("right", "starboard"))

KIND = Kind(
    name="ship",
    summary="a ship's fore-and-aft turbine rotor: gyroscopic couple and its effect in steering, "
            "pitching (simple harmonic) and rolling",
    chapter="Eq. 11.29 in vector form, C = omega_p x H; Khurmi, Theory of Machines, ch. 14",
    params=(
        Param("spin", "rate", "omega", "rotor speed (a positive rate; its sense in rotor_sense)",
              nonnegative=True, reason="give the rotor's speed as a positive rate and its sense "
              "in rotor_sense (e.g. clockwise_from_stern)",
              required="give the rotor's speed `spin` (e.g. 1800 rpm)"),
        Param("rotor_sense", "word", "sense", "sense of the rotor seen from the stern or the bow",
              choices=V.SHIP_SENSES, words=SENSE_WORDS),
        Param("motion", "word", "motion", "steering (default), pitching, rolling, or "
              "stabilising (a stabiliser gyro spinning about the vertical)",
              choices=("steering", "pitching", "rolling", "stabilising"), words=MOTION_WORDS),
        Param("speed", "speed", "v", "ship's speed (steering)", nonnegative=True,
              reason="the ship goes ahead"),
        Param("turn_radius", "length", "R", "radius of the turn (steering)", positive=True),
        Param("turn_rate", "rate", "omega_p", "steering: the ship's rate of turn (rad/s, deg/s), "
              "instead of speed and turn_radius", positive=True,
              reason="turn_rate is a positive rate; say which way in turn (left or right)"),
        Param("turn", "word", "turn", "left (to port, default) or right (to starboard)",
              choices=("left", "right"), words=TURN_WORDS),
        Param("amplitude", "angle", "phi", "pitching: largest angle from the mean position "
              "(half the total swing)", **_AMPLITUDE),
        Param("pitch_amplitude", "angle", "phi", "pitching: the amplitude, as `amplitude`",
              **_AMPLITUDE),
        Param("pitch_total", "angle", "phi_total", "pitching: the total swing between the two "
              "extremes, twice the amplitude (Khurmi: '12 deg between the extreme positions')",
              **_TOTAL),
        Param("between_extremes", "angle", "phi_total", "pitching: as pitch_total", **_TOTAL),
        Param("period", "time", "T", "pitching: period of the simple harmonic pitching",
              positive=True),
        Param("frequency", "rate", "omega_1", "pitching: its frequency, instead of the period "
              "(0.025 Hz is one oscillation in 40 s; rad/s is 2 pi / T)", positive=True),
        Param("pitch_rate", "rate", "omega_p", "pitching: the pitching rate at the instant "
              "(instead of amplitude and period)"),
        Param("bow", "word", "bow", "pitching: the bow rising or falling at the instant asked",
              choices=("rising", "falling"), words=BOW_WORDS),
        Param("roll_rate", "rate", "omega_r", "rolling: the rolling rate (the couple is zero "
              "whatever it is)"),
        Param("gyro_sense", "word", "sense", "stabilising: the rotor's sense seen from above "
              "or below", choices=V.GYRO_SENSES, words=GYRO_SENSE_WORDS),
        Param("precession", "rate", "omega_p", "stabilising: the rate at which the rotor's "
              "frame is precessed about the athwartship axis", positive=True),
        Param("rolling_couple", "moment", "M", "stabilising: instead of precession, the "
              "rolling couple to resist (omega_p = M / (J omega))", positive=True),
        Param("axle_top", "word", "axle_top", "stabilising: which way the top of the rotor's "
              "axle moves, forward (toward the bow) or aft", choices=("forward", "aft"),
              words=AXLE_TOP_WORDS),
        Param("roll", "word", "roll", "stabilising: the roll to counteract, to port or to "
              "starboard (finds axle_top)", choices=("port", "starboard"), words=ROLL_WORDS),
    ),
    answers=(
        AnswerSpec("couple", "moment", "C", "gyroscopic couple J omega omega_p (the maximum in "
                   "pitching; 0 in rolling)"),
        AnswerSpec("precession", "rate", "omega_p", "precession rate used (the maximum in "
                   "pitching)"),
        AnswerSpec("max_precession", "rate", "omega_p,max", "pitching: largest pitching rate "
                   "phi 2 pi / T"),
        AnswerSpec("max_angular_acceleration", "angular_acceleration", "alpha_max",
                   "pitching: largest angular acceleration phi (2 pi / T)^2"),
        AnswerSpec("effect", None, "effect", "what the reactive couple does to the ship: "
                   "'raises the bow and lowers the stern', 'turns the ship to starboard', "
                   "'none' for rolling, 'lifts the port side and dips the starboard' for a "
                   "stabiliser, ...", words=V.EFFECT_WORDS["ship"]),
        AnswerSpec("axle_top", None, "axle_top", "stabilising: which way the top of the "
                   "rotor's axle must move to counteract the roll: forward or aft",
                   words=("forward", "aft")),
    ),
    solve=solve,
    gravity=False, body_keys=("mass", "weight", "J", "k_axial", "shape", "radius", "diameter", "inner_radius", "width", "length"), example={
        "statement": ("The turbine rotor of a ship has a mass of {mass} and a radius of gyration "
                      "of {k_axial}, and it turns at {spin}, {rotor_sense}. The ship steers to "
                      "the {turn} at {speed} on a curve of radius {turn_radius}. Find the "
                      "gyroscopic couple and its effect on the ship."),
        "given": {"mass": "8000 kg", "k_axial": "0.6 m", "spin": "1800 rpm",
                  "rotor_sense": "clockwise seen from the stern", "motion": "steering",
                  "speed": "100 km/h", "turn_radius": "75 m", "turn": "left"},
        "find": {"couple": "kN*m", "effect": None},
        "vary": {"speed": "[0.8, 1.2]"}},
)
