"""The gimballed gyroscope as an inertial reference: drift and nutation.

Chapter 11, section 11.3 (Fig. 11-13): a rotor of axial inertia J spins at
psidot in gimbals; H = J psidot. A small moment M about a gimbal axis x at
right angles to the spin (bearing friction, drag, imbalance) does not turn the
rotor about x but makes the spin axis precess about the other gimbal axis y,
at the rate M / H (Eq. 11.29 read backwards: Q_theta = J phidot psidot). With
a and b the small rotations of the spin axis about x and y, and I_x, I_y the
inertias of rotor and gimbals about those axes, the linearised gimbal
equations are

    I_x a'' + H b' = M,     I_y b'' - H a' = 0.

From rest (a = b = a' = b' = 0 at t = 0, M switched on then) they give, with
the nutation frequency w_n = H / sqrt(I_x I_y):

    b(t) = (M / H) t - (M / (H w_n)) sin(w_n t)           drift plus a ripple
    a(t) = (M I_y / H^2) (1 - cos(w_n t))                  a bounded deflection

(check by substitution: I_y b'' = (M I_y w_n / H) sin(w_n t) = H a', and
I_x a'' + H b' = (M I_x I_y w_n^2 / H^2) cos(w_n t) + M (1 - cos(w_n t)) = M,
since I_x I_y w_n^2 = H^2; all four initial values are zero). So the spin axis
drifts at M / H about y while it nutates on an ellipse of semi-axes
M I_y / H^2 (about x, the moment's axis) and M sqrt(I_x I_y) / H^2 (about y);
for equal inertias both are M I / H^2, the cone of the fast top. A linear
(small-angle) analysis: the deflections must stay small.

The formulas are written once for floats and formula trees (core/generic.py): the kind
calls them with its symbols to write its steps.
"""

from __future__ import annotations

from ..core.generic import V, sqrt


def drift_rate(moment: V, H: V) -> V:
    """Precession (drift) of the spin axis under a moment at right angles: M / H."""
    return moment / H


def nutation_frequency(H: V, Ix: V, Iy: V) -> V:
    """w_n = H / sqrt(I_x I_y), rad/s."""
    return H / sqrt(Ix * Iy)
