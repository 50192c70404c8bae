"""The edge-runner (muller) mill: a heavy roller on a horizontal axle hinged to a vertical
shaft, rolling round a pan (plain floats, SI).

Axes at the hinge O, on the shaft's axis: e_r along the axle toward the roller, e_t
horizontal in the sense of the shaft's turning, z up. The shaft turns at Omega about z;
the roller's line of contact is at the path radius R from the shaft's axis, its own
radius is r. Rolling without slipping, the contact point is at rest:

    v_G + omega_total x (-r z) = Omega R e_t + omega_s r e_t = 0   ->   omega_s = -Omega R / r,

so the roller spins at omega = Omega R / r, its spin vector pointing in toward the shaft
(for Omega > 0). About O the axle is an axis of symmetry, so the angular momentum is
H = J omega_s e_r + I_O Omega z, and only its first part turns:

    dH/dt = Omega z x (J omega_s e_r) = -J omega Omega e_t      (Eq. 11.29),   C = J omega Omega.

The moments about O of the forces on the roller are the weight's, m g R e_t, and the
pan's upward force N at the contact point, -N R e_t (the hinge pin gives none about
e_t, and the pan is taken to push only upward: the pin carries the centripetal force).
Equal to dH/dt:

    (m g - N) R = -J omega Omega   ->   N = m g + C / R = m g + J Omega^2 / r.

The couple always adds to the pressure on the pan, whichever way the shaft turns
(Omega^2); that is why the mill is built so. (R.S. Khurmi and J.K. Gupta, *Theory of
Machines*, ch. 14, and the Physics LibreTexts millstone: "the normal force is larger
when the runner stone is rolling around".)
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class EdgeRunner:
    """One roller's motion and forces, SI."""

    roller_spin: float     # omega = Omega R / r
    couple: float          # C = J omega Omega
    extra_pressure: float  # C / R = J Omega^2 / r, the couple's share of the pan's force


def edge_runner(J: float, roller_radius: float, path_radius: float,
                shaft_speed: float) -> EdgeRunner:
    """The roller's spin, the gyroscopic couple and the extra pressure on the pan."""
    omega = abs(shaft_speed) * path_radius / roller_radius
    couple = J * omega * abs(shaft_speed)
    return EdgeRunner(omega, couple, couple / path_radius)


def pan_force(weight: float, extra_pressure: float) -> float:
    """N = m g + C / R: the pan's upward force on one roller (and the roller's on the pan)."""
    return weight + extra_pressure
