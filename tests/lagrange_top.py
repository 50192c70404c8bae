"""An independent reference for the heavy top: Lagrange's equations 11.13 integrated
numerically in (theta, phi, psi), second order, without the momentum integrals.

    I thetaddot = I phidot^2 sin th cos th - J omega_z phidot sin th + m g l sin th
    d/dt [I phidot sin^2 th + J omega_z cos th] = 0   ->  phiddot = theta_dot sin th (J omega_z
                                                           - 2 I phidot cos th) / (I sin^2 th)
    d/dt [J omega_z] = 0, omega_z = psidot + phidot cos th  ->  psiddot = -phiddot cos th
                                                                  + phidot thetadot sin th

Turning points of theta are located as events (thetadot = 0) on the dense output.
Nothing here comes from gyro_cli.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

RTOL, ATOL = 1e-12, 1e-13


def rhs(I: float, J: float, mgl: float):
    def f(_, y):
        th, _phi, _psi, thd, phd, psd = y
        s, c = math.sin(th), math.cos(th)
        wz = psd + phd * c
        thdd = (I * phd * phd * s * c - J * wz * phd * s + mgl * s) / I
        phdd = thd * s * (J * wz - 2 * I * phd * c) / (I * s * s)
        psdd = -phdd * c + phd * thd * s
        return [thd, phd, psd, thdd, phdd, psdd]
    return f


@dataclass
class Measured:
    theta_min: float
    theta_max: float
    nutation_period: float
    mean_precession: float
    t_max: np.ndarray       # times of theta maxima
    phi_max: np.ndarray     # phi there
    sol: object


def integrate(I, J, mgl, theta0, spin, precession0=0.0, theta_rate0=0.0, t_end=1.0,
              t_eval=None) -> Measured:
    """Integrate from the initial state; theta extrema from thetadot = 0 events."""
    def turn(_, y):
        return y[3]

    sol = solve_ivp(rhs(I, J, mgl), (0.0, t_end), [theta0, 0.0, 0.0, theta_rate0,
                                                   precession0, spin],
                    method="DOP853", rtol=RTOL, atol=ATOL, t_eval=t_eval, events=turn,
                    dense_output=True)
    assert sol.success, sol.message
    t_ev, y_ev = sol.t_events[0], sol.y_events[0]
    keep = t_ev > 1e-9 * t_end                       # the start itself is no turning point
    t_ev, y_ev = t_ev[keep], y_ev[keep]
    # a maximum of theta: thetaddot < 0 there
    acc = np.array([rhs(I, J, mgl)(t, y)[3] for t, y in zip(t_ev, y_ev)])
    is_max = acc < 0
    t_max, t_min = t_ev[is_max], t_ev[~is_max]
    theta_max = float(np.max(y_ev[is_max, 0])) if is_max.any() else math.nan
    theta_min = float(np.min(y_ev[~is_max, 0])) if (~is_max).any() else math.nan
    period = math.nan
    if len(t_max) >= 2:
        period = (t_max[-1] - t_max[0]) / (len(t_max) - 1)
    elif len(t_min) >= 2:
        period = (t_min[-1] - t_min[0]) / (len(t_min) - 1)
    phi_max = y_ev[is_max, 1]
    mean = (phi_max[-1] - phi_max[0]) / (t_max[-1] - t_max[0]) if len(t_max) >= 2 else math.nan
    return Measured(theta_min, theta_max, period, mean, t_max, phi_max, sol)
