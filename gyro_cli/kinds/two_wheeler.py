"""A motorcycle (or bicycle) on a curve: the heel that balances the overturning couples.

The road wheels roll, omega_w = v / r_w, and the engine turns at G omega_w in
the wheels' sense (``engine_sense: same``) or against it. Going forward, the
wheels' spin vector points to the machine's left. Turning at omega_p = v / R
about the vertical, the rotors need the couple omega_p x H, and the machine
feels the reactive gyroscopic couple, which tends to overturn it outward:

    C_g = (2 I_w +- G I_E) omega_w omega_p = (2 I_w +- G I_E) v^2 / (R r_w)

The centrifugal (inertia) force m v^2 / R at the centre of mass, h above the
road, gives the overturning couple C_c = m v^2 h / R. Heeled inward by theta,
both are multiplied by cos(theta) (the spin axes tilt; G is h cos(theta) up),
and the weight gives the balancing couple m g h sin(theta):

    tan(theta) = (C_g + C_c) / (m g h)

Reference: R.S. Khurmi and J.K. Gupta, "Theory of Machines", ch. 14 (stability
of a two-wheel vehicle taking a turn); S.S. Rattan, "Theory of Machines", ch. 14.
"""

from __future__ import annotations

import math

from ..core.body import vehicle_data, vehicle_params
from ..core.errors import refuse_overflow
from ..core.expr import Sym, cos, sin
from ..core.given import Given
from ..core.prose import deriv, names, plus, q, qvec, rel, tup
from ..core.spec import AnswerSpec, Kind, Param
from ..core.vehicle_words import ALONG_LEFT, COUPLE, reactive_couple, turn_of
from ..core.work import Work
from ..physics import vehicles as V

#: the machine's axes and the symbols its prose names (values are in the steps' trees)
x, y, z = names("x y z")
m0, g0, h0, v0, R0, N0, F0, G0, theta0 = names("m g h v R N F G theta")
H0, C0, wp0, Cg0, Cc0 = names("H C omega_p C_g C_c")

# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's own time in gyro check.
_LEFT = plus(y)
_AXES = ("machine axes: ", x, " forward, ", y, " to the left, ", z, " up. Going forward the "
         "road wheels roll: their spin vector points to the left ", tup(_LEFT), ". The "
         "engine's points the same way (engine_sense: same) or the other way (opposite).")
_REACTIVE = (*reactive_couple("machine", "rotors"), ". Couples below are about the "
             "fore-and-aft line through the contact points, positive overturning the machine "
             "outward (away from the centre).")
_CENTRIFUGAL_FORCE = m0 * v0 ** 2 / R0
_CENTRIFUGAL = ("centrifugal force ", _CENTRIFUGAL_FORCE, " at the centre of mass")
_HEEL_TITLE = ("Heel: free body of the machine heeled inward by ", theta0)
_HEEL_FREE_BODY = (
    "road: normal force ", rel(N0, "=", m0 * g0), " up and friction ",
    rel(F0, "=", _CENTRIFUGAL_FORCE), " toward the centre, at the contact; ", G0, " at ",
    h0 * sin(theta0), " inward and ", h0 * cos(theta0), " up from it. Moments about ", G0,
    " along ", x, ": ", rel(h0 * (F0 * cos(theta0) - N0 * sin(theta0)), "=", deriv(H0), "=",
                            -wp0 * H0 * cos(theta0)),
    " (the spin axes tilt by ", theta0, "), that is")
_HEEL_BALANCE = (rel(m0 * g0 * h0 * sin(theta0), "=", (Cg0 + Cc0) * cos(theta0)),)
_NET_MOMENT = m0 * g0 * h0 * sin(theta0) - (Cg0 + Cc0) * cos(theta0)


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    given = vehicle_data(given, work, 'wheel', 'engine')
    m, g, h = given["mass"], given["g"], given["cg_height"]
    Iw, rw, IE = given["wheel_inertia"], given["wheel_radius"], given["engine_inertia"]
    G, sense = given["gear_ratio"], given.word("engine_sense", "same")
    v, R = given["speed"], given["turn_radius"]
    turn, taken = turn_of(given)
    w = V.rolling_rate(v, rw)
    H = V.spin_momentum(V.rotor_inertia(2 * Iw, G, IE, sense), w)
    Cg, Cc = V.book_couples(H, V.turn_rate(v, R), m, v, h, R)
    refuse_overflow(Cg, Cc, m * g * h, w)
    heel = math.atan2(Cg + Cc, m * g * h)  # V.heel's angle, as the answers have always had it

    work.section("Conventions (Khurmi, Theory of Machines, ch. 14)")
    work.text(*_AXES)
    work.text(*_REACTIVE)

    v_, r_w, R_ = Sym("v", v, "m/s"), Sym("r_w", rw, "m"), Sym("R", R, "m")
    m_, g_, h_ = Sym("m", m, "kg"), Sym("g", g, "m/s^2"), Sym("h", h, "m")
    G_ = Sym("G", G)
    work.section("Rates")
    omega_w = Sym("omega_w", work.step("omega_w", V.rolling_rate(v_, r_w), unit="rad/s",
                                       note="road wheels (rolling)"), "rad/s")
    work.step("omega_E", V.geared_rate(G_, omega_w), unit="rad/s",
              note=f"engine, {sense} sense as the wheels")
    work.step("omega_p", V.turn_rate(v_, R_), unit="rad/s", note="precession about the vertical")

    work.section("Vector rule (upright)")
    # the spinning parts' inertia in the wheels' sense: 2 I_w + G I_E, or - with the engine against
    rotors_ = V.rotor_inertia(2 * Sym("I_w", Iw, "kg m^2"), G_, Sym("I_E", IE, "kg m^2"), sense)
    work.step("H", V.spin_momentum(rotors_, omega_w), unit="kg m^2/s",
              note=ALONG_LEFT)
    wp = V.steering_precession(v, R, turn)
    Hv = V.scale(H, V.LEFT)
    work.text(f"turning {turn}{taken}: ", rel(wp0, "=", qvec((0, 0, wp[2]), "rad/s")), "; ",
              rel(COUPLE, "=", qvec((V.couple_on_rotor(wp, Hv)[0], 0, 0), "N m")),
              " on the rotors; the reactive couple on the machine, ",
              qvec((V.reactive_couple(wp, Hv)[0], 0, 0), "N m"),
              ", lifts the " + ("inner side: it overturns the machine outward"
                                if H >= 0 else "outer side: it leans the machine inward"))

    work.section("Overturning couples, upright")
    C_g = work.step("C_g", V.overturning_couple(rotors_, v_, R_, r_w), unit="N*m",
                    ref="Eq. 11.29")
    C_c = work.step("C_c", V.centrifugal_couple(m_, v_, h_, R_), unit="N*m", note=_CENTRIFUGAL)

    work.section(*_HEEL_TITLE)
    work.text(*_HEEL_FREE_BODY)
    work.text(*_HEEL_BALANCE)
    work.step("theta", V.heel(Sym("C_g", C_g, "N m"), Sym("C_c", C_c, "N m"), m_, g_, h_),
              unit="deg")
    if heel < 0:
        work.warn("the engine's reversed gyroscopic couple outweighs the centrifugal one: the "
                  "machine leans outward")
    balance = m * g * h * math.sin(heel) - (Cg + Cc) * math.cos(heel)
    work.check(rel(_NET_MOMENT, "=", q(balance, "N m")))
    work.answer("heel_angle", "theta", [heel], "angle")
    work.answer("gyroscopic_couple", "C_g", [Cg], "moment")
    work.answer("centrifugal_couple", "C_c", [Cc], "moment")

KIND = Kind(
    name="two_wheeler",
    summary="a motorcycle on a curve: gyroscopic and centrifugal overturning couples and the "
            "heel that balances them",
    chapter="Eq. 11.29, C = omega_p x H; Khurmi, Theory of Machines, ch. 14",
    uses_body=False,
    params=(
        Param("mass", "mass", "m", "total mass of the machine with its rider", positive=True),
        Param("g", "acceleration", "g", "gravity", default="9.81 m/s^2", positive=True),
        Param("cg_height", "length", "h", "height of the centre of mass above the road, upright",
              positive=True, required=True),
        Param("wheel_inertia", "inertia", "I_w", "moment of inertia of each road wheel about "
              "its axle", nonnegative=True),
        Param("wheel_radius", "length", "r_w", "radius of the road wheels", positive=True),
        Param("engine_inertia", "inertia", "I_E", "moment of inertia of the engine's rotating "
              "parts", default="0 kg*m^2", nonnegative=True),
        Param("gear_ratio", "dimensionless", "G", "engine speed / wheel speed", default="1",
              nonnegative=True),
        Param("engine_sense", "word", "engine_sense", "same (default) or opposite: the "
              "engine's sense of rotation relative to the wheels", choices=("same", "opposite")),
        Param("speed", "speed", "v", "speed of the machine", nonnegative=True, required=True),
        Param("turn_radius", "length", "R", "radius of the curve", positive=True, required=True),
        Param("turn", "word", "turn", "left (default) or right: only the vectors shown change",
              choices=("left", "right")),
    ) + vehicle_params('wheel', 'engine'),
    answers=(
        AnswerSpec("heel_angle", "angle", "theta", "lean from the vertical, toward the centre, "
                   "that balances both couples"),
        AnswerSpec("gyroscopic_couple", "moment", "C_g", "gyroscopic overturning couple, "
                   "upright, (2 I_w +- G I_E) v^2 / (R r_w)"),
        AnswerSpec("centrifugal_couple", "moment", "C_c", "centrifugal overturning couple, "
                   "upright, m v^2 h / R"),
    ),
    solve=solve,
    example={
        "statement": ("A motor cycle with its rider has a mass of {mass}, with the centre of mass "
                      "{cg_height} above the road when upright. Each road wheel has a moment of "
                      "inertia of {wheel_inertia} and a radius of {wheel_radius}; the engine's "
                      "rotating parts have a moment of inertia of {engine_inertia}, turn "
                      "{gear_ratio} times as fast as the wheels and in the {engine_sense} sense. "
                      "It rounds a curve of radius {turn_radius} at {speed}. Find the angle of "
                      "heel, the gyroscopic couple and the centrifugal couple."),
        "given": {"mass": "250 kg", "cg_height": "0.6 m", "wheel_inertia": "1 kg*m^2",
                  "wheel_radius": "300 mm", "engine_inertia": "0.3 kg*m^2", "gear_ratio": "5",
                  "engine_sense": "same", "speed": "90 km/h", "turn_radius": "50 m"},
        "find": {"heel_angle": "deg", "gyroscopic_couple": "N*m", "centrifugal_couple": "N*m"},
        "vary": {"speed": "[0.8, 1.2]"}},
)
