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

The car as the books draw it (a banked track, the centre of mass anywhere on the
wheelbase, an engine along the car whose couple moves load between the axles) is
worked as a free body in the track's plane: physics/vehicles.py, CarLoads, gives
each wheel's load and says which equation is the books' own (each axle takes half
the roll moment).

Reference: R.S. Khurmi and J.K. Gupta, "Theory of Machines", ch. 14 (stability
of a four-wheel drive moving in a curved path); S.S. Rattan, ch. 14.
"""

from __future__ import annotations

import math

from ..core.body import vehicle_data, vehicle_params
from ..core.errors import InputError, refuse_overflow
from ..core.expr import Expr, Let, Sym, asin, cos, sin
from ..core.given import Given
from ..core.prose import names, plus, q, qvec, rel, total, tup
from ..core.spec import AnswerSpec, Kind, Param
from ..core.vehicle_words import ALONG_LEFT, COUPLE, reactive_couple, turn_of
from ..core.work import Work, qty
from ..physics import vehicles as V

#: the vehicle's axes and the symbols its prose names (values are in the steps' trees)
ax, ay, az = names("x y z")
H0, C0, wp0, Cg0, Cc0, m0, g0, R0 = names("H C omega_p C_g C_c m g R")
I_w0, I_E0, R_o0, R_i0, x0, v_lim0, I_eq0, r_w0, h0 = names("I_w I_E R_outer R_inner x v_lim I_eq "
                                                             "r_w h")
beta0, F_f0, F_r0, N0, a_f0, a_r0, Cp0 = names("beta F_front F_rear N a_f a_r C_p")
P_fo0, P_fi0, P_ro0, P_ri0 = names("P_front,outer P_front,inner P_rear,outer P_rear,inner")

# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's own time in gyro check.
_LEFT = plus(ay)
_AXES = ("vehicle axes: ", ax, " forward, ", ay, " to the left, ", az, " up. Going forward the "
         "wheels roll: their spin vector points to the left ", tup(_LEFT), "; each engine's "
         "points the same way (engine_sense: same) or the other way (opposite).")
_REACTIVE = (*reactive_couple("vehicle", "rotors"), ". Couples are about the fore-and-aft "
             "axis, positive overturning the vehicle outward (lifting the inner wheels). "
             "Reactions are the road's vertical forces on each wheel; the centre of mass is "
             "taken midway between the two axles and between the two rails, so each pair "
             "shares equally.")
_SUM_I_W, _SUM_I_E = total(I_w0), total(I_E0)
_REACTIONS, _WEIGHT = 2 * R_o0 + 2 * R_i0, m0 * g0  # the check's vertical balance
_MOMENT_OF_REACTIONS, _COUPLES = x0 * (R_o0 - R_i0), Cg0 + Cc0  # and its moment balance
_AT_THE_LIMIT = ("at the limiting speed ", v_lim0, ": ",
                 rel(m0 * g0 / 4, "=", (v_lim0 ** 2 / (2 * x0 * R0)) * (I_eq0 / r_w0 + m0 * h0)))


#: keys and answers that need the car as the books draw it (bank, wheelbase, engine along)
BOOK_KEYS = ("bank_angle", "cant", "wheelbase", "cg_to_front", "cg_to_rear", "engine_axis",
             "engine_rotation", "engine_speed")
BOOK_ANSWERS = frozenset({"wheel_loads", "axle_loads", "pitch_couple"})


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    given = vehicle_data(given, work, 'wheel', 'axle', 'engine')
    if any(k in given for k in BOOK_KEYS) or BOOK_ANSWERS & find:
        _book_car(given, find, work)
        return
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
    rotors = V.rotor_inertia(sum_w, Sym("G", G), sum_E, sense)
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
    turn, taken = turn_of(given)
    s = V.four_wheeler(m, g, h, x, rw, wheels, engines, G, sense, v, R)
    outer, inner = s.outer, s.inner  # each wheel's reaction: its three shares, added once
    refuse_overflow(outer, inner, s.gyroscopic_couple, s.centrifugal_couple, s.wheel_rate)
    v_, r_w, R_ = Sym("v", v, "m/s"), Sym("r_w", rw, "m"), Sym("R", R, "m")
    m_, x_ = Sym("m", m, "kg"), Sym("x", x, "m")
    work.section("Rates")
    omega_w = work.step("omega_w", V.rolling_rate(v_, r_w), unit="rad/s")
    work.step("omega_p", V.turn_rate(v_, R_), unit="rad/s")
    work.section("Vector rule")
    H = work.step("H", V.spin_momentum(equivalent.sym, Sym("omega_w", omega_w, "rad/s")),
                  unit="kg m^2/s",
                  note=ALONG_LEFT)
    wp, Hv = V.steering_precession(v, R, turn), V.scale(H, V.LEFT)
    work.text(f"turning {turn}{taken}: ", rel(wp0, "=", qvec((0, 0, wp[2]), "rad/s")), "; ",
              rel(COUPLE, "=", qvec((V.couple_on_rotor(wp, Hv)[0], 0, 0), "N m")),
              " on the rotors; the reactive couple on the vehicle, ",
              qvec((V.reactive_couple(wp, Hv)[0], 0, 0), "N m"), ", "
              + ("overturns it outward (lifts the inner wheels)" if H >= 0 else
                 "presses the inner wheels down (the engines' reversed momentum dominates)"))
    work.section("Couples and their shares on each wheel")
    C_g = work.step("C_g", V.overturning_couple(equivalent, v_, R_, r_w), unit="N*m",
                    ref="Eq. 11.29")
    C_c = work.step("C_c", V.centrifugal_couple(m_, v_, Sym("h", h, "m"), R_), unit="N*m")
    P_w = Sym("P_w", work.step("P_w", V.weight_share(m_, Sym("g", g, "m/s^2")), unit="N",
                               note="weight, every wheel"), "N")
    P_g = Sym("P_g", work.step("P_g", V.couple_share(Sym("C_g", C_g, "N m"), x_), unit="N",
                               note="gyroscopic: + outer, - inner"), "N")
    P_c = Sym("P_c", work.step("P_c", V.couple_share(Sym("C_c", C_c, "N m"), x_), unit="N",
                               note="centrifugal: + outer, - inner"), "N")
    work.step("R_outer", V.outer_reaction(P_w, P_g, P_c), unit="N", note="each outer wheel")
    work.step("R_inner", V.inner_reaction(P_w, P_g, P_c), unit="N", note="each inner wheel")
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
    if V.rotor_inertia(wheels, G, engines, sense) / rw + m * h <= 0:
        raise InputError(f"the inner wheels never leave the road: the engines' reversed "
                         f"gyroscopic couple, I_eq / r_w = {qty(I_eq / rw, 'kg m')}, outweighs "
                         f"the centrifugal m h = {qty(m * h, 'kg m')}", key="find.limiting_speed")
    m_ = Sym("m", m, "kg")
    v = work.step("v_lim", V.limiting_speed(m_, Sym("g", g, "m/s^2"), Sym("x", x, "m"),
                                            Sym("R", R, "m"), Sym("I_eq", I_eq, "kg m^2"),
                                            Sym("r_w", rw, "m"), Sym("h", h, "m")), unit="m/s")
    work.answer("limiting_speed", "v_lim", [v], "speed")



# ---- the car as the books draw it: bank, wheelbase, an engine along the car ---------

_BOOK_AXES = ("car axes: ", ax, " forward, ", ay, " to the left, in the track's plane (toward "
              "the centre of a left-hand curve), ", az, " up from the track, normal to it; the track is banked by "
              "the angle ", beta0, ", its outer side higher. Going forward the wheels' spin "
              "vector points to the left; an engine along the car spins forward or aft as its "
              "rotation is seen.")
_BOOK_BALANCE = ("Forces on the car in the frame turning with it: the weight, and the "
                 "centrifugal force outward through the centre of mass; the moments about it of "
                 "the track's forces equal the rate of change of the rotors' angular momentum "
                 "(Eq. 11.29).")
_HALVES = ("The roll moment is one equation for two axles: as the books do, each axle takes "
           "half of it.")
_SUM_LOADS = P_fo0 + P_fi0 + P_ro0 + P_ri0
_ROLL = x0 / 2 * (P_fo0 + P_ro0 - P_fi0 - P_ri0)
_PITCH = a_f0 * F_f0 - a_r0 * F_r0


def _book_car(given: Given, find: frozenset[str], work: Work) -> None:
    """Each wheel's load on a banked track, the centre of mass anywhere on the wheelbase,
    engines across or along the car (physics/vehicles.py, CarLoads)."""
    bank = _bank(given, work)
    L, a_f = _wheelbase(given)
    v = given["speed"] if "speed" in given else _no_speed(find)
    level_rest = v == 0 and not bank and "limiting_speed" not in find
    m, g = given["mass"], given["g"]
    h = (given.get("cg_height") or 0.0) if level_rest else given["cg_height"]
    x = (given.get("track") or 1.0) if level_rest else given["track"]
    along = given.word("engine_axis", "across") == "fore_and_aft"
    _engine_words(given, along)
    work.section("Conventions (Khurmi, Theory of Machines, ch. 14)")
    work.text(*_BOOK_AXES)
    if not level_rest:
        work.text(*_BOOK_BALANCE)
        work.text(*_HALVES)
    if v > 0 or "limiting_speed" in find:
        across_h, along_h, R = _rotors(given, work, along)
    else:
        across_h, along_h, R = (0.0, 0.0), (0.0, 0.0), 1.0
        work.text("at rest, ", rel(Sym("v", v, "m/s"), "=", 0), ": no rotor turns, so the "
                  "engines (", Sym("n_E", given["engines"]), " of ",
                  Sym("I_E", given["engine_inertia"], "kg m^2"), " geared ",
                  Sym("G", given["gear_ratio"]), ") and the wheels add no couple; the weight "
                  "alone")
    loads = V.car_loads(m, g, h, x, L, a_f, bank, v, R, across_h, along_h)
    if "speed" in given:
        _book_steps(given, work, loads, v, R, bank, L, a_f, across_h, along_h)
        _book_answers(find, work, loads)
    if "limiting_speed" in find:
        _book_limit(work, m, g, h, x, L, a_f, bank, R, across_h, along_h,
                    "given.cant" if "cant" in given else "given.bank_angle")


def _no_speed(find: frozenset[str]) -> float:
    if "limiting_speed" not in find:
        raise InputError("give the speed (or ask only for limiting_speed)", key="given.speed")
    return 0.0


def _bank(given: Given, work: Work) -> float:
    if "bank_angle" in given and "cant" in given:
        raise InputError("give bank_angle or cant, not both", key="given.cant")
    if "cant" not in given:
        return given.get("bank_angle", 0.0) or 0.0
    e, x = given["cant"], given["track"]
    if e >= x:
        raise InputError(f"a cant of {qty(e, 'm')} is not less than the track, {qty(x, 'm')}: "
                         "sin(beta) = cant / track must be below 1", key="given.cant")
    work.section("Bank from the cant")
    return work.step("beta", asin(Sym("e", e, "m") / Sym("x", x, "m")), unit="deg") * \
        math.pi / 180


def _wheelbase(given: Given) -> tuple[float, float]:
    """(L, a_f): the wheelbase and the centre of mass's distance behind the front axle."""
    ahead = [k for k in ("cg_to_front", "cg_to_rear") if k in given]
    if len(ahead) == 2:
        raise InputError("give cg_to_front or cg_to_rear, not both", key="given.cg_to_rear")
    if "wheelbase" not in given:
        if ahead:
            raise InputError(f"{ahead[0]} needs the wheelbase", key="given.wheelbase")
        return 2.0, 1.0  # no wheelbase: midway, and only ratios of it are used
    L = given["wheelbase"]
    if not ahead:
        return L, L / 2
    d = given[ahead[0]]
    if d > L:
        raise InputError(f"the centre of mass must lie between the axles: {ahead[0]} = "
                         f"{qty(d, 'm')} is more than the wheelbase {qty(L, 'm')}",
                         key=f"given.{ahead[0]}")
    return L, d if ahead[0] == "cg_to_front" else L - d


def _engine_words(given: Given, along: bool) -> None:
    """Refuse a key the engine's mounting makes meaningless, or a missing one it needs."""
    engine = given["engine_inertia"] * given["engines"] > 0
    if along:
        if "engine_sense" in given:
            raise InputError("engine_sense (same or opposite to the wheels) is for an engine "
                             "across the car; along the car give engine_rotation, as seen from "
                             "the front or the rear", key="given.engine_sense")
        if engine and "engine_rotation" not in given:
            raise InputError("an engine along the car needs engine_rotation: clockwise or "
                             "counterclockwise, seen from the front or the rear",
                             key="given.engine_rotation")
        if engine and "turn" not in given:
            raise InputError("an engine along the car loads the front or the rear wheels "
                             "according to the turn: give turn (left or right)",
                             key="given.turn")
        if engine and "wheelbase" not in given:
            raise InputError("an engine along the car moves load between the axles: give the "
                             "wheelbase", key="given.wheelbase")
    elif "engine_rotation" in given:
        raise InputError("engine_rotation is for an engine along the car (engine_axis: "
                         "fore_and_aft); across the car give engine_sense (same or opposite "
                         "to the wheels)", key="given.engine_rotation")
    if "engine_speed" in given and given.given_explicitly("gear_ratio"):
        raise InputError("give gear_ratio or engine_speed, not both", key="given.engine_speed")


def _rotors(given: Given, work: Work, along: bool) -> tuple[tuple[float, float],
                                                             tuple[float, float], float]:
    """The rotors' angular momentum, each group as (per m/s of speed, fixed), and R: the
    wheels and an engine across the car in the wheels' sense; an engine along the car as
    t s H (CarLoads). Writes the rotating parts and omega_w."""
    R, rw = given["turn_radius"], given["wheel_radius"]
    n, I_E, G = given["engines"], given["engine_inertia"], given["gear_ratio"]
    work.section("Rotating parts")
    wheels = work.step(_SUM_I_W, _wheels(given), unit="kg*m^2")
    engines = work.step(_SUM_I_E, Sym("n_E", n) * Sym("I_E", I_E, "kg m^2"), unit="kg*m^2")
    if "engine_speed" in given:
        work.text("the engine's own speed ", Sym("omega_E", given["engine_speed"], "rad/s"),
                  " is given, so the gear ratio ", Sym("G", G), " is not used")
        engine_h = (0.0, engines * given["engine_speed"])
    else:
        engine_h = (engines * G / rw, 0.0)
    if along:
        turn = 1.0 if given.word("turn") == "left" else -1.0
        spin = V.spin_direction(given.word("engine_rotation") or "clockwise_from_front") \
            if engines else 1.0
        if engines:
            work.text("the engine along the car spins ", "forward" if spin > 0 else "aft",
                      f" ({(given.word('engine_rotation') or '').replace('_', ' ')}), and "
                      f"the car turns {given.word('turn')}")
        return ((wheels / rw, 0.0), (turn * spin * engine_h[0], turn * spin * engine_h[1]), R)
    sign = 1.0 if given.word("engine_sense", "same") == "same" else -1.0
    return ((wheels / rw + sign * engine_h[0], sign * engine_h[1]), (0.0, 0.0), R)


def _momenta(given: Given, work: Work, v: float, along: bool) -> tuple[float, float]:
    """Steps for H across the car and H_L along it, at speed v (values as _rotors gave)."""
    rw = given["wheel_radius"]
    w_w = work.step("omega_w", V.rolling_rate(Sym("v", v, "m/s"), Sym("r_w", rw, "m")),
                    unit="rad/s")
    wheels, engines = _wheels(given).value, given["engines"] * given["engine_inertia"]
    S_w, S_E = Sym("sum I_w", wheels, "kg m^2"), Sym("sum I_E", engines, "kg m^2")
    omega_w = Sym("omega_w", w_w, "rad/s")
    if not engines and "engine_speed" not in given:  # the plain model's I_eq, G sum I_E = 0
        I_eq = S_w + Sym("G", given["gear_ratio"]) * S_E
        return work.step("H", I_eq * omega_w, unit="kg m^2/s", note=ALONG_LEFT), 0.0
    if "engine_speed" in given:
        w_E = Sym("omega_E", given["engine_speed"], "rad/s")
    else:
        w_E = Sym("omega_E", work.step("omega_E", V.geared_rate(Sym("G", given["gear_ratio"]),
                                                                omega_w), unit="rad/s"), "rad/s")
    if along:
        H = work.step("H", S_w * omega_w, unit="kg m^2/s", note=ALONG_LEFT)
        H_L = work.step("H_L", S_E * w_E, unit="kg m^2/s",
                        note=("the engine along the car",))
        return H, H_L
    same = given.word("engine_sense", "same") == "same"
    H = work.step("H", S_w * omega_w + S_E * w_E if same else S_w * omega_w - S_E * w_E,
                  unit="kg m^2/s", note=ALONG_LEFT)
    return H, 0.0


def _book_steps(given: Given, work: Work, loads: V.CarLoads, v: float, R: float, bank: float,
                L: float, a_f: float, across: tuple[float, float],
                along: tuple[float, float]) -> None:
    m, g = given["mass"], given["g"]
    h, x = given.get("cg_height", 0.0) or 0.0, given.get("track", 1.0) or 1.0
    m_, g_, h_, x_, v_ = (Sym("m", m, "kg"), Sym("g", g, "m/s^2"), Sym("h", h, "m"),
                          Sym("x", x, "m"), Sym("v", v, "m/s"))
    R_, b_ = Sym("R", R, "m"), Sym("beta", bank, "deg")
    work.section("Forces normal to the track, and the couples")
    N = work.step("N", m_ * (g_ * cos(b_) + v_ ** 2 / R_ * sin(b_)) if bank else m_ * g_,
                  unit="N", note=("the track's forces on all four wheels",))
    wp = work.step("omega_p", V.turn_rate(v_, R_), unit="rad/s") if v else 0.0
    is_along = given.word("engine_axis") == "fore_and_aft"
    H_L = 0.0
    if v:
        H_x, H_L = _momenta(given, work, v, is_along)
        C_g = Sym("H", H_x, "kg m^2/s") * Sym("omega_p", wp, "rad/s")
        work.step("C_g", C_g * cos(b_) if bank else C_g, unit="N*m", ref="Eq. 11.29",
                  note=("the rotors across the car: + overturns the car outward",))
    level_rest = not v and not bank
    if not level_rest:
        work.step("C_c", m_ * h_ * (v_ ** 2 / R_ * cos(b_) - g_ * sin(b_)) if bank else
                  V.centrifugal_couple(m_, v_, h_, R_), unit="N*m",
                  note=("the friction across the track, h below the centre of mass; + "
                        "outward",))
    if is_along and H_L:
        # C_p = -t s H_L omega_p cos(beta): t = +1 turning left, s = +1 spin vector forward
        C_p = Sym("H_L", H_L, "kg m^2/s") * Sym("omega_p", wp, "rad/s")
        C_p = C_p * cos(b_) if bank else C_p
        forward_left = along[0] * v + along[1] > 0
        C_p_value = work.step("C_p", -C_p if forward_left else C_p, unit="N*m",
                              note=("the engine along the car: + loads the front wheels",))
        work.text("the engine's couple " + ("loads the front wheels and unloads the rear"
                                            if C_p_value > 0 else "unloads the front wheels "
                                            "and loads the rear"))
    N_ = Sym("N", N, "N")
    if "wheelbase" in given:
        work.section("Axle loads (vertical balance and the pitch moment)")
        L_, a_f_ = Sym("L", L, "m"), Sym("a_f", a_f, "m")
        if "cg_to_front" not in given:
            a_f_ = Sym("a_f", work.step("a_f", L_ - Sym("a_r", L - a_f, "m"), unit="m")
                       if "cg_to_rear" in given else work.step("a_f", L_ / 2, unit="m",
                                                               note=("midway",)), "m")
        a_r_ = Sym("a_r", work.step("a_r", L_ - a_f_, unit="m"), "m") \
            if "cg_to_rear" not in given else Sym("a_r", L - a_f, "m")
        if is_along and H_L:
            C_p_ = Sym("C_p", loads.pitch_couple, "N m")
            F_f = work.step("F_front", N_ * a_r_ / L_ + C_p_ / L_, unit="N")
            F_r = work.step("F_rear", N_ * a_f_ / L_ - C_p_ / L_, unit="N")
        else:
            F_f = work.step("F_front", N_ * a_r_ / L_, unit="N")
            F_r = work.step("F_rear", N_ * a_f_ / L_, unit="N")
    else:
        work.section("Axle loads: the centre of mass midway between the axles")
        F_f = work.step("F_front", N_ / 2, unit="N")
        F_r = work.step("F_rear", N_ / 2, unit="N")
    work.section("Wheel loads")
    F_f_, F_r_ = Sym("F_front", F_f, "N"), Sym("F_rear", F_r, "N")
    if level_rest:
        work.text("at rest on a level track each axle's load is shared equally by its wheels")
        for name, tree in (("P_front,outer", F_f_ / 2), ("P_front,inner", F_f_ / 2),
                           ("P_rear,outer", F_r_ / 2), ("P_rear,inner", F_r_ / 2)):
            work.step(name, tree, unit="N")
        return
    C_sum = Sym("C_g", loads.gyroscopic_couple, "N m") + \
        Sym("C_c", loads.centrifugal_couple, "N m") if v else \
        Sym("C_c", loads.centrifugal_couple, "N m")
    P_s_ = Sym("P_s", work.step("P_s", C_sum / (2 * x_), unit="N",
                                note=("each wheel's share of the roll couple, half of it "
                                      "on each axle: + outer, - inner",)), "N")
    for name, tree in (("P_front,outer", F_f_ / 2 + P_s_), ("P_front,inner", F_f_ / 2 - P_s_),
                       ("P_rear,outer", F_r_ / 2 + P_s_), ("P_rear,inner", F_r_ / 2 - P_s_)):
        work.step(name, tree, unit="N")
    fo, fi, ro, ri = loads.wheels
    for value, where in ((fi, "front inner"), (ri, "rear inner"), (fo, "front outer"),
                         (ro, "rear outer")):
        if value < 0:
            work.warn(f"the {where} wheel's load is negative (", q(value, "N"), "): it leaves "
                      "the track at this speed unless held down")
    work.check(rel(_SUM_LOADS, "=", q(fo + fi + ro + ri, "N"), "=", N0, "=",
                   q(loads.normal, "N")), "; ",
               rel(_ROLL, "=", q(x / 2 * (fo + ro - fi - ri), "N m"), "=", Cg0 + Cc0, "=",
                   q(loads.gyroscopic_couple + loads.centrifugal_couple, "N m")))
    if "wheelbase" in given and is_along and H_L:
        work.check(rel(_PITCH, "=", q(a_f * (fo + fi) - (L - a_f) * (ro + ri), "N m"), "=",
                       Cp0, "=", q(loads.pitch_couple, "N m")))


def _book_answers(find: frozenset[str], work: Work, loads: V.CarLoads) -> None:
    fo, fi, ro, ri = loads.wheels
    work.answer("wheel_loads", "P", [fo, fi, ro, ri], "force",
                ["front outer", "front inner", "rear outer", "rear inner"])
    work.answer("axle_loads", "F", [loads.front_axle, loads.rear_axle], "force",
                ["front", "rear"])
    work.answer("gyroscopic_couple", "C_g", [loads.gyroscopic_couple], "moment")
    work.answer("centrifugal_couple", "C_c", [loads.centrifugal_couple], "moment")
    work.answer("pitch_couple", "C_p", [loads.pitch_couple], "moment")
    if abs(fo - ro) <= 1e-9 * max(abs(fo), abs(ro), 1.0) and \
            abs(fi - ri) <= 1e-9 * max(abs(fi), abs(ri), 1.0):
        work.answer("wheel_reactions", "R", [fo, fi], "force", ["outer", "inner"])
    elif "wheel_reactions" in find:
        raise InputError("the front and rear wheels carry different loads here (the centre of "
                         "mass off the middle of the wheelbase, or an engine along the car): "
                         "wheel_reactions [outer, inner] cannot say them; ask for wheel_loads "
                         "[front outer, front inner, rear outer, rear inner]",
                         key="find.wheel_reactions")


def _book_limit(work: Work, m: float, g: float, h: float, x: float, L: float, a_f: float,
                bank: float, R: float, across: tuple[float, float],
                along: tuple[float, float], bank_key: str) -> None:
    work.section("Limiting speed: the first wheel's load falls to zero")
    work.text("each wheel's load is a quadratic in the speed (the couples grow with its "
              "square, or with it for an engine at a set speed): its root, found exactly")
    at_rest = V.car_loads(m, g, h, x, L, a_f, bank, 0.0, R, across, along).wheels
    if min(at_rest) < 0:
        raise InputError("a wheel carries no load even at rest: the bank tips the car inward "
                         "(its centre of mass lies outside the wheels)",
                         key=bank_key)
    v = V.first_lift_speed(lambda s: V.car_loads(m, g, h, x, L, a_f, bank, s, R, across,
                                                 along).wheels)
    if v is None:
        raise InputError("no wheel leaves the track at any speed with these data",
                         key="find.limiting_speed")
    work.step("v_lim", value=v, unit="m/s", note=("the least speed at which a wheel's load "
                                                   "reaches zero",))
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
        Param("turn", "word", "turn", "left (default) or right: with the engine across, only "
              "the vectors shown change; with it along the car it is needed",
              choices=("left", "right")),
        Param("bank_angle", "angle", "beta", "the track's bank (cant) angle, its outer side "
              "higher", range=(0.0, math.pi / 2), bounds="[)"),
        Param("cant", "length", "e", "instead of bank_angle: how much higher the outer rail "
              "or wheel track is; sin(beta) = cant / track", nonnegative=True),
        Param("wheelbase", "length", "L", "distance between the front and rear axles",
              positive=True),
        Param("cg_to_front", "length", "a_f", "the centre of mass behind the front axle (with "
              "wheelbase; midway if absent)", nonnegative=True),
        Param("cg_to_rear", "length", "a_r", "instead of cg_to_front: the centre of mass ahead "
              "of the rear axle", nonnegative=True),
        Param("engine_axis", "word", "engine_axis", "across (default, parallel to the axles) "
              "or fore_and_aft (along the car)", choices=("across", "fore_and_aft"),
              words=(("transverse", "across"), ("parallel_to_the_axles", "across"),
                     ("longitudinal", "fore_and_aft"), ("along_the_car", "fore_and_aft"),
                     ("fore_aft", "fore_and_aft"), ("along", "fore_and_aft"))),
        Param("engine_rotation", "word", "engine_rotation", "for an engine along the car: "
              "its sense seen from the front or the rear", choices=V.AEROPLANE_SENSES),
        Param("engine_speed", "rate", "omega_E", "instead of gear_ratio: the engine's own "
              "speed", nonnegative=True),
    ) + vehicle_params('wheel', 'axle', 'engine'),
    answers=(
        AnswerSpec("wheel_reactions", "force", "R", "[outer, inner]: vertical reaction on each "
                   "outer and each inner wheel", sides=("outer", "inner")),
        AnswerSpec("gyroscopic_couple", "moment", "C_g", "(sum I_w +- G sum I_E) v^2 / (R r_w), "
                   "positive overturning outward"),
        AnswerSpec("centrifugal_couple", "moment", "C_c", "m v^2 h / R"),
        AnswerSpec("limiting_speed", "speed", "v_lim", "speed at which the inner wheels leave "
                   "the road"),
        AnswerSpec("wheel_loads", "force", "P", "[front outer, front inner, rear outer, rear "
                   "inner]: the track's force on each wheel, normal to the track",
                   sides=("front outer", "front inner", "rear outer", "rear inner")),
        AnswerSpec("axle_loads", "force", "F", "[front, rear]: the load on each axle",
                   sides=("front", "rear")),
        AnswerSpec("pitch_couple", "moment", "C_p", "the engine along the car: its couple "
                   "about the axis across, positive loading the front wheels"),
    ),
    solve=solve,
    example={
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
        "vary": {"speed": "[0.8, 1.2]"}},
)
