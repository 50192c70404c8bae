"""The gyroscope as a detector of motion (Eq. 11.29): single-gimbal rate gyros.

A rotor of angular momentum H = J spin turns in a gimbal; the case turns at
Omega about the input axis, perpendicular to the spin axis and to the gimbal's
(output) axis. Eq. 11.29: to keep the spin axis from turning, a moment
Q_theta = J psidot phidot = H Omega about the output axis is needed. A
torsion spring k and a damper c on the output axis supply it as the gimbal
deflects; with the gimbal's inertia I_g about its axis, for small angles

    I_g thetaddot + c thetadot + k theta = H Omega.

Spring-restrained (rate gyro): theta = H Omega / k; damper only
(rate-integrating gyro): thetadot = H Omega / c; neither: the bearings'
moment H Omega. The derivation is in gyro_cli/physics/rate_gyro.py.
"""

from __future__ import annotations

import math

from ..core.body import spin_angular_momentum
from ..core.errors import InputError
from ..core.expr import PI, Let, Sym, cos
from ..core.given import Given
from ..core.prose import names, q, rel
from ..core.spec import AnswerSpec, Kind, OneOf, Param
from ..core.work import Work, num
from ..physics.rate_gyro import (
    damping_ratio,
    gimbal_rate,
    large_angle_deflection,
    natural_frequency,
    rate_from_moment,
    steady_deflection,
)

SMALL_ANGLE = math.radians(5)
DEG = math.pi / 180

#: the symbols of the kind's steps, beside its Params: name -> the unit each is shown in
UNITS = {"H": "kg m^2/s", "Omega": "rad/s", "M": "N*m", "k": "N m/rad", "c": "N m s/rad",
         "I_g": "kg*m^2", "theta": "rad", "thetadot": "rad/s", "phi": "rad",
         "omega_n": "rad/s", "H/c": ""}


def _sym(name: str, value: float) -> Sym:
    """The kind's symbol ``name`` holding ``value`` (SI)."""
    return Sym(name, value, UNITS[name])


#: the symbols the sentences name (values are in the steps' trees)
th, thd, thdd, Om, H0, I0, k0, c0, M0, phi0, zeta0, Q0 = \
    names("theta thetadot thetaddot Omega H I_g k c M phi zeta Q_theta")

# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's own time in gyro check.
_AXES = ("Spin axis, output (gimbal) axis and input axis mutually perpendicular at ",
         rel(th, "=", 0), "; positive senses chosen so that a positive input rate deflects the "
         "gimbal positively. All results are for small gimbal angles.")
_GYROSCOPIC_MOMENT = H0 * Om  # Eq. 11.29 about the output axis
_TILTED = H0 * Om * cos(th)  # its exact value with the spin axis tilted by theta
_EQUATION_TITLE = ("Gimbal equation (Eq. 11.29: ", rel(Q0, "=", _GYROSCOPIC_MOMENT),
                   " about the output axis)")
_SYMBOLS = (Om, ": the input rate, about the input axis; ", th, ": the gimbal's deflection "
            "about the output axis; ", I0, ": the gimbal's moment of inertia about that axis; ",
            k0, ": the spring's stiffness; ", c0, ": the damping coefficient")
_EQUATION = (rel(I0 * thdd + c0 * thd + k0 * th, "=", _GYROSCOPIC_MOMENT), "   (small ", th,
             "; exactly ", _TILTED, " on the right)")
#: the steady state of each restraint
_STEADY = {"spring": ("spring-restrained rate gyro: steady ", rel(th, "=", H0 * Om / k0)),
           "integrating": ("rate-integrating gyro (damper, no spring): steady ",
                           rel(thd, "=", H0 * Om / c0), ", ", rel(th, "=", H0 / c0 * phi0),
                           ", where ", phi0, " is the angle the case turned"),
           "rigid": ("rigidly restrained rotor: the bearings supply ",
                     rel(M0, "=", _GYROSCOPIC_MOMENT), " (Eq. 11.29)")}
_SPRING_MOMENT = k0 * th
_TILTED_BALANCE = rel(_SPRING_MOMENT, "=", _TILTED)  # k theta = H Omega cos(theta)
_GAIN = H0 / c0  # a rate-integrating gyro's gimbal angle per unit angle turned
_DAMPER_MOMENT, _RATE_FROM_MOMENT = c0 * thd, M0 / H0
_SETTLES_FASTEST = (zeta0, " near ", q(0.7, exact=True), " lets the reading settle fastest "
                    "without much overshoot")
_RINGS = (rel(zeta0, "<", q(0.5, exact=True)), ": the reading rings before it settles")
_OVERDAMPED = (rel(zeta0, ">", 1), ": overdamped, the reading creeps up to its value")
_NO_INERTIA = ("damping given without gimbal_inertia: the damping ratio needs ", I0)


def _angular_momentum(given: Given, work: Work) -> float:
    H = spin_angular_momentum(given, work)
    return H


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    H = _angular_momentum(given, work)
    k = given.get("stiffness")
    c = given.get("damping")
    I_g = given.get("gimbal_inertia")
    mode = "spring" if k is not None else "integrating" if c is not None else "rigid"
    given_key = next(key for key in _INPUTS.keys if key in given)  # the kind's one_of
    if given_key == "deflection" and mode == "rigid":
        raise InputError("a deflection needs a restraining spring (stiffness) or a damper "
                         "(damping, with input_angle)", key="given.stiffness")
    if given_key == "deflection" and mode == "integrating":
        raise InputError("a rate-integrating gyro's deflection measures the angle turned, not "
                         "the rate: give input_angle, or its gimbal_rate", key="given.deflection")
    if given_key == "gimbal_rate" and mode != "integrating":
        raise InputError("a steady gimbal_rate belongs to a rate-integrating gyro (a damper, "
                         "no spring): give damping and leave out stiffness",
                         key="given.gimbal_rate")
    if given_key == "input_angle" and mode != "integrating":
        raise InputError("input_angle goes with a rate-integrating gyro (damping, no "
                         "stiffness)", key="given.input_angle")

    work.section("Conventions")
    work.text(*_AXES)
    work.section(*_EQUATION_TITLE)
    work.text(*_SYMBOLS)
    work.text(*_EQUATION)
    work.text(*_STEADY[mode])

    work.answer("angular_momentum", "H", [H], "angular_momentum")
    if given_key == "input_angle":
        assert c is not None  # refused above unless rate-integrating
        _integrated_angle(given, H, c, I_g, work)
        _refuse_missing(find, work)
        return
    rate = _input_rate(given, given_key, H, k, c, work)
    work.answer("rate", "Omega", [rate], "rate")
    H_, Omega = _sym("H", H), _sym("Omega", rate)
    M = work.step("M", H_ * Omega, unit="N*m", ref="Eq. 11.29",
                  note="moment about the output axis")
    work.answer("moment", "M", [M], "moment")

    if mode == "spring":
        assert k is not None
        work.section("Spring-restrained: deflection and sensitivity")
        linear = steady_deflection(H, rate, k)
        if abs(linear) >= math.pi / 2:
            exact = large_angle_deflection(H, rate, k)
            raise InputError(f"H Omega / k = {num(linear / DEG)} deg: the small-angle rate gyro "
                             "is far outside its range (the gimbal would pass 90 deg); the exact "
                             f"steady state, k theta = H Omega cos(theta), is {num(exact / DEG)} "
                             "deg: use a stiffer spring", key="given.rate")
        k_ = _sym("k", k)
        theta = work.step("theta", steady_deflection(H_, Omega, k_), unit="rad")
        work.step("theta", value=theta / DEG, unit="deg")
        S = work.step("S", H_ / k_, unit="s", note="deflection per unit rate (rad per rad/s)")
        work.answer("deflection", "theta", [theta], "angle")
        work.answer("sensitivity", "S", [S], "time")
        if abs(theta) > SMALL_ANGLE and given_key != "deflection":
            exact = large_angle_deflection(H, rate, k)
            work.warn("the deflection ", q(theta, "deg"), " is not small: with the spin axis "
                      "tilted, ", _TILTED_BALANCE, " gives ", q(exact, "deg"))
        work.check(rel(_SPRING_MOMENT, "=", q(k * theta, "N m"), "=", _GYROSCOPIC_MOMENT, "=",
                       q(M, "N m")))
        if I_g is not None:
            work.section("Dynamics of the gimbal")
            I_g_ = _sym("I_g", I_g)
            wn = work.step("omega_n", natural_frequency(k_, I_g_), unit="rad/s")
            # f_n in Hz from the angular frequency omega_n in rad/s
            work.step("f_n", _sym("omega_n", wn) / (2 * PI), unit="Hz", substitute=False)
            work.answer("natural_frequency", "omega_n", [wn], "rate")
            if c is not None:
                zeta = work.step("zeta", damping_ratio(_sym("c", c), k_, I_g_), unit="")
                work.answer("damping_ratio", "zeta", [zeta], "dimensionless")
                if 0.5 <= zeta <= 1:
                    work.text(*_SETTLES_FASTEST)
                elif zeta < 0.5:
                    work.text(*_RINGS)
                else:
                    work.text(*_OVERDAMPED)
        elif c is not None:
            work.text(*_NO_INERTIA)
    elif mode == "integrating":
        assert c is not None
        work.section("Rate-integrating: gimbal rate and gain")
        c_ = _sym("c", c)
        td = work.step("thetadot", gimbal_rate(H_, Omega, c_), unit="rad/s")
        gain = work.step(_GAIN, H_ / c_, unit="", state=False,
                         note="gimbal angle per unit angle turned by the case")
        work.answer("gimbal_rate", "thetadot", [td], "rate")
        work.answer("gain", _GAIN, [gain], "dimensionless")
        _time_constant(c, I_g, work)
        work.check(rel(_DAMPER_MOMENT, "=", q(c * td, "N m"), "=", _GYROSCOPIC_MOMENT, "=",
                       q(M, "N m")))
    else:
        work.check(rel(_RATE_FROM_MOMENT, "=", q(M / H, "rad/s"), "=", Om))
    if "gimbal_inertia" in given and mode == "rigid":
        work.text("gimbal_inertia is not used: a rigid restraint does not move")
    _refuse_missing(find, work)


def _time_constant(c: float, I_g: float | None, work: Work) -> None:
    if I_g is not None:
        tau = work.step("tau", _sym("I_g", I_g) / _sym("c", c), unit="s",
                        note="the time constant: in this time the gimbal rate reaches about two "
                        "thirds of its value, nearly all of "
                        "it in three times as long")
        work.answer("time_constant", "tau", [tau], "time")


_DAMPER_IMPULSE, _ANGULAR_IMPULSE = c0 * th, H0 * phi0  # c theta = H phi
_INTEGRATING = ("integrating ", rel(_DAMPER_MOMENT, "=", _GYROSCOPIC_MOMENT), " over time: ",
                rel(_DAMPER_IMPULSE, "=", _ANGULAR_IMPULSE), ", where ", phi0, ", the integral "
                "of ", Om, " over time, is the angle the case turned (once the transient, time "
                "constant ", I0 / c0, ", has passed)")
_ANGLE_TURNED = (phi0, ": the angle the case turned")


def _integrated_angle(given: Given, H: float, c: float, I_g: float | None, work: Work) -> None:
    """Rate-integrating gyro: the gimbal angle for the angle the case turned."""
    work.section("Rate-integrating: gimbal angle for the angle turned")
    work.text(*_INTEGRATING)
    H_c = _sym("H", H) / _sym("c", c)
    gain = work.step(_GAIN, H_c, unit="", state=False)
    phi = given["input_angle"]
    theta = work.step("theta", Let(_sym("H/c", gain), H_c) * _sym("phi", phi), unit="rad",
                      note=_ANGLE_TURNED)
    work.step("theta", value=theta / DEG, unit="deg")
    work.answer("deflection", "theta", [theta], "angle")
    work.answer("gain", _GAIN, [gain], "dimensionless")
    _time_constant(c, I_g, work)
    if abs(theta) > SMALL_ANGLE:
        work.warn("the gimbal angle ", q(theta, "deg"), " is not small: the linear relation "
                  "holds only for small angles")
    work.check(rel(_DAMPER_IMPULSE, "=", q(c * theta, "N m s"), "=", _ANGULAR_IMPULSE, "=",
                   q(H * phi, "N m s")))


def _refuse_missing(find: frozenset[str], work: Work) -> None:
    """Name what an asked-for answer needs when the data did not give it."""
    missing = {"natural_frequency": "stiffness and gimbal_inertia",
               "damping_ratio": "stiffness, damping and gimbal_inertia",
               "time_constant": "damping (no stiffness) and gimbal_inertia",
               "sensitivity": "stiffness", "gain": "damping (no stiffness)",
               "gimbal_rate": "damping (no stiffness)",
               "deflection": "stiffness (or damping with input_angle)",
               "rate": "an input (rate, deflection, moment or gimbal_rate)",
               "moment": "the input rate"}
    for name in sorted(find):
        if name in missing and name not in work.answers:
            raise InputError(f"{name} needs {missing[name]}", key=f"find.{name}")


def _input_rate(given: Given, key: str, H: float, k: float | None, c: float | None,
                work: Work) -> float:
    if key == "rate":
        return given["rate"]
    work.section("Input rate from the measurement")
    if key == "deflection":
        assert k is not None  # a deflection without a spring is refused in solve
        theta = given["deflection"]
        if abs(theta) > SMALL_ANGLE:
            work.warn("the deflection ", q(theta, "deg"), " is not small: with the spin axis "
                      "tilted, ", _TILTED_BALANCE, " gives ",
                      rel(Om, "=", q(k * theta / (H * math.cos(theta)), "rad/s")))
        return work.step("Omega", _sym("k", k) * _sym("theta", theta) / _sym("H", H),
                         unit="rad/s")
    if key == "moment":
        M = given["moment"]
        return work.step("Omega", rate_from_moment(_sym("H", H), _sym("M", M)), unit="rad/s",
                         ref="Eq. 11.29")
    assert c is not None  # a gimbal rate without a damper is refused in solve
    td = given["gimbal_rate"]
    return work.step("Omega", _sym("c", c) * _sym("thetadot", td) / _sym("H", H),
                     unit="rad/s")


# why a key's limit is what it is (the loader adds it to the refusal)
_SENSES = "the rotor's angular momentum must be positive (spin > 0): a rotor that does not spin " \
    "senses nothing"
_NONE = "leave it out if there is none"

_ONE_INPUT = ("give one input: the case's rate, or a measured deflection, gimbal_rate or moment "
              "(or input_angle for a rate-integrating gyro)")
_INPUTS = OneOf(("rate", "deflection", "moment", "gimbal_rate", "input_angle"), _ONE_INPUT,
                _ONE_INPUT + "; got {present}")

KIND = Kind(
    name="rate_gyro",
    summary="the gyroscope as a detector of motion: single-gimbal rate gyro with a spring, "
            "rate-integrating gyro with a damper, or the bearing moment (Eq. 11.29)",
    chapter="Eqs. 11.27-11.29, the gyroscope as a detector of motion",
    params=(
        Param("spin", "rate", "psidot", "spin of the rotor (with J, k_axial or a shape)",
              positive=True, reason=_SENSES),
        Param("angular_momentum", "angular_momentum", "H", "the rotor's angular momentum J spin "
              "(instead of spin and J)", positive=True, reason=_SENSES),
        Param("stiffness", "stiffness", "k", "torsion spring on the gimbal (output) axis",
              positive=True, reason=_NONE),
        Param("damping", "damping", "c", "viscous damper on the gimbal axis (alone: a "
              "rate-integrating gyro)", positive=True, reason=_NONE),
        Param("gimbal_inertia", "inertia", "I_g", "moment of inertia of gimbal and rotor about "
              "the gimbal axis", positive=True, reason=_NONE),
        Param("rate", "rate", "Omega", "input: the case's angular rate about the input axis"),
        Param("deflection", "angle", "theta", "measured steady gimbal deflection (spring) -> "
              "the input rate", range=(-math.pi / 2, math.pi / 2), bounds="()",
              reason="at 90 deg the spin axis lies along the input axis and no input rate gives "
              "a moment about the gimbal axis"),
        Param("moment", "moment", "M", "measured moment about the output axis -> the input "
              "rate"),
        Param("gimbal_rate", "rate", "thetadot", "measured steady gimbal rate (rate-integrating)"
              " -> the input rate"),
        Param("input_angle", "angle", "phi", "angle the case turned (rate-integrating) -> the "
              "gimbal angle"),
    ),
    answers=(
        AnswerSpec("rate", "rate", "Omega", "the input rate (given, or from the measurement)"),
        AnswerSpec("deflection", "angle", "theta", "steady gimbal angle (small angles)"),
        AnswerSpec("gimbal_rate", "rate", "thetadot", "steady gimbal rate of a rate-integrating "
                   "gyro"),
        AnswerSpec("moment", "moment", "M", "moment about the output axis, H Omega"),
        AnswerSpec("sensitivity", "time", "S", "deflection per unit input rate, H / k (e.g. "
                   "write s: deg per deg/s)"),
        AnswerSpec("gain", "dimensionless", "H/c", "rate-integrating: gimbal angle per angle "
                   "turned (and gimbal rate per input rate)"),
        AnswerSpec("natural_frequency", "rate", "omega_n", "sqrt(k / I_g) of the gimbal"),
        AnswerSpec("damping_ratio", "dimensionless", "zeta", "c / (2 sqrt(k I_g))"),
        AnswerSpec("time_constant", "time", "tau", "rate-integrating: I_g / c"),
        AnswerSpec("angular_momentum", "angular_momentum", "H", "the rotor's J spin"),
    ),
    solve=solve,
    one_of=(_INPUTS,),
    gravity=False, body_keys=("mass", "weight", "J", "k_axial", "shape", "radius", "diameter", "inner_radius", "width", "length"), example={
        "statement": ("The rotor of a rate gyro has a moment of inertia of {J} and spins at "
                      "{spin}. Its gimbal, with a moment of inertia of {gimbal_inertia} about the "
                      "gimbal axis, is held by a torsion spring of stiffness {stiffness} and a "
                      "damper of {damping}. The case turns at {rate} about the input axis. Find "
                      "the steady gimbal angle, the sensitivity, the natural frequency and the "
                      "damping ratio."),
        "given": {"J": "2e-4 kg m^2", "spin": "24000 rpm", "stiffness": "0.8 N m/rad",
                  "damping": "0.015 N m s/rad", "gimbal_inertia": "1e-4 kg m^2",
                  "rate": "5 deg/s"},
        "find": {"deflection": "deg", "sensitivity": "s", "natural_frequency": "Hz",
                 "damping_ratio": None},
        "vary": {"rate": "[0.5, 2]"}},
)
