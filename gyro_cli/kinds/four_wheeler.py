"""A four-wheeled car or rail trolley on a curve: the vertical reaction of each wheel.

The wheels roll, omega_w = v / r_w; each engine (motor) turns at G omega_w in
the wheels' sense or against it (``engine_sense``). Turning at omega_p = v / R
about the vertical:

- weight: m g / 4 on every wheel (centre of mass midway between the axles and
  between the wheels);
- gyroscopic couple C_g = (sum I_w +- G sum I_E) v^2 / (R r_w) (Eq. 11.29,
  reactive): with the wheels' own sense it overturns the vehicle outward; the
  two wheel pairs, x apart, take it as +-C_g / (2 x) on each wheel;
- centrifugal couple C_c = m v^2 h / R, taken as +-C_c / (2 x) on each wheel.

Outer wheels: m g / 4 + C_g / (2 x) + C_c / (2 x); inner: the shares subtracted.
The inner wheels leave the road when their reaction reaches zero:

    v_lim^2 = m g x R / (2 (I_eq / r_w + m h)),  I_eq = sum I_w +- G sum I_E

Reference: R.S. Khurmi and J.K. Gupta, "Theory of Machines", ch. 14 (stability
of a four-wheel drive moving in a curved path); S.S. Rattan, ch. 14.
"""

from __future__ import annotations

import math

from ..core.body import vehicle_data, vehicle_params
from ..core.errors import InputError
from ..core.given import Given
from ..physics import vehicles as V
from ..core.spec import AnswerSpec, Kind, Param
from ..core.expr import Expr, Let, Sym, sqrt
from ..core.prose import names, plus, q, qvec, rel, total, tup
from ..core.vehicle_words import ALONG_LEFT, COUPLE, reactive_couple
from ..core.work import Work, qty

#: the vehicle's axes and the symbols its prose names (values are in the steps' trees)
ax, ay, az = names("x y z")
H0, C0, wp0, Cg0, Cc0, m0, g0, R0 = names("H C omega_p C_g C_c m g R")
I_w0, I_E0, R_o0, R_i0, x0, v_lim0, I_eq0, r_w0, h0 = names("I_w I_E R_outer R_inner x v_lim I_eq "
                                                             "r_w h")

# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's own time in gyro check.
_LEFT = plus(ay)
_AXES = ("vehicle axes: ", ax, " forward, ", ay, " to the left, ", az, " up. Going forward the "
         "wheels roll: their spin vector points to the left ", tup(_LEFT), "; each engine's "
         "points the same way (engine_sense: same) or the other way (opposite).")
_REACTIVE = (*reactive_couple("vehicle", "rotors"), ". Couples are about the fore-and-aft "
             "axis, positive overturning the vehicle outward (lifting the inner wheels). "
             "Reactions are the road's vertical forces on each wheel; the centre of mass is "
             "taken midway between the axles and the wheels, so each pair shares equally.")
_SUM_I_W, _SUM_I_E = total(I_w0), total(I_E0)
_REACTIONS, _WEIGHT = 2 * R_o0 + 2 * R_i0, m0 * g0  # the check's vertical balance
_MOMENT_OF_REACTIONS, _COUPLES = x0 * (R_o0 - R_i0), Cg0 + Cc0  # and its moment balance
_AT_THE_LIMIT = ("at the limiting speed ", v_lim0, ": ",
                 rel(m0 * g0 / 4, "=", (v_lim0 ** 2 / (2 * x0 * R0)) * (I_eq0 / r_w0 + m0 * h0)))


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    given = vehicle_data(given, work, 'wheel', 'axle', 'engine')
    engines = given["engines"]
    m, g, h, x = given["mass"], given["g"], given["cg_height"], given["track"]
    rw, R = given["wheel_radius"], given["turn_radius"]
    IE, G, sense = given["engine_inertia"], given["gear_ratio"], given.word("engine_sense", "same")
    wheels = _wheels(given)

    work.section("Conventions (Khurmi, Theory of Machines, ch. 14)")
    work.text(*_AXES)
    work.text(*_REACTIVE)
    work.section("Rotating parts")
    wheel_total = work.step(_SUM_I_W, wheels, unit="kg*m^2")
    engine_total = work.step(_SUM_I_E, Sym("n_E", engines) * Sym("I_E", IE, "kg m^2"),
                             unit="kg*m^2")
    sum_w, sum_E = Sym("sum I_w", wheel_total, "kg m^2"), Sym("sum I_E", engine_total, "kg m^2")
    # in the wheels' sense: sum I_w + G sum I_E, or - with the engines against the wheels
    rotors: Expr = sum_w + Sym("G", G) * sum_E if sense == "same" else sum_w - Sym("G", G) * sum_E
    I_eq = work.step("I_eq", rotors, unit="kg*m^2")
    equivalent = Let(Sym("I_eq", I_eq, "kg m^2"), rotors)

    if "speed" not in given and "limiting_speed" not in find:
        raise InputError("give the speed (or ask only for limiting_speed)", key="given.speed")
    if "speed" in given:
        _at_speed(given, work, m, g, h, x, rw, R, wheel_total, engine_total, G, sense,
                  equivalent)
    if "limiting_speed" in find:
        _limit(work, m, g, h, x, rw, R, wheel_total, engine_total, G, sense, I_eq)


def _wheels(given: Given) -> Expr:
    """sum I_w: four wheels' 4 I_w, or two axles' 2 I_axle."""
    if ("wheel_inertia" in given) == ("axle_inertia" in given):
        raise InputError("give wheel_inertia (each of the four wheels) or axle_inertia (each of "
                         "the two axles with its pair of wheels and gears), one of them",
                         key="given.wheel_inertia")
    if "wheel_inertia" in given:
        Iw = given["wheel_inertia"]
        return 4 * Sym("I_w", Iw, "kg m^2")
    Ia = given["axle_inertia"]
    return 2 * Sym("I_axle", Ia, "kg m^2")


def _at_speed(given: Given, work: Work, m: float, g: float, h: float, x: float, rw: float,
              R: float, wheels: float, engines: float, G: float, sense: str,
              equivalent: Let) -> None:
    v = given["speed"]
    turn = given.word("turn", "left")
    s = V.four_wheeler(m, g, h, x, rw, wheels, engines, G, sense, v, R)
    outer, inner = s.outer, s.inner  # each wheel's reaction: its three shares, added once
    if not all(math.isfinite(q) for q in (outer, inner, s.gyroscopic_couple,
                                           s.centrifugal_couple, s.wheel_rate)):
        raise InputError("these data are outside what gyro can compute reliably in double "
                         "precision (a product overflows); check the magnitudes and units",
                         key="given")
    v_, r_w, R_ = Sym("v", v, "m/s"), Sym("r_w", rw, "m"), Sym("R", R, "m")
    m_, x_ = Sym("m", m, "kg"), Sym("x", x, "m")
    work.section("Rates")
    omega_w = work.step("omega_w", v_ / r_w, unit="rad/s")
    work.step("omega_p", v_ / R_, unit="rad/s")
    work.section("Vector rule")
    H = work.step("H", equivalent.sym * Sym("omega_w", omega_w, "rad/s"), unit="kg m^2/s",
                  note=ALONG_LEFT)
    wp, Hv = V.steering_precession(v, R, turn), V.scale(H, V.LEFT)
    work.text(f"turning {turn}: ", rel(wp0, "=", qvec((0, 0, wp[2]), "rad/s")), "; ",
              rel(COUPLE, "=", qvec((V.couple_on_rotor(wp, Hv)[0], 0, 0), "N m")),
              " on the rotors; the reactive couple on the vehicle, ",
              qvec((V.reactive_couple(wp, Hv)[0], 0, 0), "N m"), ", "
              + ("overturns it outward (lifts the inner wheels)" if H >= 0 else
                 "presses the inner wheels down (the engines' reversed momentum dominates)"))
    work.section("Couples and their shares on each wheel")
    C_g = work.step("C_g", equivalent * v_ ** 2 / (R_ * r_w), unit="N*m", ref="Eq. 11.29")
    C_c = work.step("C_c", m_ * v_ ** 2 * Sym("h", h, "m") / R_, unit="N*m")
    P_w = Sym("P_w", work.step("P_w", m_ * Sym("g", g, "m/s^2") / 4, unit="N",
                               note="weight, every wheel"), "N")
    P_g = Sym("P_g", work.step("P_g", Sym("C_g", C_g, "N m") / (2 * x_), unit="N",
                               note="gyroscopic: + outer, - inner"), "N")
    P_c = Sym("P_c", work.step("P_c", Sym("C_c", C_c, "N m") / (2 * x_), unit="N",
                               note="centrifugal: + outer, - inner"), "N")
    work.step("R_outer", P_w + P_g + P_c, unit="N", note="each outer wheel")
    work.step("R_inner", P_w - P_g - P_c, unit="N", note="each inner wheel")
    if inner < 0:
        work.warn("the inner wheels' reaction is negative (", q(inner, "N"), "): at this speed "
                  "the inner wheels leave the road (the vehicle overturns) unless held down")
    if outer < 0:
        work.warn("the outer wheels' reaction is negative (", q(outer, "N"), "): they leave "
                  "the road")
    work.check(rel(_REACTIONS, "=", q(2 * (outer + inner), "N"), "=", _WEIGHT, "=",
                   q(m * g, "N")), "; ",
               rel(_MOMENT_OF_REACTIONS, "=", q(x * (outer - inner), "N m"), "=", _COUPLES,
                   "=", q(s.gyroscopic_couple + s.centrifugal_couple, "N m")))
    work.answer("wheel_reactions", "R", [outer, inner], "force", ["outer", "inner"])
    work.answer("gyroscopic_couple", "C_g", [s.gyroscopic_couple], "moment")
    work.answer("centrifugal_couple", "C_c", [s.centrifugal_couple], "moment")


def _limit(work: Work, m: float, g: float, h: float, x: float, rw: float, R: float,
           wheels: float, engines: float, G: float, sense: str, I_eq: float) -> None:
    work.section("Limiting speed: the inner wheels' reaction falls to zero")
    work.text(*_AT_THE_LIMIT)
    v2 = V.limiting_speed_squared(m, g, h, x, rw, wheels, engines, G, sense, R)
    if v2 is None:
        raise InputError(f"the inner wheels never leave the road: the engines' reversed "
                         f"gyroscopic couple, I_eq / r_w = {qty(I_eq / rw, 'kg m')}, outweighs "
                         f"the centrifugal m h = {qty(m * h, 'kg m')}", key="find.limiting_speed")
    m_ = Sym("m", m, "kg")
    v = work.step("v_lim", sqrt(m_ * Sym("g", g, "m/s^2") * Sym("x", x, "m") * Sym("R", R, "m")
                                / (2 * (Sym("I_eq", I_eq, "kg m^2") / Sym("r_w", rw, "m")
                                        + m_ * Sym("h", h, "m")))), unit="m/s")
    work.answer("limiting_speed", "v_lim", [v], "speed")


KIND = Kind(
    name="four_wheeler",
    summary="a four-wheeled car or rail trolley on a curve: wheel reactions with their weight, "
            "gyroscopic and centrifugal parts, and the speed at which the inner wheels lift",
    chapter="Eq. 11.29, C = omega_p x H; Khurmi, Theory of Machines, ch. 14",
    uses_body=False,
    params=(
        Param("mass", "mass", "m", "total mass of the vehicle", positive=True),
        Param("g", "acceleration", "g", "gravity", default="9.81 m/s^2", positive=True),
        Param("cg_height", "length", "h", "height of the centre of mass above the road or rails",
              positive=True),
        Param("track", "length", "x", "track width: distance between the wheels of an axle "
              "(between the rails)", positive=True),
        Param("wheel_radius", "length", "r_w", "radius of the wheels", positive=True),
        Param("wheel_inertia", "inertia", "I_w", "moment of inertia of each of the four wheels",
              nonnegative=True),
        Param("axle_inertia", "inertia", "I_axle", "instead of wheel_inertia: each of the two "
              "axles with its wheels and gears", nonnegative=True),
        Param("engine_inertia", "inertia", "I_E", "moment of inertia of each engine (motor) with "
              "its rotating parts", default="0 kg*m^2", nonnegative=True),
        Param("engines", "dimensionless", "n_E", "number of engines (motors)", default="1",
              nonnegative=True, whole=True, reason="engines is a count (0, 1, 2, ...)"),
        Param("gear_ratio", "dimensionless", "G", "engine speed / wheel speed", default="1",
              nonnegative=True),
        Param("engine_sense", "word", "engine_sense", "same (default) or opposite: the "
              "engines' sense of rotation relative to the wheels", choices=("same", "opposite")),
        Param("speed", "speed", "v", "speed of the vehicle", nonnegative=True,
              reason="the vehicle goes forward"),
        Param("turn_radius", "length", "R", "radius of the curve", positive=True),
        Param("turn", "word", "turn", "left (default) or right: only the vectors shown change",
              choices=("left", "right")),
    ) + vehicle_params('wheel', 'axle', 'engine'),
    answers=(
        AnswerSpec("wheel_reactions", "force", "R", "[outer, inner]: vertical reaction on each "
                   "outer and each inner wheel"),
        AnswerSpec("gyroscopic_couple", "moment", "C_g", "(sum I_w +- G sum I_E) v^2 / (R r_w), "
                   "positive overturning outward"),
        AnswerSpec("centrifugal_couple", "moment", "C_c", "m v^2 h / R"),
        AnswerSpec("limiting_speed", "speed", "v_lim", "speed at which the inner wheels leave "
                   "the road"),
    ),
    solve=solve,
    extra={"example": {
        "statement": ("A rail car of total mass {mass} has its centre of mass {cg_height} above "
                      "the rails, which are {track} apart. Its wheels have a radius of "
                      "{wheel_radius}, and each of its two axles, with its wheels and gears, has "
                      "a moment of inertia of {axle_inertia}. It is driven by {engines} motors, "
                      "each with a moment of inertia of {engine_inertia}, geared {gear_ratio} to "
                      "1 to the axles and turning in the {engine_sense} sense to the wheels. It "
                      "rounds a curve of radius {turn_radius} at {speed}. Find the reaction of "
                      "the rails on each outer and each inner wheel, the gyroscopic couple and "
                      "the centrifugal couple."),
        "given": {"mass": "2500 kg", "cg_height": "0.9 m", "track": "1.5 m",
                  "wheel_radius": "0.375 m", "axle_inertia": "18 kg*m^2",
                  "engine_inertia": "12 kg*m^2", "engines": "2", "gear_ratio": "5",
                  "engine_sense": "opposite", "speed": "24 km/h", "turn_radius": "30 m"},
        "find": {"wheel_reactions": "N", "gyroscopic_couple": "N*m",
                 "centrifugal_couple": "N*m"},
        "vary": {"speed": "[0.8, 1.2]"}}},
)
