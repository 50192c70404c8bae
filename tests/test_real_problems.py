"""Real problems as people write them (issue 8): least data, one-root keys, new answers.

Every answer is checked against a hand calculation written out here, or
against an independent method (vectors for the pivot's free body, numerical
integration for the released top), never against gyro's own formula.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from lagrange_top import integrate

from gyro_cli.solving.solve import solve_file

RPM = 2 * math.pi / 60
G_IN = 32.2 * 12  # in/s^2
IN = 0.0254
OZF = 0.27801385095378125  # N, 1/16 lbf


def si(path, name):
    return solve_file(str(path)).answers[name].si_values


TOP_11_3 = """\
id: x
kind: steady_precession
given: {weight: 3 oz, k_axial: 0.84 in, k_pivot: 1.80 in, cg_distance: 1.5 in,
        spin: 1800 rpm, theta: 30 deg}
find: {precession: rad/s, %s}
"""


# ---- the bundled problems written as other books state them ----------------

def test_toy_gyroscope_by_hand(problems_dir):
    m, g, l, J = 0.140 + 0.0250, 9.80, 0.0400, 1.20e-4
    Omega = 2 * math.pi / 2.20                      # one revolution in 2.20 s
    spin = m * g * l / (J * Omega)                  # torque = J omega Omega at 90 deg
    assert spin / RPM == pytest.approx(1802.5, abs=0.5)
    result = solve_file(str(problems_dir / "toy_gyroscope_pivot.yaml"))
    assert result.answers["spin"].si_values[0] == pytest.approx(spin, rel=1e-5)
    vertical, horizontal, size = result.answers["pivot_force"].si_values
    assert vertical == pytest.approx(m * g)         # 1.617 N, the book's 1.62 N
    assert horizontal == pytest.approx(m * l * Omega ** 2, rel=1e-5)
    assert size == pytest.approx(math.hypot(m * g, m * l * Omega ** 2), rel=1e-5)
    # no transverse inertia was read: none is given and none appears in the work
    text = json.dumps(solve_file(str(problems_dir / "toy_gyroscope_pivot.yaml")).solution.given,
                      default=str)
    assert "I_pivot" not in text and "k_pivot" not in text


def test_top_in_rev_per_s_and_cm_by_hand(problems_dir):
    m, g, r, I, omega = 0.492, 9.8, 0.0388, 5.12e-4, -28.6 * 2 * math.pi
    Omega = m * g * r / (I * omega)                 # the introductory-book formula
    assert Omega / (2 * math.pi) == pytest.approx(-0.3236, abs=1e-4)
    result = solve_file(str(problems_dir / "top_rev_per_s.yaml"))
    answer = result.answers["precession"]
    assert answer.si_values == [pytest.approx(Omega, rel=1e-9)]
    assert answer.labels == ["approximation"]
    assert any("exact roots need I" in w for w in result.solution.warnings)


def test_spherical_top_by_hand_and_without_its_mass(problems_dir, write):
    g, R, d, omega = 9.80, 0.030, 0.040, 1200 * RPM
    Omega = g * d / (0.4 * R * R * omega)           # M g d / (2/5 M R^2 omega): M cancels
    assert Omega / RPM == pytest.approx(82.75, abs=0.01)
    assert si(problems_dir / "spherical_top_knight.yaml", "precession") == \
        [pytest.approx(Omega, rel=1e-9)]
    assert si(problems_dir / "spherical_top_knight.yaml", "precession_period") == \
        [pytest.approx(2 * math.pi / Omega, rel=1e-9)]
    text = (problems_dir / "spherical_top_knight.yaml").read_text().replace("  mass: 75 g\n", "")
    path = write(text)
    assert si(path, "precession") == [pytest.approx(Omega, rel=1e-9)]


def test_aircraft_at_360_kmph_by_hand(problems_dir):
    I, omega, v, R = 500 * 0.25 ** 2, 2000 * RPM, 360 * 1000 / 3600, 100.0
    assert v == pytest.approx(100.0)
    couple = I * omega * v / R
    assert couple == pytest.approx(6545, abs=1)
    (moment,) = si(problems_dir / "aircraft_360_kmph.yaml", "moment")
    assert abs(moment) == pytest.approx(couple, rel=1e-9)


def test_answer_units_print_like_the_steps(run, problems_dir):
    out = run("solve", problems_dir / "aircraft_360_kmph.yaml")
    assert "M = 6.545 kN m" in out.stdout or "M = -6.545 kN m" in out.stdout
    assert "N*m" not in out.stdout.split("Answer")[1]


# ---- the least data ----------------------------------------------------------

def test_ninety_degrees_needs_no_transverse_inertia(run, write):
    path = write("""\
        id: x
        kind: steady_precession
        given: {mass: 2 kg, J: 0.005 kg m^2, cg_distance: 100 mm, spin: 3000 rpm,
                theta: 90 deg}
        find: {precession: rad/s}
        """)
    out = run("solve", path)
    assert out.exit_code == 0, out.output
    M, J, spin = 2 * 9.81 * 0.1, 0.005, 3000 * RPM
    assert "phidot = M / (J psidot) = 1.962 N m / (0.005000 kg m^2 (314.2 rad/s)) = 1.249 " \
           "rad/s" in out.stdout
    assert si(path, "precession") == [pytest.approx(M / (J * spin), rel=1e-12)]


def test_exact_roots_away_from_ninety_degrees_need_i(run, write):
    path = write("""\
        id: x
        kind: steady_precession
        given: {mass: 2 kg, J: 0.005 kg m^2, cg_distance: 100 mm, spin: 3000 rpm,
                theta: 60 deg}
        find: {precession_slow: rad/s}
        """)
    out = run("solve", path)
    assert out.exit_code == 2
    assert out.stderr.count("\n") == 1 and "given.I_pivot" in out.stderr
    assert "transverse inertia" in out.stderr


def test_approximation_beside_the_exact_roots(write):
    path = write(TOP_11_3 % "precession_approx: rad/s")
    result = solve_file(str(path))
    # m g l / (J psidot) = W l / ((W/g) k_z^2 psidot) = g l / (k_z^2 psidot), inches
    approx = G_IN * 1.5 / (0.84 ** 2 * 1800 * RPM)
    assert approx == pytest.approx(4.358, abs=1e-3)
    assert result.answers["precession_approx"].si_values == [pytest.approx(approx, rel=1e-6)]
    slow = min(result.answers["precession"].si_values, key=abs)
    line = next(s.text for sec in result.solution.sections for s in sec.steps
                if "from the slow root" in s.text)
    assert f"{abs(approx - slow) / slow * 100:.3g}%" in line


def test_torque_free_body_has_no_zero_root_and_needs_no_mass(write):
    path = write("""\
        id: x
        kind: steady_precession
        given: {J: 0.02 kg m^2, I_pivot: 0.01 kg m^2, cg_distance: 0 m, spin: 100 rad/s,
                theta: 30 deg}
        find: {precession: rad/s}
        """)
    # (J - I) cos(theta) phidot^2 + J psidot phidot = 0: phidot = 0 or -J psidot / ((J - I) cos)
    only = -0.02 * 100 / ((0.02 - 0.01) * math.cos(math.radians(30)))
    assert si(path, "precession") == [pytest.approx(only, rel=1e-12)]


def test_zero_spin_is_too_low_without_a_least_of_zero(run, write):
    path = write("""\
        id: x
        kind: steady_precession
        given: {mass: 2 kg, J: 0.005 kg m^2, cg_distance: 100 mm, spin: 0 rpm, theta: 90 deg}
        find: {precession: rad/s}
        """)
    out = run("solve", path)
    assert out.exit_code == 2 and "too low" in out.stderr
    assert "the least is 0" not in out.stderr and out.stderr.count("\n") == 1


def test_textbook_inertia_no_body_has_is_solved_with_a_warning(run, write):
    # k about the pivot (1.0 in) shorter than the pivot-to-centre distance (1.5 in)
    path = write(TOP_11_3.replace("1.80 in", "1.0 in").replace("1800 rpm", "3000 rpm")
                 % "min_spin: rpm" + "expected: {precession: [1 rad/s, 2 rad/s]}\n")
    out = run("solve", path)
    assert out.exit_code == 0, out.output
    assert "k_pivot" in out.stdout and "no rigid body" in out.stdout
    checked = run("check", path)
    assert "! k_pivot" in checked.stdout  # the warning beside the answers


# ---- answers people ask for ----------------------------------------------------

def test_period_speed_and_acceleration_of_the_centre_by_hand(write):
    path = write(TOP_11_3 % "precession_period: s, cg_speed: m/s, cg_acceleration: m/s^2")
    result = solve_file(str(path))
    rates = result.answers["precession"].si_values
    radius = 1.5 * IN * math.sin(math.radians(30))   # the centre's circle
    assert result.answers["precession_period"].si_values == \
        [pytest.approx(2 * math.pi / abs(p)) for p in rates]
    assert result.answers["cg_speed"].si_values == [pytest.approx(radius * abs(p)) for p in rates]
    assert result.answers["cg_acceleration"].si_values == \
        [pytest.approx(radius * p * p) for p in rates]
    # the slow root 45.13 rpm turns once in 60 / 45.13 s
    assert result.answers["precession_period"].si_values[0] == pytest.approx(60 / 45.13, rel=1e-3)


def test_pivot_force_free_body(write):
    """The pivot force from gyro against a free body drawn with vectors.

    (1) Kinematics: the centre of mass r_G(t) = l (sin th cos phi, sin th sin phi, cos th)
        differentiated twice numerically gives a_G; F = m a_G - m g.
    (2) Moments about G: r_OG x ... the moment of F about G must equal dH_G/dt,
        with H_G = J omega_z k + I_G (omega - omega_z k) turning at phidot about Z.
    """
    path = write(TOP_11_3 % "pivot_force: N")
    result = solve_file(str(path))
    body = result.problem.given.body
    m, g, l, J, I_G = body.m, body.g, body.l, body.J, body.I_pivot - body.m * body.l ** 2
    theta, spin = math.radians(30), 1800 * RPM
    rates = result.answers["precession"].si_values
    values = result.answers["pivot_force"].si_values
    assert values[0] == pytest.approx(m * g)
    for i, p in enumerate(rates):
        horizontal, size = values[1 + 2 * i], values[2 + 2 * i]

        def r_G(t):
            return l * np.array([math.sin(theta) * math.cos(p * t),  # noqa: B023 (called in this iteration)
                                 math.sin(theta) * math.sin(p * t), math.cos(theta)])  # noqa: B023 (called in this iteration)
        h = 1e-4 / abs(p)
        a_G = (r_G(h) - 2 * r_G(0) + r_G(-h)) / h ** 2
        F = m * a_G - m * np.array([0, 0, -g])
        assert F[2] == pytest.approx(values[0], rel=1e-6)
        assert -F[0] == pytest.approx(horizontal, rel=1e-5)   # toward the axis: -x here
        assert np.linalg.norm(F) == pytest.approx(size, rel=1e-5)
        # moments about G
        Z = np.array([0.0, 0.0, 1.0])
        k = np.array([math.sin(theta), 0.0, math.cos(theta)])
        omega = p * Z + spin * k
        wz = omega @ k
        H_G = J * wz * k + I_G * (omega - wz * k)
        dH = p * np.cross(Z, H_G)
        moment = np.cross(-r_G(0), F)               # the force acts at O, G -> O = -r_G
        assert moment == pytest.approx(dH, rel=1e-6, abs=1e-9 * np.linalg.norm(dH))


def test_one_root_by_name_and_spin_roots(write):
    path = write(TOP_11_3 % "precession_slow: rpm, precession_fast: rpm")
    result = solve_file(str(path))
    assert result.answers["precession_slow"].values == [pytest.approx(45.13, abs=0.01)]
    assert result.answers["precession_fast"].values == [pytest.approx(533.5, abs=0.1)]
    # given omega_z, the spin has two roots: psidot = omega_z - phidot cos(theta)
    path = write(TOP_11_3.replace("spin: 1800 rpm", "axial_rate: 1800 rpm")
                 % "spin_slow: rpm, spin_fast: rpm", "b.yaml")
    result = solve_file(str(path))
    rates = result.answers["precession"]
    for which in ("slow", "fast"):
        p = rates.si_values[rates.labels.index(which)]
        assert result.answers[f"spin_{which}"].si_values == \
            [pytest.approx(1800 * RPM - p * math.cos(math.radians(30)))]


def test_gyroscopic_moment_along_the_precession_axis_is_zero(run, write):
    for theta in ("0 deg", "180 deg"):
        path = write(f"""\
            id: ship
            kind: gyroscopic_torque
            given: {{mass: 500 kg, k_axial: 0.4 m, spin: 3000 rpm, precession: 0.1 rad/s,
                    theta: {theta}}}
            find: {{moment: N m}}
            """)
        out = run("solve", path)
        assert out.exit_code == 0, out.output
        assert "no gyroscopic moment" in out.stdout
        assert si(path, "moment") == [0.0]


def test_released_top_spin_at_limits_and_reversal_against_integration(problems_dir):
    result = solve_file(str(problems_dir / "11_2_released_top_loops.yaml"))
    problem = result.problem
    problem.find.update({"spin_at_limits": "rad/s", "reversal_theta": "deg"})
    from gyro_cli.solving.solve import solve
    result = solve(problem)
    body = problem.given.body
    measured = integrate(body.I_pivot, body.J, body.mgl, math.radians(30), 1800 * RPM,
                         precession0=-20 * RPM, t_end=0.5)
    sol = measured.sol
    t = np.linspace(0, 0.5, 200001)
    th, _, _, thd, phd, psd = sol.sol(t)
    at_max, at_min = result.answers["spin_at_limits"].si_values
    i_max, i_min = np.argmax(th), np.argmin(th[1000:]) + 1000
    assert psd[i_max] == pytest.approx(at_max, rel=1e-6)
    assert psd[i_min] == pytest.approx(at_min, rel=1e-6)
    # where phidot changes sign, theta is the reversal angle
    crossings = np.where(np.diff(np.sign(phd)) != 0)[0]
    assert len(crossings) > 0
    (theta_rev,) = result.answers["reversal_theta"].si_values
    for c in crossings[:4]:
        assert th[c] == pytest.approx(theta_rev, abs=2e-5)


# ---- check: keys with fewer roots, magnitudes, percent -------------------------

def test_check_one_keyed_root_named_root_magnitude_and_percent(run, write):
    one = write(TOP_11_3 % "min_spin: rpm" + "expected: {precession: 45.13 rpm}\n")
    out = run("check", one)
    assert out.exit_code == 0 and "not keyed" in out.stdout
    assert run("check", "--strict", one).exit_code == 1
    named = write(TOP_11_3 % "min_spin: rpm" + "expected: {precession_slow: 45.13 rpm}\n"
                  "tolerance: 1 percent\n", "named.yaml")
    out = run("check", "--strict", named)
    assert out.exit_code == 0, out.stdout
    flipped = write(TOP_11_3 % "min_spin: rpm" + "expected: {precession_slow: -45.13 rpm}\n",
                    "flipped.yaml")
    out = run("check", flipped)
    assert out.exit_code == 1 and "likely slip: the sign" in out.stdout
    magnitude = write(TOP_11_3 % "min_spin: rpm" + "expected: {precession_slow: -45.13 rpm}\n"
                      "tolerance: 1% magnitude\n", "magnitude.yaml")
    assert run("check", magnitude).exit_code == 0


def test_solve_a_directory(run, problems_dir):
    out = run("solve", "--format", "json", problems_dir)
    assert out.exit_code == 0
    files = sorted(p for p in problems_dir.glob("*.yaml"))
    assert len(out.stdout.strip().splitlines()) == len(files)


def test_misspelt_compound_key_suggests_its_family(run, write):
    path = write("""\
        id: x
        kind: gyroscopic_torque
        given: {mass: 500 kg, k_axial: 0.4 m, spin: 3000 rpm, speed: 36 km/h,
                turn_diameter: 200 m, theta: 90 deg}
        find: {moment: N m}
        """)
    out = run("solve", path)
    assert out.exit_code == 2 and "did you mean 'turn_radius'" in out.stderr


def test_kinds_and_schema_list_the_new_answers_and_units(run):
    import re

    from gyro_cli.commands.authoring import QUANTITY_PATTERN, schema

    listing = run("kinds").stdout
    for name in ("precession_slow", "precession_fast", "spin_slow", "spin_fast",
                 "precession_approx", "pivot_force", "precession_period", "cg_speed",
                 "cg_acceleration", "spin_at_limits", "reversal_theta"):
        assert name in listing
        assert name in json.dumps(schema())
    for unit in ("kmph", "rev/min", "N-m", "lb ft", "tonne"):
        assert unit in listing
    for text in ("2 N.m", "2 N-m", "360 kmph", "5 1/s", "50 lb-ft", "60 r/min"):
        assert re.match(QUANTITY_PATTERN, text), text


def test_coin_rolling_by_itself_needs_no_mass(write):
    """A coin (uniform disk) rolling on a circle, given by shape and radius only.

    Moments about G per unit mass (J = r^2/2, I_G = r^2/4 per kg):
    g r sin(b) = Omega^2 cos(b) [rho (r + J/r) + I_G sin(b)], Omega = v / rho, so
    g r sin(b) rho^2 - v^2 cos(b) (3 r / 2) rho - v^2 cos(b) (r^2 / 4) sin(b) = 0.
    """
    r, v, b, g = 0.012, 0.5, math.radians(10), 9.81
    qa, qb, qc = g * r * math.sin(b), -v * v * math.cos(b) * 1.5 * r, \
        -v * v * math.cos(b) * r * r / 4 * math.sin(b)
    rho = (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)
    text = """\
        id: coin
        kind: rolling_disk
        given: {arrangement: free, %sshape: disk, radius: 12 mm, speed: 0.5 m/s, tilt: 10 deg}
        find: {precession: rad/s, path_radius: mm}
        """
    for mass in ("", "mass: 5 g, "):
        path = write(text % mass, f"coin{len(mass)}.yaml")
        assert si(path, "precession") == [pytest.approx(v / rho, rel=1e-9)]
        assert si(path, "path_radius") == [pytest.approx(rho + r * math.sin(b), rel=1e-9)]


def test_force_answer_in_lb_and_expected_in_n_dot_m(run, write):
    path = write(TOP_11_3 % "pivot_force: lb" + "expected: {moment: 0.01589 N.m}\n")
    result = solve_file(str(path))
    reported = result.answers["pivot_force"]
    assert reported.unit == "lbf"
    assert reported.values[0] == pytest.approx(3 / 16, rel=1e-9)  # the weight, 3 ozf, in lbf
    out = run("check", path)
    assert out.exit_code == 0, out.stdout
    assert "0.01589 N m (slow)" in out.stdout  # got: as the steps print it


def test_applied_moment_of_zero_has_no_zero_root(write):
    path = write("""\
        id: x
        kind: steady_precession
        given: {J: 0.02 kg m^2, I_pivot: 0.01 kg m^2, moment: 0 N m, spin: 100 rad/s,
                theta: 60 deg}
        find: {precession: rad/s}
        """)
    assert si(path, "precession") == [pytest.approx(-0.02 * 100 / (0.01 * 0.5), rel=1e-12)]


def test_simulate_without_transverse_inertia_is_one_line(run, problems_dir):
    out = run("simulate", problems_dir / "toy_gyroscope_pivot.yaml", "--periods", "1")
    assert out.exit_code == 2 and out.stderr.count("\n") == 1
    assert "given.I_pivot" in out.stderr and "Traceback" not in out.stderr


@pytest.mark.parametrize("spin", ["1800 rpm*", "1800 ()", "1800 (rpm", "1800 rpm)", "1800 rmp",
                                  "1800 mrpm"])
def test_bad_unit_roots_exit_2_with_one_line(run, write, spin):
    path = write(TOP_11_3.replace("1800 rpm", f'"{spin}"') % "min_spin: rpm")
    out = run("solve", path)
    assert out.exit_code == 2 and out.stdout == ""
    assert out.stderr.count("\n") == 1 and "given.spin" in out.stderr
    assert "Traceback" not in out.stderr and "AssertionError" not in out.stderr
