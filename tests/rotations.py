"""Rotation matrices and finite-difference kinematics shared by the tests.

Independent of gyro's code: angular velocity is read off dR/dt R^T, and the
angular momentum H = R I_body R^T omega is differentiated numerically.
"""

from __future__ import annotations

import math

import numpy as np

K = np.array([0.0, 0.0, 1.0])


def cross3(a, b) -> list:
    """a x b of two 3-vectors as a list: np.cross's own products in its order (the same
    bits), without its cost for arrays of any shape; on lists of floats, a twentieth of
    the time. The integrations of the equations of motion call it a hundred thousand times."""
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def cross(a, b) -> np.ndarray:
    """a x b of two 3-vectors (cross3) as an array."""
    return np.array(cross3(a, b))


def rz(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])


def rx(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0, 0], [0, c, -s], [0, s, c]])


def omega_of(R_of, t: float, h: float = 1e-6) -> np.ndarray:
    """Angular velocity from the skew matrix dR/dt R^T (central differences)."""
    W = (R_of(t + h) - R_of(t - h)) / (2 * h) @ R_of(t).T
    return np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]]) / 2


def rows_times_skew(R: list[float], w: list[float]) -> list[float]:
    """R [omega]x for R given by rows as 9 floats: row i is R_i x omega (the numpy product
    of two 3x3 matrices cost the torque-free integrations most of their time)."""
    return cross3(R[0:3], w) + cross3(R[3:6], w) + cross3(R[6:9], w)
