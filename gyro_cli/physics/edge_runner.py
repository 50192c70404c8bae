"""The edge-runner (muller) mill: a heavy roller on a horizontal axle hinged to a vertical
shaft, rolling round a pan (SI).

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

The formulas are written once for floats and formula trees (core/generic.py):
the kind calls them with its symbols to write its steps, and with floats for its answers.
"""

from __future__ import annotations

from ..core.generic import V


def roller_spin(shaft_speed: V, path_radius: V, roller_radius: V) -> V:
    """omega = Omega R / r: rolling without slipping."""
    return shaft_speed * path_radius / roller_radius


def couple(J: V, roller_spin: V, shaft_speed: V) -> V:
    """C = J omega Omega (Eq. 11.29): the gyroscopic couple on one roller."""
    return J * roller_spin * shaft_speed


def extra_pressure(couple: V, path_radius: V) -> V:
    """C / R = J Omega^2 / r: the couple's share of the pan's force."""
    return couple / path_radius


def pan_force(weight: V, extra_pressure: V) -> V:
    """N = m g + C / R: the pan's upward force on one roller (and the roller's on the pan)."""
    return weight + extra_pressure
