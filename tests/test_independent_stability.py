"""Independent checks of the stability answers.

Kinds and answers checked: `stability`, `growth_rate` (and the oscillation
frequency sqrt(k) printed in the worked answer) of `steady_precession` and of
`rolling_disk` with `arrangement: free`, its `upright_speed`, and the kind
`bicycle` (eigenvalues, weave and capsize speeds, self-stable range, matrices).

Nothing here comes from gyro's implementation. Every reference value is
derived in this file from first principles:

- the heavy top: Lagrange's equations in z-x-z Euler angles, integrated in
  time after a small kick, and the Routh effective potential differentiated
  by finite differences;
- the rolling disk: the full nonlinear Newton-Euler equations of a thin disk
  rolling without slipping, written in world axes with the contact force
  eliminated through the rolling constraint; steady states found by root
  finding on those equations, their linearisation by finite differences in a
  frame turning with the steady precession, and perturbed motions integrated
  in time;
- the bicycle: M, C1, K0, K2 built here from the formulas of Meijaard et al.
  (2007), Appendix A; the eigenvalues of the 4x4 state matrix; weave and
  capsize speeds by a scan in speed and bisection.
"""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest
from rotations import cross
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

# ---------------------------------------------------------------- units ----
INCH = 0.0254
FT = 0.3048
LBF = 4.4482216152605          # N (exact definition: 0.45359237 kg * 9.80665)
OZF = LBF / 16.0
RPM = 2.0 * math.pi / 60.0
KMH = 1000.0 / 3600.0
G_SI = 9.81                    # gyro's default
G_US = 32.2 * FT               # textbook 32.2 ft/s^2 for US customary data


# ------------------------------------------------------------ the CLI ----
def solve(run, write, text: str, name: str = "p.yaml") -> dict:
    path = write(text, name)
    res = run("solve", "--format", "json", path)
    assert res.exit_code == 0, res.output
    return json.loads(res.stdout)


def given_block(text: str, indent: int) -> str:
    """The case's given keys, one per line, each indented by `indent` spaces."""
    lines = [ln.strip() for ln in text.strip().splitlines()]
    return "".join("\n" + " " * indent + ln for ln in lines)


def si(d: dict, key: str) -> list:
    return d["answers"][key]["si_values"]


def step_lines(d: dict) -> list[str]:
    return [line for step in d["steps"] for line in step["lines"]]


_NUM = r"([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)"


def printed_rates(d: dict) -> list[tuple[str, float]]:
    """The rates gyro prints per state: ('stable', sqrt(k)) or ('unstable', sqrt(-k))."""
    out = []
    for line in step_lines(d):
        m = re.search(r"sqrt\(k\) = " + _NUM + r" rad/s", line)
        if m:
            out.append(("stable", float(m.group(1))))
            continue
        m = re.search(r"sqrt\(-k\) = " + _NUM + r" 1/s", line)
        if m:
            out.append(("unstable", float(m.group(1))))
    return out


# Four significant figures are printed: the rounding is at most 5e-4 relative.
PRINTED = 6e-4


# =================================================================
# 1. The heavy symmetric top: every steady precession, checked by
#    Lagrange's equations.
# =================================================================
#
# Euler angles z-x-z: phi precession about the upward vertical, theta the
# angle of the axis (fixed point -> centre of mass) from it, psi the spin.
# I is the transverse inertia about the fixed point, J the axial one.
#
#   L = I/2 (thetadot^2 + phidot^2 sin^2 th) + J/2 omega_z^2 - m g l cos th,
#   omega_z = psidot + phidot cos th.
#
# Lagrange:
#   theta: I thetaddot = I phidot^2 sin th cos th - J omega_z phidot sin th
#                        + m g l sin th
#   phi:   p_phi = I phidot sin^2 th + J omega_z cos th = const
#          => I sin^2 th phiddot = thetadot sin th (J omega_z - 2 I phidot cos th)
#   psi:   p_psi = J omega_z = const.
# Steady precession (thetaddot = 0, thetadot = 0), with omega_z written out:
#   (J - I) cos th phidot^2 + J psidot phidot - m g l = 0.
# Reduced to theta with p_phi, p_psi fixed (Routh), I thetaddot = -U'(theta),
#   U(theta) = (p_phi - p_psi cos th)^2 / (2 I sin^2 th) + m g l cos th,
# so a small change of theta oscillates with k = U''(theta0) / I.


def top_roots(I, J, m, g, l, th, psid):
    a = (J - I) * math.cos(th)
    b = J * psid
    c = -m * g * l
    if abs(a) < 1e-12 * max(abs(b), abs(c), 1e-300):
        return [-c / b]                       # theta = 90 deg: one root
    disc = b * b - 4 * a * c
    assert disc >= 0
    q = math.sqrt(disc)
    return sorted([(-b - q) / (2 * a), (-b + q) / (2 * a)])


def top_k_fd(I, J, m, g, l, th, phid, psid):
    """k = U''(theta0)/I by central differences of the Routh potential."""
    wz = psid + phid * math.cos(th)
    p_psi = J * wz
    p_phi = I * phid * math.sin(th) ** 2 + p_psi * math.cos(th)

    def U(t):
        return (p_phi - p_psi * math.cos(t)) ** 2 / (2 * I * math.sin(t) ** 2) + m * g * l * math.cos(t)

    h = 1e-4
    d1 = (U(th + h) - U(th - h)) / (2 * h)
    d2 = (U(th + h) - 2 * U(th) + U(th - h)) / h ** 2
    # Richardson with h/2 for d2
    h2 = h / 2
    d2b = (U(th + h2) - 2 * U(th) + U(th - h2)) / h2 ** 2
    d2 = (4 * d2b - d2) / 3
    scale = abs(m * g * l) + abs(p_phi * p_psi / I) + I * phid ** 2
    assert abs(d1) < 1e-6 * scale, "not a steady precession of the Lagrange equations"
    return d2 / I


def top_integrate(I, J, m, g, l, th0, phid0, psid0, kick, periods=20):
    """Integrate Lagrange's equations from the steady precession with thetadot = kick.

    Returns (measured angular frequency of theta, max |theta - theta0|)."""
    wz = psid0 + phid0 * math.cos(th0)

    def rhs(t, y):
        th, thd, phd, w = y
        s, c = math.sin(th), math.cos(th)
        thdd = (I * phd ** 2 * s * c - J * w * phd * s + m * g * l * s) / I
        phdd = thd * s * (J * w - 2 * I * phd * c) / (I * s * s)
        return [thd, thdd, phdd, 0.0]

    def ev(t, y):
        return y[1]

    # a rough frequency only to choose the time span
    w_est = math.sqrt(top_k_fd(I, J, m, g, l, th0, phid0, psid0))
    T = 2 * math.pi / w_est
    sol = solve_ivp(rhs, (0, periods * T), [th0, kick, phid0, wz], method="DOP853",
                    rtol=1e-12, atol=1e-16, events=ev, dense_output=True)
    assert sol.success
    tz = sol.t_events[0]
    tz = tz[tz > 0.1 * T]
    n = np.arange(len(tz))
    half = np.polyfit(n, tz, 1)[0]             # zero crossings of thetadot: every half period
    ts = np.linspace(0, periods * T, 20000)
    amp = np.max(np.abs(sol.sol(ts)[0] - th0))
    return math.pi / half, amp


def _top_mass_inertia_11_3():
    W = 3 * OZF
    m = W / G_US
    return m, m * (0.84 * INCH) ** 2, m * (1.80 * INCH) ** 2, 1.5 * INCH


def _psid_min_11_3():
    # real roots need J^2 psidot^2 >= 4 (I - J) m g l cos th  (discriminant above)
    m, J, I, l = _top_mass_inertia_11_3()
    return 2 * math.sqrt((I - J) * m * G_US * l * math.cos(math.radians(30))) / J


def _top_cases():
    cases = []
    # (a) Problem 11/3 as the book states it: ounces, inches, rpm, g = 32.2 ft/s^2.
    m, J, I, l = _top_mass_inertia_11_3()
    cases.append(dict(
        id="top-11-3", yaml="""
            weight: 3 oz
            k_axial: 0.84 in
            k_pivot: 1.80 in
            cg_distance: 1.5 in
            spin: 1800 rpm
            theta: 30 deg""",
        m=m, J=J, I=I, l=l, g=G_US, th=math.radians(30), psid=1800 * RPM, given="spin"))
    # (b) The same top spun only 0.05 % above its least spin: the roots nearly meet.
    psid = 1.0005 * _psid_min_11_3()
    cases.append(dict(
        id="top-near-least-spin", yaml=f"""
            weight: 3 oz
            k_axial: 0.84 in
            k_pivot: 1.80 in
            cg_distance: 1.5 in
            spin: {psid!r} rad/s
            theta: 30 deg""",
        m=m, J=J, I=I, l=l, g=G_US, th=math.radians(30), psid=psid, given="spin"))
    # (c) A gyroscope hanging below its support (theta = 120 deg), SI data.
    cases.append(dict(
        id="top-hanging", yaml="""
            mass: 1.2 kg
            J: 2.4e-3 kg m^2
            I_pivot: 1.2e-2 kg m^2
            cg_distance: 80 mm
            spin: 900 rpm
            theta: 120 deg""",
        m=1.2, J=2.4e-3, I=1.2e-2, l=0.080, g=G_SI, th=math.radians(120), psid=900 * RPM,
        given="spin"))
    # (d) Zero spin: a hanging body swinging as a conical pendulum, both senses.
    cases.append(dict(
        id="top-zero-spin", yaml="""
            mass: 1 kg
            J: 1e-3 kg m^2
            I_pivot: 2e-2 kg m^2
            cg_distance: 0.1 m
            spin: 0 rpm
            theta: 150 deg""",
        m=1.0, J=1e-3, I=2e-2, l=0.1, g=G_SI, th=math.radians(150), psid=0.0, given="spin"))
    # (e) Axis horizontal (theta = 90 deg): one root. Pounds and inches.
    W = 2 * LBF
    m2 = W / G_US
    cases.append(dict(
        id="top-horizontal", yaml="""
            weight: 2 lb
            k_axial: 2 in
            k_pivot: 5 in
            cg_distance: 4 in
            spin: 3000 rpm
            theta: 90 deg""",
        m=m2, J=m2 * (2 * INCH) ** 2, I=m2 * (5 * INCH) ** 2, l=4 * INCH, g=G_US,
        th=math.radians(90), psid=3000 * RPM, given="spin"))
    # (f) A flat disk (J > I about the fixed point) given a clockwise precession.
    md, rd, ld = 0.5, 0.060, 0.020
    Jd, IGd = md * rd ** 2 / 2, md * rd ** 2 / 4
    cases.append(dict(
        id="top-flat-disk-precession", yaml="""
            mass: 500 g
            shape: disk
            radius: 60 mm
            cg_distance: 20 mm
            precession: -4 rad/s
            theta: 60 deg""",
        m=md, J=Jd, I=IGd + md * ld ** 2, l=ld, g=G_SI, th=math.radians(60), phid=-4.0,
        given="precession"))
    return cases


TOP_CASES = _top_cases()


@pytest.mark.parametrize("case", TOP_CASES, ids=[c["id"] for c in TOP_CASES])
def test_top_every_steady_precession_stable_at_lagrange_frequency(run, write, case):
    c = case
    d = solve(run, write, f"""
        id: {c['id']}
        kind: steady_precession
        given:{given_block(c['yaml'], 10)}
        find:
          precession: rad/s
          stability: null
          growth_rate: s^-1
        """)
    I, J, m, g, l, th = c["I"], c["J"], c["m"], c["g"], c["l"], c["th"]
    if c["given"] == "spin":
        psid = c["psid"]
        roots = top_roots(I, J, m, g, l, th, psid)
        states = [(phid, psid) for phid in roots]
    else:
        phid = c["phid"]
        # the steady equation solved for psidot
        psid = (m * g * l - (J - I) * math.cos(th) * phid ** 2) / (J * phid)
        states = [(phid, psid)]
    gy_prec = si(d, "precession")
    assert len(gy_prec) == len(states)
    # gyro lists the roots in its own order (slow / fast): pair them by value
    order = [min(range(len(states)), key=lambda i: abs(states[i][0] - p)) for p in gy_prec]
    assert sorted(order) == list(range(len(states)))
    printed = printed_rates(d)
    assert len(printed) == len(states)
    for j, i in enumerate(order):
        phid, psid_i = states[i]
        assert gy_prec[j] == pytest.approx(phid, rel=1e-9)
        # k by finite differences of the Routh potential
        k = top_k_fd(I, J, m, g, l, th, phid, psid_i)
        assert k > 0
        w = math.sqrt(k)
        # Lagrange's equations integrated after a kick of thetadot
        kick = 1e-6 * w
        w_meas, amp = top_integrate(I, J, m, g, l, th, phid, psid_i, kick)
        assert w_meas == pytest.approx(w, rel=1e-6)
        assert amp == pytest.approx(kick / w, rel=1e-3)   # it stays at the kick's size
        # gyro: stable, no growth, and the printed oscillation frequency
        assert si(d, "stability")[j] == "stable"
        assert si(d, "growth_rate")[j] == 0.0
        assert printed[j][0] == "stable"
    # the printed frequencies, as a set (printed per root in gyro's order)
    mine = sorted(math.sqrt(top_k_fd(I, J, m, g, l, th, p, s)) for p, s in states)
    theirs = sorted(v for _, v in printed)
    for a, b in zip(mine, theirs):
        assert b == pytest.approx(a, rel=PRINTED)


def test_top_fast_spin_nutation_limit(run, write):
    """A very fast top: k -> (J omega_z / I)^2 (the nutation frequency) for the slow root."""
    m, J, I, l, g = 0.3, 4e-5, 8e-4, 0.04, G_SI
    psid = 100000 * RPM
    th = math.radians(45)
    d = solve(run, write, f"""
        id: fast
        kind: steady_precession
        given:
          mass: 300 g
          J: {J} kg m^2
          I_pivot: {I} kg m^2
          cg_distance: 4 cm
          spin: 100000 rpm
          theta: 45 deg
        find:
          precession: rad/s
          stability: null
          growth_rate: s^-1
        """)
    slow = min(top_roots(I, J, m, g, l, th, psid), key=abs)
    k = top_k_fd(I, J, m, g, l, th, slow, psid)
    wz = psid + slow * math.cos(th)
    assert math.sqrt(k) == pytest.approx(J * wz / I, rel=2e-3)
    assert si(d, "stability") == ["stable", "stable"]
    assert si(d, "growth_rate") == [0.0, 0.0]
    w_meas, _ = top_integrate(I, J, m, g, l, th, slow, psid, 1e-6 * math.sqrt(k), periods=10)
    assert w_meas == pytest.approx(math.sqrt(k), rel=1e-6)


@pytest.mark.parametrize("given", [
    "spin: 1800 rpm\n  precession: 50 rpm",
    "spin: 1800 rpm\n  moment: 0.01 N m",
])
def test_top_stability_refused_without_gravity_alone(run, write, given):
    """Documented: with two rates, or an applied moment, stability is not defined (exit 2)."""
    path = write(f"""\
id: refused
kind: steady_precession
given:
  weight: 3 oz
  k_axial: 0.84 in
  k_pivot: 1.80 in
  cg_distance: 1.5 in
  theta: 30 deg
  {given}
find:
  stability: null
""")
    res = run("solve", "--format", "json", path)
    assert res.exit_code == 2


# =================================================================
# 2. The rolling disk: full nonlinear Newton-Euler with the rolling
#    constraint.
# =================================================================
#
# World axes, K up. The state is (k, w): the unit axis of the disk and its
# angular velocity, both world vectors. A thin disk (knife edge) of radius r
# touches the plane at the lowest point of its rim; the unit vector from the
# contact point P to the centre G is
#     u = (K - (K.k) k) / |K - (K.k) k|.
# Rolling without slipping: v_P = 0, so v_G = w x (r u), and
#     a_G = wdot x r u + w x r udot,
# with kdot = w x k and udot from the formula for u. Newton: the contact force
# F = m a_G + m g K. Euler about G, H_G = I_G w + (J - I_G)(w.k) k:
#     I_G wdot + (J - I_G)[(wdot.k) k + (w.kdot) k + (w.k) kdot] = (-r u) x F.
# Substituting F gives a 3x3 linear system for wdot:
#     [I_G 1 + (J - I_G) k k^T + m r^2 (1 - u u^T)] wdot
#         = -(J - I_G)[(w.kdot) k + (w.k) kdot] - m r^2 u x (w x udot) - m g r u x K.
# The motion of G follows from (k, w), so (k, w) is a closed system.

KV = np.array([0.0, 0.0, 1.0])


def disk_wdot(k, w, m, r, J, IG, g):
    """wdot from the 3x3 system above, in plain floats: the integrations call this a
    hundred thousand times, where numpy's cost per small array would be most of the time."""
    k0, k1, c = k
    n = math.sqrt(k0 * k0 + k1 * k1 + c * c)
    k0, k1, c = k0 / n, k1 / n, c / n
    w0, w1, w2 = w
    s = math.sqrt(1.0 - c * c)
    u0, u1, u2 = -c * k0 / s, -c * k1 / s, (1.0 - c * c) / s
    kd0, kd1, cd = w1 * c - w2 * k1, w2 * k0 - w0 * c, w0 * k1 - w1 * k0   # kdot = w x k
    f = c * cd / s ** 2
    ud0 = (-cd * k0 - c * kd0) / s + u0 * f
    ud1 = (-cd * k1 - c * kd1) / s + u1 * f
    ud2 = (-cd * c - c * cd) / s + u2 * f
    a, mr2 = J - IG, m * r * r
    # A = I_G 1 + (J - I_G) k k^T + m r^2 (1 - u u^T), symmetric
    a00 = IG + a * k0 * k0 + mr2 * (1.0 - u0 * u0)
    a11 = IG + a * k1 * k1 + mr2 * (1.0 - u1 * u1)
    a22 = IG + a * c * c + mr2 * (1.0 - u2 * u2)
    a01 = a * k0 * k1 - mr2 * u0 * u1
    a02 = a * k0 * c - mr2 * u0 * u2
    a12 = a * k1 * c - mr2 * u1 * u2
    wkd, wk = w0 * kd0 + w1 * kd1 + w2 * cd, w0 * k0 + w1 * k1 + w2 * c
    x0, x1, x2 = w1 * ud2 - w2 * ud1, w2 * ud0 - w0 * ud2, w0 * ud1 - w1 * ud0  # w x udot
    mgr = m * g * r
    b0 = -a * (wkd * k0 + wk * kd0) - mr2 * (u1 * x2 - u2 * x1) - mgr * u1     # u x K = (u1, -u0, 0)
    b1 = -a * (wkd * k1 + wk * kd1) - mr2 * (u2 * x0 - u0 * x2) + mgr * u0
    b2 = -a * (wkd * c + wk * cd) - mr2 * (u0 * x1 - u1 * x0)
    # Cramer's rule
    c00 = a11 * a22 - a12 * a12
    c01 = a02 * a12 - a01 * a22
    c02 = a01 * a12 - a02 * a11
    det = a00 * c00 + a01 * c01 + a02 * c02
    return np.array([(c00 * b0 + c01 * b1 + c02 * b2) / det,
                     (c01 * b0 + (a00 * a22 - a02 * a02) * b1 + (a02 * a01 - a00 * a12) * b2) / det,
                     (c02 * b0 + (a01 * a02 - a00 * a12) * b1 + (a00 * a11 - a01 * a01) * b2) / det])


def disk_normal_force(k, w, wd, m, r, g):
    k = k / np.linalg.norm(k)
    c = k[2]
    s = math.sqrt(1.0 - c * c)
    u = (KV - c * k) / s
    kd = cross(w, k)
    cd = kd[2]
    ud = (-cd * k - c * kd) / s + u * c * cd / s ** 2
    aG = cross(wd, r * u) + cross(w, r * ud)
    return m * (aG[2] + g)


def disk_steady_state(beta, rho, Om, r):
    """Steady rolling: G on a circle of radius rho about the origin, counter-clockwise
    at Omega; at t = 0 G is on the +x axis moving along +y, the disk leans toward
    the centre by beta, its axis k = (cos b, 0, sin b) points outward and up.
    w = Omega K + psidot k, and v_G = w x r u = Omega rho y gives
    psidot = -Omega (rho + r sin b) / r."""
    k0 = np.array([math.cos(beta), 0.0, math.sin(beta)])
    psid = -Om * (rho + r * math.sin(beta)) / r
    return k0, Om * KV + psid * k0


def disk_residual(beta, rho, Om, m, r, J, IG, g):
    """Steady rolling needs wdot = Omega K x w (w turns with the precession)."""
    k0, w0 = disk_steady_state(beta, rho, Om, r)
    return disk_wdot(k0, w0, m, r, J, IG, g) - Om * cross(KV, w0)


def disk_tilts(v, R, m, r, J, IG, g):
    """Every tilt 0 < b < 90 deg with rho = R - r sin b > 0 for speed v on contact circle R."""
    def h(b):
        rho = R - r * math.sin(b)
        return disk_residual(b, rho, v / rho, m, r, J, IG, g)[1]
    bmax = math.pi / 2 - 1e-6
    if R < r:
        bmax = min(bmax, math.asin(R / r) - 1e-12)
    # a fine geometric grid near upright (tilts of 1e-4 deg and less occur), then uniform
    bs = np.unique(np.concatenate([np.geomspace(1e-12, 1e-2, 400),
                                   np.linspace(1e-2, bmax, 4000)]))
    hs = [h(b) for b in bs]
    roots = []
    for i in range(len(bs) - 1):
        if hs[i] == 0.0:
            roots.append(bs[i])
        elif hs[i] * hs[i + 1] < 0:
            roots.append(brentq(h, bs[i], bs[i + 1], xtol=1e-15, rtol=1e-15))
    return roots


def disk_rho_from_tilt_speed(beta, v, m, r, J, IG, g):
    def h(rho):
        return disk_residual(beta, rho, v / rho, m, r, J, IG, g)[1]
    lo, hi = 1e-9, 1.0
    while h(lo) * h(hi) > 0:
        hi *= 2
        assert hi < 1e9
    return brentq(h, lo, hi, xtol=1e-15, rtol=1e-15)


def disk_rotating_field(y, Om, m, r, J, IG, g):
    """(k, w) seen in a frame turning at Omega about K: steady rolling is a fixed point."""
    k, w = y[:3], y[3:]
    wd = disk_wdot(k, w, m, r, J, IG, g)
    return np.concatenate([cross(w, k) - Om * cross(KV, k), wd - Om * cross(KV, w)])


def disk_linearisation(beta, rho, Om, m, r, J, IG, g):
    """Jacobian of the rotating-frame field at the steady state, by central differences.

    Its eigenvalues are a pair +-sqrt(-k) and four zeros (the length of k, turning
    about K, and the two-parameter family of neighbouring steady motions), so the
    second elementary symmetric function of the eigenvalues is exactly k:
        k = (tr(A)^2 - tr(A^2)) / 2,
    which, unlike an eigenvalue, is not spoilt by the cluster at zero."""
    k0, w0 = disk_steady_state(beta, rho, Om, r)
    y0 = np.concatenate([k0, w0])
    wscale = max(np.linalg.norm(w0), 1e-3)
    A = np.zeros((6, 6))
    for i in range(6):
        h = 1e-6 * (1.0 if i < 3 else wscale)
        e = np.zeros(6)
        e[i] = h
        A[:, i] = (disk_rotating_field(y0 + e, Om, m, r, J, IG, g)
                   - disk_rotating_field(y0 - e, Om, m, r, J, IG, g)) / (2 * h)
    kval = (np.trace(A) ** 2 - np.trace(A @ A)) / 2
    return kval, np.linalg.eigvals(A)


def disk_integrate(beta, rho, Om, m, r, J, IG, g, kval, kick_rel=1e-9):
    """Kick the tilt rate of the steady state and integrate the full equations.

    Returns the measured growth rate (unstable) or angular frequency (stable)."""
    k0, w0 = disk_steady_state(beta, rho, Om, r)
    e_t = cross(KV, k0)
    e_t /= np.linalg.norm(e_t)
    w1 = w0 + kick_rel * max(np.linalg.norm(w0), 1.0) * e_t

    def rhs(t, y):
        k, w = y[:3], y[3:]
        return np.concatenate([cross(w, k), disk_wdot(k, w, m, r, J, IG, g)])

    def betadot(y):
        k, w = y[:3], y[3:]
        kn = np.linalg.norm(k)
        return cross(w, k)[2] / kn / math.sqrt(1 - (k[2] / kn) ** 2)

    y0 = np.concatenate([k0, w1])
    if kval < 0:
        s = math.sqrt(-kval)
        sol = solve_ivp(rhs, (0, 10.5 / s), y0, method="DOP853", rtol=1e-12, atol=1e-15,
                        dense_output=True)
        assert sol.success
        ts = np.linspace(5.0 / s, 10.0 / s, 400)
        bd = np.array([betadot(sol.sol(t)) for t in ts])
        assert np.all(np.abs(bd) > 0)
        # the tilt is still a small disturbance, and the contact still pushes up
        yend = sol.sol(ts[-1])
        assert abs(math.asin(yend[2] / np.linalg.norm(yend[:3])) - beta) < 1e-3
        return np.polyfit(ts, np.log(np.abs(bd)), 1)[0]
    wf = math.sqrt(kval)
    T = 2 * math.pi / wf
    sol = solve_ivp(rhs, (0, 20 * T), y0, method="DOP853", rtol=1e-12, atol=1e-15,
                    events=lambda t, y: cross(y[3:], y[:3])[2], dense_output=True)
    assert sol.success
    tz = sol.t_events[0]
    tz = tz[tz > 0.1 * T]
    half = np.polyfit(np.arange(len(tz)), tz, 1)[0]
    # the tilt stays within a few times kick / sqrt(k): the disturbance does not grow
    ts = np.linspace(0, 20 * T, 4000)
    ys = sol.sol(ts)
    bet = np.arcsin(ys[2] / np.linalg.norm(ys[:3], axis=0))
    assert np.max(np.abs(bet - beta)) < 5 * kick_rel * max(np.linalg.norm(w0), 1.0) / wf
    return math.pi / half


def straight_k(v, m, r, J, IG, g):
    k0 = np.array([1.0, 0.0, 0.0])
    w0 = -(v / r) * k0
    y0 = np.concatenate([k0, w0])
    A = np.zeros((6, 6))
    for i in range(6):
        h = 1e-6 * (1.0 if i < 3 else max(abs(v / r), 1e-3))
        e = np.zeros(6)
        e[i] = h
        A[:, i] = (disk_rotating_field(y0 + e, 0.0, m, r, J, IG, g)
                   - disk_rotating_field(y0 - e, 0.0, m, r, J, IG, g)) / (2 * h)
    return (np.trace(A) ** 2 - np.trace(A @ A)) / 2


def upright_speed_bisect(m, r, J, IG, g):
    """The speed at which straight upright rolling changes from unstable to stable."""
    lo, hi = 1e-3 * math.sqrt(g * r), 1.0 * math.sqrt(g * r)
    while straight_k(hi, m, r, J, IG, g) < 0:
        hi *= 2
    assert straight_k(lo, m, r, J, IG, g) < 0
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if straight_k(mid, m, r, J, IG, g) < 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def test_disk_equations_reproduce_routh_upright_limit():
    """Self-check of the equations written here: straight upright rolling of a thin
    uniform disk is stable exactly for v^2 > g r / 3, of a thin ring for v^2 > g r / 4
    (Routh, Advanced Rigid Dynamics, Sec. 244). By hand, linearised about upright
    rolling at spin w = v / r, with lean beta and heading rate phidot (signs so that
    the lean turns the disk toward it):
        I_G phiddot = -J w betadot                             (about the vertical at G)
        (I_G + m r^2) betaddot = (J + m r^2) w phidot + m g r beta   (about the contact line)
    so phidot = -J w beta / I_G and
        (I_G + m r^2) betaddot = -[J (J + m r^2) w^2 / I_G - m g r] beta."""
    m, r, g = 0.8, 0.12, 9.81
    for J, IG, ratio in [(m * r * r / 2, m * r * r / 4, 3.0), (m * r * r, m * r * r / 2, 4.0)]:
        v = upright_speed_bisect(m, r, J, IG, g)
        assert v == pytest.approx(math.sqrt(g * r / ratio), rel=1e-8)
        for vv in (0.5 * v, 2 * v):
            w = vv / r
            k_hand = (J * (J + m * r * r) * w * w / IG - m * g * r) / (IG + m * r * r)
            assert straight_k(vv, m, r, J, IG, g) == pytest.approx(k_hand, rel=1e-7)


# ------------------------------------------------- the disk problems ----
def _euro_coin():
    m, r = 7.5e-3, 23.25e-3 / 2
    return m, r, m * r * r / 2, m * r * r / 4


def _disk_cases():
    cases = []
    m, r, J, IG = _euro_coin()
    vR = math.sqrt(G_SI * r / 3)               # Routh, for checking the scan only
    # (a) A 1-euro coin rolling almost upright and straight, at speeds around
    #     Routh's critical speed, in cm/s. It is stated with a tiny lean
    #     (0.0001 deg): the circle is then hundreds of metres across.
    for f in (0.5, 0.9, 0.98, 1.02, 1.1, 2.0):
        v = f * vR
        cases.append(dict(
            id=f"euro-coin-{f}vR", yaml=f"""
              mass: 7.5 g
              shape: disk
              diameter: 23.25 mm
              speed: {v * 100!r} cm/s
              tilt: 0.0001 deg""",
            m=m, r=r, J=J, IG=IG, g=G_SI, v=v, beta=math.radians(1e-4),
            integrate=f in (0.5, 2.0)))
    # (a') The same coin at 10 cm/s on a 1 m circle (speed and circle given).
    cases.append(dict(
        id="euro-coin-1m-circle", yaml="""
              mass: 7.5 g
              shape: disk
              diameter: 23.25 mm
              speed: 10 cm/s
              path_radius: 1 m""",
        m=m, r=r, J=J, IG=IG, g=G_SI, v=0.1, R=1.0, integrate=True))
    # (b) A hoop in US units on a tight circle: 3 lb, 2 ft across, 6 ft/s, 4 ft circle.
    mh = 3 * LBF / G_US
    rh = 1 * FT
    cases.append(dict(
        id="hoop-us", yaml="""
              weight: 3 lb
              shape: ring
              diameter: 2 ft
              speed: 6 ft/s
              path_radius: 4 ft""",
        m=mh, r=rh, J=mh * rh ** 2, IG=mh * rh ** 2 / 2, g=G_US, v=6 * FT, R=4 * FT,
        integrate=True))
    # (c) The same hoop crawling at 1 ft/s on a 20 ft circle: below sqrt(g r / 4).
    cases.append(dict(
        id="hoop-us-slow", yaml="""
              weight: 3 lb
              shape: ring
              diameter: 2 ft
              speed: 1 ft/s
              path_radius: 20 ft""",
        m=mh, r=rh, J=mh * rh ** 2, IG=mh * rh ** 2 / 2, g=G_US, v=1 * FT, R=20 * FT,
        integrate=True))
    # (d) A disk leaning 30 deg at 2 km/h (tilt and speed given).
    md, rd = 2.0, 0.15
    cases.append(dict(
        id="disk-tilt30-kmh", yaml="""
              mass: 2 kg
              shape: disk
              radius: 15 cm
              tilt: 30 deg
              speed: 2 km/h""",
        m=md, r=rd, J=md * rd ** 2 / 2, IG=md * rd ** 2 / 4, g=G_SI, v=2 * KMH,
        beta=math.radians(30), integrate=True))
    # (e) A disk leaning 60 deg on a 25 cm contact circle (tilt and path_radius given).
    cases.append(dict(
        id="disk-tilt60-circle", yaml="""
              mass: 2 kg
              shape: disk
              radius: 15 cm
              tilt: 60 deg
              path_radius: 25 cm""",
        m=md, r=rd, J=md * rd ** 2 / 2, IG=md * rd ** 2 / 4, g=G_SI,
        beta=math.radians(60), R=0.25, integrate=True))
    # (f) Two steady tilts for one speed and circle: 20 cm/s on an 8 cm contact circle.
    cases.append(dict(
        id="disk-two-tilts", yaml="""
              mass: 1 kg
              shape: disk
              radius: 10 cm
              speed: 20 cm/s
              path_radius: 8 cm""",
        m=1.0, r=0.1, J=0.005, IG=0.0025, g=G_SI, v=0.2, R=0.08, integrate=True))
    # (g) A spoked wheel given by its inertias (not a uniform disk or ring).
    cases.append(dict(
        id="wheel-inertias", yaml="""
              mass: 1.2 kg
              radius: 0.35 m
              J: 0.11 kg m^2
              I_cg: 0.06 kg m^2
              speed: 1.2 m/s
              path_radius: 3 m""",
        m=1.2, r=0.35, J=0.11, IG=0.06, g=G_SI, v=1.2, R=3.0, integrate=False))
    return cases


DISK_CASES = _disk_cases()


def _disk_states(c):
    """(beta, rho, Omega) of every steady state, found from the equations above."""
    m, r, J, IG, g = c["m"], c["r"], c["J"], c["IG"], c["g"]
    if "beta" in c and "v" in c:
        rho = disk_rho_from_tilt_speed(c["beta"], c["v"], m, r, J, IG, g)
        return [(c["beta"], rho, c["v"] / rho)]
    if "beta" in c and "R" in c:
        beta = c["beta"]
        rho = c["R"] - r * math.sin(beta)

        def h(Om):
            return disk_residual(beta, rho, Om, m, r, J, IG, g)[1]
        Om = brentq(h, 1e-6, 1e3, xtol=1e-15, rtol=1e-15)
        return [(beta, rho, Om)]
    out = []
    for b in disk_tilts(c["v"], c["R"], m, r, J, IG, g):
        rho = c["R"] - r * math.sin(b)
        out.append((b, rho, c["v"] / rho))
    return out


@pytest.mark.parametrize("case", DISK_CASES, ids=[c["id"] for c in DISK_CASES])
def test_rolling_disk_stability_against_newton_euler(run, write, case):
    c = case
    d = solve(run, write, f"""
        id: {c['id']}
        kind: rolling_disk
        given:
          arrangement: free{given_block(c['yaml'], 10)}
        find:
          tilt: deg
          speed: m/s
          path_radius: m
          stability: null
          growth_rate: s^-1
          upright_speed: m/s
        """)
    m, r, J, IG, g = c["m"], c["r"], c["J"], c["IG"], c["g"]
    states = _disk_states(c)
    tilts = si(d, "tilt")
    assert len(tilts) == len(states)
    printed = printed_rates(d)
    assert len(printed) == len(states)
    for j, (beta, rho, Om) in enumerate(sorted(states)):
        # the steady state itself, from the full equations
        assert tilts[j] == pytest.approx(beta, rel=1e-7, abs=1e-12)
        assert si(d, "path_radius")[0] == pytest.approx(rho + r * math.sin(beta), rel=1e-7)
        assert si(d, "speed")[0] == pytest.approx(Om * rho, rel=1e-7)
        res = disk_residual(beta, rho, Om, m, r, J, IG, g)
        assert np.linalg.norm(res) < 1e-9 * (Om * Om + g / r)
        k0, w0 = disk_steady_state(beta, rho, Om, r)
        assert disk_normal_force(k0, w0, disk_wdot(k0, w0, m, r, J, IG, g), m, r, g) \
            == pytest.approx(m * g, rel=1e-9)
        # the linearisation of the full equations
        kval, eig = disk_linearisation(beta, rho, Om, m, r, J, IG, g)
        big = max(abs(eig))
        assert big == pytest.approx(math.sqrt(abs(kval)), rel=1e-5)
        assert sorted(abs(eig))[-3] < 1e-2 * big          # the rest is the cluster at zero
        if kval < 0:
            s = math.sqrt(-kval)
            assert si(d, "stability")[j] == "unstable"
            assert si(d, "growth_rate")[j] == pytest.approx(s, rel=1e-6)
            assert printed[j] == ("unstable", pytest.approx(s, rel=PRINTED))
            if c["integrate"]:
                assert disk_integrate(beta, rho, Om, m, r, J, IG, g, kval) \
                    == pytest.approx(s, rel=1e-4)
        else:
            wf = math.sqrt(kval)
            assert si(d, "stability")[j] == "stable"
            assert si(d, "growth_rate")[j] == 0.0
            assert printed[j] == ("stable", pytest.approx(wf, rel=PRINTED))
            if c["integrate"]:
                assert disk_integrate(beta, rho, Om, m, r, J, IG, g, kval) \
                    == pytest.approx(wf, rel=1e-4)
    # upright speed: my bisection on the full equations, and Routh's closed form
    vu = upright_speed_bisect(m, r, J, IG, g)
    assert si(d, "upright_speed")[0] == pytest.approx(vu, rel=1e-7)
    assert si(d, "upright_speed")[0] == pytest.approx(
        r * math.sqrt(m * g * r * IG / (J * (J + m * r * r))), rel=1e-9)


SMALL_TILT = [(0.05, 1.0), (0.4, 100.0), (0.1, 500.0), (0.4, 65.0)]


# Once missed (exit 2, "no tilt between 0 and 90 deg"): the tilt search started at
# 0.0225 deg; e.g. 0.02190 deg for a 1-euro coin at 5 cm/s on a 1 m circle.
@pytest.mark.parametrize("v,R", SMALL_TILT, ids=[f"{v}mps-{R}m" for v, R in SMALL_TILT])
def test_disk_small_tilt_from_speed_and_circle(run, write, v, R):
    m, r, J, IG = _euro_coin()
    (beta,) = disk_tilts(v, R, m, r, J, IG, G_SI)
    rho = R - r * math.sin(beta)
    assert np.linalg.norm(disk_residual(beta, rho, v / rho, m, r, J, IG, G_SI)) < 1e-12
    kval, _ = disk_linearisation(beta, rho, v / rho, m, r, J, IG, G_SI)
    d = solve(run, write, f"""\
id: small-tilt
kind: rolling_disk
given:
  arrangement: free
  mass: 7.5 g
  shape: disk
  diameter: 23.25 mm
  speed: {v * 100!r} cm/s
  path_radius: {R!r} m
find:
  tilt: deg
  stability: null
  growth_rate: s^-1
""")
    assert si(d, "tilt") == [pytest.approx(beta, rel=1e-7)]
    assert si(d, "stability") == ["unstable" if kval < 0 else "stable"]
    assert si(d, "growth_rate") == [pytest.approx(math.sqrt(-kval) if kval < 0 else 0.0,
                                                  rel=1e-6)]


def test_euro_coin_changes_over_at_routh_speed(run, write):
    """Below sqrt(g r / 3) the coin is unstable, above it stable (scan of case (a))."""
    words = {}
    for c in DISK_CASES:
        if c["id"].startswith("euro-coin-"):
            d = solve(run, write, f"""
                id: x
                kind: rolling_disk
                given:
                  arrangement: free{given_block(c['yaml'], 18)}
                find:
                  stability: null
                """)
            words[c["v"]] = si(d, "stability")[0]
    m, r, J, IG = _euro_coin()
    vR = math.sqrt(G_SI * r / 3)
    for v, w in words.items():
        assert w == ("unstable" if v < vR else "stable")


def test_disk_warning_for_unstable_state(run, write):
    """An unstable state is warned about whether or not stability is asked; the growth
    rate in the warning is the one of the full equations."""
    path = write("""\
id: coin
kind: rolling_disk
given:
  arrangement: free
  mass: 7.5 g
  shape: disk
  diameter: 23.25 mm
  speed: 8 cm/s
  path_radius: 50 cm
find:
  tilt: deg
""")
    res = run("solve", "--format", "json", path)
    assert res.exit_code == 0
    d = json.loads(res.stdout)
    m, r, J, IG = _euro_coin()
    (beta,) = disk_tilts(0.08, 0.5, m, r, J, IG, G_SI)
    rho = 0.5 - r * math.sin(beta)
    kval, _ = disk_linearisation(beta, rho, 0.08 / rho, m, r, J, IG, G_SI)
    s = math.sqrt(-kval)
    assert len(d["warnings"]) == 1
    nums = [float(x) for x in re.findall(r"sigma = " + _NUM + " 1/s", d["warnings"][0])]
    assert nums and nums[0] == pytest.approx(s, rel=PRINTED)
    dbl = re.search(r"doubling every " + _NUM + " s", d["warnings"][0])
    assert float(dbl.group(1)) == pytest.approx(math.log(2) / s, rel=PRINTED)


# =================================================================
# 3. The bicycle: Meijaard et al. (2007), Appendix A, built here.
# =================================================================

BENCH = dict(
    w=1.02, c=0.08, lam=math.pi / 10, g=9.81,
    rR=0.3, mR=2.0, IRxx=0.0603, IRyy=0.12,
    xB=0.3, zB=-0.9, mB=85.0, IBxx=9.2, IByy=11.0, IBzz=2.8, IBxz=2.4,
    xH=0.9, zH=-0.7, mH=4.0, IHxx=0.05892, IHyy=0.06, IHzz=0.00708, IHxz=-0.00756,
    rF=0.35, mF=3.0, IFxx=0.1405, IFyy=0.28,
)


def bicycle_matrices(p, gyroscopic=True):
    """M, C1, K0, K2 of the linearised Whipple bicycle (phi lean, delta steer)."""
    w, c, lam = p["w"], p["c"], p["lam"]
    sl, cl = math.sin(lam), math.cos(lam)
    rR, rF = p["rR"], p["rF"]
    mR, mB, mH, mF = p["mR"], p["mB"], p["mH"], p["mF"]
    xB, zB, xH, zH = p["xB"], p["zB"], p["xH"], p["zH"]
    IRyy = p["IRyy"] if gyroscopic else 0.0
    IFyy = p["IFyy"] if gyroscopic else 0.0
    # the whole bicycle T about the rear contact (A1-A5); wheels: I_zz = I_xx
    mT = mR + mB + mH + mF
    xT = (xB * mB + xH * mH + w * mF) / mT
    zT = (-rR * mR + zB * mB + zH * mH - rF * mF) / mT
    ITxx = (p["IRxx"] + p["IBxx"] + p["IHxx"] + p["IFxx"]
            + mR * rR ** 2 + mB * zB ** 2 + mH * zH ** 2 + mF * rF ** 2)
    ITxz = p["IBxz"] + p["IHxz"] - mB * xB * zB - mH * xH * zH + mF * w * rF
    ITzz = (p["IRxx"] + p["IBzz"] + p["IHzz"] + p["IFxx"]
            + mB * xB ** 2 + mH * xH ** 2 + mF * w ** 2)
    # the front assembly A = H + F (A6-A14)
    mA = mH + mF
    xA = (xH * mH + w * mF) / mA
    zA = (zH * mH - rF * mF) / mA
    IAxx = p["IHxx"] + p["IFxx"] + mH * (zH - zA) ** 2 + mF * (rF + zA) ** 2
    IAxz = p["IHxz"] - mH * (xH - xA) * (zH - zA) + mF * (w - xA) * (rF + zA)
    IAzz = p["IHzz"] + p["IFxx"] + mH * (xH - xA) ** 2 + mF * (w - xA) ** 2
    uA = (xA - w - c) * cl - zA * sl
    IAll = mA * uA ** 2 + IAxx * sl ** 2 + 2 * IAxz * sl * cl + IAzz * cl ** 2
    IAlx = -mA * uA * zA + IAxx * sl + IAxz * cl
    IAlz = mA * uA * xA + IAxz * sl + IAzz * cl
    # (A15-A17)
    mu = c * cl / w
    SR, SF = IRyy / rR, IFyy / rF
    ST = SR + SF
    SA = mA * uA + mu * mT * xT
    # (A20-A23)
    M = np.array([[ITxx, IAlx + mu * ITxz],
                  [IAlx + mu * ITxz, IAll + 2 * mu * IAlz + mu ** 2 * ITzz]])
    K0 = np.array([[mT * zT, -SA], [-SA, -SA * sl]])
    K2 = np.array([[0.0, (ST - mT * zT) * cl / w], [0.0, (SA + SF * sl) * cl / w]])
    C1 = np.array([[0.0, mu * ST + SF * cl + ITxz * cl / w - mu * mT * zT],
                   [-(mu * ST + SF * cl), IAlz * cl / w + mu * (SA + ITzz * cl / w)]])
    return M, C1, K0, K2


def bicycle_eigs(mats, v, g):
    M, C1, K0, K2 = mats
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((2, 2)), np.eye(2)],
                  [-Minv @ (g * K0 + v * v * K2), -v * Minv @ C1]])
    return np.linalg.eigvals(A)


def _weave_fn(mats, v, g):
    """Largest real part among the oscillatory eigenvalues (None if none oscillates)."""
    ev = bicycle_eigs(mats, v, g)
    osc = [e.real for e in ev if abs(e.imag) > 1e-9 * max(1.0, abs(e))]
    return max(osc) if osc else None


def _capsize_fn(mats, v, g):
    """det(g K0 + v^2 K2): the product of the eigenvalues (times det M); a real
    eigenvalue passes through zero where it changes sign."""
    M, C1, K0, K2 = mats
    return np.linalg.det(g * K0 + v * v * K2)


def _bisect(f, a, b, n=100):
    fa = f(a)
    for _ in range(n):
        mid = 0.5 * (a + b)
        fm = f(mid)
        if (fm > 0) == (fa > 0):
            a, fa = mid, fm
        else:
            b = mid
        if b - a <= 1e-15 * b:
            break
    return 0.5 * (a + b)


def _scan(mats, vs, g):
    """_weave_fn and _capsize_fn at every speed of vs, the eigenvalues and
    determinants of all the speeds computed together (one call each)."""
    M, C1, K0, K2 = mats
    Minv = np.linalg.inv(M)
    v = vs[:, None, None]
    n = len(vs)
    A = np.zeros((n, 4, 4))
    A[:, :2, 2:] = np.eye(2)
    A[:, 2:, :2] = -Minv @ (g * K0 + v * v * K2)
    A[:, 2:, 2:] = -v * (Minv @ C1)
    ev = np.linalg.eigvals(A)
    osc = np.abs(ev.imag) > 1e-9 * np.maximum(1.0, np.abs(ev))
    lead = np.where(osc, ev.real, -np.inf).max(axis=1)
    wf = [float(x) if o else None for x, o in zip(lead, osc.any(axis=1))]
    cf = np.linalg.det(g * K0 + v * v * K2)
    return wf, cf


def bicycle_speeds(mats, g, vmax=60.0, dv=0.005):
    """Weave speeds (an oscillatory pair crosses Re = 0) and capsize speeds (a real
    eigenvalue crosses 0), by a scan in v and bisection."""
    vs = np.arange(dv, vmax, dv)
    weave, capsize = [], []
    wf, cf = _scan(mats, vs, g)
    for i in range(len(vs) - 1):
        if wf[i] is not None and wf[i + 1] is not None and wf[i] * wf[i + 1] < 0:
            weave.append(_bisect(lambda v: _weave_fn(mats, v, g), vs[i], vs[i + 1]))
        if cf[i] * cf[i + 1] < 0:
            capsize.append(_bisect(lambda v: _capsize_fn(mats, v, g), vs[i], vs[i + 1]))
    return weave, capsize


def stable_at(mats, v, g):
    return max(bicycle_eigs(mats, v, g).real) < 0


def test_bicycle_matrices_reproduce_published_benchmark():
    """Self-check: the formulas written here give the paper's printed matrices and speeds."""
    M, C1, K0, K2 = bicycle_matrices(BENCH)
    pub = dict(
        M=[80.81722, 2.31941332208709, 2.31941332208709, 0.29784188199686],
        C1=[0, 33.86641391492494, -0.85035641456978, 1.68540397397560],
        K0=[-80.95, -2.59951685249872, -2.59951685249872, -0.80329488458618],
        K2=[0, 76.59734589573222, 0, 2.65431523794604])
    for name, mat in dict(M=M, C1=C1, K0=K0, K2=K2).items():
        assert list(mat.ravel()) == pytest.approx(pub[name], rel=1e-12, abs=1e-12)
    weave, capsize = bicycle_speeds((M, C1, K0, K2), 9.81)
    assert weave == pytest.approx([4.29238253634111], rel=1e-11)
    assert capsize == pytest.approx([6.02426201538837], rel=1e-11)


def _sorted_eigs(ev):
    return sorted(ev, key=lambda e: (round(e.real, 9), e.imag))


def _yaml_bicycle(p, lengths="m"):
    f = {"m": 1.0, "cm": 100.0, "in": 1 / INCH}[lengths]
    out = []
    for key in ("w", "c", "rR", "rF", "xB", "zB", "xH", "zH"):
        out.append(f"  {key}: {p[key] * f!r} {lengths}")
    out.append(f"  lambda: {math.degrees(p['lam'])!r} deg")
    for key in ("mR", "mB", "mH", "mF"):
        out.append(f"  {key}: {p[key]!r} kg")
    for key in ("IRxx", "IRyy", "IBxx", "IByy", "IBzz", "IBxz",
                "IHxx", "IHyy", "IHzz", "IHxz", "IFxx", "IFyy"):
        out.append(f"  {key}: {p[key]!r} kg m^2")
    out.append(f"  g: {p['g']!r} m/s^2")
    return "\n".join(out)


def _scaled(p, s):
    """Every length times s, masses kept, inertias times s^2 (a bigger copy)."""
    q = dict(p)
    for key in ("w", "c", "rR", "rF", "xB", "zB", "xH", "zH"):
        q[key] = p[key] * s
    for key in ("IRxx", "IRyy", "IBxx", "IByy", "IBzz", "IBxz",
                "IHxx", "IHyy", "IHzz", "IHxz", "IFxx", "IFyy"):
        q[key] = p[key] * s * s
    return q


def _bicycle_cases():
    cases = []
    # (a) the benchmark itself, by preset, at 3, 5 and 7 m/s stated in km/h
    cases.append(dict(id="benchmark", p=BENCH, gyro=True,
                      given="  preset: benchmark", speeds_kmh=[10.8, 18.0, 25.2]))
    # (b) the benchmark with half the trail (preset plus one key, in mm)
    p = dict(BENCH, c=0.04)
    cases.append(dict(id="benchmark-trail-40mm", p=p, gyro=True,
                      given="  preset: benchmark\n  c: 40 mm", speeds_kmh=[12.0, 15.0, 20.0]))
    # (c) a 10 % bigger copy of the benchmark, every key written out in cm
    p = _scaled(BENCH, 1.1)
    cases.append(dict(id="scaled-1.1-cm", p=p, gyro=True, given=_yaml_bicycle(p, "cm"),
                      speeds_kmh=[9.0, 17.0, 30.0]))
    # (d) a different design in inches: steeper head (lambda 15 deg), 6 cm of trail,
    #     a lighter rider further back and lower, a heavier front frame
    p = dict(BENCH, lam=math.radians(15), c=0.06, mB=70.0, xB=0.25, zB=-0.85,
             IBxx=7.5, IByy=9.0, IBzz=2.3, IBxz=1.9, mH=5.5, xH=0.92, zH=-0.75, IHxx=0.08, IHyy=0.085, IHzz=0.01,
             IHxz=-0.01, w=1.05, rF=0.33, rR=0.33)
    cases.append(dict(id="other-design-in", p=p, gyro=True, given=_yaml_bicycle(p, "in"),
                      speeds_kmh=[7.2, 16.0, 24.0]))
    # (e) the bigger copy without the wheels' spin angular momentum
    p = _scaled(BENCH, 1.1)
    cases.append(dict(id="scaled-no-spin", p=p, gyro=False,
                      given=_yaml_bicycle(p, "m") + "\n  gyroscopic: false",
                      speeds_kmh=[10.0, 18.0, 36.0]))
    # (f) the benchmark without spin and with zero trail
    p = dict(BENCH, c=0.0)
    cases.append(dict(id="benchmark-no-trail-no-spin", p=p, gyro=False,
                      given="  preset: benchmark\n  c: 0 m\n  gyroscopic: false",
                      speeds_kmh=[5.0, 18.0]))
    return cases


BIKE_CASES = _bicycle_cases()


@pytest.mark.parametrize("case", BIKE_CASES, ids=[c["id"] for c in BIKE_CASES])
def test_bicycle_against_own_meijaard_matrices(run, write, case):
    p = case["p"]
    mats = bicycle_matrices(p, gyroscopic=case["gyro"])
    g = p["g"]
    weave, capsize = bicycle_speeds(mats, g)
    first = True
    for vk in case["speeds_kmh"]:
        v = vk * KMH
        d = solve(run, write, f"""\
id: {case['id']}
kind: bicycle
given:
{case['given']}
  speed: {vk!r} km/h
find:
  weave_speed: m/s
  capsize_speed: m/s
  stable_speeds: m/s
  eigenvalues_real: s^-1
  eigenvalues_imag: s^-1
  motion: null
  M: kg m^2
  C1: kg m
  K0: kg m
  K2: kg
""")
        if first:
            first = False
            for name, mat in zip(("M", "C1", "K0", "K2"), mats):
                assert si(d, name) == pytest.approx(list(mat.ravel()), rel=1e-11, abs=1e-11)
            # weave and capsize speeds: every crossing my scan found
            assert si(d, "weave_speed") == pytest.approx(weave, rel=1e-9)
            assert si(d, "capsize_speed") == pytest.approx(capsize, rel=1e-9)
            # the self-stable range from the crossings: stable just inside, not outside
            crossings = sorted(weave + capsize)
            stable = []
            pts = [0.0] + crossings + [crossings[-1] * 1.5 + 1 if crossings else 60.0]
            for a, b in zip(pts[:-1], pts[1:]):
                if stable_at(mats, 0.5 * (a + b), g):
                    stable.append((a, b))
            flat = [x for ab in stable for x in ab]
            assert si(d, "stable_speeds") == pytest.approx(flat, rel=1e-9)
        ev = _sorted_eigs(bicycle_eigs(mats, v, g))
        scale = max(abs(e) for e in ev)
        assert si(d, "eigenvalues_real") == pytest.approx([e.real for e in ev], abs=1e-9 * scale)
        assert si(d, "eigenvalues_imag") == pytest.approx([e.imag for e in ev], abs=1e-9 * scale)
        # motion: which growing mode, from my eigenvalues
        grow_real = any(e.real > 0 and abs(e.imag) < 1e-9 * scale for e in ev)
        grow_osc = any(e.real > 0 and abs(e.imag) >= 1e-9 * scale for e in ev)
        word = {(False, False): "stable", (True, False): "capsize",
                (False, True): "weave", (True, True): "capsize and weave"}[(grow_real, grow_osc)]
        assert si(d, "motion") == [word]


def test_bicycle_growth_matches_integration():
    """The eigenvalues of my matrices describe the motion: integrate
    M q'' + v C1 q' + (g K0 + v^2 K2) q = 0 for the other design and compare the
    growth of the lean with the largest real part."""
    p = BIKE_CASES[3]["p"]
    mats = bicycle_matrices(p)
    M, C1, K0, K2 = mats
    g = p["g"]
    Minv = np.linalg.inv(M)
    for v in (1.5, 3.0, 8.0):
        ev = bicycle_eigs(mats, v, g)
        lead = max(ev, key=lambda e: e.real)

        def rhs(t, y):
            q, qd = y[:2], y[2:]
            return np.concatenate([qd, -Minv @ (v * C1 @ qd + (g * K0 + v * v * K2) @ q)])  # noqa: B023 (called in this iteration)
        others = [e for e in ev if abs(e - lead) > 1e-9 and abs(e - lead.conjugate()) > 1e-9]
        gap = lead.real - max(e.real for e in others)
        T = 30.0 / gap
        if abs(lead.imag) > 0:
            T = max(T, 12 * 2 * math.pi / abs(lead.imag))   # several periods in the window
        sol = solve_ivp(rhs, (0, T), [1e-3, 0, 0, 0], method="DOP853", rtol=1e-12,
                        atol=1e-20, dense_output=True)
        assert sol.success
        t1 = 0.6 * T
        if abs(lead.imag) > 0:
            # the measured period of the lean, from its zero crossings
            ts = np.linspace(t1, T, 20001)
            ph = sol.sol(ts)[0]
            idx = np.nonzero(np.sign(ph[:-1]) != np.sign(ph[1:]))[0]
            tz = [brentq(lambda t: sol.sol(t)[0], ts[i], ts[i + 1]) for i in idx]  # noqa: B023 (called in this iteration)
            P = 2 * np.polyfit(np.arange(len(tz)), tz, 1)[0]
            assert 2 * math.pi / P == pytest.approx(abs(lead.imag), rel=1e-5)
            n = max(1, int(0.3 * T / P))
            dt = n * P
        else:
            dt = 0.3 * T
        # over whole periods the dominant mode comes back to itself times exp(Re(s) dt)
        rate = math.log(np.linalg.norm(sol.sol(t1 + dt)) / np.linalg.norm(sol.sol(t1))) / dt
        assert rate == pytest.approx(lead.real, rel=1e-5, abs=1e-6 * abs(lead))
