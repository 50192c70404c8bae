"""A disk rolling without slipping on a horizontal plane: the full Newton-Euler equations.

Used to animate a free rolling disk from the integration itself (a steady state
slightly disturbed: stable rolling wobbles, unstable rolling falls). The
state is the disk's unit normal k, a unit vector e fixed in the disk's plane
(the spin's stripe), the angular velocity w (fixed axes) and the centre's
horizontal position (x, y). With K the upward vertical, the centre G lies at
r u above the contact point P, u = (K - (K.k) k) / |K - (K.k) k| (the lowest
point of the rim touches the plane). Then

    k' = w x k,  e' = w x e,  v_G = w x (r u)                    (rolling: v_P = 0)
    F = m a_G + m g K                                            (Newton, the contact force)
    dH_G/dt = (P - G) x F,  H_G = I_G w + (J - I_G)(w.k) k       (Euler about G; Eq. 11.29
                                                                  for the symmetric disk)

and with a_G = w' x r u + w x r u', the moment equation is linear in w':

    [I_G 1 + (J - I_G) k k^T + m r^2 (1 - u u^T)] w'
        = -(J - I_G)[(w.k') k + (w.k) k'] - m r^2 u x (w x u') - m g r u x K,

with u' = -(c' k + c k') / s + u c c' / s^2, c = k.K, s = sqrt(1 - c^2). The mass
divides out of every rate (J, I_G and m r^2 all scale with it). Energy
T + V = m v_G^2 / 2 + w.H_G / 2 + m g r s is conserved (the contact force does no work).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .euler_kinematics import cross

K_UP = np.array([0.0, 0.0, 1.0])
EYE = np.eye(3)
FLAT = math.radians(80.0)   # tilt beyond which the disk has fallen (rim nearly on the plane)


@dataclass(frozen=True)
class Disk:
    """Per unit mass: radius r, J / m and I_G / m (SI), and g."""

    r: float
    j: float
    i: float
    g: float


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """a x b of two 3-vectors, worked on floats by euler_kinematics.cross: np.cross's own
    products in its order (the same bits), where np.cross of one pair costs about twenty
    times as much, 25 us: most of an integration's time."""
    return np.array(cross(a.tolist(), b.tolist()))


def _contact_vector(k: np.ndarray) -> tuple[np.ndarray, float, float]:
    c = float(k[2])
    s = math.sqrt(max(1.0 - c * c, 1e-300))
    return (K_UP - c * k) / s, c, s


def angular_acceleration(d: Disk, k: np.ndarray, w: np.ndarray) -> np.ndarray:
    """w' from the moment equation about G (module docstring), per unit mass."""
    u, c, s = _contact_vector(k)
    kd = _cross(w, k)
    cd = float(kd[2])
    ud = -(cd * k + c * kd) / s + u * (c * cd / (s * s))
    r2 = d.r * d.r
    A = d.i * EYE + (d.j - d.i) * np.outer(k, k) + r2 * (EYE - np.outer(u, u))
    b = (-(d.j - d.i) * (float(w @ kd) * k + float(w @ k) * kd)
         - r2 * _cross(u, _cross(w, ud)) - d.g * d.r * _cross(u, K_UP))
    return np.linalg.solve(A, b)


def rhs(d: Disk):
    """The right-hand side for y = (k, e, w, x_G, y_G)."""
    def f(t: float, y: np.ndarray) -> np.ndarray:
        k, e, w = y[0:3], y[3:6], y[6:9]
        u, _, _ = _contact_vector(k)
        vG = _cross(w, d.r * u)
        return np.concatenate([_cross(w, k), _cross(w, e),
                               angular_acceleration(d, k, w), vG[:2]])
    return f


def energy(d: Disk, y: np.ndarray) -> float:
    """T + V per unit mass (conserved)."""
    k, w = y[0:3], y[6:9]
    u, _, s = _contact_vector(k)
    vG = _cross(w, d.r * u)
    H = d.i * w + (d.j - d.i) * float(w @ k) * k
    return 0.5 * float(vG @ vG) + 0.5 * float(w @ H) + d.g * d.r * float(u[2])


def steady_start(d: Disk, tilt: float, centre_radius: float, precession: float,
                 kick: float = 0.0) -> np.ndarray:
    """The steady rolling of the kind's answer at t = 0, its tilt rate kicked by ``kick`` rad/s.

    G on a circle of radius rho about the origin, at (rho, 0) moving along +y for
    Omega > 0; the disk leans toward the centre by beta, its normal k = (cos b, 0,
    sin b) outward and up; w = Omega K + psidot k with psidot = -Omega (rho + r sin b) / r
    (rolling), so that v_G = w x r u = Omega rho along y.
    """
    k = np.array([math.cos(tilt), 0.0, math.sin(tilt)])
    spin = -precession * (centre_radius + d.r * math.sin(tilt)) / d.r
    w = precession * K_UP + spin * k
    across = np.array([0.0, 1.0, 0.0])          # K x k: turning about it changes the tilt
    w = w + kick * across
    e = np.array([-math.sin(tilt), 0.0, math.cos(tilt)])   # in the disk's plane
    return np.concatenate([k, e, w, [centre_radius, 0.0]])


def integrate(d: Disk, y0: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, float]:
    """States at the (increasing) times t, and the relative energy drift.

    Stops early (the remaining rows repeat the last state) once the tilt passes
    FLAT (the disk has fallen) or the plane would have to pull (N < 0, the disk
    leaves it): rolling contact no longer describes the motion.
    """
    from scipy.integrate import solve_ivp

    def fallen(_t, y):
        return math.asin(min(1.0, abs(float(y[2])) / float(np.linalg.norm(y[0:3])))) - FLAT

    def lifts(_t, y):
        return normal_force(d, y)

    # solve_ivp reads an event's terminal from a function attribute, which mypy does not model
    fallen.terminal = lifts.terminal = True  # type: ignore[attr-defined]
    sol = solve_ivp(rhs(d), (float(t[0]), float(t[-1])), y0, method="DOP853", t_eval=t,
                    rtol=1e-10, atol=1e-12, events=[fallen, lifts])
    if sol.status == -1:
        raise RuntimeError(f"integration failed: {sol.message}")
    ys = sol.y.T
    if len(ys) < len(t):
        last = ys[-1] if len(ys) else y0
        ys = np.vstack([ys, np.repeat(last[None, :], len(t) - len(ys), axis=0)])
    e0 = energy(d, y0)
    scale = max(abs(e0), d.g * d.r)
    drift = max(abs(energy(d, y) - e0) for y in ys[:: max(1, len(ys) // 50)]) / scale
    return ys, drift


def normal_force(d: Disk, y: np.ndarray) -> float:
    """The plane's upward push per unit mass, N / m = a_G.K + g (Newton)."""
    k, w = y[0:3], y[6:9]
    u, c, s = _contact_vector(k)
    kd = _cross(w, k)
    cd = float(kd[2])
    ud = -(cd * k + c * kd) / s + u * (c * cd / (s * s))
    wd = angular_acceleration(d, k, w)
    aG = _cross(wd, d.r * u) + _cross(w, d.r * ud)
    return float(aG[2]) + d.g


def tilt_of(y: np.ndarray) -> np.ndarray:
    """Tilt of the disk's plane from the vertical, beta = asin(k.K)."""
    return np.arcsin(np.clip(y[..., 2] / np.linalg.norm(y[..., 0:3], axis=-1), -1, 1))
