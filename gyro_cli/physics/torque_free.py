"""Torque-free motion of an axisymmetric rigid body, on plain floats.

J is the moment of inertia about the symmetry axis k, I the transverse one,
both about the centre of mass. With no moment about the centre of mass, H is
fixed in space; take the inertial axis Z along H and the z-x-z Euler angles of
the chapter (phi about Z, theta from Z to k, psi about k, Eqs. 11.5-11.8), so
omega = phidot Z + thetadot n + psidot k and omega_z = psidot + phidot cos(theta).

Components of H along k and along e (perpendicular to k in the plane of Z and
k): H cos(theta) = J omega_z and H sin(theta) = I omega_e with
omega_e = phidot sin(theta) (thetadot = 0). From these, for 0 < theta < 90 deg:

    phidot = H / I                                   (precession of k about H)
    tan(theta) = (I / J) tan(beta),  tan(beta) = omega_e / omega_z
    psidot = omega_z - phidot cos(theta) = (I - J) / I * omega_z      (spin)
    H^2 = J^2 omega_z^2 + I^2 omega_e^2

Given H itself (Hibbeler's football, "H_G = ... kg m^2/s"), it stands for I phidot:
with an angle omega_z = H cos(theta) / J; with omega_z, cos(theta) = J omega_z / H; with
omega, sin^2(beta) = (H^2 - J^2 omega^2) / ((I^2 - J^2) omega^2). H and phidot together fix
no angle.

(Meriam & Kraige, Dynamics, Art. 7/9; Hibbeler, Dynamics, Sec. 21.6;
Beer & Johnston, Vector Mechanics, Sec. 18.10; Goldstein, Classical
Mechanics, Sec. 5.6.) Euler's equations with no moment,
I omega_x' = (I - J) omega_y omega_z, I omega_y' = (J - I) omega_z omega_x,
J omega_z' = 0, turn omega about k in the body at the rate -psidot, so the
body sees omega (and H) go round once in 2 pi / |psidot|: for the Earth,
with (C - A) / A = 0.00328, Euler's period of about 305 days.

omega lies in the plane of H and k, at beta from k (the body cone, semi-angle
beta) and at |theta - beta| from H (the space cone). With I > J (prolate:
a football, a long capsule) theta > beta, psidot and phidot have the same
sense and the body cone rolls on the outside of the space cone: direct
precession. With J > I (oblate: a disk, the Earth) beta > theta, psidot is
negative and the body cone rolls with the space cone inside it: retrograde.

Energy and its dissipation (Curtis, Orbital Mechanics for Engineering Students,
Sec. 10.5; Kaplan, Modern Spacecraft Dynamics and Control, the major-axis rule):
T = (1/2) (J omega_z^2 + I omega_e^2) and, with H^2 = J^2 omega_z^2 + I^2 omega_e^2,
2 T I_min <= H^2 <= 2 T I_max. Flexing parts or fuel sloshing turn kinetic energy into
heat while no external moment acts, so H is kept and T falls to its least value for that
H, T_f = H^2 / (2 I_max): the body ends turning about its axis of largest moment at
omega_f = H / I_max. T - T_f = (1/2) I omega_e^2 (J - I) / J for an oblate body (J > I),
which ends spinning about k, and (1/2) J omega_z^2 (I - J) / I for a prolate one, which
ends in a flat spin about a transverse axis. So a spin about the symmetry axis is stable
under dissipation only for J > I (Explorer 1, a prolate spinner, went into a flat spin).

Sign conventions: H is along +Z and k is taken on the side of H
(H . k > 0), so omega_z, phidot, H, theta and beta are positive, with
theta and beta below 90 deg; psidot carries the sign of I - J.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

# What may be given: two of these.
MOTION_KEYS = ("omega", "omega_angle", "nutation_angle", "axial_rate", "precession", "spin",
               "angular_momentum")
ANGLE_KEYS = ("omega_angle", "nutation_angle")


class TorqueFreeError(ValueError):
    """Data that fix no torque-free motion; ``key`` names the datum at fault."""

    def __init__(self, message: str, key: str) -> None:
        super().__init__(message)
        self.message = message
        self.key = key


@dataclass(frozen=True)
class FreeMotion:
    """The steady torque-free motion, SI: fixed by J, I, omega_z > 0 and 0 <= beta < 90 deg
    (beta = 0: a spin about the axis with no wobble, whose precession and spin are limits
    with no motion behind them).

    Every other quantity is worked out from these four when first asked for and kept (a
    worked answer asks for each several times; precession alone was H, so tan and hypot,
    again on every reading)."""

    J: float
    I: float
    axial_rate: float   # omega_z, along k
    omega_angle: float  # beta, from k to omega

    @cached_property
    def nutation_angle(self) -> float:
        """theta from tan(theta) = (I / J) tan(beta), as atan2 (no overflow near 90 deg)."""
        return math.atan2(self.I * math.sin(self.omega_angle), self.J * math.cos(self.omega_angle))

    @cached_property
    def transverse_rate(self) -> float:
        """omega_e = omega_z tan(beta), the part of omega across the axis."""
        return self.axial_rate * math.tan(self.omega_angle)

    @cached_property
    def omega(self) -> float:
        return math.hypot(self.axial_rate, self.transverse_rate)

    @cached_property
    def angular_momentum(self) -> float:
        """H = sqrt((J omega_z)^2 + (I omega_e)^2)."""
        return math.hypot(self.J * self.axial_rate, self.I * self.transverse_rate)

    @cached_property
    def precession(self) -> float:
        """phidot = H / I."""
        return self.angular_momentum / self.I

    @cached_property
    def spin(self) -> float:
        """psidot = (I - J) / I omega_z: positive for I > J, negative for J > I."""
        return (self.I - self.J) / self.I * self.axial_rate

    @cached_property
    def precession_period(self) -> float:
        return 2 * math.pi / self.precession

    @cached_property
    def body_wobble_period(self) -> float:
        """2 pi / |psidot|: the period of omega (and H) going round k, seen in the body."""
        return 2 * math.pi / abs(self.spin)

    @cached_property
    def body_cone_angle(self) -> float:
        return self.omega_angle

    @cached_property
    def space_cone_angle(self) -> float:
        return abs(self.nutation_angle - self.omega_angle)

    @cached_property
    def motion(self) -> str:
        return "direct" if self.I > self.J else "retrograde"

    @cached_property
    def kinetic_energy(self) -> float:
        """T = (1/2) (J omega_z^2 + I omega_e^2), Eq. 11.2 on the principal axes."""
        return 0.5 * (self.J * self.axial_rate ** 2 + self.I * self.transverse_rate ** 2)

    @cached_property
    def major_moment(self) -> float:
        """The largest principal moment: J (oblate) or I (prolate)."""
        return max(self.J, self.I)

    @cached_property
    def final_rate(self) -> float:
        """omega_f = H / I_max: the rate once dissipation has brought omega to the major axis."""
        return self.angular_momentum / self.major_moment

    @cached_property
    def final_kinetic_energy(self) -> float:
        """T_f = H^2 / (2 I_max), the least energy a body with this H can have."""
        return self.angular_momentum * self.final_rate / 2

    @cached_property
    def energy_lost(self) -> float:
        """T - T_f, written without the cancellation of T - H^2 / (2 I_max):
        (1/2) I omega_e^2 (J - I) / J for J > I, (1/2) J omega_z^2 (I - J) / I for I > J."""
        if self.J > self.I:
            return 0.5 * self.I * self.transverse_rate ** 2 * (self.J - self.I) / self.J
        return 0.5 * self.J * self.axial_rate ** 2 * (self.I - self.J) / self.I

    @cached_property
    def spin_stability(self) -> str:
        """The major-axis rule: a spin about the symmetry axis survives energy dissipation
        only if that axis has the largest moment (J > I)."""
        return "stable" if self.J > self.I else "unstable"


def omega_angle_from_nutation(J: float, I: float, theta: float) -> float:
    """beta from tan(beta) = (J / I) tan(theta)."""
    return math.atan2(J * math.sin(theta), I * math.cos(theta))


def axial_rate_from_spin(J: float, I: float, spin: float) -> float:
    """omega_z = I psidot / (I - J); TorqueFreeError if psidot has the wrong sign."""
    if spin == 0:
        raise TorqueFreeError("spin must not be zero: with J != I the body always spins "
                              "relative to its precessing frame, psidot = (I - J) / I omega_z",
                              "spin")
    axial = I * spin / (I - J)
    if axial <= 0:
        shape, sign = (("prolate (I > J)", "positive") if I > J else
                       ("oblate (J > I)", "negative"))
        raise TorqueFreeError(f"spin must be {sign} for this {shape} body: psidot = (I - J) / I "
                              "omega_z, with k taken on the side of H so that omega_z > 0 "
                              f"({'direct' if I > J else 'retrograde'} precession)", "spin")
    return axial


def solve_motion(J: float, I: float, known: dict[str, float]) -> FreeMotion:
    """The motion from exactly two of MOTION_KEYS (SI values); TorqueFreeError otherwise.

    Every pair but three fixes one motion (no second root, since k is taken on
    the side of H): omega_angle with nutation_angle, axial_rate with spin, and
    angular_momentum with precession are tied to each other by the inertias and
    fix no rate or no angle.
    """
    if J <= 0 or I <= 0:
        raise TorqueFreeError("J and I must be positive", "J" if J <= 0 else "I_cg")
    if math.isclose(J, I, rel_tol=1e-9):
        raise TorqueFreeError("J = I: every axis through the centre of mass is principal, "
                              "omega stays along H and there is no precession or wobble to find",
                              "J")
    keys = [k for k in MOTION_KEYS if k in known]
    if len(keys) != 2:
        extra = keys[2] if len(keys) > 2 else "omega"
        raise TorqueFreeError(f"give exactly two of {', '.join(MOTION_KEYS)} (got "
                              f"{', '.join(keys) or 'none'})", extra)
    for key in keys:
        value = known[key]
        if key in ANGLE_KEYS:
            if not 0 <= value < math.pi / 2:
                raise TorqueFreeError(
                    f"{key} must lie from 0 up to (not at) 90 deg, got "
                    f"{math.degrees(value):.6g} deg: at 90 deg the body turns about a "
                    "transverse axis and does not wobble; above 90 deg take the axis k the "
                    "other way (180 deg minus the angle)", key)
        elif key != "spin" and not value > 0:
            raise TorqueFreeError(f"{key} must be positive (H is taken along +Z and k on the "
                                  f"side of H), got {value:.6g} (SI)", key)
    pair = set(keys)
    steady = [k for k in keys if k in ANGLE_KEYS and known[k] == 0]
    if steady and pair & {"spin", "precession"}:
        other = next(iter(pair & {"spin", "precession"}))
        raise TorqueFreeError(f"{steady[0]} = 0: the body spins steadily about its axis and "
                              f"nothing precesses, so {other} is not defined; give the rate as "
                              "axial_rate or omega (equal here), or angular_momentum", other)
    if pair == set(ANGLE_KEYS):
        raise TorqueFreeError("omega_angle and nutation_angle are tied by tan(theta) = (I / J) "
                              "tan(beta) and fix no rate: give one of them with a rate",
                              "nutation_angle")
    if pair == {"angular_momentum", "precession"}:
        raise TorqueFreeError("angular_momentum and precession are tied by phidot = H / I and "
                              "fix no angle: give one of them with an angle or another rate",
                              "precession")
    if pair == {"axial_rate", "spin"}:
        raise TorqueFreeError("axial_rate and spin are tied by psidot = (I - J) / I omega_z and "
                              "fix no angle: give one of them with an angle or another rate",
                              "spin")

    # The angle beta, where an angle is given.
    beta = None
    if "omega_angle" in known:
        beta = known["omega_angle"]
    elif "nutation_angle" in known:
        beta = omega_angle_from_nutation(J, I, known["nutation_angle"])

    # The axial rate, where a rate fixes it alone.
    axial = None
    if "axial_rate" in known:
        axial = known["axial_rate"]
    elif "spin" in known:
        axial = axial_rate_from_spin(J, I, known["spin"])

    if beta is not None:
        if axial is None:
            if "omega" in known:
                axial = known["omega"] * math.cos(beta)
            else:  # H (given, or I phidot): omega_z = H cos(theta) / J
                theta = math.atan2(I * math.sin(beta), J * math.cos(beta))
                axial = _momentum(I, known) * math.cos(theta) / J
        return FreeMotion(J, I, axial, beta)

    # No angle: two rates.
    if "omega" in known and axial is not None:
        omega = known["omega"]
        if not axial < omega:
            by = "axial_rate" if "axial_rate" in known else "spin"
            raise TorqueFreeError(f"omega = {omega:.6g} rad/s must exceed the axial rate "
                                  f"omega_z = {axial:.6g} rad/s (from {by}): omega_z is one "
                                  "component of omega, equal only without wobble (a spin "
                                  "with no wobble: give omega_angle: 0 deg)", "omega")
        return FreeMotion(J, I, axial, math.acos(axial / omega))
    by = "angular_momentum" if "angular_momentum" in known else "precession"
    H = _momentum(I, known)
    if "omega" in known:  # with H: H^2 = J^2 omega^2 + (I^2 - J^2) omega^2 sin^2(beta)
        omega = known["omega"]
        s2 = (H * H - (J * omega) ** 2) / ((I * I - J * J) * omega * omega)
        if not 0 < s2 < 1:
            if by == "precession":
                lo, hi = sorted((J * omega / I, omega))
                raise TorqueFreeError(f"precession must lie strictly between J omega / I and "
                                      f"omega ({lo:.6g} and {hi:.6g} rad/s) for omega = "
                                      f"{omega:.6g} rad/s, got {known['precession']:.6g} rad/s",
                                      "precession")
            lo, hi = sorted((J * omega, I * omega))
            raise TorqueFreeError(f"angular_momentum must lie strictly between J omega and "
                                  f"I omega ({lo:.6g} and {hi:.6g} kg m^2/s) for omega = "
                                  f"{omega:.6g} rad/s, got {H:.6g} kg m^2/s: H^2 = (J omega_z)^2 "
                                  "+ (I omega_e)^2 with omega_z^2 + omega_e^2 = omega^2",
                                  "angular_momentum")
        beta = math.asin(math.sqrt(s2))
        return FreeMotion(J, I, omega * math.cos(beta), beta)
    # axial rate (given or from spin) with H: cos(theta) = J omega_z / H
    assert axial is not None, "two rates without omega or an axial rate were refused above"
    cos_theta = J * axial / H
    if not cos_theta < 1:
        if by == "precession":
            raise TorqueFreeError(f"precession must exceed J omega_z / I = {J * axial / I:.6g} "
                                  f"rad/s (got {known['precession']:.6g} rad/s): phidot = H / I "
                                  "and H >= J omega_z, equal only without wobble", "precession")
        source = "axial_rate" if "axial_rate" in known else "spin"
        raise TorqueFreeError(f"angular_momentum must exceed J omega_z = {J * axial:.6g} kg m^2/s "
                              f"(omega_z from {source}), got {H:.6g} kg m^2/s: H cos(theta) = "
                              "J omega_z, equal only without wobble", "angular_momentum")
    theta = math.acos(cos_theta)
    return FreeMotion(J, I, axial, omega_angle_from_nutation(J, I, theta))


def _momentum(I: float, known: dict[str, float]) -> float:
    """H about the centre of mass: given, or I phidot from the precession (phidot = H / I)."""
    if "angular_momentum" in known:
        return known["angular_momentum"]
    return I * known["precession"]
