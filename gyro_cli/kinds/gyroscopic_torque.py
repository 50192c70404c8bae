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

from ..core.errors import InputError
from ..core.expr import PI, Expr, Let, Sym, absolute, cos as cos_, sin as sin_, sqrt
from ..core.given import Given
from ..core.prose import cross, deriv, names, q, rel, signed
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work, num
from ..physics.algebra import cos_theta, quadratic_roots

RPM = 2 * math.pi / 60


# ---- physics on floats ------------------------------------------------------

def gyroscopic_moment(J: float, I: float, spin: float, precession: float, theta: float) -> float:
    """Moment on the rotor along n = K x k / sin(theta): Omega sin th (J omega_z - I Omega cos th)."""
    cos = cos_theta(theta)
    axial = spin + precession * cos
    return precession * math.sin(theta) * (J * axial - I * precession * cos)


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
        couple=(moment / L, -moment / L),
        side=(mass * toward * b / L, mass * toward * a / L),
        thrust=mass * (g * cos_theta(theta) + along_k))


def counterweight_offset(moment: float, counterweight: float, g: float) -> float:
    """How far the block moves from the balance point so its weight gives the moment: M / (m_c g)."""
    return abs(moment) / (counterweight * g)


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


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    body = given.body
    theta = given["theta"]
    if 0 <= theta <= math.pi and abs(math.sin(theta)) < 1e-12:
        _along_the_axis(given, find, theta, work)
        return
    body.require("J")
    cos = cos_theta(theta)
    if cos != 0:
        body.require("I_cg")
    J, I = body.J, body.I_cg if body.I_cg is not None else 0.0
    work.section("Conventions")
    K, k, n, A, B, th, W, L = names("K k n A B theta Omega L")
    work.text(K, ": the precession axis, ",
              *(("horizontal along the track (the axle tilts about it while a wheel drops)",)
                if "drop" in given else ("upward (gravity along ", -K, ")")),
              "; ", k, ": the spin axis, from bearing ", A, " to bearing ", B, "; spin and "
              "precession positive counter-clockwise seen from the tips of ", k, " and of ", K,
              " (right-hand rule).")
    work.text(rel(n, "=", cross(K, k) / sin_(th)), ": the line of nodes, perpendicular to both "
              "the spin and the precession axes",
              *((" (vertical here).",) if "drop" in given else
                (" (with ", k, " pointing east and ", K, " up, ", n, " points north).")))
    if "drop" in given:
        work.text("a wheel drops: the wheel set tilts about ", K, " at the rate ", W, "; ", k,
                  " is the axle, from wheel ", A, " to wheel ", B, ", and the bearing_spacing ",
                  L, " is the distance between the wheels (rails)")
    spin = _spin(given, work)
    precession = _precession(given, J, I, spin, theta, work)
    H = names("H")[0]
    work.section("Moment on the rotor, ", rel(deriv(H), "=", cross(W * K, H)),
                 " (Eqs. 11.28-11.29 generalised)")
    work.text(H, ": the angular momentum of the rotor about its centre of mass; ", W, ": the "
              "precession rate about ", K)
    psidot, Omega = _rate("psidot", spin), _rate("Omega", precession)
    J_, I_ = Sym("J", J, "kg m^2"), Sym("I", I, "kg m^2")
    axial = work.step("omega_z", psidot + Omega * _cos(theta), unit="rad/s", ref="Eq. 11.8")
    if cos == 0:
        w_z, ps, I0 = names("omega_z psidot I")
        work.text(rel(th, "=", q(math.pi / 2, "deg", exact=True)), ": ", rel(w_z, "=", ps),
                  ", the ", I0, " term drops out (", I0, " is not needed)")
        M = work.step("M", J_ * psidot * Omega, unit="N*m", ref="Eq. 11.29")
    else:
        M = work.step("M", Omega * sin_(_theta(theta)) * (
            J_ * _rate("omega_z", axial) - I_ * Omega * _cos(theta)), unit="N*m",
            ref="Eq. 11.29 generalised")
    _sense(M, work)
    work.answer("moment", "M", [M], "moment")
    work.answer("precession", "Omega", [precession], "rate")
    work.check(absolute(H), " is constant in the turning frame; ",
               rel(absolute(deriv(H)), "=", absolute(W) * absolute(cross(K, H)), "=",
                   q(abs(M), "N m")))

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
        psidot, v, r_w = names("psidot v r_w")
        work.text(psidot, ", the wheels' spin: they roll without slipping, so the axle's speed "
                  "is ", rel(v, "=", psidot * r_w))
        return work.step("psidot", Sym("v", given["speed"], "m/s") / Sym("r_w", r, "m"),
                         unit="rad/s")
    if "spin" not in given:
        raise InputError("give the rotor's spin relative to the frame (or the vehicle's speed "
                         "and wheel_radius)", key="given.spin")
    return given["spin"]


def tilt_rate_uniform(drop: float, speed: float, drop_length: float, spacing: float) -> float:
    """Tilt rate of an axle when one wheel drops ``drop`` evenly over ``drop_length`` of track
    at ``speed``: the drop takes t = s / v, the axle turns through drop / L in it."""
    return drop * speed / (drop_length * spacing)


def tilt_rate_harmonic(drop: float, drop_time: float, spacing: float) -> float:
    """Greatest tilt rate when one wheel falls ``drop`` and rises again in ``drop_time`` with
    simple harmonic motion: y = (drop / 2)(1 - cos(2 pi t / T)), so y' peaks at pi drop / T."""
    return math.pi * drop / (drop_time * spacing)


def _drop(given: Given, work: Work) -> float:
    """Omega: the tilt rate of the axle while one wheel drops (Khurmi's defective ballasting)."""
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
        h_, L_ = names("h L")
        return work.step("Omega", Sym("h", h, "m") / Sym("L", L, "m") / Sym("t", t, "s"),
                         unit="rad/s", note=("the axle turns through ", h_ / L_, " (small "
                                             "angle) while the wheel drops"))
    T = given["drop_time"]
    h_, T_d, y, t_ = names("h T_d y t")
    work.text("the wheel falls ", h_, " and rises again in the time ", T_d, " with simple "
              "harmonic motion: ", rel(y, "=", h_ / 2 * (1 - cos_(2 * PI * t_ / T_d))),
              ", whose greatest speed is ", h_ / 2 * (2 * PI / T_d))
    y_dot = work.step("ydot_max", Sym("h", h, "m") / 2 * (2 * PI / Sym("T_d", T, "s")),
                      unit="m/s")
    return work.step("Omega", Sym("ydot_max", y_dot, "m/s") / Sym("L", L, "m"), unit="rad/s",
                     note="greatest tilt rate of the axle")


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
        turn = given.word("turn", "left")
        sign = 1.0 if turn == "left" else -1.0
        work.section("Precession from the path")
        W, v_, R_ = names("Omega v R")
        work.text(f"the frame turns {turn} on a circle: ",
                  rel(W, "=", (signed("+", v_) if sign > 0 else -v_) / R_),
                  " about the upward vertical (a left turn is counter-clockwise from above)")
        v = Sym("v", given["speed"], "m/s")
        return work.step("Omega", (v if sign > 0 else -v) / Sym("R", R, "m"), unit="rad/s")
    M = given["moment"]
    work.section("Precession that the applied moment sustains (moment along n given)")
    W, I0, J0, th, ps, M0 = names("Omega I J theta psidot M")
    work.text(W, ": the precession rate sought; ", I0, ": the transverse moment of inertia "
              "about the centre of mass")
    work.text(rel((J0 - I0) * cos_(th) * sin_(th) * W ** 2 + J0 * ps * sin_(th) * W - M0, "=",
                  0))
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


def _sense(M: float, work: Work) -> None:
    M_, n, K, A, B = names("M n K A B")
    if M == 0:
        work.text(rel(M_, "=", 0), ": no moment is needed")
        return
    work.text("Sense: the moment the bearings exert on the rotor points along ",
              signed("+", n) if M > 0 else -n, ", the line of nodes; it turns the spin axis "
              "about ", n, " so that the ", B if M > 0 else A, " end of the axis is pushed "
              "toward ", -K, " (down). The rotor exerts the equal and opposite moment on its "
              "frame.")


def _bearings(given: Given, find: frozenset[str], M: float, precession: float, theta: float, work: Work) -> None:
    body = given.body
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
    if "supported_mass" not in given and (body.mass is None or "drop" in given):
        wanted = sorted(find & {"bearing_side_forces", "bearing_loads", "axial_thrust"})
        if wanted:
            raise InputError(f"{wanted[0]} needs the mass the bearings carry (mass, weight or "
                             "supported_mass)" + (" and a vertical precession axis" if "drop"
                                                  in given else "") +
                             "; couple_forces needs none", key="given.mass"
                             if "drop" not in given else f"find.{wanted[0]}")
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
    work.section("Bearing forces: free body of the rotor (forces on the rotor)")
    ms = "m_s" if "supported_mass" in given else "m"  # the Given table's symbol
    F_A, F_B, K, k, n, A, B, G = names("F_A F_B K k n A B G")
    work.text(F_A, ", ", F_B, ": forces of the bearings on the rotor, perpendicular to the spin "
              "axis. 'up' components lie in the plane of ", K, " and ", k, ", positive toward ",
              signed("+", K), " (upward); 'side' components lie along ", n, ", positive toward "
              "the precession axis. Labelled ", A, ", ", B, " in that order.")
    work.step("a", value=a, unit="m", note=("from bearing ", A, " to the centre of mass ", G,
                                            " along ", k) +
              ((" (default: midway)",) if "cg_position" not in given else ()))
    m_, g_, L_, a_ = Sym(ms, m, "kg"), Sym("g", g, "m/s^2"), Sym("L", L, "m"), Sym("a", a, "m")
    b_ = Sym("b", work.step("b", L_ - a_, unit="m"), "m")
    Omega, R_, th = _rate("Omega", precession), Sym("R", R, "m"), _theta(theta)
    a_up_, a_k_, R0, W0, m0, g0, th0, a0, b0, M0 = names(f"a_up a_k R Omega {ms} g theta a b M")
    work.text(a_up_, ", ", a_k_, ": the acceleration of ", G, " upward and along ", k, "; ", G,
              " moves on a circle of radius ", R0, " about the precession axis, with the "
              "centripetal acceleration ", W0 ** 2 * R0)
    work.text("up:   ", rel(F_A + F_B, "=", m0 * (g0 * sin_(th0) + a_up_)), ";   ",
              rel(a0 * F_A - b0 * F_B, "=", M0), "   (moments about ", G, " along ", n, ")")
    parts: dict[str, list[Sym]] = {"A": [], "B": []}
    for end, arm in (("A", b_), ("B", a_)):
        parts[end].append(Sym(f"F_{end},weight", work.step(
            f"F_{end},weight", m_ * g_ * sin_(th) * arm / L_, unit="N",
            note="static share of the weight" if end == "A" else ""), "N"))
    if forces.inertial != (0.0, 0.0):
        a_up = Sym("a_up", work.step("a_up", Omega ** 2 * R_ * _cos(theta), unit="m/s^2",
                                     note=("(centre off the axis along ", k, ")")), "m/s^2")
        for end, arm in (("A", b_), ("B", a_)):
            parts[end].append(Sym(f"F_{end},accel", work.step(
                f"F_{end},accel", m_ * a_up * arm / L_, unit="N", substitute=False), "N"))
    M_ = Sym("M", M, "N m")
    for end, couple in (("A", M_ / L_), ("B", -M_ / L_)):
        parts[end].append(Sym(f"F_{end},couple", work.step(
            f"F_{end},couple", couple, unit="N",
            note="gyroscopic couple" if end == "A" else ""), "N"))
    for end, (first, *rest) in parts.items():
        total: Expr = first
        for part in rest:
            total = total + part
        work.step(f"F_{end}", total, unit="N", substitute=False)
    work.text("side: ", rel(F_A + F_B, "=", m0 * W0 ** 2 * R0), " (toward the axis);   ",
              rel(a0 * F_A - b0 * F_B, "=", 0))
    if offset == "across" and R:
        work.step("F_A,side", m_ * Omega ** 2 * R_ * b_ / L_, unit="N",
                  note="centripetal force of the centre of mass")
        work.step("F_B,side", m_ * Omega ** 2 * R_ * a_ / L_, unit="N", substitute=False)
    else:
        work.text(rel(*names("F_A,side"), "=", *names("F_B,side"), "=", 0), ": no side forces "
                  "(the centre of mass is not off the axis across the spin axis)")
    a_k = Sym("a_k", centre_acceleration(precession, theta, R, offset)[0], "m/s^2")
    work.step("T", m_ * (g_ * _cos(theta) + a_k), unit="N", substitute=False,
              note=("axial, along ", k, ", taken by the thrust bearing"))
    if min(forces.up) < 0:
        work.text("a negative 'up' force pulls the rotor down: that bearing must hold the shaft "
                  "against lifting")
    work.answer("bearing_forces", "F", list(forces.up), "force", ["A", "B"])
    work.answer("couple_forces", "F_couple", list(forces.couple), "force", ["A", "B"])
    work.answer("bearing_side_forces", "F_side", list(forces.side), "force", ["A", "B"])
    work.answer("bearing_loads", absolute(names("F")[0]), list(forces.loads), "force",
                ["A", "B"])
    work.answer("axial_thrust", "T", [forces.thrust], "force")
    work.check("up: ", rel(F_A + F_B, "=", q(sum(forces.up), "N")), ", ",
               rel(m0 * g0 * sin_(th0) + m0 * a_up_, "=",
                   q(m * g * sin + sum(forces.inertial), "N")), "; ",
               rel(a0 * F_A - b0 * F_B, "=", q(a * forces.up[0] - b * forces.up[1], "N m")), ", ",
               rel(M0, "=", q(M, "N m")))


def couple_forces(moment: float, spacing: float) -> tuple[float, float]:
    """The gyroscopic couple's share of the bearing (or rail) forces: +M / L at A, -M / L at B,
    a pair of equal and opposite forces L apart whose moment is M."""
    return moment / spacing, -moment / spacing


def _couple_only(given: Given, M: float, L: float, warn: bool, work: Work) -> None:
    """No mass (or a tilting axle): the couple's share of the bearing forces alone."""
    work.section("Forces of the gyroscopic couple on the bearings (rails)")
    K, A, B, M0, L0 = names("K A B M L")
    why_pieces = (("the wheel set tilts about a horizontal axis, so the weight is not along ", K)
                  if "drop" in given else ("no mass is given",))
    work.text(*why_pieces, ": the forces below are the gyroscopic couple's share alone, equal "
              "and opposite at ", A, " and ", B, "; the static load (the weight's share) is added "
              "to them where the weight is known")
    F_A, F_B = couple_forces(M, L)
    M_, L_ = Sym("M", M, "N m"), Sym("L", L, "m")
    work.step("F_A,couple", M_ / L_, unit="N",
              note=("on the rotor at ", A) + ((", toward ", signed("+", K)) if M >= 0 else ()))
    work.step("F_B,couple", -M_ / L_, unit="N")
    work.text("the rotor pushes each bearing (rail) the other way: one is loaded by ",
              absolute(M0) / L0, " more, the other relieved by as much")
    work.answer("couple_forces", "F_couple", [F_A, F_B], "force", ["A", "B"])
    work.answer("bearing_forces", "F", [F_A, F_B], "force", ["A", "B"])
    if warn:
        work.warn(*why_pieces, ": bearing_forces are the gyroscopic couple's share alone, ",
                  rel(signed("+-", M0) / L0, "=", signed("+-", q(abs(F_A), "N"))),
                  ", without the weight's share" +
                  ("" if "drop" in given else " (give mass for the whole force)"))
    F_Ac, F_A0, F_B0 = names("F_A,couple F_A F_B")
    work.check(rel(F_Ac * L0, "=", q(F_A * L, "N m"), "=", M0, "=", q(M, "N m")), "; ",
               rel(F_A0 + F_B0, "=", 0))


def _counterweight(given: Given, M: float, theta: float, work: Work) -> None:
    body = given.body
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
    b_, b0n, db0, m_c, g0, M0 = names("b b0 db m_c g M")
    work.text("At ", rel(b_, "=", b0n), " the arm balances with the rotor at rest. Moving the "
              "block by ", db0, " unbalances the arm by ", m_c * g0 * db0, ", which must equal "
              "the moment ", M0, " the precession needs; the spin may turn either way, so the "
              "block may go out or in.")
    abs_M = Let(Sym("abs_M", abs(M), "N m"), absolute(Sym("M", M, "N m")))
    db = work.step("db", abs_M / (Sym("m_c", mc, "kg") * Sym("g", g, "m/s^2")), unit="m")
    b0_, db_ = Sym("b0", b0, "m"), Sym("db", db, "m")
    positions = [work.step("b", b0_ - db_, unit="m", note="rotor side heavier"),
                 work.step("b", b0_ + db_, unit="m", note="block side heavier")]
    work.text("With the spin vector pointing out along the arm toward the rotor, the rotor-side-"
              "heavier position (", b0n - db0, ") gives precession counter-clockwise seen from "
              "above; the block-side-heavier one (", b0n + db0, ") clockwise (or the same sense "
              "with the spin reversed).")
    if positions[0] < 0:
        work.warn(b0n - db0, " is negative: the block would have to pass the pivot")
    work.answer("counterweight_position", "b", positions, "length",
                ["rotor side heavier", "block side heavier"])
    work.check(rel(m_c * g0 * (b_ - b0n), "=", q(mc * g * db, "N m"), "=", absolute(M0), "=",
                   q(abs(M), "N m")))


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
                   "perpendicular to k in the plane of K and k, upward positive"),
        AnswerSpec("bearing_side_forces", "force", "F_side", "[A, B]: along the line of nodes, "
                   "toward the precession axis positive"),
        AnswerSpec("bearing_loads", "force", "|F|", "[A, B]: magnitudes of the radial bearing "
                   "forces"),
        AnswerSpec("axial_thrust", "force", "T", "force along the spin axis (A to B) on the "
                   "rotor"),
        AnswerSpec("couple_forces", "force", "F_couple", "[A, B]: the gyroscopic couple's "
                   "share of the bearing (rail) forces, +M / L and -M / L; needs no mass"),
        AnswerSpec("counterweight_position", "length", "b", "block positions for the "
                   "precession, ascending (one per spin sense)"),
    ),
    solve=solve,
    extra={"example": {
        "given": {"mass": "2.5 kg", "k_axial": "35 mm", "supported_mass": "10 kg",
                  "spin": "-1725 rpm", "precession": "48 rpm", "bearing_spacing": "200 mm"},
        "find": {"bearing_forces": "N", "moment": "N*m"},
        "vary": {"precession": "[0.8, 1.2]"}}},
)
