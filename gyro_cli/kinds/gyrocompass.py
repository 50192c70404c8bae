"""The gyrocompass (section 11.3): a horizontal rotor free to turn about the local vertical.

On the rotating Earth a rotor whose spin axis is held horizontal, but left
free to turn about the vertical, feels about the vertical the moment
H Omega_E cos(lambda) sin(alpha) (alpha the deviation of the spin vector from
north), which turns it back to north: the chapter's "bearing torques act in
such a way that the gyroscope axis always lines up with ... the northerly
direction". Small swings about north are those of a pendulum,

    I_v alphaddot + H Omega_E cos(lambda) alpha = 0,   T = 2 pi sqrt(I_v / (H Omega_E cos(lambda))),

and with any damping about the vertical the axis settles on the meridian. The
derivation is in gyro_cli/physics/gyrocompass.py and docs/applications.md.
"""

from __future__ import annotations

import math

from ..core.body import spin_angular_momentum
from ..core.errors import InputError
from ..core.expr import PI, Let, Sym, cos, ellipk, sin
from ..core.given import Given
from ..core.prose import cross, dot, fn, names, q, rel
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work, num, qty
from ..physics.algebra import cos_theta
from ..physics.gyrocompass import directive_stiffness, north_seeking_moment, period

POLAR_WARNING_LATITUDE = math.radians(70)

#: the symbols the sentences name (values are in the steps' trees)
E, N, U, a0, W0, OmE0, lam0 = names("E N U alpha Omega Omega_E lambda")
M_U0, I_v0, adot0, addot0, H0, T0, K0, m0, alpha_eq0, I_G0 = \
    names("M_U I_v alphadot alphaddot H T K m alpha_eq I_G")

# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's own time in gyro check.
_AXES = (E, ", ", N, ", ", U, ": east, north, up at the site. The rotor's spin vector "
         "(right-hand rule) points along the horizontal axis at azimuth ", a0, ", east of north "
         "positive; moments about the vertical are positive counter-clockwise seen from above.")
_EARTH_RATE = ("Earth rate: ", rel(OmE0, "=", W0 * (cos(lam0) * N + sin(lam0) * U)), ", where ",
               W0, " is the Earth's rotation rate; only the horizontal part ",
               W0 * cos(lam0) * N, " can turn a horizontal spin vector.")
_MOMENT_TITLE = ("Moment about the vertical (angular momentum about ", U, " on the rotating "
                 "Earth)")
_MOMENT_SYMBOLS = (M_U0, ": the moment about the vertical on the rotor and its gimbal; ", I_v0,
                   ": their moment of inertia about the vertical; ", adot0, ": the rate of the "
                   "azimuth ", a0)
_ANGULAR_MOMENTUM = (rel(fn("d/dt", dot(H0, U)), "=", M_U0 + dot(H0, cross(OmE0, U))), ",  ",
                     rel(cross(OmE0, U), "=", W0 * cos(lam0) * E), ",  ",
                     rel(dot(H0, U), "=", I_v0 * (W0 * sin(lam0) - adot0)))
_PENDULUM = ("so  ", rel(I_v0 * addot0, "=", -H0 * W0 * cos(lam0) * sin(a0)),
             "  (terms of order ", I_v0 * W0**2, " dropped): a pendulum about north")
_SOUTH = q(math.pi, "deg", exact=True)  # the deviation of the unstable equilibrium
_SETTLES = (rel(alpha_eq0, "=", 0), " (spin vector north) is the stable equilibrium (",
            rel(a0, "=", _SOUTH), " is unstable): the axis swings about north and, with any "
            "damping about the vertical, settles there.")
_POINTS_SOUTH = (rel(a0, "=", _SOUTH), ": the spin vector points south, the unstable "
                 "equilibrium; released there at rest the axis stays (in theory) and never "
                 "swings")
_RELEASED = ("released at rest at ", a0, " (the pendulum's exact period; ", K0, " is the "
             "complete elliptic integral of the first kind, of parameter ",
             rel(m0, "=", sin(a0 / 2) ** 2), ")")
_SWING_STIFFNESS = I_v0 * (2 * PI / T0)**2  # the check: I_v (2 pi / T)^2 = H Omega_E cos(lambda)
_DIRECTIVE = H0 * OmE0 * cos(lam0)
_ROTOR_ALONE = ("no I_vertical: the rotor alone turns about the vertical (massless gimbal), ",
                rel(I_v0, "=", I_G0), ", its transverse moment about a diameter")


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    lat = given["latitude"]
    Omega = given["earth_rate"]
    if cos_theta(lat) == 0:
        raise InputError(f"at latitude {num(math.degrees(lat))} deg (a pole) a gyrocompass cannot "
                         "settle: the Earth's rate has no horizontal component (Omega_E "
                         "cos(lambda) = 0), so there is no north-seeking moment and no north to "
                         "seek; the period 2 pi sqrt(I_v / (H Omega_E cos(lambda))) grows without "
                         "bound toward the pole", key="given.latitude")
    H = spin_angular_momentum(given, work)
    if H == 0:
        raise InputError("the rotor must spin: with no angular momentum there is no "
                         "north-seeking moment", key="given.spin")
    H_abs = abs(H)
    alpha = given["deviation"]

    work.section("Conventions")
    work.text(*_AXES)
    work.text(*_EARTH_RATE)
    if H < 0:
        work.text("spin < 0: the spin vector points along the other end of the axis; that end "
                  "seeks north")
    work.section(*_MOMENT_TITLE)
    work.text(*_MOMENT_SYMBOLS)
    work.text(*_ANGULAR_MOMENTUM)
    work.text(*_PENDULUM)
    H_, Omega_E = Sym("H", H_abs, "kg m^2/s"), Sym("Omega_E", Omega, "rad/s")
    lam, alpha_ = Sym("lambda", lat, "deg"), Sym("alpha", alpha, "deg")
    stiffness = directive_stiffness(H_, Omega_E, lam)
    D = work.step("D", stiffness, unit="N m/rad",
                  note="north-seeking moment per radian of deviation")
    D_ = Sym("D", D, "N m/rad")
    M = work.step("M", north_seeking_moment(Let(D_, stiffness), alpha_), unit="N*m")
    if alpha:
        work.text(f"the moment turns the axis {'west' if alpha > 0 else 'east'}, back toward "
                  "north")
    work.answer("moment", "M", [M], "moment")
    work.answer("settles", "alpha_eq", ["north"], None)
    work.answer("directive_moment", "D", [D], "stiffness")
    work.text(*_SETTLES)

    I_v = _vertical_inertia(given, work)
    if I_v is not None:
        work.section("Swing about north")
        I_v_ = Sym("I_v", I_v, "kg m^2")
        T = work.step("T", period(I_v_, Let(D_, stiffness)), unit="s",
                      note="small swings")
        work.step("T", value=T / 60, unit="min")
        work.answer("period", "T", [T], "time")
        if abs(alpha) > math.pi * (1 - 1e-9):
            work.text(*_POINTS_SOUTH)
            if "swing_period" in find:
                raise InputError("at a deviation of 180 deg the axis balances in unstable "
                                 "equilibrium (spin vector south): a swing released there at rest "
                                 "never returns, its period is unbounded", key="given.deviation")
        elif alpha:
            Ts = work.step("T(alpha)", Sym("T", T, "s") * (2 / PI) * ellipk(
                sin(alpha_ / 2) ** 2), unit="s", substitute=False, note=_RELEASED)
            work.answer("swing_period", "T(alpha)", [Ts], "time")
        work.check(rel(_SWING_STIFFNESS, "=", q(I_v * (2 * math.pi / T) ** 2, "N m/rad"), "=",
                       _DIRECTIVE, "=", q(D, "N m/rad")))
    elif {"period", "swing_period"} & find:
        raise InputError("the period needs I_vertical (or the rotor's I_cg, k_cg or shape)",
                         key="given.I_vertical")
    if abs(lat) > POLAR_WARNING_LATITUDE:
        work.warn(f"at latitude {num(math.degrees(lat))} deg the north-seeking moment is only "
                  f"cos(lambda) = {num(math.cos(lat))} of its value at the equator: the compass is "
                  "sluggish and a gyrocompass fails toward the poles")


def _vertical_inertia(given: Given, work: Work) -> float | None:
    body = given.solid_body
    if "I_vertical" in given:
        I_v = given["I_vertical"]
        if body.I_cg is not None and I_v < body.I_cg * (1 - 0.01):
            raise InputError(f"I_vertical = {qty(I_v, 'kg*m^2')} is less than the rotor's own "
                             f"moment about a diameter, I_G = {qty(body.I_cg, 'kg*m^2')}: the "
                             "sensitive element includes the rotor", key="given.I_vertical")
        return I_v
    if body.I_cg is not None:
        work.text(*_ROTOR_ALONE)
        return body.I_cg
    return None


KIND = Kind(
    name="gyrocompass",
    summary="gyrocompass: a horizontal rotor free about the vertical on the rotating Earth "
            "(north-seeking moment, period of the swing about north)",
    chapter="section 11.3, the gyrocompass; dH/dt on the rotating Earth",
    params=(
        Param("latitude", "angle", "lambda", "latitude of the site (north or south: '50 N', "
              "'35 S')", range=(-math.pi / 2, math.pi / 2), hemisphere="NS", required=True),
        Param("spin", "rate", "psidot", "spin of the rotor about its axis (with J, k_axial or a "
              "shape)"),
        Param("angular_momentum", "angular_momentum", "H", "the rotor's angular momentum J spin "
              "(instead of spin)"),
        Param("I_vertical", "inertia", "I_v", "moment of inertia of the sensitive element "
              "(rotor and its gimbal) about the vertical; default the rotor's I_cg",
              positive=True),
        Param("deviation", "angle", "alpha", "angle of the spin vector from north, east "
              "positive", default="0 deg", range=(-math.pi, math.pi),
              reason="east of north positive"),
        Param("earth_rate", "rate", "Omega_E", "the Earth's rate of rotation (sidereal)",
              default="7.292115e-5 rad/s", positive=True,
              reason="the Earth's sidereal rate is 7.292e-5 rad/s"),
    ),
    answers=(
        AnswerSpec("period", "time", "T", "period of small swings about north"),
        AnswerSpec("swing_period", "time", "T(alpha)", "period of the swing released at rest "
                   "at the deviation (exact, any amplitude)"),
        AnswerSpec("moment", "moment", "M", "north-seeking moment about the vertical at the "
                   "deviation, H Omega_E cos(lambda) sin(alpha)"),
        AnswerSpec("directive_moment", "stiffness", "D", "north-seeking moment per radian of "
                   "deviation, H Omega_E cos(lambda)"),
        AnswerSpec("settles", None, "alpha_eq", "where the axis settles: north (the spin "
                   "vector's end); a pole is refused with the reason"),
    ),
    solve=solve,
    gravity=False, body_keys=("mass", "weight", "J", "k_axial", "I_cg", "k_cg", "shape", "radius", "diameter", "inner_radius", "width", "length"), example={
        "statement": ("The rotor of a gyrocompass, a {shape} of mass {mass} and radius {radius}, "
                      "spins at {spin} at a latitude of {latitude}. Its sensitive element has a "
                      "moment of inertia of {I_vertical} about the vertical. Find the period of "
                      "its small swings about north, the north-seeking moment when its axis "
                      "points {deviation} east of north, and where the axis settles."),
        "given": {"mass": "2 kg", "shape": "disk", "radius": "60 mm", "spin": "12000 rpm",
                  "I_vertical": "0.004 kg m^2", "latitude": "50 deg", "deviation": "10 deg"},
        "find": {"period": "s", "moment": "N*m", "settles": None},
        "vary": {"latitude": "[0 deg, 70 deg]"}},
)
