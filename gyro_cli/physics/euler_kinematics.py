"""Rigid body with one point fixed: Euler angles, angular velocity, inertia, T and H.

Chapter 11, section 11.1. The chapter's sequence is z-x-z (Fig. 11-2): rotate
the fixed frame {I, J, K} by phi about K, then by theta about the line of nodes
i' = i'', then by psi about the body's k. The body's axes, written in the fixed
frame, are the columns of

    R = Rz(phi) Rx(theta) Rz(psi),

and the angular velocity omega = phidot K + thetadot i'' + psidot k (Eq. 11.5)
has the body components (Eqs. 11.6-11.8)

    omega_x = phidot sin(theta) sin(psi) + thetadot cos(psi)
    omega_y = phidot sin(theta) cos(psi) - thetadot sin(psi)
    omega_z = phidot cos(theta) + psidot.

Aircraft books use z-y-x (yaw psi about Z, pitch theta about the new y, roll
phi about the body's x): R = Rz(yaw) Ry(pitch) Rx(roll) and

    p = rolldot - yawdot sin(pitch)
    q = pitchdot cos(roll) + yawdot cos(pitch) sin(roll)
    r = -pitchdot sin(roll) + yawdot cos(pitch) cos(roll)

(as flight-dynamics texts write them, e.g. Etkin, Dynamics of Atmospheric
Flight; re-derived in the tests from R^T dR/dt). Each inverse divides
by sin(theta) (z-x-z) or cos(pitch) (z-y-x): there the first and last rotations
turn about the same axis and the rates are not determined.

Inertia from particles follows Eqs. 11.1-11.3: I_x = sum m (y^2 + z^2), ...,
and the products as the chapter defines them, I_xy = sum m x y, ...; the
kinetic energy T = (1/2) sum m v.v (first line of Eq. 11.2) is then
(1/2) omega . (I omega) with the inertia matrix

        [  I_x   -I_xy  -I_zx ]
    I = [ -I_xy   I_y   -I_yz ]
        [ -I_zx  -I_yz   I_z  ],

which is Eq. 11.2 when the products vanish (principal axes), and H = I omega.

Plain floats only: no units, no files, no printing.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

Vector = tuple[float, float, float]
Matrix = tuple[Vector, Vector, Vector]

# Below this |sin(theta)| (z-x-z) or |cos(pitch)| (z-y-x) the inverse is refused.
SINGULAR = 1e-9


class SingularAngles(ValueError):
    """The Euler-angle rates are not determined at this attitude (gimbal lock)."""


def sin_exact(a: float) -> float:
    """sin(a), exactly 0 at multiples of pi written in floating point."""
    s = math.sin(a)
    return 0.0 if abs(s) < 1e-15 else s


def cos_exact(a: float) -> float:
    """cos(a), exactly 0 at odd multiples of pi/2 written in floating point."""
    c = math.cos(a)
    return 0.0 if abs(c) < 1e-15 else c


# ---- rotations --------------------------------------------------------------

def rot_x(a: float) -> Matrix:
    c, s = cos_exact(a), sin_exact(a)
    return ((1.0, 0.0, 0.0), (0.0, c, -s), (0.0, s, c))


def rot_y(a: float) -> Matrix:
    c, s = cos_exact(a), sin_exact(a)
    return ((c, 0.0, s), (0.0, 1.0, 0.0), (-s, 0.0, c))


def rot_z(a: float) -> Matrix:
    c, s = cos_exact(a), sin_exact(a)
    return ((c, -s, 0.0), (s, c, 0.0), (0.0, 0.0, 1.0))


def matmul(a: Matrix, b: Matrix) -> Matrix:
    return tuple(tuple(sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3))
                 for i in range(3))  # type: ignore[return-value]


def matvec(a: Matrix, v: Sequence[float]) -> Vector:
    return tuple(sum(a[i][k] * v[k] for k in range(3)) for i in range(3))  # type: ignore




def attitude(sequence: str, first: float, second: float, third: float) -> Matrix:
    """R: body axes (columns) in the fixed frame.

    ``zxz``: (phi, theta, psi), R = Rz(phi) Rx(theta) Rz(psi) (Fig. 11-2);
    ``zyx``: (yaw, pitch, roll), R = Rz(yaw) Ry(pitch) Rx(roll).
    """
    if sequence == "zxz":
        return matmul(matmul(rot_z(first), rot_x(second)), rot_z(third))
    if sequence == "zyx":
        return matmul(matmul(rot_z(first), rot_y(second)), rot_x(third))
    raise ValueError(f"unknown sequence {sequence!r}")


# ---- angular velocity -------------------------------------------------------

def body_rates_zxz(theta: float, psi: float, phi_rate: float, theta_rate: float,
                   psi_rate: float) -> Vector:
    """(omega_x, omega_y, omega_z) in body axes, Eq. 11.8."""
    st, ct, sp, cp = sin_exact(theta), cos_exact(theta), sin_exact(psi), cos_exact(psi)
    return (phi_rate * st * sp + theta_rate * cp,
            phi_rate * st * cp - theta_rate * sp,
            phi_rate * ct + psi_rate)


def euler_rates_zxz(theta: float, psi: float, wx: float, wy: float, wz: float) -> Vector:
    """(phidot, thetadot, psidot) from body rates: Eq. 11.8 solved.

    thetadot = wx cos(psi) - wy sin(psi);  phidot = (wx sin(psi) + wy cos(psi)) / sin(theta);
    psidot = wz - phidot cos(theta). SingularAngles where sin(theta) = 0.
    """
    st = sin_exact(theta)
    if abs(st) < SINGULAR:
        raise SingularAngles("sin(theta) = 0")
    sp, cp = sin_exact(psi), cos_exact(psi)
    phi_rate = (wx * sp + wy * cp) / st
    return (phi_rate, wx * cp - wy * sp, wz - phi_rate * cos_exact(theta))


def body_rates_zyx(pitch: float, roll: float, yaw_rate: float, pitch_rate: float,
                   roll_rate: float) -> Vector:
    """(p, q, r) in body axes for yaw-pitch-roll."""
    sr, cr, sq, cq = sin_exact(roll), cos_exact(roll), sin_exact(pitch), cos_exact(pitch)
    return (roll_rate - yaw_rate * sq,
            pitch_rate * cr + yaw_rate * cq * sr,
            -pitch_rate * sr + yaw_rate * cq * cr)


def euler_rates_zyx(pitch: float, roll: float, p: float, q: float, r: float) -> Vector:
    """(yawdot, pitchdot, rolldot) from body rates; SingularAngles where cos(pitch) = 0.

    yawdot = (q sin(roll) + r cos(roll)) / cos(pitch); pitchdot = q cos(roll) - r sin(roll);
    rolldot = p + yawdot sin(pitch).
    """
    cq = cos_exact(pitch)
    if abs(cq) < SINGULAR:
        raise SingularAngles("cos(pitch) = 0")
    sr, cr = sin_exact(roll), cos_exact(roll)
    yaw_rate = (q * sr + r * cr) / cq
    return (yaw_rate, q * cr - r * sr, p + yaw_rate * sin_exact(pitch))


# ---- angular acceleration ---------------------------------------------------
#
# alpha = d(omega)/dt is the same vector whether the derivative is taken in the fixed
# frame or in the body (d/dt|fixed = d/dt|body + omega x, and omega x omega = 0), so the
# body components of alpha are the time derivatives of Eq. 11.8's, and the fixed ones
# the derivatives of the fixed components of omega (Hibbeler, Dynamics, Sec. 20.1).

def body_accel_zxz(theta: float, psi: float, rates: Sequence[float],
                   accels: Sequence[float]) -> Vector:
    """(alpha_x, alpha_y, alpha_z): Eq. 11.8 differentiated in time.

    alpha_x = phiddot s(th) s(ps) + phidot thetadot c(th) s(ps) + phidot psidot s(th) c(ps)
              + thetaddot c(ps) - thetadot psidot s(ps)
    alpha_y = phiddot s(th) c(ps) + phidot thetadot c(th) c(ps) - phidot psidot s(th) s(ps)
              - thetaddot s(ps) - thetadot psidot c(ps)
    alpha_z = phiddot c(th) - phidot thetadot s(th) + psiddot
    """
    p1, p2, p3 = rates
    a1, a2, a3 = accels
    st, ct, sp, cp = sin_exact(theta), cos_exact(theta), sin_exact(psi), cos_exact(psi)
    return (a1 * st * sp + p1 * p2 * ct * sp + p1 * p3 * st * cp + a2 * cp - p2 * p3 * sp,
            a1 * st * cp + p1 * p2 * ct * cp - p1 * p3 * st * sp - a2 * sp - p2 * p3 * cp,
            a1 * ct - p1 * p2 * st + a3)


def body_accel_zyx(pitch: float, roll: float, rates: Sequence[float],
                   accels: Sequence[float]) -> Vector:
    """(pdot, qdot, rdot): the yaw-pitch-roll body rates differentiated in time."""
    y1, y2, y3 = rates
    a1, a2, a3 = accels
    sq, cq, sr, cr = sin_exact(pitch), cos_exact(pitch), sin_exact(roll), cos_exact(roll)
    return (a3 - a1 * sq - y1 * y2 * cq,
            a2 * cr - y2 * y3 * sr + a1 * cq * sr - y1 * y2 * sq * sr + y1 * y3 * cq * cr,
            -a2 * sr - y2 * y3 * cr + a1 * cq * cr - y1 * y2 * sq * cr - y1 * y3 * cq * sr)


def euler_moment(matrix: Matrix, omega: Sequence[float], alpha: Sequence[float]) -> Vector:
    """M = dH/dt = I alpha + omega x (I omega), body axes (I constant in the body): Euler's
    equations, M_x = I_x alpha_x - (I_y - I_z) omega_y omega_z, ... on principal axes
    (Hibbeler, Dynamics, Eqs. 21-25; Meriam, Art. 7/8)."""
    Iw = matvec(matrix, omega)
    Ia = matvec(matrix, alpha)
    gyro = cross(omega, Iw)
    return (Ia[0] + gyro[0], Ia[1] + gyro[1], Ia[2] + gyro[2])


# ---- inertia ----------------------------------------------------------------

def inertia_from_particles(particles: Iterable[Sequence[float]]
                           ) -> tuple[float, float, float, float, float, float]:
    """(I_x, I_y, I_z, I_xy, I_yz, I_zx) of particles (m, x, y, z), Eq. 11.3.

    Products as the chapter defines them: I_xy = sum m x y (no minus sign).
    """
    Ix = Iy = Iz = Ixy = Iyz = Izx = 0.0
    for m, x, y, z in particles:
        Ix += m * (y * y + z * z)
        Iy += m * (z * z + x * x)
        Iz += m * (x * x + y * y)
        Ixy += m * x * y
        Iyz += m * y * z
        Izx += m * z * x
    return Ix, Iy, Iz, Ixy, Iyz, Izx


def inertia_matrix(Ix: float, Iy: float, Iz: float, Ixy: float = 0.0, Iyz: float = 0.0,
                   Izx: float = 0.0) -> Matrix:
    """The inertia matrix with the chapter's products: minus signs off the diagonal."""
    return ((Ix, -Ixy, -Izx), (-Ixy, Iy, -Iyz), (-Izx, -Iyz, Iz))


#: principal axes whose moments lie in this range (or are 0) are answered by sorting the
#: moments; outside it symmetric_eigenvalues is asked, as for every other matrix (a diagonal
#: matrix leaves it sorted, without a rotation: the same floats unless its power-of-two
#: scaling takes a moment below the normal range)
DIAGONAL_RANGE = (1e-100, 1e100)

#: pairs (p, q) in cyclic order with r, the third index: the off-diagonal entry a_pq is kept
#: as off[r], so a_rp is off[q] and a_rq is off[p]
_JACOBI_PAIRS = ((0, 1, 2), (0, 2, 1), (1, 2, 0))
_MAX_SWEEPS = 50


def symmetric_eigenvalues(matrix: Matrix) -> list[float]:
    """Eigenvalues of a real symmetric 3x3 matrix, ascending: the cyclic Jacobi method.

    Each rotation in the plane (p, q) zeroes a_pq (Golub and Van Loan, Matrix Computations,
    4th ed., sec. 8.5); sweeps repeat until every a_pq is 0 or below eps (|a_pp| + |a_qq|).
    Accurate to a few ulps of the matrix's norm, nearly equal eigenvalues included. The
    lower triangle is read; ValueError for an entry that is not finite.
    """
    lower = (matrix[0][0], matrix[1][0], matrix[1][1], matrix[2][0], matrix[2][1], matrix[2][2])
    if not all(math.isfinite(x) for x in lower):
        raise ValueError("an entry of the matrix is not finite")
    # scaled by a power of two (exact) so that the largest entry lies in [0.5, 1): no sum
    # below can overflow, for any finite matrix
    exponent = math.frexp(max(abs(x) for x in lower))[1]
    a00, a10, a11, a20, a21, a22 = (math.ldexp(x, -exponent) for x in lower)
    diag = [a00, a11, a22]
    off = [a21, a20, a10]
    eps = math.ulp(1.0)
    for _ in range(_MAX_SWEEPS):
        rotated = False
        for p, q, r in _JACOBI_PAIRS:
            apq = off[r]
            if apq == 0:
                continue
            if abs(apq) <= eps * (abs(diag[p]) + abs(diag[q])):
                off[r] = 0.0
                continue
            rotated = True
            # |theta| < 1 / (2 eps) here, so theta^2 cannot overflow
            theta = (diag[q] - diag[p]) / (2.0 * apq)
            t = math.copysign(1.0, theta) / (abs(theta) + math.sqrt(theta * theta + 1.0))
            c = 1.0 / math.sqrt(t * t + 1.0)
            s = t * c
            tau = s / (1.0 + c)
            diag[p] -= t * apq
            diag[q] += t * apq
            off[r] = 0.0
            arp, arq = off[q], off[p]
            off[q] = arp - s * (arq + tau * arp)
            off[p] = arq + s * (arp - tau * arq)
        if not rotated:
            break
    return sorted(math.ldexp(d, exponent) for d in diag)


def principal_moments(matrix: Matrix) -> list[float]:
    """Eigenvalues of the (symmetric) inertia matrix, ascending (Eq. 11.3's matrix).

    On principal axes (every product exactly 0) they are the moments of inertia
    themselves, sorted. Otherwise, and for moments beyond DIAGONAL_RANGE,
    symmetric_eigenvalues: pure Python, because gyro check must not import numpy (its
    import would be a twentieth of the time a bank takes to check).
    """
    lo, hi = DIAGONAL_RANGE
    diagonal = (matrix[0][0], matrix[1][1], matrix[2][2])
    if (matrix[0][1] == matrix[0][2] == matrix[1][2] == 0
            and matrix[1][0] == matrix[2][0] == matrix[2][1] == 0
            and all(lo <= d <= hi or (d == 0 and math.copysign(1.0, d) > 0)
                    for d in diagonal)):
        return sorted(float(d) for d in diagonal)
    return symmetric_eigenvalues(matrix)


def is_diagonal(matrix: Matrix, rel: float = 1e-12) -> bool:
    scale = max(abs(matrix[i][i]) for i in range(3)) or 1.0
    return all(abs(matrix[i][j]) <= rel * scale for i in range(3) for j in range(3) if i != j)


# ---- energy and momentum ----------------------------------------------------

def dot(a: Sequence[float], b: Sequence[float]) -> float:
    return sum(x * y for x, y in zip(a, b))


def norm(a: Sequence[float]) -> float:
    return math.sqrt(dot(a, a))


def cross(a: Sequence[float], b: Sequence[float]) -> Vector:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def angular_momentum(matrix: Matrix, omega: Sequence[float]) -> Vector:
    """H = I omega about the fixed point, in the axes I and omega are written in."""
    return matvec(matrix, omega)


def kinetic_energy(matrix: Matrix, omega: Sequence[float]) -> float:
    """T = (1/2) omega . I omega (Eq. 11.2, products included)."""
    return 0.5 * dot(omega, matvec(matrix, omega))


def angle_between(a: Sequence[float], b: Sequence[float]) -> float:
    """The angle between two vectors, atan2(|a x b|, a . b): accurate near 0 and pi."""
    return math.atan2(norm(cross(a, b)), dot(a, b))
