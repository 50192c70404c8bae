"""Steady precession checked against independent methods.

(a) the equations of motion (Eqs. 11.13-11.16) integrated from the computed
    steady state keep theta constant and precess at the computed rate;
(b) problem 11/3 and 11/1 worked by hand, step by step, in the test;
(c) the same problem in SI and in US units gives the same SI answer.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from gyro_cli.solving.solve import solve_file

RPM = 2 * math.pi / 60


def integrate_top(I, J, D, theta, spin, precession, periods=3.0):
    """Integrate Lagrange's equations (11.13) for theta, phi from a given state.

    The momentum integrals (11.14) give phidot; the theta equation gives
    thetaddot. The moment about the line of nodes is D sin(theta) (gravity's
    m g l sin(theta) when D = m g l).
    """
    P2 = J * (spin + precession * math.cos(theta))
    P1 = I * precession * math.sin(theta) ** 2 + P2 * math.cos(theta)

    def rhs(t, y):
        th, thdot, phi = y
        s, c = math.sin(th), math.cos(th)
        phidot = (P1 - P2 * c) / (I * s * s)
        thddot = (I * phidot ** 2 * s * c - P2 * phidot * s + D * s) / I
        return [thdot, thddot, phidot]

    T = periods * 2 * math.pi / abs(precession)
    sol = solve_ivp(rhs, (0, T), [theta, 0.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14,
                    dense_output=True)
    t = np.linspace(0, T, 2001)
    th, _, phi = sol.sol(t)
    return t, th, phi


def answers(path):
    return solve_file(str(path)).answers


@pytest.mark.parametrize("name", ["11_3.yaml"])
def test_integration_keeps_theta_and_rate(problems_dir, name):
    result = solve_file(str(problems_dir / name))
    body = result.problem.given.body
    theta = result.problem.given["theta"]
    spin = result.problem.given["spin"]
    for precession in result.answers["precession"].si_values:
        t, th, phi = integrate_top(body.I_pivot, body.J, body.mgl, theta, spin, precession)
        assert np.max(np.abs(th - theta)) < 1e-8
        mean_rate = (phi[-1] - phi[0]) / (t[-1] - t[0])
        assert mean_rate == pytest.approx(precession, rel=1e-8)


@pytest.mark.parametrize("name", ["11_1.yaml", "11_2.yaml"])
def test_integration_with_spin_answer(problems_dir, name):
    """For 11/1 and 11/2 the computed spin must make theta stay put at phidot = 36 rpm."""
    result = solve_file(str(problems_dir / name))
    body = result.problem.given.body
    theta = result.problem.given["theta"]
    precession = result.problem.given["precession"]
    spin = result.answers["spin"].si_values[0]
    t, th, phi = integrate_top(body.I_pivot, body.J, body.mgl, theta, spin, precession)
    assert np.max(np.abs(th - theta)) < 1e-8
    assert (phi[-1] - phi[0]) / t[-1] == pytest.approx(precession, rel=1e-8)


def test_wrong_spin_does_not_stay_steady(problems_dir):
    """The integration test can fail: 1% off the slow root, theta moves."""
    result = solve_file(str(problems_dir / "11_3.yaml"))
    body = result.problem.given.body
    theta, spin = result.problem.given["theta"], result.problem.given["spin"]
    slow = result.answers["precession"].si_values[0]
    _, th, _ = integrate_top(body.I_pivot, body.J, body.mgl, theta, spin, 1.01 * slow)
    assert np.max(np.abs(th - theta)) > 1e-4


def test_11_3_by_hand(problems_dir):
    """Problem 11/3 worked by hand with the textbook's g = 32.2 ft/s^2."""
    inch = 0.0254
    ozf = 0.45359237 / 16 * 9.80665          # N
    g = 32.2 * 0.3048                        # m/s^2
    m = 3 * ozf / g                          # 0.084980 kg
    J = m * (0.84 * inch) ** 2               # 3.8685e-5 kg m^2
    I = m * (1.80 * inch) ** 2               # 1.7764e-4 kg m^2
    mgl = 3 * ozf * 1.5 * inch               # 0.031777 N m
    spin = 1800 * RPM                        # 188.50 rad/s
    c = math.cos(math.radians(30))
    # (J - I) c phidot^2 + J spin phidot - m g l = 0, i.e. A x^2 + B x + C = 0
    A, B, C = (J - I) * c, J * spin, -mgl
    disc = B * B - 4 * A * C
    slow, fast = sorted([(-B + math.sqrt(disc)) / (2 * A), (-B - math.sqrt(disc)) / (2 * A)])
    assert slow / RPM == pytest.approx(45.13, abs=0.005)   # the textbook's 45.1 rpm
    assert fast / RPM == pytest.approx(533.5, abs=0.05)    # the textbook's 534 rpm
    got = answers(problems_dir / "11_3.yaml")["precession"]
    assert got.unit == "rpm"
    assert got.si_values == pytest.approx([slow, fast], rel=1e-12)
    assert got.values == pytest.approx([slow / RPM, fast / RPM], rel=1e-12)
    least = 2 * math.sqrt((I - J) * mgl * c) / J
    assert answers(problems_dir / "11_3.yaml")["min_spin"].si_values[0] == \
        pytest.approx(least, rel=1e-12)


@pytest.mark.parametrize("name,theta_deg,printed", [("11_1.yaml", 120, 3006),
                                                    ("11_2.yaml", 150, 1326)])
def test_11_1_and_11_2_by_hand(problems_dir, name, theta_deg, printed):
    """11/1, 11/2: thin disk 2 kg, r = 75 mm, l = 0.6 m, theta = 180 - beta, phidot = 36 rpm."""
    m, r, l, g = 2.0, 0.075, 0.6, 9.81
    J = m * r * r / 2
    I = m * r * r / 4 + m * l * l
    phidot = 36 * RPM
    c = math.cos(math.radians(theta_deg))
    # Moment balance about the line of nodes (dH/dt = M), sin(theta) divided out:
    #   phidot (J omega_z - I phidot cos) = m g l,   omega_z = psidot + phidot cos
    omega_z = (m * g * l + I * phidot ** 2 * c) / (J * phidot)
    psidot = omega_z - phidot * c
    assert psidot / RPM == pytest.approx(printed, abs=0.5)
    assert answers(problems_dir / name)["spin"].si_values[0] == pytest.approx(psidot,
                                                                                        rel=1e-12)


def test_unit_invariance(write, problems_dir):
    """11/3 written in SI with exact conversion factors gives the same SI answers."""
    inch, ozf, g = 0.0254, 0.45359237 / 16 * 9.80665, 32.2 * 0.3048
    si = write(f"""
        id: si
        kind: steady_precession
        given:
          weight: {3 * ozf!r} N
          g: {g!r} m/s^2
          k_axial: {0.84 * inch!r} m
          k_pivot: {1.80 * inch!r} m
          cg_distance: {1.5 * inch!r} m
          spin: {1800 * RPM!r} rad/s
          theta: {math.pi / 6!r} rad
        find: {{precession: rad/s, min_spin: rad/s}}
    """)
    us, metric = answers(problems_dir / "11_3.yaml"), answers(si)
    for name in ("precession", "min_spin"):
        assert metric[name].si_values == pytest.approx(us[name].si_values, rel=1e-12)


def test_mass_in_slug_and_pound_mass_use_us_g(write):
    """A mass in US units (lb = pound mass) also means the textbook g."""
    base = """
        id: x
        kind: steady_precession
        given: {{mass: {mass}, J: 1e-4 kg m^2, I_pivot: 2e-3 kg m^2, cg_distance: 0.05 m,
                spin: 3000 rpm, theta: 60 deg}}
        find: {{precession: rad/s}}
    """
    lb = answers(write(base.format(mass="1 lb"), "lb.yaml"))["precession"].si_values
    kg = answers(write(base.format(mass=f"{0.45359237!r} kg") + "", "kg.yaml"))
    ratio = (32.2 * 0.3048) / 9.81
    # The slow root is close to m g l / (J omega_z): it scales with g.
    assert lb[0] / kg["precession"].si_values[0] == pytest.approx(ratio, rel=1e-3)


def test_axial_rate_route_agrees_with_spin_route(write):
    """Given omega_z instead of psidot (Eq. 11.20), the roots satisfy the kinematics."""
    common = """
        id: x
        kind: steady_precession
        given: {{mass: 0.5 kg, k_axial: 20 mm, k_pivot: 45 mm, cg_distance: 40 mm,
                theta: 50 deg, {rate}}}
        find: {{precession: rad/s, spin: rad/s, axial_rate: rad/s}}
    """
    by_spin = answers(write(common.format(rate="spin: 200 rad/s"), "a.yaml"))
    omega_slow = by_spin["axial_rate"].si_values[0]
    by_axial = answers(write(common.format(rate=f"axial_rate: {omega_slow!r} rad/s"), "b.yaml"))
    # The slow root for this omega_z must be the slow root for the spin.
    assert by_axial["precession"].si_values[0] == pytest.approx(
        by_spin["precession"].si_values[0], rel=1e-10)
    assert by_axial["spin"].si_values[0] == pytest.approx(200, rel=1e-10)


def test_ninety_degrees_has_one_root(write):
    """At theta = 90 deg the phidot^2 term vanishes: phidot = m g l / (J psidot)."""
    path = write("""
        id: x
        kind: steady_precession
        given: {mass: 1 kg, J: 2e-3 kg m^2, I_pivot: 0.02 kg m^2, cg_distance: 0.1 m,
                spin: 100 rad/s, theta: 90 deg}
        find: {precession: rad/s}
    """)
    got = answers(path)["precession"].si_values
    assert got == pytest.approx([1 * 9.81 * 0.1 / (2e-3 * 100)], rel=1e-12)


def test_applied_moment_replaces_gravity(write):
    """A gyroscope with l = 0 driven by an applied moment M about the line of nodes."""
    path = write("""
        id: x
        kind: steady_precession
        given: {J: 0.01 kg m^2, I_pivot: 0.006 kg m^2, spin: 500 rad/s, theta: 90 deg,
                moment: 2 N m}
        find: {precession: rad/s}
    """)
    # Eq. 11.29 at theta = 90 deg: M = J phidot psidot.
    assert answers(path)["precession"].si_values == pytest.approx([2 / (0.01 * 500)], rel=1e-12)


def test_moment_for_given_motion(write):
    """Given spin and precession, the moment is the rate of change of H (finite differences)."""
    I, J, theta, spin, phidot = 0.02, 0.005, math.radians(70), 150.0, 3.0
    path = write(f"""
        id: x
        kind: steady_precession
        given: {{J: {J} kg m^2, I_pivot: {I} kg m^2, spin: {spin} rad/s,
                theta: 70 deg, precession: {phidot} rad/s}}
        find: {{moment: N m}}
    """)

    def H(t):
        # Angular momentum in space: body axes k (symmetry) and the two transverse ones.
        phi = phidot * t
        k = np.array([math.sin(theta) * math.sin(phi), -math.sin(theta) * math.cos(phi),
                      math.cos(theta)])
        omega = phidot * np.array([0, 0, 1.0]) + spin * k
        omega_axial = omega @ k
        return J * omega_axial * k + I * (omega - omega_axial * k)

    h = 1e-4
    dHdt = (H(h) - H(-h)) / (2 * h)
    got = answers(path)["moment"].si_values[0]
    assert abs(got) == pytest.approx(np.linalg.norm(dHdt), rel=1e-7)


def test_json_output_contract(run, problems_dir):
    out = run("solve", "--format", "json", problems_dir / "11_3.yaml", problems_dir / "11_1.yaml")
    assert out.exit_code == 0, out.output
    lines = out.stdout.strip().splitlines()
    assert len(lines) == 2
    doc = json.loads(lines[0])
    assert doc["id"] == "11/3" and doc["kind"] == "steady_precession"
    assert doc["answers"]["precession"]["unit"] == "rpm"
    assert doc["answers"]["precession"]["si_unit"] == "rad/s"
    assert len(doc["answers"]["precession"]["values"]) == 2
    assert doc["steps"] and isinstance(doc["warnings"], list)


def test_text_output_shows_work(run, problems_dir):
    out = run("solve", problems_dir / "11_3.yaml")
    assert out.exit_code == 0
    for piece in ("Given", "Body", "Eq. 11.13", "Eq. 11.21", "45.13 rpm (slow)",
                  "533.5 rpm (fast)", "32.2 ft/s^2", "ozf"):
        assert piece in out.stdout


def _least_of_11_3() -> tuple[float, float]:
    """11/3's least psidot and least omega_z, by hand, in rpm: W = 3 ozf, l = 1.5 in,
    k = 0.84 in and 1.80 in, theta = 30 deg, the US textbook g = 32.2 ft/s^2 (no mass
    given). The least psidot is the discriminant of Eq. 11.13 at a given psidot,
    (J - I) cos(theta) phidot^2 + J psidot phidot - W l = 0: J^2 psidot^2 >= 4 (I - J) W l
    cos(theta); the least omega_z is Eq. 11.21 corrected: J^2 omega_z^2 >= 4 I W l
    cos(theta). 965.4 rpm and 1092 rpm: two bounds on two rates, not one."""
    inch, g = 0.0254, 32.2 * 0.3048
    weight = 3 / 16 * 4.4482216152605
    m, Wl, c = weight / g, weight * 1.5 * inch, math.cos(math.radians(30))
    J, I = m * (0.84 * inch) ** 2, m * (1.80 * inch) ** 2
    rpm = 2 * math.pi / 60
    return 2 * math.sqrt((I - J) * Wl * c) / J / rpm, 2 * math.sqrt(I * Wl * c) / J / rpm


@pytest.mark.parametrize("rate, where", [("spin", "the discriminant of Eq. 11.13; Eq. 11.21 "
                                          "is its omega_z form"), ("axial_rate", "Eq. 11.21")])
def test_each_least_rate_cites_where_it_comes_from(problems_dir, tmp_path, run, rate, where):
    least = dict(zip(("spin", "axial_rate"), _least_of_11_3()))[rate]
    assert f"{least:.1f}" == {"spin": "965.4", "axial_rate": "1091.6"}[rate]
    text = (problems_dir / "11_3.yaml").read_text().replace("spin: 1800 rpm", f"{rate}: 500 rpm")
    text = text.split("\nstatement:")[0] + "\n"  # the statement names {spin}
    (tmp_path / "low.yaml").write_text(text)
    result = run("solve", tmp_path / "low.yaml")
    assert result.exit_code == 2, result.output
    assert f"({least:.4g} rpm), {where}" in result.output, result.output
    if rate == "spin":  # the worked answer's own line, at 1800 rpm
        out = run("solve", problems_dir / "11_3.yaml").stdout
        assert f"= 101.1 rad/s    ({where})" in out and "(Eq. 11.21)" not in out
