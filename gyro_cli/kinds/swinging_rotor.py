"""A spinning rotor on an arm that swings about a horizontal shaft (problem 11/8).

A rotor (a thin disk in 11/8) spins at a steady rate p about its own axis k,
which lies along an arm of length L. The arm is rigidly fixed to a horizontal
shaft turning in bearings A and B (spacing d, the arm at a from A). Released
from rest at theta0 (theta from the upward vertical, 0 = arm straight up), the
arm swings down under gravity; the spin axis turns with it, so the bearings
must supply the gyroscopic couple J p thetadot as well as the forces that carry
and accelerate the rotor's centre.

With i along the shaft (A to B), k along the arm (shaft to rotor) and n the
unit perpendicular to both on the upper side (n = -i x k, against the swing):

    energy:          I_O thetadot^2 / 2 = m g L (cos theta0 - cos theta),  I_O = I_G + m L^2
    moment about AB: I_O thetaddot = m g L sin(theta)
    moments about O: H_O = I_O thetadot i + J p k,  dH_O/dt = I_O thetaddot i - J p thetadot n
    forces:          F_A + F_B = m a_G + m g (up),  a_G = -L thetaddot n - L thetadot^2 k

so along the arm F_A = (b/d) m (g cos th - L thetadot^2) - J p thetadot / d,
F_B = (a/d) m (g cos th - L thetadot^2) + J p thetadot / d, and along n
F_A = (b/d) m (g sin th - L thetaddot), F_B = (a/d) m (g sin th - L thetaddot).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..core import generic
from ..core.errors import InputError
from ..core.expr import Chain, Expr, Let, Sym, absolute, cos, sin, sqrt
from ..core.given import Given
from ..core.prose import cross, deriv, names, q, rel, signed
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work, num
from ..physics.algebra import cos_theta

# ---- physics, for floats (the answers) and trees (the steps) ------------------

def swing_rate_sq(m: generic.V, g: generic.V, L: generic.V, I_O: generic.V, theta0: generic.V,
                  theta: generic.V) -> generic.V:
    """thetadot^2 from energy: 2 m g L (cos theta0 - cos theta) / I_O."""
    return 2 * m * g * L * (generic.cos(theta0) - generic.cos(theta)) / I_O


def swing_acceleration(m: generic.V, g: generic.V, L: generic.V, I_O: generic.V,
                       theta: generic.V) -> generic.V:
    """thetaddot from moments about the shaft: m g L sin(theta) / I_O."""
    return m * g * L * generic.sin(theta) / I_O


@dataclass(frozen=True)
class SwingForces:
    """Bearing forces on the rotor assembly at theta, SI, as (A, B).

    ``arm``: along the arm, from the shaft toward the rotor positive; ``normal``:
    perpendicular to the arm and the shaft, on the upper side (against the swing).
    """

    thetadot: float
    thetaddot: float
    arm: tuple[float, float]
    normal: tuple[float, float]
    couple: float  # J p thetadot / d, the gyroscopic share along the arm (+B, -A)

    @property
    def magnitudes(self) -> tuple[float, float]:
        return (math.hypot(self.arm[0], self.normal[0]), math.hypot(self.arm[1], self.normal[1]))


def swing_forces(m: float, g: float, J: float, I_G: float, spin: float, L: float, d: float,
                 a: float, theta0: float, theta: float) -> SwingForces:
    """Forces in A and B as the arm passes theta (energy, moment about AB, free body)."""
    I_O = I_G + m * L * L
    thetadot = math.sqrt(max(swing_rate_sq(m, g, L, I_O, theta0, theta), 0.0))
    thetaddot = swing_acceleration(m, g, L, I_O, theta)
    b = d - a
    S_arm = m * (g * math.cos(theta) - L * thetadot ** 2)
    S_normal = m * (g * math.sin(theta) - L * thetaddot)
    couple = J * spin * thetadot / d
    return SwingForces(thetadot, thetaddot, (b * S_arm / d - couple, a * S_arm / d + couple),
                       (b * S_normal / d, a * S_normal / d), couple)


# ---- the worked answer ------------------------------------------------------

def _inertia_trees(body, m: float) -> tuple[Expr, Expr]:
    """I_G / m and J / m as trees in the rotor's own symbols (r^2 / 4 and r^2 / 2 for a
    disk, else the radii of gyration k_G^2 and k_z^2)."""
    if body.shape in ("disk", "ring"):
        r = Sym("r", body.radius, "m")
        return (r ** 2 / 4, r ** 2 / 2) if body.shape == "disk" else (r ** 2 / 2, r ** 2)
    return (Sym("k_G", math.sqrt(body.I_cg / m), "m") ** 2,
            Sym("k_z", math.sqrt(body.J / m), "m") ** 2)


# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's time in gyro check.
i, k, n, A, B, AB, O, G, td, tdd, p0 = names("i k n A B AB O G thetadot thetaddot p")
H_O, I_O0, J0, d0 = names("H_O I_O J d")
a_G, L0 = names("a_G L")
F_A, F_B, m0, g0 = names("F_A F_B m g")
a0, b0 = names("a b")
F_Aarm, F_Barm = names("F_A,arm F_B,arm")
_AXES = (i, ": along the shaft from ", A, " to ", B, "; the arm swings at the rate ", td,
         ", its angular velocity ", signed("+", td) * i, " (counter-clockwise seen from ", B,
         "); ", k, ": along the arm from the shaft to the rotor; spin ", p0, " positive about ",
         k, " (counter-clockwise seen from outside the rotor's face). ", n, ": perpendicular "
         "to the arm and the shaft on the upper side (against the swing).")
_FORCES = ("Forces are those of the bearings on the rotor assembly: 'arm' components along ", k,
           " (from the shaft toward the rotor positive), 'normal' components along ", n,
           ". Labelled ", A, ", ", B, " in that order. The bearings exert no moment about ", AB,
           ".")
_SWING_TITLE = ("Swing: energy and moments about ", AB)
_TD2 = td ** 2
_COUPLE_TITLE = ("Gyroscopic couple: ",
                 rel(deriv(H_O), "=", I_O0 * tdd * i + J0 * p0 * td * cross(i, k)))
_H_O_LINE = (rel(H_O, "=", I_O0 * td * i + J0 * p0 * k), ": the angular momentum about ", O,
             ", the centre of the shaft; ", k, " turns about ", i, " at ", td)
_COUPLE = J0 * p0 * td / d0
_COUPLE_NOTE = ("+ at ", B, ", - at ", A, ", along the arm")
_FREE_BODY_TITLE = ("Bearing forces: free body of the rotor, ",
                    rel(F_A + F_B, "=", m0 * a_G + m0 * g0), " (up)")
_ACCELERATION = (a_G, ": the acceleration of the rotor's centre ", G, ", ", L0 * tdd, " across "
                 "the arm and ", L0 * td ** 2, " toward the shaft")
_F_ABS = {end: absolute(names(f"F_{end}")[0]) for end in "AB"}
_PUSHES = ("the gyroscopic couple pushes ", B, " along ", signed("+", k), " and ", A, " along ",
           -k, " when ", rel(p0 * td, ">", 0), "; reversing the spin swaps the two")
_F = absolute(names("F")[0])
_MOMENTS = ("moments about ", O, " along ", cross(i, k), ": ")
_ARM_MOMENTS = b0 * F_Barm - a0 * F_Aarm
_J_P_THETADOT = J0 * p0 * td


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.solid_body
    J, I_G = body.needed("J"), body.needed("I_cg")
    m, g = body.m, body.g
    p, L, d = given["spin"], given["arm_length"], given["bearing_spacing"]
    theta, theta0 = given["theta"], given["theta0"]
    a = given["arm_position"] if "arm_position" in given else d / 2
    if not 0 <= a <= d:
        raise InputError(f"arm_position {num(a)} m puts the arm outside the bearings (0 to "
                         f"{num(d)} m from A)", key="given.arm_position")
    if math.cos(theta) > math.cos(theta0) + 1e-12 or not 0 <= theta <= 2 * math.pi - theta0:
        raise InputError(f"released from rest at theta0 = {num(math.degrees(theta0))} deg the "
                         f"arm never reaches theta = {num(math.degrees(theta))} deg (it swings "
                         f"between {num(math.degrees(theta0))} and "
                         f"{num(360 - math.degrees(theta0))} deg)", key="given.theta")
    b = d - a
    c, s = cos_theta(theta), math.sin(theta)
    f = swing_forces(m, g, J, I_G, p, L, d, a, theta0, theta)
    I_O = I_G + m * L * L

    work.section("Conventions")
    work.text(*_AXES)
    work.text(*_FORCES)
    work.section(*_SWING_TITLE)
    m_, g_, L_, d_ = Sym("m", m, "kg"), Sym("g", g, "m/s^2"), Sym("L", L, "m"), Sym("d", d, "m")
    th, th0, p_ = Sym("theta", theta, "deg"), Sym("theta0", theta0, "deg"), Sym("p", p, "rad/s")
    kG2_, kz2_ = _inertia_trees(body, m)
    # I_O in general and in the rotor's own symbols, m (r^2 / 4 + L^2) for a disk
    I_O_ = Sym("I_O", work.step("I_O", Chain(Sym("I_G", I_G, "kg m^2") + m_ * L_ ** 2,
                                             m_ * (kG2_ + L_ ** 2)), unit="kg*m^2"), "kg m^2")
    # I_O / m in the rotor's own symbols, its value from I_O as swing_forces takes it
    per_m = Let(Sym("I_O/m", I_O / m, "m^2"), kG2_ + L_ ** 2)
    drop = cos(th0) - cos(th)  # cos theta0 - cos theta: the centre's fall is L times it
    work.step(_TD2, Chain(swing_rate_sq(m_, g_, L_, I_O_, th0, th), 2 * g_ * L_ * drop / per_m),
              unit="rad^2/s^2", ref="energy")
    work.step("thetadot", value=f.thetadot, unit="rad/s")
    work.step("thetaddot", Chain(swing_acceleration(m_, g_, L_, I_O_, th),
                                 g_ * L_ * sin(th) / per_m),
              unit="rad/s^2", ref="moments about AB")
    work.section(*_COUPLE_TITLE)
    work.text(*_H_O_LINE)
    thetadot = Sym("thetadot", f.thetadot, "rad/s")
    couple = work.step(_COUPLE, Let(Sym("J", J, "kg m^2"), m_ * kz2_) * p_ * thetadot
                       / d_, unit="N", note=_COUPLE_NOTE)
    work.section(*_FREE_BODY_TITLE)
    work.text(*_ACCELERATION)
    # the common parts, shown by their definitions in the formula and by value after it
    per_m_sq = kG2_ + L_ ** 2
    arm_part = Let(Sym("S_arm", m * (g * c - L * f.thetadot ** 2), "N"),
                   m_ * g_ * (cos(th) - 2 * L_ ** 2 * drop / per_m_sq))
    normal_part = Let(Sym("S_normal", m * (g * s - L * f.thetaddot), "N"),
                      m_ * g_ * sin(th) * kG2_ / per_m_sq)
    couple_part = Let(Sym("F_couple", couple, "N"),
                      m_ * kz2_ * p_ * sqrt(2 * g_ * L_ * drop / per_m_sq) / d_)
    b_d = Let(Sym("b/d", b / d), Sym("b", b, "m") / d_)
    a_d = Let(Sym("a/d", a / d), Sym("a", a, "m") / d_)
    work.text(rel(a0, "=", q(a, "m")), " (", A, " to the arm), ",
              rel(b0, "=", d0 - a0, "=", q(b, "m")), "; ", rel(b0 / d0, "=", q(b / d)), ", ",
              rel(a0 / d0, "=", q(a / d)))
    forces = {"F_A,arm": b_d * arm_part - couple_part, "F_B,arm": a_d * arm_part + couple_part,
              "F_A,normal": b_d * normal_part, "F_B,normal": a_d * normal_part}
    values = {name: work.step(name, tree, unit="N") for name, tree in forces.items()}
    for end in "AB":
        arm, normal = (Sym(f"F_{end},{part}", values[f"F_{end},{part}"], "N")
                       for part in ("arm", "normal"))
        work.step(_F_ABS[end], sqrt(arm ** 2 + normal ** 2), unit="N", substitute=False)
    if abs(f.couple) > 0:
        work.text(*_PUSHES)
    work.answer("bearing_forces", _F, list(f.magnitudes), "force", ["A", "B"])
    work.answer("bearing_forces_arm", "F_arm", list(f.arm), "force", ["A", "B"])
    work.answer("bearing_forces_normal", "F_normal", list(f.normal), "force", ["A", "B"])
    work.answer("angular_rate", "thetadot", [f.thetadot], "rate")
    work.check(*_MOMENTS, rel(_ARM_MOMENTS, "=", q(b * f.arm[1] - a * f.arm[0], "N m")), "; ",
               rel(_J_P_THETADOT, "=", q(J * p * f.thetadot, "N m")))


KIND = Kind(
    name="swinging_rotor",
    summary="spinning rotor on an arm swinging about a horizontal shaft in two bearings "
            "(problem 11/8)",
    chapter="Eq. 11.29 (couple J p thetadot), energy, moments about the shaft",
    params=(
        Param("spin", "rate", "p", "steady spin of the rotor about the arm, positive from the "
              "shaft outward", required=True),
        Param("arm_length", "length", "L", "distance from the shaft AB to the rotor's centre, "
              "along the arm", positive=True, reason="shaft to the rotor's centre", required=True),
        Param("bearing_spacing", "length", "d", "distance between bearings A and B",
              positive=True, reason="bearings at one point cannot take the gyroscopic couple", required=True),
        Param("arm_position", "length", "a", "distance from A to the arm along the shaft "
              "(default midway)"),
        Param("theta", "angle", "theta", "angle of the arm from the upward vertical at which "
              "the forces are wanted", required=True),
        Param("theta0", "angle", "theta0", "release angle (from rest)", default="0 deg",
              range=(0.0, math.pi), bounds="[)"),
    ),
    answers=(
        AnswerSpec("bearing_forces", "force", "|F|", "[A, B]: magnitudes of the bearing forces",
                   sides=("A", "B")),
        AnswerSpec("bearing_forces_arm", "force", "F_arm", "[A, B]: along the arm, shaft to "
                   "rotor positive", sides=("A", "B")),
        AnswerSpec("bearing_forces_normal", "force", "F_normal", "[A, B]: perpendicular to the arm "
                   "and shaft, upper side positive", sides=("A", "B")),
        AnswerSpec("angular_rate", "rate", "thetadot", "rate of swing at theta"),
    ),
    solve=solve,
    example={
        "statement": ("A {shape} of mass {mass} and radius {radius} spins at {spin} on an arm; "
                      "its centre is {arm_length} from a horizontal shaft held in two bearings "
                      "{bearing_spacing} apart, about which the arm swings. Find the forces on "
                      "the bearings and the arm's rate of swing when the arm is at {theta} from "
                      "the upward vertical."),
        "given": {"mass": "2 kg", "shape": "disk", "radius": "100 mm", "spin": "300 rad/s",
                  "arm_length": "250 mm", "bearing_spacing": "200 mm", "theta": "90 deg"},
        "find": {"bearing_forces": "N", "angular_rate": "rad/s"},
        "vary": {"spin": "[0.8, 1.2]"}},
)
