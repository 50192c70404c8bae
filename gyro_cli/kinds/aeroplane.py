"""An aeroplane's engine and propeller on a turn: the gyroscopic couple and its effect.

The rotor (engine and propeller) turns about the fore-and-aft axis x; its
angular momentum H = J omega s points forward or aft (``rotor_sense``, seen
from the front or the rear). Turning on a circle of radius R at speed v turns
H at omega_p = v / R about the vertical, so the rotor needs the couple
C = omega_p x H, of size J omega v / R (Eq. 11.29 in vector form), and the
aeroplane feels the reactive couple -C, which pitches it: it raises the nose
and dips the tail, or dips the nose and raises the tail.

Reference: R.S. Khurmi and J.K. Gupta, "Theory of Machines", ch. 14 (effect of
the gyroscopic couple on an aeroplane); S.S. Rattan, "Theory of Machines", ch. 14.
"""

from __future__ import annotations

from ..core.errors import InputError, refuse_overflow
from ..core.expr import Sym, absolute
from ..core.given import Given
from ..core.prose import names, paren, plus, q, qvec, rel
from ..core.spec import AnswerSpec, Kind, Param
from ..core.vehicle_words import COUPLE, reactive_couple, rotor_steps, turn_of
from ..core.work import Work
from ..physics import vehicles as V

#: the aeroplane's axes and the symbols its prose names (values are in the steps' trees)
x, y, z, H0, wp0, C0 = names("x y z H omega_p C")

# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's own time in gyro check.
_AXES = ("aeroplane axes: ", x, " forward (toward the nose), ", y, " to the left (looking "
         "forward), ", z, " up. The engine's axis lies fore and aft. A rotation that looks "
         "clockwise to an observer has its vector pointing away from the observer "
         "(right-hand rule).")
_REACTIVE = (*reactive_couple("aeroplane", precession="the aeroplane's angular velocity: about "
                                                   "the vertical in a turn, about its lateral "
                                                   "axis in a loop or a pull-out"), ". About ", -y, " it raises the nose; about ",
             plus(y), " it dips it; about ", plus(z), " it turns the nose to the left.")
_FORWARD, _AFT = plus(x), -x
_COUPLE_TITLE = ("Gyroscopic couple, ", rel(C0, "=", COUPLE))
_REACTION, _SIZE = -paren(COUPLE), absolute(COUPLE)


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.solid_body
    J = body.needed("J")
    motion = given.word("motion", "turn")
    _refuse_foreign(given, motion)
    radius_key = "loop_radius" if motion == "loop" else "turn_radius"
    if radius_key not in given:  # spin and speed are declared required; the radius is the
        raise InputError(f"the aeroplane needs spin (engine speed), speed and {radius_key}"
                         + (" (the loop's radius: motion is loop)" if motion == "loop" else ""),
                         key=f"given.{radius_key}")  # motion's
    spin, v, R = given["spin"], given["speed"], given[radius_key]
    sense = given.word("rotor_sense")
    if sense is None and "effect" in find:
        raise InputError("the effect needs the engine's sense: rotor_sense, one of "
                         f"{', '.join(V.AEROPLANE_SENSES)}", key="given.rotor_sense")

    work.section("Conventions (Khurmi, Theory of Machines, ch. 14)")
    work.text(*_AXES)
    work.text(*_REACTIVE)

    direction = V.spin_direction(sense) if sense else 1.0
    work.section("Engine and propeller")
    J_, omega, _ = rotor_steps(work, J, spin, "axial moment of inertia of the rotating parts",
                               "engine speed")
    H = V.spin_vector(J, spin, direction)
    if sense:
        work.text(f"{sense.replace('_', ' ')}: the spin vector points "
                  f"{'forward (toward the nose), ' if direction > 0 else 'aft (toward the tail), '}",
                  _FORWARD if direction > 0 else _AFT, "; ", rel(H0, "=", qvec(H, "kg m^2/s")))

    if motion == "loop":
        wp, rate = _loop(given, v, R, work)
    else:
        turn, taken = turn_of(given)
        work.section("Turn: precession about the vertical")
        rate = work.step("omega_p", V.turn_rate(Sym("v", v, "m/s"), Sym("R", R, "m")), unit="rad/s")
        wp = V.steering_precession(v, R, turn)
        work.text(f"turning {turn} ({'counter-clockwise' if turn == 'left' else 'clockwise'} "
                  "seen from above)" + taken + ": ", rel(wp0, "=", qvec(wp, "rad/s")))

    work.section(*_COUPLE_TITLE)
    C = work.step("C", V.gyroscopic_couple(J_, omega, Sym("omega_p", rate, "rad/s")), unit="N*m", ref="Eq. 11.29")
    refuse_overflow(C)
    work.answer("couple", "C", [C], "moment")
    work.answer("precession", "omega_p", [rate], "rate")
    if sense:
        active = V.couple_on_rotor(wp, H)
        reactive = V.reactive_couple(wp, H)
        work.text("couple on the rotor ", rel(COUPLE, "=", qvec(active, "N m")))
        work.text("reactive couple on the aeroplane ", rel(_REACTION, "=", qvec(reactive, "N m")))
        words = V.effect_of(wp, H, "aeroplane")
        work.text(f"effect on the aeroplane: {words}")
        work.answer("effect", "effect", [words], None)
        work.check(rel(_SIZE, "=", q(V.norm(active), "N m"), "=", C0, "=", q(C, "N m")))


def _loop(given: Given, v: float, R: float, work: Work) -> tuple[V.Vector, float]:
    """A loop (or a pull-out from a dive) on a vertical circle: the aeroplane pitches at v / R
    about its own lateral axis, nose rising (an inside loop) unless ``nose`` says falling."""
    nose = given.word("nose")
    work.section("Loop: precession about the lateral axis")
    rate = work.step("omega_p", V.turn_rate(Sym("v", v, "m/s"), Sym("R", R, "m")), unit="rad/s",
                     note="the rate of pitch on the vertical circle")
    if nose is None:
        nose = "rising"
        work.text("nose not given: an inside loop (pulling up, or out of a dive), the nose rising "
                  "about the aeroplane's own lateral axis all the way round")
    work.text("in a loop the precession is this pitching, about the aeroplane's lateral axis ",
              y, ", not about the vertical")
    wp = V.pitching_precession(rate, nose)
    rising = nose == "rising"
    work.text(f"nose {nose}: the rotation carries ", x, " toward ", plus(z) if rising else -z,
              ", a rotation about ", -y if rising else plus(y), ": ",
              rel(wp0, "=", qvec(wp, "rad/s")))
    return wp, rate


#: the motion each motion's own key belongs to (_refuse_foreign)
_MOTION_OF_KEY = {"turn_radius": "turn", "turn": "turn", "loop_radius": "loop", "nose": "loop"}


def _refuse_foreign(given: Given, motion: str) -> None:
    """Keys of the other motion are refused rather than silently ignored."""
    for key, owner in _MOTION_OF_KEY.items():
        if key in given and owner != motion:
            raise InputError(f"{key} belongs to `motion: {owner}`, but motion is {motion}",
                             key=f"given.{key}")


NOSE_WORDS = (("nose_rising", "rising"), ("pulling_up", "rising"), ("pull_up", "rising"),
              ("pulling_out_of_a_dive", "rising"), ("inside_loop", "rising"),
              ("nose_up", "rising"), ("nose_falling", "falling"), ("nose_down", "falling"),
              ("pushing_over", "falling"), ("push_over", "falling"),
              ("outside_loop", "falling"))


_NEEDS = ("the aeroplane needs spin (engine speed), speed and turn_radius (loop_radius in "
          "a loop)")

KIND = Kind(
    name="aeroplane",
    summary="an aeroplane's engine and propeller on a turn: gyroscopic couple and whether it "
            "raises or dips the nose",
    chapter="Eq. 11.29 in vector form, C = omega_p x H; Khurmi, Theory of Machines, ch. 14",
    params=(
        Param("spin", "rate", "omega", "engine (propeller) speed, a positive rate; its sense in "
              "rotor_sense", nonnegative=True, reason="give the engine speed as a positive "
              "rate and its sense in rotor_sense (e.g. clockwise_from_rear)", required=_NEEDS),
        Param("rotor_sense", "word", "sense", "sense of the engine seen from the front (nose) or "
              "the rear (tail, the pilot's view)", choices=V.AEROPLANE_SENSES),
        Param("speed", "speed", "v", "flying speed", nonnegative=True,
              reason="the aeroplane flies forward", required=_NEEDS),
        Param("turn_radius", "length", "R", "radius of the turn", positive=True),
        Param("turn", "word", "turn", "left (default) or right", choices=("left", "right")),
        Param("motion", "word", "motion", "turn (default: a horizontal turn) or loop (a loop "
              "or a pull-out from a dive, on a vertical circle)", choices=("turn", "loop")),
        Param("loop_radius", "length", "R", "loop: radius of the vertical circle",
              positive=True),
        Param("nose", "word", "nose", "loop: the nose rising (default: an inside loop, pulling "
              "up) or falling (an outside loop, pushing over)", choices=("rising", "falling"),
              words=NOSE_WORDS),
    ),
    answers=(
        AnswerSpec("couple", "moment", "C", "gyroscopic couple J omega v / R"),
        AnswerSpec("precession", "rate", "omega_p", "rate of turn (or of pitch in a loop) v / R"),
        AnswerSpec("effect", None, "effect", "what the reactive couple does: 'raises the nose "
                   "and dips the tail' or 'dips the nose and raises the tail' on a turn; "
                   "'turns the nose to the right' or 'to the left' in a loop",
                   words=V.EFFECT_WORDS["aeroplane"]),
    ),
    solve=solve,
    gravity=False, body_keys=("mass", "weight", "J", "k_axial", "shape", "radius", "diameter", "inner_radius", "width", "length"), example={
        "statement": ("An aeroplane makes a {turn} turn of radius {turn_radius} at {speed}. Its "
                      "engine and propeller have a mass of {mass} and a radius of gyration of "
                      "{k_axial}, and they turn at {spin}, {rotor_sense}. Find the gyroscopic "
                      "couple on the aeroplane and its effect."),
        "given": {"mass": "400 kg", "k_axial": "0.3 m", "spin": "2400 rpm",
                  "rotor_sense": "clockwise seen from the rear", "speed": "200 km/h",
                  "turn_radius": "50 m", "turn": "left"},
        "find": {"couple": "N*m", "effect": None},
        "vary": {"speed": "[0.8, 1.2]"}},
)
