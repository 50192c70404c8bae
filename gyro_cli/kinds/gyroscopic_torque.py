"""Gyroscopic torque on a rotor carried by a turning frame (Eqs. 11.27-11.29, generalised).

A rotor of axial inertia J and transverse inertia I (about its centre G) spins
at psidot (``spin``) relative to a frame that turns at Omega (``precession``)
about an axis K at ``theta`` to the spin axis k. Its angular velocity is
omega = Omega K + psidot k, and in the turning frame its angular momentum about
G, H = J omega_z k + I Omega (K - cos(theta) k), is constant, so

    dH/dt = Omega K x H = Omega sin(theta) (J omega_z - I Omega cos(theta)) n,
    omega_z = psidot + Omega cos(theta),   n = K x k / sin(theta)   (line of nodes).

At theta = 90 deg this is Eq. 11.29, Q_theta = J phidot psidot. The bearings
supply that moment as a couple of forces on the spin axis, on top of the
weight and of the force that accelerates an off-axis centre of mass
(``bearing_forces``); a movable counterweight on a pivoted arm can supply it
instead (problem 11/4, ``counterweight_position``).

Conventions: K is the precession axis, pointing up (gravity along -K); k is the
spin axis pointing from bearing A to bearing B; spin and precession are positive
counter-clockwise seen from the tips of k and K (right-hand rule).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

from ..core.errors import InputError
from ..core.expr import PI, Expr, Let, Sym, absolute, sqrt
from ..core.expr import cos as cos_
from ..core.expr import sin as sin_
from ..core.generic import V
from ..core.given import Given
from ..core.prose import cross, deriv, names, q, rel, signed
from ..core.spec import AnswerSpec, Kind, Param
from ..core.vehicle_words import turn_of
from ..core.work import Work, num
from ..physics.algebra import cos_theta, quadratic_roots

RPM = 2 * math.pi / 60


# ---- physics on floats ------------------------------------------------------

def precession_for_moment(J: float, I: float, spin: float, theta: float,
                          moment: float) -> list[float]:
    """Precession rates at which the moment along n is ``moment`` (roots, ascending).

    (J - I) cos(th) sin(th) Omega^2 + J psidot sin(th) Omega - M = 0.
    """
    sin, cos = math.sin(theta), cos_theta(theta)
    return quadratic_roots((J - I) * cos * sin, J * spin * sin, -moment)


@dataclass(frozen=True)
class BearingForces:
    """Forces of bearings A and B on the rotor, SI, split by cause.

    ``up``: perpendicular to k in the plane of K and k, toward +K (upward when
    K is the upward vertical); ``side``: along the line of nodes, toward the
    precession axis; ``thrust``: along k (A to B), taken by the thrust bearing.
    """

    weight: tuple[float, float]
    inertial: tuple[float, float]
    couple: tuple[float, float]
    side: tuple[float, float]
    thrust: float

    @property
    def up(self) -> tuple[float, float]:
        return (self.weight[0] + self.inertial[0] + self.couple[0],
                self.weight[1] + self.inertial[1] + self.couple[1])

    @property
    def loads(self) -> tuple[float, float]:
        return (math.hypot(self.up[0], self.side[0]), math.hypot(self.up[1], self.side[1]))


def centre_acceleration(precession: float, theta: float, cg_radius: float,
                        offset: str) -> tuple[float, float, float]:
    """Acceleration of G (centripetal, Omega^2 R toward the axis) as (along k, up, toward axis).

    ``across``: G lies off the axis along the line of nodes (a ship's rotor on a
    turn); ``along``: G lies off the axis in the plane of K and k, on the side
    k points to, horizontal unit h = (k - cos th K) / sin th.
    """
    a = precession * precession * cg_radius
    if offset == "across":
        return 0.0, 0.0, a
    return -a * math.sin(theta), a * cos_theta(theta), 0.0


def bearing_forces(mass: float, g: float, moment: float, spacing: float, cg_position: float,
                   precession: float, theta: float, cg_radius: float = 0.0,
                   offset: str = "across") -> BearingForces:
    """Bearing forces from the free body of the rotor (weight, m a_G, couple M along n).

    With a = AG and b = GB = L - a along k:
    up:   F_A + F_B = m (g sin th + a_up),   a F_A - b F_B = M       (moments about G along n)
    side: F_A + F_B = m a_toward_axis,       a F_A - b F_B = 0
    axial: T = m (g cos th + a_k).
    """
    L, a = spacing, cg_position
    b = L - a
    along_k, up, toward = centre_acceleration(precession, theta, cg_radius, offset)
    W = mass * g * math.sin(theta)
    return BearingForces(
        weight=(W * b / L, W * a / L),
        inertial=(mass * up * b / L, mass * up * a / L),
        couple=couple_forces(moment, L),
        side=(mass * toward * b / L, mass * toward * a / L),
        thrust=mass * (g * cos_theta(theta) + along_k))


# ---- the worked answer ------------------------------------------------------

def _theta(theta: float) -> Sym:
    return Sym("theta", theta, "deg")


def _rate(name: str, value: float) -> Sym:
    return Sym(name, value, "rad/s")


def _cos(theta: float) -> Expr:
    """cos(theta), exactly 0 at 90 deg as physics.algebra.cos_theta takes it (the float
    cos(pi/2) is 6e-17): there the substitution shows its value, 0."""
    if cos_theta(theta) == 0:
        return Let(Sym("cos(theta)", 0.0), cos_(_theta(theta)))
    return cos_(_theta(theta))


def _slow_root(J: Sym, I: Sym, spin: Sym, theta: float, M: Sym, root: float) -> Expr:
    """The slow root of (J - I) cos(th) sin(th) Omega^2 + J psidot sin(th) Omega - M = 0,
    written without cancellation as 2 M / (b +- sqrt(b^2 + 4 a M)), b = J psidot sin(th):
    the sign whose value is ``root`` (the root physics picked)."""
    b = J * spin * sin_(_theta(theta))
    disc = b ** 2 + 4 * (J - I) * _cos(theta) * sin_(_theta(theta)) * M
    best: tuple[float, Expr] | None = None
    for tree in (2 * M / (b + sqrt(disc)), 2 * M / (b - sqrt(disc))):
        try:
            value = tree.value
        except (ZeroDivisionError, ValueError):
            continue
        if best is None or abs(value - root) < abs(best[0] - root):
            best = (value, tree)
    assert best is not None
    return best[1]


#: the symbols the sentences name (values are in the steps' trees)
K0, k0, n0, A0, B0, th0, W0, L0, H0, G0 = names("K k n A B theta Omega L H G")
w_z0, ps0, I0, J0, M0, v0, R0, r_w0 = names("omega_z psidot I J M v R r_w")
h0, T_d0, y0, t0 = names("h T_d y t")  # a wheel's drop
F_A0, F_B0, a_up0, a_k0, g0, a0, b0 = names("F_A F_B a_up a_k g a b")  # the bearing forces
b_balance0, db0, m_c0 = names("b0 db m_c")  # the counterweight


# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's own time in gyro check.
def _conventions(drop: bool) -> tuple[tuple, tuple]:
    """The axes and the line of nodes: K horizontal along the track when a wheel drops
    (``drop``), else upward."""
    axes = (K0, ": the precession axis, ",
            *(("horizontal along the track (the axle tilts about it while a wheel drops)",)
              if drop else ("upward (gravity along ", -K0, ")")),
            "; ", k0, ": the spin axis, from bearing ", A0, " to bearing ", B0, "; spin and "
            "precession positive counter-clockwise seen from the tips of ", k0, " and of ", K0,
            " (right-hand rule).")
    nodes = (rel(n0, "=", cross(K0, k0) / sin_(th0)), ": the line of nodes, perpendicular to "
             "both the spin and the precession axes",
             *((" (vertical here).",) if drop else
               (" (with ", k0, " pointing east and ", K0, " up, ", n0, " points north).")))
    return axes, nodes


_CONVENTIONS = {drop: _conventions(drop) for drop in (False, True)}
_WHEEL_DROPS = ("a wheel drops: the wheel set tilts about ", K0, " at the rate ", W0, "; ", k0,
                " is the axle, from wheel ", A0, " to wheel ", B0, ", and the bearing_spacing ",
                L0, " is the distance between the wheels (rails)")
_MOMENT_TITLE = ("Moment on the rotor, ", rel(deriv(H0), "=", cross(W0 * K0, H0)),
                 " (Eqs. 11.28-11.29 generalised)")
_MOMENT_SYMBOLS = (H0, ": the angular momentum of the rotor about its centre of mass; ", W0,
                   ": the precession rate about ", K0)
_AT_90 = (rel(th0, "=", q(math.pi / 2, "deg", exact=True)), ": ", rel(w_z0, "=", ps0),
          ", the ", I0, " term drops out (", I0, " is not needed)")
_H_CONSTANT = (absolute(H0), " is constant in the turning frame; ")
_RATE_OF_H = absolute(deriv(H0))
_TURNING_H = absolute(W0) * absolute(cross(K0, H0))


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.solid_body
    theta = given["theta"]
    if "drop" in given and abs(theta - math.pi / 2) > 1e-9:
        raise InputError("a wheel set's axle lies across the track, at 90 deg to the axis it "
                         "tilts about while a wheel drops: leave theta out (or give 90 deg)",
                         key="given.theta")
    if 0 <= theta <= math.pi and abs(math.sin(theta)) < 1e-12:
        _along_the_axis(given, find, theta, work)
        return
    J = body.needed("J")
    cos = cos_theta(theta)
    if cos != 0:
        body.require("I_cg")
    I = body.I_cg if body.I_cg is not None else 0.0
    work.section("Conventions")
    drop = "drop" in given
    axes, nodes = _CONVENTIONS[drop]
    work.text(*axes)
    work.text(*nodes)
    if drop:
        work.text(*_WHEEL_DROPS)
    spin = _spin(given, work)
    precession = _precession(given, J, I, spin, theta, work)
    work.section(*_MOMENT_TITLE)
    work.text(*_MOMENT_SYMBOLS)
    psidot, Omega = _rate("psidot", spin), _rate("Omega", precession)
    J_, I_ = Sym("J", J, "kg m^2"), Sym("I", I, "kg m^2")
    axial = work.step("omega_z", psidot + Omega * _cos(theta), unit="rad/s", ref="Eq. 11.8")
    if cos == 0:
        work.text(*_AT_90)
        M = work.step("M", J_ * psidot * Omega, unit="N*m", ref="Eq. 11.29")
    else:
        M = work.step("M", Omega * sin_(_theta(theta)) * (
            J_ * _rate("omega_z", axial) - I_ * Omega * _cos(theta)), unit="N*m",
            ref="Eq. 11.29 generalised")
    _sense(M, drop, work)
    work.answer("moment", "M", [M], "moment")
    work.answer("precession", "Omega", [precession], "rate")
    work.check(*_H_CONSTANT, rel(_RATE_OF_H, "=", _TURNING_H, "=", q(abs(M), "N m")))

    bearing_keys = [k for k in ("cg_position", "arrangement", "supported_mass", "cg_radius",
                                "cg_offset") if k in given]
    if bearing_keys and "bearing_spacing" not in given:
        raise InputError(f"{bearing_keys[0]} is used only for bearing forces, which need "
                         "bearing_spacing", key="given.bearing_spacing")
    if {"bearing_forces", "bearing_side_forces", "bearing_loads", "axial_thrust",
            "couple_forces"} & find \
            or "bearing_spacing" in given:
        _bearings(given, find, M, precession, theta, work)
    if "counterweight_position" in find or "counterweight" in given:
        _counterweight(given, M, theta, work)


def _along_the_axis(given: Given, find: frozenset[str], theta: float, work: Work) -> None:
    """theta = 0 or 180 deg: the spin axis along the precession axis; the moment is 0.

    omega = (psidot + Omega cos(theta)) k lies along K, so H = J omega_z k is
    fixed in space and dH/dt = Omega K x H = 0 (sin(theta) = 0 in Eq. 11.29).
    """
    deg = round(math.degrees(theta))
    work.section("Spin axis along the precession axis")
    k, K, th, w_z, ps, W, H, J, I = names("k K theta omega_z psidot Omega H J I")
    work.text(k, ": the spin axis; ", K, ": the precession axis, upward; ",
              rel(th, "=", q(math.radians(deg), "deg", exact=True)), ": the spin axis lies "
              "along the precession axis, so the precession only adds to (or takes from) the "
              "spin, ", rel(w_z, "=", ps + W * cos_(th)), "; ", rel(H, "=", J * w_z * k),
              " stays along ", K, " and does not turn: ",
              rel(deriv(H), "=", cross(W * K, H), "=", 0), ", no gyroscopic moment (",
              rel(sin_(th), "=", 0), " in Eq. 11.29)")
    for key in ("moment", "bearing_spacing", "counterweight"):
        if key in given:
            raise InputError(f"at theta = {deg} deg there is no gyroscopic moment: {key} has "
                             "nothing to balance (the spin axis lies along the precession axis)",
                             key=f"given.{key}")
    wanted = find & {"bearing_forces", "bearing_side_forces", "bearing_loads", "axial_thrust",
                     "couple_forces", "counterweight_position"}
    if wanted:
        raise InputError(f"at theta = {deg} deg the gyroscopic moment is 0; {sorted(wanted)[0]} "
                         "is not computed for a spin axis along the precession axis",
                         key=f"find.{sorted(wanted)[0]}")
    precession = _precession(given, 0.0, 0.0, given.get("spin", 0.0) or 0.0, theta, work)
    work.step("M", value=0.0, unit="N*m", note=(
        rel(sin_(th), "=", 0), " in ", W * sin_(th) * (J * w_z - I * W * cos_(th)),
        ", whatever the transverse inertia ", I))
    work.answer("moment", "M", [0.0], "moment")
    work.answer("precession", "Omega", [precession], "rate")


_ROLLING_WHEELS = (ps0, ", the wheels' spin: they roll without slipping, so the axle's speed "
                   "is ", rel(v0, "=", ps0 * r_w0))


def _spin(given: Given, work: Work) -> float:
    """psidot: given, or a road or rail wheel's v / r_w (rolling without slip)."""
    if "wheel_radius" in given:
        if "spin" in given:
            raise InputError("give spin or wheel_radius (spin = v / r_w), not both",
                             key="given.wheel_radius")
        if "speed" not in given:
            raise InputError("wheel_radius gives the spin with the vehicle's speed: "
                             "psidot = v / r_w; give speed", key="given.speed")
        r = given["wheel_radius"]
        work.section("Spin of the wheels from the vehicle's speed")
        work.text(*_ROLLING_WHEELS)
        return work.step("psidot", Sym("v", given["speed"], "m/s") / Sym("r_w", r, "m"),
                         unit="rad/s")
    if "spin" not in given:
        raise InputError("give the rotor's spin relative to the frame (or the vehicle's speed "
                         "and wheel_radius)", key="given.spin")
    return given["spin"]


_AXLE_TURNS = ("the axle turns through ", h0 / L0, " (small angle) while the wheel drops")
_HARMONIC_DROP = ("the wheel falls ", h0, " and rises again in the time ", T_d0, " with simple "
                  "harmonic motion: ", rel(y0, "=", h0 / 2 * (1 - cos_(2 * PI * t0 / T_d0))),
                  ", whose greatest speed is ", h0 / 2 * (2 * PI / T_d0))


def _drop(given: Given, work: Work) -> float:
    """Omega: the tilt rate of the axle while one wheel drops (Khurmi's defective ballasting)."""
    if "counterweight" in given or "balance_position" in given:
        raise InputError("a wheel's drop makes a couple about the vertical, which no weight "
                         "can balance: leave out the counterweight", key="given.counterweight"
                         if "counterweight" in given else "given.balance_position")
    if "bearing_spacing" not in given:
        raise InputError("a wheel's drop tilts the axle at drop / L per unit time: give "
                         "bearing_spacing, the distance between the wheels", 
                         key="given.bearing_spacing")
    h, L = given["drop"], given["bearing_spacing"]
    how = [k for k in ("drop_length", "drop_time") if k in given]
    if len(how) != 1:
        raise InputError("give how the wheel drops: drop_length (the length of track over "
                         "which it falls, with speed) or drop_time (the time in which it falls "
                         "and rises again, simple harmonic)",
                         key=f"given.{how[1]}" if how else "given.drop_length")
    work.section("Tilt rate of the axle while the wheel drops")
    if how == ["drop_length"]:
        if "speed" not in given:
            raise InputError("drop_length needs the vehicle's speed (the drop takes "
                             "drop_length / v)", key="given.speed")
        s, v = given["drop_length"], given["speed"]
        t = work.step("t", Sym("s", s, "m") / Sym("v", v, "m/s"), unit="s",
                      note="time the wheel takes to drop")
        return work.step("Omega", Sym("h", h, "m") / Sym("L", L, "m") / Sym("t", t, "s"),
                         unit="rad/s", note=_AXLE_TURNS)
    T = given["drop_time"]
    work.text(*_HARMONIC_DROP)
    y_dot = work.step("ydot_max", Sym("h", h, "m") / 2 * (2 * PI / Sym("T_d", T, "s")),
                      unit="m/s")
    return work.step("Omega", Sym("ydot_max", y_dot, "m/s") / Sym("L", L, "m"), unit="rad/s",
                     note="greatest tilt rate of the axle")


#: Omega = +v / R on a left turn, -v / R on a right one
_PATH_RATE = {"left": rel(W0, "=", signed("+", v0) / R0), "right": rel(W0, "=", -v0 / R0)}
_SOUGHT = (W0, ": the precession rate sought; ", I0, ": the transverse moment of inertia about "
           "the centre of mass")
_SUSTAINED = (rel((J0 - I0) * cos_(th0) * sin_(th0) * W0 ** 2 + J0 * ps0 * sin_(th0) * W0 - M0,
                  "=", 0),)


def _precession(given: Given, J: float, I: float, spin: float, theta: float,
                work: Work) -> float:
    """Omega: given, from a path (v / R), from a wheel's drop, or from an applied moment."""
    ways = [k for k in ("precession", "turn_radius", "drop", "moment") if k in given]
    spelled = {"turn_radius": "speed with turn_radius", "drop": "a wheel's drop"}
    if len(ways) > 1:
        raise InputError(f"give one of precession, speed (with turn_radius), drop or moment, "
                         f"not {' and '.join(spelled.get(w, w) for w in ways)}",
                         key=f"given.{ways[1]}")
    if not ways:
        raise InputError("give the precession (or speed and turn_radius, a wheel's drop, or "
                         "the moment)", key="given.turn_radius" if "speed" in given
                         else "given.precession")
    if "turn_radius" in given and "speed" not in given:
        raise InputError("turn_radius goes with speed (Omega = v / R)", key="given.turn_radius")
    if "speed" in given and not {"turn_radius", "wheel_radius", "drop_length"} & set(given.values):
        raise InputError("speed gives the precession with turn_radius (Omega = v / R), the "
                         "spin with wheel_radius (psidot = v / r_w) or a tilt rate with drop "
                         "and drop_length", key="given.speed")
    for key in ("drop_length", "drop_time"):
        if key in given and ways != ["drop"]:
            raise InputError(f"{key} goes with drop", key=f"given.{key}")
    if "turn" in given and ways != ["turn_radius"]:
        raise InputError("turn (left or right) goes with speed and turn_radius",
                         key="given.turn")
    if ways == ["precession"]:
        return given["precession"]
    if ways == ["drop"]:
        return _drop(given, work)
    if ways == ["turn_radius"]:
        R = given["turn_radius"]
        turn, taken = turn_of(given)
        sign = 1.0 if turn == "left" else -1.0
        work.section("Precession from the path")
        work.text(f"the frame turns {turn} on a circle{taken}: ", _PATH_RATE[turn],
                  " about the upward vertical (a left turn is counter-clockwise from above)")
        v = Sym("v", given["speed"], "m/s")
        return work.step("Omega", (v if sign > 0 else -v) / Sym("R", R, "m"), unit="rad/s")
    M = given["moment"]
    work.section("Precession that the applied moment sustains (moment along n given)")
    work.text(*_SOUGHT)
    work.text(*_SUSTAINED)
    roots = precession_for_moment(J, I, spin, theta, M)
    if not roots:
        raise InputError(f"no steady precession carries the moment {num(M)} N m at this spin "
                         "(the quadratic has no real root): raise the spin", key="given.moment")
    if len(roots) > 1:
        slow = min(roots, key=abs)
        listed = [piece for r in roots for piece in (", ", q(r, "rad/s"))][1:]
        work.text("two roots ", *listed, "; the slow one is taken (the fast one is a top-like "
                  "motion, see steady_precession)")
        roots = [slow]
    M_, J_, psidot = Sym("M", M, "N m"), Sym("J", J, "kg m^2"), _rate("psidot", spin)
    if cos_theta(theta) == 0:
        return work.step("Omega", M_ / (J_ * psidot), unit="rad/s", ref="Eq. 11.29")
    return work.step("Omega", _slow_root(J_, Sym("I", I, "kg m^2"), psidot, theta, M_, roots[0]),
                     unit="rad/s", substitute=False, note="the slow root of the quadratic, "
                     "written without cancellation")


def _sense_of(positive: bool, drop: bool) -> tuple:
    """Where the moment points and which way it pushes the end of the axis: down when K is
    up; along the track when a wheel drops (K along the track, n vertical: a yawing couple)."""
    toward = (" (along the track): a couple about the vertical, which would swerve the wheel "
              "set",) if drop else (" (down)",)
    return ("Sense: the moment the bearings exert on the rotor points along ",
            signed("+", n0) if positive else -n0, ", the line of nodes; it turns the spin axis "
            "about ", n0, " so that the ", B0 if positive else A0, " end of the axis is pushed "
            "toward ", -K0, *toward, ". The rotor exerts the equal and opposite moment on its "
            "frame.")


_NO_MOMENT = (rel(M0, "=", 0), ": no moment is needed")
_SENSE = {(positive, drop): _sense_of(positive, drop)
          for positive in (True, False) for drop in (True, False)}


def _sense(M: float, drop: bool, work: Work) -> None:
    if M == 0:
        work.text(*_NO_MOMENT)
        return
    work.text(*_SENSE[M > 0, drop])


_BEARING_FORCES = (F_A0, ", ", F_B0, ": forces of the bearings on the rotor, perpendicular to "
                   "the spin axis. 'up' components lie in the plane of ", K0, " and ", k0,
                   ", positive toward ", signed("+", K0), " (upward); 'side' components lie "
                   "along ", n0, ", positive toward the precession axis. Labelled ", A0, ", ", B0,
                   " in that order.")
_CG_FROM_A = ("from bearing ", A0, " to the centre of mass ", G0, " along ", k0)
_CG_FROM_A_DEFAULT = _CG_FROM_A + (" (default: midway)",)
_CG_ACCELERATION = (a_up0, ", ", a_k0, ": the acceleration of ", G0, " upward and along ", k0,
                    "; ", G0, " moves on a circle of radius ", R0, " about the precession "
                    "axis, with the centripetal acceleration ", W0 ** 2 * R0)
_SUM_OF_FORCES, _MOMENT_ABOUT_G = F_A0 + F_B0, a0 * F_A0 - b0 * F_B0
_OFF_THE_AXIS = ("(centre off the axis along ", k0, ")")
_NO_SIDE_FORCES = (rel(*names("F_A,side"), "=", *names("F_B,side"), "=", 0), ": no side forces "
                   "(the centre of mass is not off the axis across the spin axis)")
_AXIAL = ("axial, along ", k0, ", taken by the thrust bearing")
_LOAD = absolute(names("F")[0])  # |F|, a bearing's load


class _FreeBody(NamedTuple):
    """The free body's sentences that name the mass the bearings carry."""

    up: tuple  # the forces and moments perpendicular to the spin axis, in the plane of K, k
    side: tuple  # along the line of nodes
    weight_and_acceleration: Expr  # the check's m g sin(theta) + m a_up


def _free_body(ms: str) -> _FreeBody:
    """The sentences with the mass written ``ms``: m, or m_s for a supported_mass."""
    m = names(ms)[0]
    return _FreeBody(
        up=("up:   ", rel(_SUM_OF_FORCES, "=", m * (g0 * sin_(th0) + a_up0)), ";   ",
            rel(_MOMENT_ABOUT_G, "=", M0), "   (moments about ", G0, " along ", n0, ")"),
        side=("side: ", rel(_SUM_OF_FORCES, "=", m * W0 ** 2 * R0), " (toward the axis);   ",
              rel(_MOMENT_ABOUT_G, "=", 0)),
        weight_and_acceleration=m * g0 * sin_(th0) + m * a_up0)


_FREE_BODY = {ms: _free_body(ms) for ms in ("m", "m_s")}


def _bearings(given: Given, find: frozenset[str], M: float, precession: float, theta: float, work: Work) -> None:
    body = given.solid_body
    if "bearing_spacing" not in given:
        raise InputError("bearing forces need bearing_spacing (the distance AB)",
                         key="given.bearing_spacing")
    L = given["bearing_spacing"]
    arrangement = given.word("arrangement", "between")
    a = given["cg_position"] if "cg_position" in given else L / 2
    if arrangement == "between" and not 0 <= a <= L:
        raise InputError(f"cg_position {num(a)} m puts the centre of mass outside the bearings "
                         f"(0 to {num(L)} m from A); write `arrangement: overhung` if the rotor "
                         "really overhangs a bearing", key="given.cg_position")
    # a wheel's drop: the couple's forces are along the track, the weight vertical, so the
    # two are never summed, whatever mass is given
    if "drop" in given or ("supported_mass" not in given and body.mass is None):
        wanted = sorted(find & {"bearing_side_forces", "bearing_loads", "axial_thrust"})
        if wanted:
            if "drop" in given:
                raise InputError(f"{wanted[0]} needs a vertical precession axis, and a wheel's "
                                 "drop tilts the axle about the track: ask couple_forces (the "
                                 "couple's forces, along the track)", key=f"find.{wanted[0]}")
            raise InputError(f"{wanted[0]} needs the mass the bearings carry (mass, weight or "
                             "supported_mass); couple_forces needs none", key="given.mass")
        _couple_only(given, M, L, "bearing_forces" in find, work)
        return
    m = given["supported_mass"] if "supported_mass" in given else body.m
    offset = given.word("cg_offset", "across")
    R = given.get("cg_radius")
    if R is None:
        R = given["turn_radius"] if "turn_radius" in given else 0.0
        if "turn_radius" in given:
            work.text("the rotor's centre travels on the turn: cg_radius = turn_radius, across "
                      "the spin axis")
    g = body.g
    sin = math.sin(theta)
    forces = bearing_forces(m, g, M, L, a, precession, theta, R, offset)
    b = L - a
    ms = "m_s" if "supported_mass" in given else "m"  # the Given table's symbol
    # with supported_mass the free body is all the bearings carry (a motor with its rotor)
    work.section("Bearing forces: free body of the rotor (forces on the rotor)" if ms == "m"
                 else "Bearing forces: free body of what the bearings carry, the rotor with "
                 "its housing")
    work.text(*_BEARING_FORCES)
    work.step("a", value=a, unit="m", note=_CG_FROM_A_DEFAULT if "cg_position" not in given
              else _CG_FROM_A)
    m_, g_, L_, a_ = Sym(ms, m, "kg"), Sym("g", g, "m/s^2"), Sym("L", L, "m"), Sym("a", a, "m")
    b_ = Sym("b", work.step("b", L_ - a_, unit="m"), "m")
    Omega, R_, th = _rate("Omega", precession), Sym("R", R, "m"), _theta(theta)
    free_body = _FREE_BODY[ms]
    work.text(*_CG_ACCELERATION)
    work.text(*free_body.up)
    parts: dict[str, list[Sym]] = {"A": [], "B": []}
    for end, arm in (("A", b_), ("B", a_)):
        parts[end].append(Sym(f"F_{end},weight", work.step(
            f"F_{end},weight", m_ * g_ * sin_(th) * arm / L_, unit="N",
            note="static share of the weight" if end == "A" else ""), "N"))
    if forces.inertial != (0.0, 0.0):
        a_up = Sym("a_up", work.step("a_up", Omega ** 2 * R_ * _cos(theta), unit="m/s^2",
                                     note=_OFF_THE_AXIS), "m/s^2")
        for end, arm in (("A", b_), ("B", a_)):
            parts[end].append(Sym(f"F_{end},accel", work.step(
                f"F_{end},accel", m_ * a_up * arm / L_, unit="N", substitute=False), "N"))
    M_ = Sym("M", M, "N m")
    for end, couple in zip("AB", couple_forces(M_, L_)):
        parts[end].append(Sym(f"F_{end},couple", work.step(
            f"F_{end},couple", couple, unit="N",
            note="gyroscopic couple" if end == "A" else ""), "N"))
    for end, (first, *rest) in parts.items():
        total: Expr = first
        for part in rest:
            total = total + part
        work.step(f"F_{end}", total, unit="N", substitute=False)
    work.text(*free_body.side)
    if offset == "across" and R:
        work.step("F_A,side", m_ * Omega ** 2 * R_ * b_ / L_, unit="N",
                  note="centripetal force of the centre of mass")
        work.step("F_B,side", m_ * Omega ** 2 * R_ * a_ / L_, unit="N", substitute=False)
    else:
        work.text(*_NO_SIDE_FORCES)
    a_k = Sym("a_k", centre_acceleration(precession, theta, R, offset)[0], "m/s^2")
    work.step("T", m_ * (g_ * _cos(theta) + a_k), unit="N", substitute=False,
              note=_AXIAL)
    if min(forces.up) < 0:
        work.text("a negative 'up' force pulls the rotor down: that bearing must hold the shaft "
                  "against lifting")
    work.answer("bearing_forces", "F", list(forces.up), "force", ["A", "B"])
    work.answer("couple_forces", "F_couple", list(forces.couple), "force", ["A", "B"])
    work.answer("bearing_side_forces", "F_side", list(forces.side), "force", ["A", "B"])
    work.answer("bearing_loads", _LOAD, list(forces.loads), "force", ["A", "B"])
    work.answer("axial_thrust", "T", [forces.thrust], "force")
    work.check("up: ", rel(_SUM_OF_FORCES, "=", q(sum(forces.up), "N")), ", ",
               rel(free_body.weight_and_acceleration, "=",
                   q(m * g * sin + sum(forces.inertial), "N")), "; ",
               rel(_MOMENT_ABOUT_G, "=", q(a * forces.up[0] - b * forces.up[1], "N m")), ", ",
               rel(M0, "=", q(M, "N m")))


def couple_forces(moment: V, spacing: V) -> tuple[V, V]:
    """The gyroscopic couple's share of the bearing (or rail) forces: +M / L at A, -M / L at B,
    a pair of equal and opposite forces L apart whose moment is M (floats or trees)."""
    return moment / spacing, -moment / spacing


_TILTS = ("the wheel set tilts about a horizontal axis, so the weight is not along ", K0)
_NO_MASS = ("no mass is given",)
_COUPLE_SHARE = (": the forces below are the gyroscopic couple's share alone, equal and opposite "
                 "at ", A0, " and ", B0, "; the static load (the weight's share) is added to them "
                 "where the weight is known")
# a wheel drops: K lies along the track and the couple is about the vertical, so its forces
# are horizontal, fore and aft, and the weight (vertical) is never added to them
_COUPLE_ALONG_TRACK = (": the forces below are the gyroscopic couple's alone, equal and "
                       "opposite at ", A0, " and ", B0, " and horizontal, along the track "
                       "(along ", K0, "); the weight is vertical, across them, and the couple "
                       "changes no wheel's vertical load")
_ON_THE_ROTOR = ("on the rotor at ", A0)
_ON_THE_ROTOR_UP = _ON_THE_ROTOR + (", toward ", signed("+", K0))
_PUSHES_BACK = ("the rotor pushes each bearing (rail) the other way: one is loaded by ",
                absolute(M0) / L0, " more, the other relieved by as much")
_PUSHES_ALONG_TRACK = ("the wheel set is held against this yawing where it is carried, taken "
                       "here at the wheels, ", L0, " apart (its axle boxes in the frame, or "
                       "the rails through the treads): one side is pushed forward and the "
                       "other back by ", absolute(M0) / L0)
_PLUS_MINUS_SHARE = signed("+-", M0) / L0  # +-M / L
_COUPLE_OF_FORCES = names("F_A,couple")[0] * L0
_FORCES_CANCEL = ("; ", rel(F_A0 + F_B0, "=", 0))


def _couple_only(given: Given, M: float, L: float, warn: bool, work: Work) -> None:
    """No mass (or a tilting axle): the couple's share of the bearing forces alone."""
    drop = "drop" in given
    work.section("Forces of the gyroscopic couple at the wheels, along the track" if drop
                 else "Forces of the gyroscopic couple on the bearings (rails)")
    why_pieces = _TILTS if drop else _NO_MASS
    work.text(*why_pieces, *(_COUPLE_ALONG_TRACK if drop else _COUPLE_SHARE))
    F_A, F_B = couple_forces(M, L)
    M_, L_ = Sym("M", M, "N m"), Sym("L", L, "m")
    on_A, on_B = couple_forces(M_, L_)
    work.step("F_A,couple", on_A, unit="N", note=_ON_THE_ROTOR_UP if M >= 0 else _ON_THE_ROTOR)
    work.step("F_B,couple", on_B, unit="N")
    work.text(*(_PUSHES_ALONG_TRACK if drop else _PUSHES_BACK))
    # along the track, which way is forward the data do not say: a size is placed (A, B)
    # and signed by its number, never by up, down, pressed or relieved
    signs: list[tuple[str, int]] | None = [] if drop else None
    work.answer("couple_forces", "F_couple", [F_A, F_B], "force", ["A", "B"], signs=signs)
    work.answer("bearing_forces", "F", [F_A, F_B], "force", ["A", "B"], signs=signs)
    if warn:
        work.warn(*why_pieces, ": bearing_forces are the gyroscopic couple's "
                  + ("forces, along the track, " if drop else "share alone, "),
                  rel(_PLUS_MINUS_SHARE, "=", signed("+-", q(abs(F_A), "N"))),
                  ", the weight (vertical) not among them" if drop else
                  ", without the weight's share (give mass for the whole force)")
    work.check(rel(_COUPLE_OF_FORCES, "=", q(F_A * L, "N m"), "=", M0, "=", q(M, "N m")),
               *_FORCES_CANCEL)


_ARM = ("At ", rel(b0, "=", b_balance0), " the arm balances with the rotor at rest. Moving the "
        "block by ", db0, " unbalances the arm by ", m_c0 * g0 * db0, ", which must equal the "
        "moment ", M0, " the precession needs; the spin may turn either way, so the block may go "
        "out or in.")
_ROTOR_SIDE, _BLOCK_SIDE = b_balance0 - db0, b_balance0 + db0  # the two positions, b0 -+ db
_SENSE_OF_PRECESSION = (
    "With the spin vector pointing out along the arm toward the rotor, the rotor-side-heavier "
    "position (", _ROTOR_SIDE, ") gives precession counter-clockwise seen from above; the "
    "block-side-heavier one (", _BLOCK_SIDE, ") clockwise (or the same sense with the spin "
    "reversed).")
_UNBALANCE, _SIZE_OF_M = m_c0 * g0 * (b0 - b_balance0), absolute(M0)


def _counterweight(given: Given, M: float, theta: float, work: Work) -> None:
    body = given.solid_body
    if "counterweight" not in given or "balance_position" not in given:
        missing = "counterweight" if "counterweight" not in given else "balance_position"
        raise InputError("counterweight_position needs the block's mass (counterweight) and its "
                         "position when the unit balances with the rotor at rest "
                         "(balance_position)", key=f"given.{missing}")
    if cos_theta(theta) != 0:
        raise InputError("the counterweight arm is built for a horizontal spin axis (theta = 90 "
                         "deg)", key="given.theta")
    mc, b0 = given["counterweight"], given["balance_position"]
    g = body.g
    work.section("Counterweight on the pivoted arm (problem 11/4)")
    work.text(*_ARM)
    abs_M = Let(Sym("abs_M", abs(M), "N m"), absolute(Sym("M", M, "N m")))
    db = work.step("db", abs_M / (Sym("m_c", mc, "kg") * Sym("g", g, "m/s^2")), unit="m")
    b0_, db_ = Sym("b0", b0, "m"), Sym("db", db, "m")
    positions = [work.step("b", b0_ - db_, unit="m", note="rotor side heavier"),
                 work.step("b", b0_ + db_, unit="m", note="block side heavier")]
    work.text(*_SENSE_OF_PRECESSION)
    if positions[0] < 0:
        work.warn(_ROTOR_SIDE, " is negative: the block would have to pass the pivot")
    work.answer("counterweight_position", "b", positions, "length",
                ["rotor side heavier", "block side heavier"])
    work.check(rel(_UNBALANCE, "=", q(mc * g * db, "N m"), "=", _SIZE_OF_M, "=",
                   q(abs(M), "N m")))


#: the words that sign a bearing's force as books print it: "116.5 N upwards at A"
UP_DOWN = (("up", 1), ("upward", 1), ("upwards", 1), ("down", -1), ("downward", -1),
           ("downwards", -1))

KIND = Kind(
    name="gyroscopic_torque",
    summary="moment and bearing forces of a rotor carried by a turning frame (gyroscope, turbine "
            "in a turning ship, counterweighted fan)",
    chapter="Eqs. 11.27-11.29 (generalised to any theta), dH/dt = Omega x H",
    params=(
        Param("spin", "rate", "psidot", "spin of the rotor relative to its frame, positive about "
              "k (A to B)"),
        Param("precession", "rate", "Omega", "rate at which the frame turns, positive "
              "counter-clockwise seen from above"),
        Param("theta", "angle", "theta", "angle between the precession axis and the spin axis",
              default="90 deg", range=(0.0, math.pi), reason="the angle between the precession "
              "and the spin axes (at 0 or 180 deg the precession only adds to the spin)"),
        Param("speed", "speed", "v", "speed of a turning vehicle (instead of precession; with "
              "turn_radius)"),
        Param("turn_radius", "length", "R", "radius of the vehicle's turn: Omega = v / R",
              positive=True),
        Param("turn", "word", "turn", "left (counter-clockwise from above, default) or right",
              choices=("left", "right")),
        Param("moment", "moment", "M", "applied moment along the line of nodes, to find the "
              "precession it sustains"),
        Param("wheel_radius", "length", "r_w", "radius of a road or rail wheel: spin = speed / "
              "r_w (instead of spin)", positive=True),
        Param("drop", "length", "h", "how far one wheel drops (the axle tilts about the track: "
              "the precession)", positive=True),
        Param("drop_length", "length", "s", "length of track over which the wheel drops at "
              "speed: Omega = h v / (s L)", positive=True),
        Param("drop_time", "time", "T_d", "time in which the wheel falls and rises again, "
              "simple harmonic: greatest Omega = pi h / (T_d L)", positive=True),
        Param("bearing_spacing", "length", "L", "distance between bearings A and B on the spin "
              "axis", positive=True, reason="two bearings at one point cannot take a couple"),
        Param("cg_position", "length", "a", "distance from bearing A to the centre of mass, "
              "toward B (default midway)"),
        Param("arrangement", "word", "arrangement", "between (default: the centre of mass lies "
              "between the bearings) or overhung", choices=("between", "overhung")),
        Param("supported_mass", "mass", "m_s", "mass the bearings carry, if more than the rotor "
              "(a motor's housing); default the body's mass", positive=True),
        Param("cg_radius", "length", "R_G", "distance of the centre of mass from the precession "
              "axis (default 0, or turn_radius)", nonnegative=True,
              reason="cg_radius is a distance"),
        Param("cg_offset", "word", "offset", "across (default: off the axis along the line of "
              "nodes) or along (in the plane of the two axes, k pointing away)",
              choices=("across", "along")),
        Param("counterweight", "mass", "m_c", "mass of the movable block on the pivoted arm",
              positive=True),
        Param("balance_position", "length", "b0", "block position at which the arm balances "
              "with the rotor at rest"),
    ),
    answers=(
        AnswerSpec("moment", "moment", "M", "moment the bearings exert on the rotor, along the "
                   "line of nodes n = K x k / sin(theta)"),
        AnswerSpec("precession", "rate", "Omega", "precession rate (given, v / R, or sustained by "
                   "a given moment)"),
        AnswerSpec("bearing_forces", "force", "F", "[A, B]: forces of the bearings on the rotor "
                   "perpendicular to k in the plane of K and k, upward positive",
                   sides=("A", "B"), signs=UP_DOWN),
        AnswerSpec("bearing_side_forces", "force", "F_side", "[A, B]: along the line of nodes, "
                   "toward the precession axis positive", sides=("A", "B"),
                   signs=(("inward", 1), ("inwards", 1), ("outward", -1), ("outwards", -1))),
        AnswerSpec("bearing_loads", "force", "|F|", "[A, B]: magnitudes of the radial bearing "
                   "forces", sides=("A", "B")),
        AnswerSpec("axial_thrust", "force", "T", "force along the spin axis (A to B) on the "
                   "rotor"),
        AnswerSpec("couple_forces", "force", "F_couple", "[A, B]: the gyroscopic couple's "
                   "share of the bearing (rail) forces, +M / L and -M / L (upward on the rotor "
                   "positive: that bearing or rail is pressed); needs no mass",
                   sides=("A", "B"), signs=UP_DOWN + (("pressed", 1), ("relieved", -1))),
        AnswerSpec("counterweight_position", "length", "b", "block positions for the "
                   "precession, ascending (one per spin sense)"),
    ),
    solve=solve,
    animation="turning_rotor",
    example={
        "statement": ("A rotor of mass {mass} with a radius of gyration of {k_axial} spins at "
                      "{spin} in two bearings {bearing_spacing} apart, which carry a total mass "
                      "of {supported_mass}. Its frame turns about the vertical at {precession}. "
                      "Find the forces on the two bearings and the gyroscopic moment."),
        "given": {"mass": "2.5 kg", "k_axial": "35 mm", "supported_mass": "10 kg",
                  "spin": "-1725 rpm", "precession": "48 rpm", "bearing_spacing": "200 mm"},
        "find": {"bearing_forces": "N", "moment": "N*m"},
        "vary": {"precession": "[0.8, 1.2]"}},
)
