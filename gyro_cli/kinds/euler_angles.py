"""A rigid body with one point fixed, described by Euler angles (section 11.1).

Given the three angles and their rates (or the body components of omega, the
inverse), the angular velocity in body axes (Eq. 11.8) and in the fixed frame,
the kinetic energy (Eq. 11.2) and the angular momentum about the fixed point,
from principal moments, from I and J (a symmetric body), from a body as the
other kinds describe one, or from particles (Eq. 11.3, products included). The
formulas are in gyro_cli/physics/euler_kinematics.py.

Sequences: ``zxz`` (the chapter's, default: phi about K, theta about the line of
nodes, psi about the body's k) and ``zyx`` (yaw, pitch, roll as aircraft books
write it).
"""

from __future__ import annotations

import math

from ..core.errors import InputError
from ..core.expr import Expr, Let, Num, SumOf, Sym, absolute, atan2, cos, sin, sqrt
from ..core.given import Given
from ..core.prose import cross, deriv, dot, fn, mat, names, prime, rel, total, tup
from ..core.prose import q as qv
from ..core.spec import AnswerSpec, Kind, Param
from ..core.work import Work, num
from ..physics import euler_kinematics as ek

# sequence -> (first, second, third) angle keys; the first only turns about the fixed axis
ANGLES = {"zxz": ("phi", "theta", "psi"), "zyx": ("yaw", "pitch", "roll")}
SYMBOLS = {"phi": "phi", "theta": "theta", "psi": "psi", "yaw": "yaw", "pitch": "pitch",
           "roll": "roll"}
INERTIA_SLACK = 0.01  # rounded data may break I_max <= I_a + I_b by this much
MAX_LISTED = 12

#: the symbols of the kind's steps, beside its Params: angles are held in rad, shown in deg
ANGLE_SYMBOLS = ("phi", "theta", "psi", "yaw", "pitch", "roll")
HALF = Num(0.5, "1/2")


def _sym(name: str, value: float) -> Sym:
    """The kind's symbol ``name`` (an angle, a rate ``phidot``/``omega_x``/``p``, an inertia
    ``I_x``/``I_xy``, or a moment of momentum ``H_x``) holding ``value`` (SI)."""
    if name in ANGLE_SYMBOLS:
        unit = "deg"
    elif name.startswith("I_"):
        unit = "kg m^2"
    elif name.startswith("H_"):
        unit = "kg m^2/s"
    elif name.startswith("M_"):
        unit = "N m"
    elif name.startswith("alpha_") or name.endswith("ddot"):
        unit = "rad/s^2"
    else:
        unit = "rad/s"
    return Sym(name, value, unit)


def _sin(angle: Sym) -> Expr:
    """sin(angle); at a multiple of 180 deg, where sin of the angle in floating point is
    ~1e-16 and the physics takes it as exactly 0, the substitution shows that 0."""
    exact = ek.sin_exact(angle.si)
    if exact == math.sin(angle.si):
        return sin(angle)
    return Let(Sym(f"sin({angle.name})", exact), sin(angle))


def _cos(angle: Sym) -> Expr:
    """cos(angle); exactly 0 at an odd multiple of 90 deg, as `_sin`."""
    exact = ek.cos_exact(angle.si)
    if exact == math.cos(angle.si):
        return cos(angle)
    return Let(Sym(f"cos({angle.name})", exact), cos(angle))


def _deg(x: float) -> str:
    return f"{num(math.degrees(x))} deg"


# The sentences that hold no values are built once, here: building their trees again on
# every solve was a large part of the kind's time in gyro check.
_x, _y, _z = names("x y z")
_INERTIA_AXES = (_x, ", ", _y, ", ", _z, ": the body axes through the fixed point, about which "
                 "the moments and products of inertia are taken; no angle or rate is needed "
                 "for them")


def _conventions_zxz() -> tuple:
    I, J, K, i, j, k, x, y, z, ph, th, ps, phd, thd, psd = \
        names("I J K i j k x y z phi theta psi phidot thetadot psidot")
    return ("Euler angles z-x-z (Fig. 11-2): rotate the fixed frame {", I, ", ", J, ", ",
            K, "} by ", ph, " about ", K, ", then by ", th, " about the line of nodes ",
            rel(prime(i), "=", prime(i, 2)), ", then by ", ps, " about the body's ", k,
            "; ", i, ", ", j, ", ", k, ": the body axes, along ", x, ", ", y, ", ", z,
            ". The body axes in the fixed frame are the columns of ",
            rel(names("R")[0], "=", fn("Rz", ph) * fn("Rx", th) * fn("Rz", ps)), ". ",
            phd, ", ", thd, ", ", psd, ": the rates of ", ph, ", ", th, ", ", ps, ".")


def _conventions_zyx() -> tuple:
    X, Y, Z, x, y, z, yaw, pitch, roll, p, q_, r, wx, wy, wz, w = names(
        "X Y Z x y z yaw pitch roll p q r omega_x omega_y omega_z omega")
    return ("Euler angles z-y-x (yaw, pitch, roll, as aircraft books write them): rotate "
            "the fixed frame ", X, ", ", Y, ", ", Z, " by the yaw angle about ", Z,
            ", then by the pitch angle about the new ", y, ", then by the roll angle "
            "about the body's ", x, ". ",
            rel(names("R")[0], "=", fn("Rz", yaw) * fn("Ry", pitch) * fn("Rx", roll)),
            "; ", *names("yawdot"), ", ", *names("pitchdot"), ", ", *names("rolldot"),
            ": the rates of the three angles; ", p, ", ", q_, ", ", r, ": the components "
            "of ", w, " along the body's ", x, ", ", y, ", ", z, ", also written ", wx,
            ", ", wy, ", ", wz, ".")


_CONVENTIONS = {"zxz": _conventions_zxz(), "zyx": _conventions_zyx()}
_OMEGA: tuple[str | Expr, ...] = (*names("omega"), ": the body's angular velocity relative to the fixed frame; the "
          "origin is the fixed point, about which the moments of inertia are taken.")
_W_ABS = absolute(names("omega")[0])


def solve(given: Given, find: frozenset[str], work: Work) -> None:
    _drop_empty_body_section(work)
    sequence = given.word("sequence", "zxz")
    first, second, third = ANGLES[sequence]
    other = ANGLES["zyx" if sequence == "zxz" else "zxz"]
    for key in other + tuple(f"{k}_{w}" for k in other for w in ("rate", "acceleration")):
        if key in given:
            raise InputError(f"{key} belongs to `sequence: {'zyx' if sequence == 'zxz' else 'zxz'}`"
                             f"; with sequence {sequence} give {first}, {second}, {third} and "
                             "their rates", key=f"given.{key}")
    wrong = [n for n in find if n.endswith("_rate") and n.split("_")[0] in other]
    if wrong:
        raise InputError(f"{wrong[0]} is a rate of the {'zyx' if sequence == 'zxz' else 'zxz'} "
                         f"sequence; this problem uses {sequence} ({first}_rate, {second}_rate, "
                         f"{third}_rate)", key=f"find.{wrong[0]}")
    if find and find <= INERTIA_ONLY and not any(k in given for k in (second, third)):
        # the inertia tensor needs no angles (Eq. 11.3): answer it alone
        work.section("Conventions")
        work.text(*_INERTIA_AXES)
        if _inertia(given, find, work) is None:
            raise InputError(f"{sorted(find)[0]} needs the body's inertia: give particles, "
                             "I_x, I_y, I_z, or I and J", key="given.particles")
        return
    if (second not in given and third not in given
            and any(k in given for k in BODY_OMEGA_KEYS)
            and not any(f"{k}_{w}" in given for k in (first, second, third)
                        for w in ("rate", "acceleration"))):
        _without_angles(given, find, sequence, work)
        return
    for key in (second, third):
        if key not in given:
            raise InputError(f"Eq. 11.8 needs the angles {second} and {third}"
                             if sequence == "zxz" else
                             f"the body rates need the {second} and {third} angles",
                             key=f"given.{key}")
    a2, a3 = given[second], given[third]
    a1 = given.get(first)

    work.section("Conventions")
    work.text(*_CONVENTIONS[sequence])
    work.text(*_OMEGA)

    omega, rates = _angular_velocity(given, find, sequence, a2, a3, work)
    if a1 is not None:
        R = ek.attitude(sequence, a1, a2, a3)
        fixed = ek.matvec(R, omega)
        _fixed_frame(sequence, R, omega, fixed, rates, a1, a2, a3, work)
        for name, value in zip(("omega_X", "omega_Y", "omega_Z"), fixed):
            work.answer(name, name, [value], "rate")
    else:
        R = None
        asked = sorted(n for n in find if n in FIXED_FRAME_ANSWERS)
        if asked:
            raise InputError(f"{asked[0]} (a fixed-frame component) depends on the first angle: "
                             f"give {first}", key=f"given.{first}")
    wx, wy, wz = (_sym(n, v) for n, v in zip(("omega_x", "omega_y", "omega_z"), omega))
    wabs = _W_ABS
    work.step(wabs, sqrt(wx ** 2 + wy ** 2 + wz ** 2), unit="rad/s", substitute=False)
    for name, value in zip(("omega_x", "omega_y", "omega_z"), omega):
        work.answer(name, name, [value], "rate")
    work.answer("omega", wabs, [ek.norm(omega)], "rate")
    for name, value in zip((first, second, third), rates):
        work.answer(f"{name}_rate", f"{SYMBOLS[name]}dot", [value], "rate")

    alpha = None
    if find & ACCEL_ANSWERS or any(k in given for k in ACCEL_KEYS[sequence] + BODY_ALPHA_KEYS):
        if any(k in given for k in rate_keys_of(sequence)):
            alpha = _euler_acceleration(given, sequence, a1, a2, a3, rates, work)
        else:
            alpha = _given_alpha(given, sequence, work)
        _alpha_answers(alpha, R, work)
    _inertia_answers(given, find, omega, alpha, R, work)


def rate_keys_of(sequence: str) -> tuple[str, ...]:
    return tuple(f"{k}_rate" for k in ANGLES[sequence])


def _inertia_answers(given: Given, find: frozenset[str], omega, alpha, R, work: Work) -> None:
    """The inertia, T and H from omega, and the moment Euler's equations ask for."""
    matrix = _inertia(given, find, work)
    if matrix is None:
        asked = sorted(n for n in find if n in NEEDS_INERTIA)
        if asked:
            raise InputError(f"{asked[0]} needs the body's inertia about the fixed point: give "
                             "I_x, I_y, I_z; or I and J (a symmetric body); or the body (J, "
                             "I_pivot, shape, ...); or particles", key="given.I_x")
        return
    _energy_and_momentum(matrix, omega, R, work)
    if "omega_H_angle" in find and "omega_H_angle" not in work.answers:
        raise InputError("omega_H_angle is undefined here: H = 0 (the body is at rest, or turns "
                         "about a line on which all its mass lies)", key="find.omega_H_angle")
    if alpha is not None:
        _moment(matrix, omega, alpha, R, work)


BODY_OMEGA_KEYS = ("omega_x", "omega_y", "omega_z")
BODY_ALPHA_KEYS = ("alpha_x", "alpha_y", "alpha_z")
ACCEL_KEYS = {seq: tuple(f"{k}_acceleration" for k in keys) for seq, keys in ANGLES.items()}
MOMENT_ANSWERS = frozenset({"M_x", "M_y", "M_z", "M_X", "M_Y", "M_Z", "moment"})
ACCEL_ANSWERS = frozenset({"alpha_x", "alpha_y", "alpha_z", "alpha_X", "alpha_Y", "alpha_Z",
                           "angular_acceleration"}) | MOMENT_ANSWERS
#: what body components of omega (and alpha) answer with no Euler angle at all
ANGLE_FREE = frozenset({"omega_x", "omega_y", "omega_z", "omega", "kinetic_energy", "H_x", "H_y",
                        "H_z", "angular_momentum", "omega_H_angle", "alpha_x", "alpha_y",
                        "alpha_z", "angular_acceleration", "M_x", "M_y", "M_z", "moment"})


def _body_only_words() -> tuple:
    x, y, z, w, T, H, M = names("x y z omega T H M")
    return (x, ", ", y, ", ", z, ": the body axes through the fixed point (or the centre of "
            "mass); ", w, ": the body's angular velocity, given by its components along them. "
            "The kinetic energy, the angular momentum and the moment are taken in these axes "
            "and need no Euler angle.")


_BODY_ONLY = _body_only_words()


def _taken_as_zero(missing: list[str], work: Work) -> None:
    """The body components not given (symbols, so written as maths)."""
    if missing:
        pieces: list = ["not given, taken as zero: "]
        for n, key in enumerate(missing):
            pieces += [", "] * bool(n) + [names(key)[0]]
        work.text(*pieces)


def _without_angles(given: Given, find: frozenset[str], sequence: str, work: Work) -> None:
    """T, H, alpha and M from the body components of omega (and alpha) alone: no angle is
    needed for what is taken in body axes."""
    first, second, third = ANGLES[sequence]
    needing = sorted(find - ANGLE_FREE - INERTIA_ONLY)
    if needing:
        raise InputError(f"{needing[0]} needs the angles {second} and {third} (with omega_x, "
                         "omega_y, omega_z alone only body-axis answers are found: T, H, alpha, "
                         "M)", key=f"given.{second}")
    work.section("Conventions")
    work.text(*_BODY_ONLY)
    work.section("Angular velocity in body axes (given)")
    _taken_as_zero([k for k in BODY_OMEGA_KEYS if k not in given], work)
    omega = tuple(given.get(k, 0.0) for k in BODY_OMEGA_KEYS)
    wx, wy, wz = (_sym(n, v) for n, v in zip(BODY_OMEGA_KEYS, omega))
    work.step(_W_ABS, sqrt(wx ** 2 + wy ** 2 + wz ** 2), unit="rad/s", substitute=False)
    for name, value in zip(BODY_OMEGA_KEYS, omega):
        work.answer(name, name, [value], "rate")
    work.answer("omega", _W_ABS, [ek.norm(omega)], "rate")
    alpha = None
    if find & ACCEL_ANSWERS or any(k in given for k in BODY_ALPHA_KEYS):
        alpha = _given_alpha(given, sequence, work)
        _alpha_answers(alpha, None, work)
    _inertia_answers(given, find, omega, alpha, None, work)


INERTIA_ONLY = frozenset({"I_x", "I_y", "I_z", "I_xy", "I_yz", "I_zx", "principal_moments"})
FIXED_FRAME_ANSWERS = {"omega_X", "omega_Y", "omega_Z", "H_X", "H_Y", "H_Z", "alpha_X",
                       "alpha_Y", "alpha_Z", "M_X", "M_Y", "M_Z"}
NEEDS_INERTIA = {"kinetic_energy", "H_x", "H_y", "H_z", "H_X", "H_Y", "H_Z", "angular_momentum",
                 "omega_H_angle", "I_x", "I_y", "I_z", "I_xy", "I_yz", "I_zx",
                 "principal_moments", "M_x", "M_y", "M_z", "M_X", "M_Y", "M_Z", "moment"}


def _drop_empty_body_section(work: Work) -> None:
    """The body section is written only where the body's inertias are worked out."""
    work.sections[:] = [s for s in work.sections if s.steps or s.title != "Body"]


def _eq_11_5() -> tuple:
    w, phd, thd, psd, K, i, j, k, ps, th = names("omega phidot thetadot psidot K i j k psi theta")
    i2, j2 = prime(i, 2), prime(j, 2)
    return (rel(w, "=", phd * K + thd * i2 + psd * k), "  (Eq. 11.5), with ",
            rel(i2, "=", cos(ps) * i - sin(ps) * j), ", ",
            rel(K, "=", cos(th) * k + sin(th) * j2), " (Eq. 11.6)")


def _yaw_pitch_roll() -> tuple:
    w, yd, pd, rd, Z, y, x = names("omega yawdot pitchdot rolldot Z y x")
    return (rel(w, "=", yd * Z + pd * prime(y) + rd * x), " (each rate about its own axis)")


_RATES_LINE = {"zxz": _eq_11_5(), "zyx": _yaw_pitch_roll()}
#: the names of each sequence's three rates, and the words of the inverse's check
_DOTS = {sequence: names(" ".join(f"{SYMBOLS[k]}dot" for k in keys))
         for sequence, keys in ANGLES.items()}
_GIVES_BACK = "the inverse of Eq. 11.8 gives back the rates: "
_p, _q, _r = names("p q r")
_RATES_TITLE: dict[str, tuple[str | Expr, ...]] = {"zxz": ("Euler rates from ", *names("omega"), " (Eq. 11.8 solved for the rates)"),
                "zyx": ("Euler rates from ", _p, ", ", _q, ", ", _r, " (yaw, pitch, roll)")}
_PUT_BACK = ("the rates put back into Eq. 11.8 give ",)
_OMEGA0 = names("omega")[0]


def _angular_velocity(given: Given, find: frozenset[str], sequence: str, a2: float, a3: float,
                      work: Work) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """omega in body axes and the three Euler rates, forward (rates given) or inverse."""
    first, second, third = ANGLES[sequence]
    rate_keys = [f"{k}_rate" for k in (first, second, third)]
    omega_keys = ["omega_x", "omega_y", "omega_z"]
    have_rates = [k for k in rate_keys if k in given]
    have_omega = [k for k in omega_keys if k in given]
    if have_rates and have_omega:
        raise InputError(f"give the Euler rates or the body components of omega, not both "
                         f"({have_rates[0]} and {have_omega[0]})", key=f"given.{have_omega[0]}")
    if not have_rates and not have_omega:
        raise InputError(f"give the Euler rates ({', '.join(rate_keys)}) or, for the inverse, "
                         f"omega_x, omega_y, omega_z", key=f"given.{rate_keys[0]}")
    if have_rates:
        missing = [k for k in rate_keys if k not in given]
        r1, r2, r3 = (given.get(k, 0.0) for k in rate_keys)
        work.section("Angular velocity in body axes (Eqs. 11.5-11.8)" if sequence == "zxz"
                     else "Angular velocity in body axes (yaw, pitch, roll)")
        if missing:
            work.text(f"not given, taken as zero: {', '.join(missing)}")
        work.text(*_RATES_LINE[sequence])
        if sequence == "zxz":
            omega = ek.body_rates_zxz(a2, a3, r1, r2, r3)
            th, ps = _sym("theta", a2), _sym("psi", a3)
            p1, p2, p3 = _sym("phidot", r1), _sym("thetadot", r2), _sym("psidot", r3)
            work.step("omega_x", p1 * _sin(th) * _sin(ps) + p2 * _cos(ps), unit="rad/s",
                      ref="Eq. 11.8")
            work.step("omega_y", p1 * _sin(th) * _cos(ps) - p2 * _sin(ps), unit="rad/s",
                      ref="Eq. 11.8")
            work.step("omega_z", p1 * _cos(th) + p3, unit="rad/s", ref="Eq. 11.8")
        else:
            omega = ek.body_rates_zyx(a2, a3, r1, r2, r3)
            pi_, ro = _sym("pitch", a2), _sym("roll", a3)
            y1, y2, y3 = _sym("yawdot", r1), _sym("pitchdot", r2), _sym("rolldot", r3)
            work.step("p", y3 - y1 * _sin(pi_), unit="rad/s")
            work.step("q", y2 * _cos(ro) + y1 * _cos(pi_) * _sin(ro), unit="rad/s")
            work.step("r", -y2 * _sin(ro) + y1 * _cos(pi_) * _cos(ro), unit="rad/s")
        back = _inverse(sequence, a2, a3, omega, raise_singular=False)
        if back is not None:
            dots = _DOTS[sequence]
            pieces: list = [_GIVES_BACK]
            for n, (sym, v) in enumerate(zip(dots, back)):
                pieces += [", "] * bool(n) + [rel(sym, "=", qv(v, "rad/s"))]
            work.check(*pieces)
        return omega, (r1, r2, r3)

    missing = [k for k in omega_keys if k not in given]
    given_x, given_y, given_z = (given.get(k, 0.0) for k in omega_keys)
    omega = (given_x, given_y, given_z)
    rates = _inverse(sequence, a2, a3, omega, raise_singular=True)
    work.section(*_RATES_TITLE[sequence])
    if missing:
        work.text(f"not given, taken as zero: {', '.join(missing)}")
    if sequence == "zxz":
        th, ps = _sym("theta", a2), _sym("psi", a3)
        wx, wy, wz = (_sym(n, v) for n, v in zip(omega_keys, omega))
        work.step("thetadot", wx * _cos(ps) - wy * _sin(ps), unit="rad/s")
        work.step("phidot", (wx * _sin(ps) + wy * _cos(ps)) / _sin(th), unit="rad/s")
        work.step("psidot", wz - _sym("phidot", rates[0]) * _cos(th), unit="rad/s")
    else:
        pi_, ro = _sym("pitch", a2), _sym("roll", a3)
        p, q, r = (_sym(n, v) for n, v in zip("pqr", omega))
        work.step("yawdot", (q * _sin(ro) + r * _cos(ro)) / _cos(pi_), unit="rad/s")
        work.step("pitchdot", q * _cos(ro) - r * _sin(ro), unit="rad/s")
        work.step("rolldot", p + _sym("yawdot", rates[0]) * _sin(pi_), unit="rad/s")
    near = abs(ek.sin_exact(a2)) if sequence == "zxz" else abs(ek.cos_exact(a2))
    if near < math.sin(math.radians(1)):
        work.warn(*names(SYMBOLS[second]), " is within ", qv(math.radians(1), "deg", exact=True),
                  f" of the singular attitude: the rates {first}_rate and {third}_rate are "
                  "large and sensitive to rounding in the data")
    check = (ek.body_rates_zxz(a2, a3, *rates) if sequence == "zxz"
             else ek.body_rates_zyx(a2, a3, *rates))
    work.check(*_PUT_BACK, rel(_OMEGA0, "=", tup(*(qv(v, "rad/s") for v in check))))
    return omega, rates


def _inverse(sequence: str, a2: float, a3: float, omega, raise_singular: bool):
    try:
        if sequence == "zxz":
            return ek.euler_rates_zxz(a2, a3, *omega)
        return ek.euler_rates_zyx(a2, a3, *omega)
    except ek.SingularAngles:
        if not raise_singular:
            return None
    first, second, third = ANGLES[sequence]
    if sequence == "zxz":
        msg = (f"theta = {_deg(a2)}: at theta = 0 or 180 deg the Euler angles are singular (phi "
               "and psi turn about the same axis, so omega fixes only phidot +- psidot); the "
               "rates phi_rate and psi_rate are not determined")
    else:
        msg = (f"pitch = {_deg(a2)}: at pitch = +-90 deg the Euler angles are singular (gimbal "
               "lock: yaw and roll turn about the same axis); yaw_rate and roll_rate are not "
               "determined")
    raise InputError(msg, key=f"given.{second}")


def _fixed_frame_words() -> tuple[tuple, tuple, tuple]:
    w_XYZ, R_, w_xyz = names("omega_XYZ R omega_xyz")
    title = ("Angular velocity in the fixed frame: ", rel(w_XYZ, "=", R_ * w_xyz), ", with ",
             w_xyz, " the body components")
    w, phd, thd, psd, I0, J0, K0, k0, ph0, th0 = names(
        "omega phidot thetadot psidot I J K k phi theta")
    equivalently = ("equivalently ", rel(w, "=", phd * K0 + thd * (cos(ph0) * I0 + sin(ph0) * J0)
                                         + psd * k0), ", ",
                    rel(k0, "=", sin(th0) * sin(ph0) * I0 - sin(th0) * cos(ph0) * J0
                        + cos(th0) * K0), ":")
    yaw, pitch, roll = names("yaw pitch roll")
    attitude = (names("R")[0], "=", fn("Rz", yaw) * fn("Ry", pitch) * fn("Rx", roll), "=")
    return title, equivalently, attitude


_FIXED_TITLE, _EQUIVALENTLY, _ATTITUDE = _fixed_frame_words()


def _fixed_frame(sequence: str, R, omega, fixed, rates, a1: float, a2: float, a3: float,
                 work: Work) -> None:
    work.section(*_FIXED_TITLE)
    if sequence == "zxz":
        p1, p2, p3 = (_sym(n, v) for n, v in zip(("phidot", "thetadot", "psidot"), rates))
        ph, th = _sym("phi", a1), _sym("theta", a2)
        work.text(*_EQUIVALENTLY)
        work.step("omega_X", p2 * _cos(ph) + p3 * _sin(th) * _sin(ph), unit="rad/s")
        work.step("omega_Y", p2 * _sin(ph) - p3 * _sin(th) * _cos(ph), unit="rad/s")
        work.step("omega_Z", p1 + p3 * _cos(th), unit="rad/s")
    else:
        work.text(rel(*_ATTITUDE, mat(*((qv(v) for v in row) for row in R))))
        for name, value in zip(("omega_X", "omega_Y", "omega_Z"), fixed):
            work.step(name, value=value, unit="rad/s")


# ---- angular acceleration and the moment (Euler's equations) ------------------

def _accel_words() -> tuple:
    a, w, M, H, I_ = names("alpha omega M H I")
    same = (rel(a, "=", deriv(w)), ": the same vector whether the derivative is taken in the "
            "fixed frame or in the body (", rel(cross(w, w), "=", 0), "), so its body components are the "
            "time derivatives of Eq. 11.8's")
    euler = (rel(M, "=", deriv(H), "=", I_ * a + cross(w, I_ * w)),
             " in body axes, in which ", I_, " is constant: Euler's equations (about the fixed "
             "point, or the centre of mass)")
    return same, euler


_ALPHA_SAME, _EULER = _accel_words()
_PQR_DOT = tuple((sym,) for sym in names("pdot qdot rdot"))
_WITH_PRODUCTS = (names("I")[0] * names("alpha")[0]
                  + cross(names("omega")[0], names("I")[0] * names("omega")[0]),
                  ", with the products of inertia")
_A_ABS, _M_ABS = absolute(names("alpha")[0]), absolute(names("M")[0])


def _euler_acceleration(given: Given, sequence: str, a1: float | None, a2: float, a3: float,
                        rates, work: Work) -> tuple[float, float, float]:
    """alpha in body axes from the Euler angles' rates and accelerations."""
    first, second, third = ANGLES[sequence]
    keys = ACCEL_KEYS[sequence]
    if any(k in given for k in BODY_ALPHA_KEYS):
        key = next(k for k in BODY_ALPHA_KEYS if k in given)
        raise InputError(f"{key} goes with omega_x, omega_y, omega_z; with the Euler rates give "
                         f"the Euler accelerations {', '.join(keys)}", key=f"given.{key}")
    accels = tuple(given.get(k, 0.0) for k in keys)
    work.section("Angular acceleration in body axes (Eq. 11.8 differentiated)")
    missing = [k for k in keys if k not in given]
    if missing:
        work.text(f"not given, taken as zero: {', '.join(missing)}")
    work.text(*_ALPHA_SAME)
    if sequence == "zxz":
        alpha = ek.body_accel_zxz(a2, a3, rates, accels)
        th, ps = _sym("theta", a2), _sym("psi", a3)
        p1, p2, p3 = (_sym(n, v) for n, v in zip(("phidot", "thetadot", "psidot"), rates))
        d1, d2, d3 = (_sym(n, v) for n, v in zip(("phiddot", "thetaddot", "psiddot"), accels))
        st, ct, sp, cp = _sin(th), _cos(th), _sin(ps), _cos(ps)
        work.step("alpha_x", d1 * st * sp + p1 * p2 * ct * sp + p1 * p3 * st * cp + d2 * cp
                  - p2 * p3 * sp, unit="rad/s^2")
        work.step("alpha_y", d1 * st * cp + p1 * p2 * ct * cp - p1 * p3 * st * sp - d2 * sp
                  - p2 * p3 * cp, unit="rad/s^2")
        work.step("alpha_z", d1 * ct - p1 * p2 * st + d3, unit="rad/s^2")
    else:
        alpha = ek.body_accel_zyx(a2, a3, rates, accels)
        pi_, ro = _sym("pitch", a2), _sym("roll", a3)
        y1, y2, y3 = (_sym(n, v) for n, v in zip(("yawdot", "pitchdot", "rolldot"), rates))
        d1, d2, d3 = (_sym(n, v) for n, v in zip(("yawddot", "pitchddot", "rollddot"), accels))
        sq, cq, sr, cr = _sin(pi_), _cos(pi_), _sin(ro), _cos(ro)
        work.step("alpha_x", d3 - d1 * sq - y1 * y2 * cq, unit="rad/s^2", note=_PQR_DOT[0])
        work.step("alpha_y", d2 * cr - y2 * y3 * sr + d1 * cq * sr - y1 * y2 * sq * sr
                  + y1 * y3 * cq * cr, unit="rad/s^2", note=_PQR_DOT[1])
        work.step("alpha_z", -d2 * sr - y2 * y3 * cr + d1 * cq * cr - y1 * y2 * sq * cr
                  - y1 * y3 * cq * sr, unit="rad/s^2", note=_PQR_DOT[2])
    if sequence == "zxz" and a1 is not None:
        ph = _sym("phi", a1)
        p1, p2, p3 = (_sym(n, v) for n, v in zip(("phidot", "thetadot", "psidot"), rates))
        d1, d2, d3 = (_sym(n, v) for n, v in zip(("phiddot", "thetaddot", "psiddot"), accels))
        th = _sym("theta", a2)
        st, ct, sf, cf = _sin(th), _cos(th), _sin(ph), _cos(ph)
        work.section("Angular acceleration in the fixed frame (the fixed components of ",
                     _OMEGA0, " differentiated)")
        work.step("alpha_X", d2 * cf - p2 * p1 * sf + d3 * st * sf + p3 * p2 * ct * sf
                  + p3 * p1 * st * cf, unit="rad/s^2")
        work.step("alpha_Y", d2 * sf + p2 * p1 * cf - d3 * st * cf - p3 * p2 * ct * cf
                  + p3 * p1 * st * sf, unit="rad/s^2")
        work.step("alpha_Z", d1 + d3 * ct - p3 * p2 * st, unit="rad/s^2")
    return alpha


def _given_alpha(given: Given, sequence: str, work: Work) -> tuple[float, float, float]:
    """alpha from its body components as given (missing ones zero)."""
    wrong = [k for k in ACCEL_KEYS[sequence] if k in given]
    if wrong:
        raise InputError(f"{wrong[0]} goes with the Euler rates; with omega_x, omega_y, omega_z "
                         "give alpha_x, alpha_y, alpha_z", key=f"given.{wrong[0]}")
    work.section("Angular acceleration in body axes (given)")
    _taken_as_zero([k for k in BODY_ALPHA_KEYS if k not in given], work)
    return tuple(given.get(k, 0.0) for k in BODY_ALPHA_KEYS)  # type: ignore[return-value]


def _alpha_answers(alpha, R, work: Work) -> None:
    ax, ay, az = (_sym(n, v) for n, v in zip(BODY_ALPHA_KEYS, alpha))
    work.step(_A_ABS, sqrt(ax ** 2 + ay ** 2 + az ** 2), unit="rad/s^2", substitute=False)
    for name, value in zip(BODY_ALPHA_KEYS, alpha):
        work.answer(name, name, [value], "angular_acceleration")
    work.answer("angular_acceleration", _A_ABS, [ek.norm(alpha)], "angular_acceleration")
    if R is not None:
        fixed = ek.matvec(R, alpha)
        stated = {step.symbol for section in work.sections for step in section.steps}
        for name, value in zip(("alpha_X", "alpha_Y", "alpha_Z"), fixed):
            if name not in stated:
                work.step(name, value=value, unit="rad/s^2", note=("fixed-frame component of ",
                                                                   names("R")[0] * names("alpha")[0]))
            work.answer(name, name, [value], "angular_acceleration")
        work.check(*names("R"), " times the body components ",
                   tup(*names("alpha_x alpha_y alpha_z")), ": ",
                   tup(*(qv(v, "rad/s^2") for v in fixed)))


def _moment(matrix, omega, alpha, R, work: Work) -> None:
    """M = I alpha + omega x (I omega) in body axes (Euler's equations), and in the fixed
    frame R M."""
    M = ek.euler_moment(matrix, omega, alpha)
    work.section("Moment the motion needs: Euler's equations")
    work.text(*_EULER)
    w = [_sym(f"omega_{n}", v) for n, v in zip("xyz", omega)]
    a = [_sym(f"alpha_{n}", v) for n, v in zip("xyz", alpha)]
    if ek.is_diagonal(matrix):
        I_ = [_sym(f"I_{n}", matrix[k][k]) for k, n in enumerate("xyz")]
        for k, n in enumerate("xyz"):
            i, j = (k + 1) % 3, (k + 2) % 3
            work.step(f"M_{n}", I_[k] * a[k] - (I_[i] - I_[j]) * w[i] * w[j], unit="N m",
                      ref="Euler's equations")
    else:
        for n, value in zip("xyz", M):
            work.step(f"M_{n}", value=value, unit="N m", note=_WITH_PRODUCTS)
    Ms = [_sym(f"M_{n}", v) for n, v in zip("xyz", M)]
    work.step(_M_ABS, sqrt(Ms[0] ** 2 + Ms[1] ** 2 + Ms[2] ** 2), unit="N m", substitute=False)
    for n, value in zip("xyz", M):
        work.answer(f"M_{n}", f"M_{n}", [value], "moment")
    work.answer("moment", _M_ABS, [ek.norm(M)], "moment")
    w0, a0, M0, I0 = names("omega alpha M I")
    work.check(rel(dot(M0, w0), "=", dot(w0, I0 * a0), "=", deriv(names("T")[0])),
               " (the gyroscopic part does no work): ",
               rel(qv(ek.dot(M, omega), "W"), "=", qv(ek.dot(omega, ek.matvec(matrix, alpha)),
                                                      "W")))
    if R is not None:
        fixed = ek.matvec(R, M)
        for name, value in zip(("M_X", "M_Y", "M_Z"), fixed):
            work.step(name, value=value, unit="N m", note=("fixed-frame component of ",
                                                           names("R")[0] * names("M")[0]))
            work.answer(name, name, [value], "moment")


# ---- inertia ----------------------------------------------------------------

PRINCIPAL_KEYS = ("I_x", "I_y", "I_z")
PRODUCT_KEYS = ("I_xy", "I_yz", "I_zx")
BODY_INERTIA_KEYS = ("J", "k_axial", "I_pivot", "k_pivot", "I_cg", "k_cg", "shape")


def _inertia(given: Given, find: frozenset[str], work: Work):
    """The inertia matrix about the fixed point in body axes, or None if none is given."""
    ways = []
    if "particles" in given:
        ways.append("particles")
    if any(k in given for k in PRINCIPAL_KEYS + PRODUCT_KEYS):
        ways.append("I_x")
    if "I" in given:
        ways.append("I")
    body_keys = [k for k in BODY_INERTIA_KEYS if k in given]
    if body_keys and "I" not in ways:
        ways.append(body_keys[0])
    if len(ways) > 1:
        raise InputError(f"give the inertia one way: {ways[0]} and {ways[1]} are both given",
                         key=f"given.{ways[1]}")
    if not ways:
        return None
    way = ways[0]
    work.section("Inertia about the fixed point, body axes (Eq. 11.3)")
    if way == "particles":
        return _from_particles(given.values["particles"], work)
    if way == "I_x":
        values = []
        for key in PRINCIPAL_KEYS:
            if key not in given:
                raise InputError(f"give all three moments I_x, I_y, I_z (or I and J for a "
                                 f"symmetric body); {key} is missing", key=f"given.{key}")
            values.append(given[key])
        products = [given.get(k, 0.0) for k in PRODUCT_KEYS]
        matrix = ek.inertia_matrix(*values, *products)
        work.text(*_AS_GIVEN[any(products)])
        moments = _check_rigid(matrix, "given.I_z" if not any(products) else "given.I_xy")
        _report_matrix(matrix, products, work, moments=moments)
        return matrix
    body = given.solid_body
    J = body.J
    if way == "I":
        I = given["I"]
        if J is None:
            raise InputError("I (transverse) goes with J (axial) for a symmetric body",
                             key="given.J")
    else:
        if J is None:
            raise InputError("the body needs its axial inertia: J, k_axial or a shape",
                             key="given.J")
        if body.I_pivot is not None:
            I = body.I_pivot
        elif body.I_cg is not None:
            I = body.I_cg
            work.text(*_AT_THE_CENTRE)
        else:
            raise InputError("the body needs its transverse inertia about the fixed point: "
                             "I_pivot, k_pivot, I_cg or k_cg (with cg_distance), or a shape",
                             key="given.I_pivot")
    work.text(*_SYMMETRIC)
    matrix = ek.inertia_matrix(I, I, J)
    moments = _check_rigid(matrix, "given.J")
    _report_matrix(matrix, [0.0, 0.0, 0.0], work, moments=moments)
    return matrix


def _inertia_words() -> tuple[dict[bool, tuple], tuple, tuple]:
    Ix, Iy, Iz, Ixy, Iyz, Izx, I0, J0 = names("I_x I_y I_z I_xy I_yz I_zx I J")
    as_given = {products: (Ix, ", ", Iy, ", ", Iz, " as given",
                           *((", with the products ", Ixy, ", ", Iyz, ", ", Izx) if products
                             else (" (principal axes)",)))
                for products in (True, False)}
    centre = ("no cg_distance: the fixed point is taken at the centre of mass, ",
              rel(*names("I"), "=", *names("I_G")))
    symmetric = ("symmetric body (Eq. 11.9): ", rel(Ix, "=", Iy, "=", I0), ", ", rel(Iz, "=", J0))
    return as_given, centre, symmetric


_AS_GIVEN, _AT_THE_CENTRE, _SYMMETRIC = _inertia_words()


def _check_rigid(matrix, key: str) -> list[float]:
    """The principal moments of a body's inertia matrix; InputError if no rigid body has
    them (not positive definite, or the largest above the sum of the other two)."""
    moments = ek.principal_moments(matrix)
    if moments[0] <= 0:
        raise InputError(f"the inertia matrix is not positive definite (principal moments "
                         f"{', '.join(num(m) for m in moments)} kg m^2): no body has it", key=key)
    if moments[2] > (moments[0] + moments[1]) * (1 + INERTIA_SLACK):
        raise InputError(f"the largest principal moment {num(moments[2])} kg m^2 exceeds the sum "
                         f"of the other two, {num(moments[0] + moments[1])} kg m^2: no rigid "
                         "body has these inertias (I_z = sum m (x^2 + y^2) <= I_x + I_y)",
                         key=key)
    return moments


#: each moment and product of inertia as a term of its sum over the particles (Eq. 11.3)
_SUMS = {"I_x": lambda m, x, y, z: m * (y ** 2 + z ** 2),
         "I_y": lambda m, x, y, z: m * (z ** 2 + x ** 2),
         "I_z": lambda m, x, y, z: m * (x ** 2 + y ** 2),
         "I_xy": lambda m, x, y, z: m * x * y, "I_yz": lambda m, x, y, z: m * y * z,
         "I_zx": lambda m, x, y, z: m * z * x}


def _particle_words() -> tuple[tuple, tuple[tuple, ...], Sym, dict[str, Expr]]:
    m, x, y, z = names("m x y z")
    intro = ("particles of mass ", m, " at the coordinates ", x, ", ", y, ", ", z, " in body "
             "axes from the fixed point; the products of inertia as the chapter defines them "
             "(the matrix has their negatives off the diagonal):")
    products = tuple((rel(*names(name), "=", total(m * a * b)),)
                     for name, (a, b) in zip(PRODUCT_KEYS, ((x, y), (y, z), (z, x))))
    # the formula of each sum as the chapter writes it, in symbols of their own
    m, x, y, z = names("m x y z")
    return intro, products, m, {name: term(m, x, y, z) for name, term in _SUMS.items()}


_PARTICLES, _PRODUCTS, _M, _SUM_FORMULAS = _particle_words()


def _from_particles(particles, work: Work):
    work.text(*_PARTICLES)
    for line in _PRODUCTS:
        work.text(*line)
    for i, (mi, xi, yi, zi) in enumerate(particles[:MAX_LISTED]):
        work.text(f"  [{i}] ", rel(_M, "=", qv(mi, "kg")), " at ",
                  tup(qv(xi, "m"), qv(yi, "m"), qv(zi, "m")))
    if len(particles) > MAX_LISTED:
        work.text(f"  ... {len(particles) - MAX_LISTED} more")
    Ix, Iy, Iz, Ixy, Iyz, Izx = ek.inertia_from_particles(particles)
    # each particle's m, x, y, z as symbols named with its index: the sums evaluate term by
    # term (the JSON expr lists them), the formula is written as the chapter writes it
    parts = [(Sym(f"m_{i}", p[0], "kg"), Sym(f"x_{i}", p[1], "m"), Sym(f"y_{i}", p[2], "m"),
              Sym(f"z_{i}", p[3], "m")) for i, p in enumerate(particles)]
    for name, term in _SUMS.items():  # the float values stay physics' (ek.inertia_from_particles)
        work.step(name, SumOf(_SUM_FORMULAS[name], tuple(term(*p) for p in parts)),
                  unit="kg*m^2", ref="Eq. 11.3" if len(name) == 3 else "", substitute=False)
    matrix = ek.inertia_matrix(Ix, Iy, Iz, Ixy, Iyz, Izx)
    _report_matrix(matrix, [Ixy, Iyz, Izx], work, listed=True)
    return matrix


def _matrix_words() -> tuple[tuple, tuple, tuple, Expr]:
    Ixy, Iyz, Izx, x, y, z, T, H = names("I_xy I_yz I_zx x y z T H")
    principal = ("the products of inertia are zero, ", rel(Ixy, "=", Iyz, "=", Izx, "=", 0),
                 ": ", x, ", ", y, ", ", z, " are principal axes")
    not_principal = ("the products of inertia are not zero: ", x, ", ", y, ", ", z, " are NOT "
                     "principal axes, and ", T, " and ", H, " below use the whole inertia "
                     "matrix, not Eq. 11.2's diagonal form")
    warning = ("the body axes are not principal axes (products of inertia not zero); ", T,
               " and ", H, " use the whole inertia matrix")
    return principal, not_principal, warning, tup(*names("I_1 I_2 I_3"))


_PRINCIPAL, _NOT_PRINCIPAL, _NOT_PRINCIPAL_WARNING, _MOMENTS = _matrix_words()


def _report_matrix(matrix, products, work: Work, listed: bool = False,
                   moments: list[float] | None = None) -> None:
    """The inertia matrix's steps and answers; ``moments``: its principal moments where they
    are known already (_check_rigid), so that its eigenvalues are not worked out again."""
    Ix, Iy, Iz = matrix[0][0], matrix[1][1], matrix[2][2]
    if not listed:
        for name, value in zip(PRINCIPAL_KEYS, (Ix, Iy, Iz)):
            work.step(name, value=value, unit="kg*m^2")
    if moments is None:
        moments = ek.principal_moments(matrix)
    if ek.is_diagonal(matrix):
        work.text(*_PRINCIPAL)
    else:
        work.text(*_NOT_PRINCIPAL)
        work.warn(*_NOT_PRINCIPAL_WARNING)
    for k, value in enumerate(moments):  # not a formula: the matrix's eigenvalues
        work.step(f"I_{k + 1}", value=value, unit="kg*m^2",
                  note="" if k else "the principal moments: the eigenvalues of the inertia "
                  "matrix, ascending")
    for name, value in zip(PRINCIPAL_KEYS, (Ix, Iy, Iz)):
        work.answer(name, name, [value], "inertia")
    for name, value in zip(PRODUCT_KEYS, products):
        work.answer(name, name, [value], "inertia")
    work.answer("principal_moments", _MOMENTS, moments, "inertia")


def _momentum_words() -> tuple[Expr, tuple, tuple, Expr, tuple, tuple]:
    w0, H0 = names("omega H")
    half_dot = (names("T")[0], "=", HALF * dot(*names("omega H")), "=")
    fixed_note = ("fixed-frame component of ", names("R")[0] * names("H")[0])
    angle = fn("angle", w0, H0)
    angle_note = ("zero only when ", w0, " lies along a principal axis")
    at_rest = (rel(w0, "=", 0), ": the body is at rest, ", rel(H0, "=", 0), " and the angle "
               "between them is undefined")
    return absolute(names("H")[0]), half_dot, fixed_note, angle, angle_note, at_rest


_H_ABS, _HALF_DOT, _FIXED_NOTE, _ANGLE, _ANGLE_NOTE, _AT_REST = _momentum_words()


def _energy_and_momentum(matrix, omega, R, work: Work) -> None:
    T = ek.kinetic_energy(matrix, omega)
    H = ek.angular_momentum(matrix, omega)
    work.section("Kinetic energy (Eq. 11.2) and angular momentum about the fixed point")
    w = {n: _sym(f"omega_{n}", v) for n, v in zip("xyz", omega)}
    I_ = {n: _sym(f"I_{n}", matrix[k][k]) for k, n in enumerate("xyz")}
    if ek.is_diagonal(matrix):
        work.step("T", HALF * (I_["x"] * w["x"] ** 2 + I_["y"] * w["y"] ** 2
                               + I_["z"] * w["z"] ** 2), unit="J", ref="Eq. 11.2")
        for n in "xyz":
            work.step(f"H_{n}", I_[n] * w[n], unit="kg m^2/s")
    else:
        Ixy, Iyz, Izx = (_sym(n, v) for n, v in zip(PRODUCT_KEYS, (
            -matrix[0][1], -matrix[1][2], -matrix[0][2])))
        work.step("T", HALF * (I_["x"] * w["x"] ** 2 + I_["y"] * w["y"] ** 2
                               + I_["z"] * w["z"] ** 2 - 2 * Iyz * w["y"] * w["z"]
                               - 2 * Izx * w["z"] * w["x"] - 2 * Ixy * w["x"] * w["y"]),
                  unit="J", ref="Eq. 11.2, first line, with the products")
        work.step("H_x", I_["x"] * w["x"] - Ixy * w["y"] - Izx * w["z"], unit="kg m^2/s",
                  substitute=False)
        work.step("H_y", -Ixy * w["x"] + I_["y"] * w["y"] - Iyz * w["z"], unit="kg m^2/s",
                  substitute=False)
        work.step("H_z", -Izx * w["x"] - Iyz * w["y"] + I_["z"] * w["z"], unit="kg m^2/s",
                  substitute=False)
    Hmag = ek.norm(H)
    Hx, Hy, Hz = (_sym(n, v) for n, v in zip(("H_x", "H_y", "H_z"), H))
    Habs = _H_ABS
    work.step(Habs, sqrt(Hx ** 2 + Hy ** 2 + Hz ** 2), unit="kg m^2/s", substitute=False)
    work.check(rel(*_HALF_DOT, qv(0.5 * ek.dot(omega, H), "J")))
    work.answer("kinetic_energy", "T", [T], "energy")
    for name, value in zip(("H_x", "H_y", "H_z"), H):
        work.answer(name, name, [value], "angular_momentum")
    work.answer("angular_momentum", Habs, [Hmag], "angular_momentum")
    if R is not None:
        fixed = ek.matvec(R, H)
        for name, value in zip(("H_X", "H_Y", "H_Z"), fixed):
            work.step(name, value=value, unit="kg m^2/s", note=_FIXED_NOTE)
            work.answer(name, name, [value], "angular_momentum")
        work.check("in the fixed frame ", rel(Habs, "=", qv(ek.norm(fixed), "kg m^2/s")))
    if Hmag > 0:
        angle = ek.angle_between(omega, H)
        # atan2(|omega x H|, omega . H), the cross and dot products by their components
        cross_ = sqrt((w["y"] * Hz - w["z"] * Hy) ** 2 + (w["z"] * Hx - w["x"] * Hz) ** 2
                      + (w["x"] * Hy - w["y"] * Hx) ** 2)
        work.step(_ANGLE, atan2(cross_, w["x"] * Hx + w["y"] * Hy + w["z"] * Hz),
                  unit="deg", substitute=False, note=_ANGLE_NOTE)
        work.answer("omega_H_angle", _ANGLE, [angle], "angle")
    else:
        work.text(*_AT_REST)


def _vector(name: str, dimension: str, body_x: str, fixed_x: str,
            body: tuple[str, str] = ("along j", "along k"),
            fixed: tuple[str, str] = ("along J", "along K")) -> tuple[AnswerSpec, ...]:
    """The six answers of a vector: its body components ``name_x``, ``_y``, ``_z`` and its
    fixed-frame ``name_X``, ``_Y``, ``_Z``, each documented by the first's words then the
    others' (``body``, ``fixed``)."""
    docs = (body_x, *body, fixed_x, *fixed)
    return tuple(AnswerSpec(f"{name}_{axis}", dimension, f"{name}_{axis}", doc)
                 for axis, doc in zip("xyzXYZ", docs, strict=True))


KIND = Kind(
    name="euler_angles",
    summary="rigid body with one point fixed: omega from Euler angles and rates (and back), "
            "kinetic energy and angular momentum, inertia from particles",
    chapter="section 11.1, Eqs. 11.1-11.8 (z-x-z, Fig. 11-2); z-y-x yaw-pitch-roll also",
    params=(
        Param("sequence", "word", "sequence", "zxz (default: the chapter's phi, theta, psi) or "
              "zyx (yaw, pitch, roll)", choices=("zxz", "zyx")),
        Param("phi", "angle", "phi", "zxz: first rotation, about the fixed K (needed only for "
              "fixed-frame answers)"),
        Param("theta", "angle", "theta", "zxz: second rotation, about the line of nodes"),
        Param("psi", "angle", "psi", "zxz: third rotation, about the body's k"),
        Param("phi_rate", "rate", "phidot", "zxz: precession rate (absent: 0 if other rates are "
              "given)"),
        Param("theta_rate", "rate", "thetadot", "zxz: nutation rate"),
        Param("psi_rate", "rate", "psidot", "zxz: spin rate relative to the precessing frame"),
        Param("yaw", "angle", "yaw", "zyx: first rotation, about the fixed Z (needed only for "
              "fixed-frame answers)"),
        Param("pitch", "angle", "pitch", "zyx: second rotation, about the new y"),
        Param("roll", "angle", "roll", "zyx: third rotation, about the body's x"),
        Param("yaw_rate", "rate", "yawdot", "zyx: yaw rate"),
        Param("pitch_rate", "rate", "pitchdot", "zyx: pitch rate"),
        Param("roll_rate", "rate", "rolldot", "zyx: roll rate"),
        Param("omega_x", "rate", "omega_x", "inverse: body component of omega along x (p)"),
        Param("omega_y", "rate", "omega_y", "inverse: along y (q)"),
        Param("omega_z", "rate", "omega_z", "inverse: along z (r)"),
        Param("phi_acceleration", "angular_acceleration", "phiddot", "zxz: rate of change of "
              "phi_rate (absent: 0)"),
        Param("theta_acceleration", "angular_acceleration", "thetaddot", "zxz: of theta_rate"),
        Param("psi_acceleration", "angular_acceleration", "psiddot", "zxz: of psi_rate"),
        Param("yaw_acceleration", "angular_acceleration", "yawddot", "zyx: of yaw_rate"),
        Param("pitch_acceleration", "angular_acceleration", "pitchddot", "zyx: of pitch_rate"),
        Param("roll_acceleration", "angular_acceleration", "rollddot", "zyx: of roll_rate"),
        Param("alpha_x", "angular_acceleration", "alpha_x", "with omega_x, omega_y, omega_z: "
              "body component of the angular acceleration along x (absent: 0)"),
        Param("alpha_y", "angular_acceleration", "alpha_y", "along y"),
        Param("alpha_z", "angular_acceleration", "alpha_z", "along z"),
        Param("I_x", "inertia", "I_x", "moment of inertia about body x through the fixed point",
              positive=True),
        Param("I_y", "inertia", "I_y", "about body y", positive=True),
        Param("I_z", "inertia", "I_z", "about body z", positive=True),
        Param("I_xy", "inertia", "I_xy", "product of inertia sum m x y (default 0)"),
        Param("I_yz", "inertia", "I_yz", "product of inertia sum m y z (default 0)"),
        Param("I_zx", "inertia", "I_zx", "product of inertia sum m z x (default 0)"),
        Param("I", "inertia", "I", "symmetric body: I_x = I_y = I about the fixed point (with J)",
              positive=True),
        Param("particles", "particles", "particles", "list of {mass, x, y, z}: point masses at "
              "positions in body axes from the fixed point"),
    ),
    answers=(
        *_vector("omega", "rate", "body component of omega along i (Eq. 11.8)",
                 "fixed-frame component along I"),
        AnswerSpec("omega", "rate", "|omega|", "magnitude of the angular velocity"),
        AnswerSpec("kinetic_energy", "energy", "T", "kinetic energy (Eq. 11.2; with products "
                   "(1/2) omega . I omega)"),
        *_vector("H", "angular_momentum", "angular momentum about the fixed point, body x",
                 "fixed frame, along I", body=("body y", "body z")),
        AnswerSpec("angular_momentum", "angular_momentum", "|H|", "magnitude of H"),
        AnswerSpec("omega_H_angle", "angle", "angle(omega, H)", "angle between omega and H "
                   "(zero only about a principal axis)"),
        *_vector("alpha", "angular_acceleration", "angular acceleration, body component "
                 "along i (Eq. 11.8 differentiated)", "fixed-frame component along I"),
        AnswerSpec("angular_acceleration", "angular_acceleration", "|alpha|", "magnitude of "
                   "the angular acceleration"),
        *_vector("M", "moment", "moment the motion needs, M = dH/dt = I alpha + omega x "
                 "(I omega) (Euler's equations), body x", "fixed frame, along I",
                 body=("body y", "body z")),
        AnswerSpec("moment", "moment", "|M|", "magnitude of the moment"),
        AnswerSpec("I_x", "inertia", "I_x", "moment of inertia about body x (Eq. 11.3)"),
        AnswerSpec("I_y", "inertia", "I_y", "about body y"),
        AnswerSpec("I_z", "inertia", "I_z", "about body z"),
        AnswerSpec("I_xy", "inertia", "I_xy", "product of inertia sum m x y"),
        AnswerSpec("I_yz", "inertia", "I_yz", "product of inertia sum m y z"),
        AnswerSpec("I_zx", "inertia", "I_zx", "product of inertia sum m z x"),
        AnswerSpec("principal_moments", "inertia", "I_1, I_2, I_3", "eigenvalues of the "
                   "inertia matrix, ascending"),
        AnswerSpec("phi_rate", "rate", "phidot", "zxz: precession rate (inverse, or as given)"),
        AnswerSpec("theta_rate", "rate", "thetadot", "zxz: nutation rate"),
        AnswerSpec("psi_rate", "rate", "psidot", "zxz: spin rate"),
        AnswerSpec("yaw_rate", "rate", "yawdot", "zyx: yaw rate"),
        AnswerSpec("pitch_rate", "rate", "pitchdot", "zyx: pitch rate"),
        AnswerSpec("roll_rate", "rate", "rolldot", "zyx: roll rate"),
    ),
    solve=solve,
    gravity=False, example={
        "statement": ("A symmetric body with one point fixed has a moment of inertia of {I} about "
                      "each transverse axis and {J} about its symmetry axis, both through the "
                      "fixed point. At an instant when its Euler angles are phi = {phi}, theta = "
                      "{theta} and psi = {psi}, their rates are {phi_rate}, {theta_rate} and "
                      "{psi_rate}, and the precession rate is increasing at {phi_acceleration}. "
                      "Find the components of the angular velocity along the body axes, the "
                      "kinetic energy, the magnitude of the angular momentum, the angular "
                      "acceleration and the moment about the fixed point that this motion "
                      "needs."),
        "given": {"phi": "30 deg", "theta": "60 deg", "psi": "45 deg", "phi_rate": "2 rad/s",
                  "theta_rate": "1 rad/s", "psi_rate": "10 rad/s",
                  "phi_acceleration": "0.5 rad/s^2", "I": "0.02 kg m^2", "J": "0.03 kg m^2"},
        "find": {"omega_x": "rad/s", "omega_y": "rad/s", "omega_z": "rad/s",
                 "kinetic_energy": "J", "angular_momentum": "kg*m^2/s",
                 "angular_acceleration": "rad/s^2", "moment": "N*m"},
        "vary": {"theta": "[20 deg, 80 deg]"}},
)
