"""Problems as other books state them, round three (issue 23).

Each test writes the book's data as printed and checks gyro's answer against a
derivation by hand written out here (or an independent method: bisection on a
residual, a balance of moments), never against gyro's own formula.
"""

from __future__ import annotations

import math

import pytest

from gyro_cli.solving.solve import solve_file

RPM = 2 * math.pi / 60


def si(path, name):
    return solve_file(str(path)).answers[name].si_values


def _bisect(f, lo, hi, n=200):
    """A root of f in [lo, hi] by bisection (f changes sign there)."""
    for _ in range(n):
        mid = (lo + hi) / 2
        if (f(lo) < 0) == (f(mid) < 0):
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


# ---- item 1: steady_precession without theta ------------------------------

def test_giancoli_toy_gyroscope_without_an_angle(problems_dir):
    # Giancoli 11-41: 170 g disk, r = 5.5 cm, centre 21/2 cm from the stand, 45 rev/s.
    m, r, l, g = 0.170, 0.055, 0.105, 9.80
    J = m * r * r / 2                            # 2.571e-4 kg m^2, a uniform disk
    omega = 45 * 2 * math.pi                     # 282.7 rad/s
    torque = m * g * l                           # 0.1749 N m, the axle horizontal
    L_horizontal = J * omega                     # 0.07270 kg m^2/s
    Omega = torque / L_horizontal                # dL/dt = torque: 2.406 rad/s
    T = 2 * math.pi / Omega
    assert T == pytest.approx(2.611, abs=1e-3)   # the book: 2.6 s
    result = solve_file(str(problems_dir / "toy_gyroscope_no_angle.yaml"))
    assert result.answers["precession_approx"].si_values == [pytest.approx(Omega, rel=1e-9)]
    assert result.answers["precession_period"].si_values == [pytest.approx(T, rel=1e-9)]
    assert result.answers["precession_period"].labels == ["approximation"]
    warning = " ".join(result.solution.warnings)
    assert "no theta given" in warning and "need theta" in warning


def test_without_theta_the_warning_says_how_far_the_exact_root_moves(problems_dir):
    # The exact slow root at 30 deg, found by bisection on the moment balance
    # dH/dt = phidot sin(th) (J omega_z - I phidot cos(th)) = m g l sin(th),
    # omega_z = psidot + phidot cos(th), I about the stand by parallel axes.
    m, r, l, g = 0.170, 0.055, 0.105, 9.80
    J, I = m * r * r / 2, m * r * r / 4 + m * l * l
    psidot, th = 45 * 2 * math.pi, math.radians(30)

    def residual(phidot):
        omega_z = psidot + phidot * math.cos(th)
        return phidot * math.sin(th) * (J * omega_z - I * phidot * math.cos(th)) \
            - m * g * l * math.sin(th)

    slow30 = _bisect(residual, 0.0, 10.0)
    at90 = m * g * l / (J * psidot)              # exact at 90 deg
    assert slow30 == pytest.approx(2.540, abs=1e-3)
    warning = " ".join(solve_file(str(problems_dir / "toy_gyroscope_no_angle.yaml"))
                       .solution.warnings)
    assert f"{slow30:.3f} rad/s at 30 deg" in warning
    assert f"{abs(slow30 - at90) / at90 * 100:.2g}% apart" in warning


def test_without_theta_a_spin_for_a_precession_and_no_inertia(write):
    # Young and Freedman's toy gyroscope turned round: one turn in 2.20 s, what spin?
    # m g l = J omega Omega -> omega = m g l / (J Omega).
    m, g, l, J = 0.165, 9.80, 0.0400, 1.20e-4
    Omega = 2 * math.pi / 2.20
    omega = m * g * l / (J * Omega)
    assert omega / RPM == pytest.approx(1802.5, abs=0.5)
    path = write("""\
        id: x
        kind: steady_precession
        given: {mass: 165 g, J: 1.20e-4 kg m^2, cg_distance: 4.00 cm, g: 9.80 m/s^2,
                precession: 0.4545 rev/s}
        find: {spin: rpm}
        """)
    result = solve_file(str(path))
    assert result.answers["spin"].si_values == [pytest.approx(omega, rel=1e-3)]
    assert result.answers["spin"].labels == ["approximation"]
    assert any("transverse inertia I" in w for w in result.solution.warnings)


@pytest.mark.parametrize("find", ["cg_speed", "pivot_force", "min_spin", "precession_slow",
                                  "moment", "axial_rate"])
def test_without_theta_answers_that_need_it_are_refused_in_one_line(run, write, find):
    path = write(f"""\
        id: x
        kind: steady_precession
        given: {{mass: 170 g, shape: disk, radius: 5.5 cm, cg_distance: 10.5 cm,
                spin: 45 rev/s}}
        find: {{precession: rad/s, {find}: null}}
        """)
    out = run("solve", path)
    assert out.exit_code == 2, out.stdout
    assert out.stderr.count("\n") == 1 and "given.theta" in out.stderr
    assert "Traceback" not in out.stderr
