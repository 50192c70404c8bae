"""Issue 35, round four, item 6: the least data, in the books' words.

A wheel by its diameter, an axis's angle from the horizontal or the downward vertical,
a shape with no size where only ratios matter, US data in inches with no mass. Every
number is worked by hand here (or integrated numerically), never by calling gyro's
formula again.
"""

from __future__ import annotations

import math

import pytest

DRIVE = ("id: x\nkind: gyroscopic_torque\n"
         "given: {{J: 180 kg m^2, speed: 95 km/h, {wheel}, precession: 0.1 rad/s}}\n"
         "find: {{moment: N m}}\n")


def _one_line_refusal(result, key: str) -> None:
    assert result.exit_code == 2, result.output
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and key in lines[0], result.stderr
    assert "Traceback" not in result.output


# ---- a. wheel_diameter wherever wheel_radius is ---------------------------------------

def test_item6a_wheel_diameter_gives_the_radius(write, run):
    """Khurmi's locomotive: treads 1.8 m in diameter, 95 km/h; spin = v / (d / 2)."""
    result = run("solve", write(DRIVE.format(wheel="wheel_diameter: 1.8 m")))
    assert result.exit_code == 0, result.output
    v = 95 / 3.6
    spin = v / 0.9
    assert f"{spin:.4g}" in result.stdout  # 29.32 rad/s
    assert f"{180 * spin * 0.1:.4g}" in result.stdout  # 527.8 N m
    assert "r_w = d_w / 2" in result.stdout  # the conversion, shown


def test_item6a_wheel_diameter_on_a_two_wheeler(write, run):
    """The motorcycle of the chapter with wheels 600 mm across: the same answers as
    with wheel_radius 300 mm (a radius of half the diameter)."""
    text = ("id: m\nkind: two_wheeler\ngiven: {{mass: 250 kg, cg_height: 0.6 m, wheel_inertia: "
            "1 kg*m^2, {wheel}, engine_inertia: 0.3 kg*m^2, gear_ratio: 5, speed: 90 km/h, "
            "turn_radius: 50 m}}\nfind: [heel_angle]\n")
    by_d = run("solve", write(text.format(wheel="wheel_diameter: 600 mm"), "d.yaml"))
    by_r = run("solve", write(text.format(wheel="wheel_radius: 300 mm"), "r.yaml"))
    assert by_d.exit_code == 0, by_d.output
    heel = [line for line in by_d.stdout.splitlines() if "heel_angle" in line]
    assert heel and heel == [line for line in by_r.stdout.splitlines() if "heel_angle" in line]


@pytest.mark.parametrize("wheel, words", [
    ("wheel_diameter: 1.8 m, wheel_radius: 0.9 m", "one way"),
    ("wheel_diameter: -1.8 m", "wheel_diameter > 0"),
    ("wheel_diameter: 1.8 kg", "wheel_diameter"),
])
def test_item6a_wheel_diameter_bad_input(write, run, wheel, words):
    result = run("solve", write(DRIVE.format(wheel=wheel)))
    _one_line_refusal(result, "given.wheel_diameter")
    assert words in result.stderr


def test_item6a_did_you_mean_wheel_diameter(write, run):
    """A misspelt diameter is offered the diameter, not the wheel's inertia."""
    result = run("solve", write(DRIVE.format(wheel="wheel_diametre: 1.8 m")))
    _one_line_refusal(result, "given.wheel_diametre")
    assert "did you mean 'wheel_diameter'" in result.stderr


# ---- b. a shape with no size where only ratios matter ---------------------------------

def _integrated_rates(theta: float, omega_z: float) -> tuple[float, float]:
    """A thin disk (I = 1, J = 2: only the ratio matters) set free with its axis at theta to
    H: Euler's equations and the attitude integrated with scipy. Returns (phidot, psidot):
    the rate of the axis about H in space, and the spin relative to the precessing frame,
    which is minus the rate at which omega turns about the axis seen in the body."""
    import numpy as np
    from scipy.integrate import solve_ivp

    I, J = 1.0, 2.0
    omega_e = omega_z * (J / I) * math.tan(theta)  # I omega_e / (J omega_z) = tan(theta)

    def rates(_t, y):
        w = y[:3]
        R = y[3:].reshape(3, 3)
        dw = [(I - J) / I * w[1] * w[2], (J - I) / I * w[0] * w[2], 0.0]
        skew = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        return np.concatenate([dw, (R @ skew).ravel()])

    t = np.linspace(0.0, 2.0, 4001)
    y0 = np.concatenate([[omega_e, 0.0, omega_z], np.eye(3).ravel()])
    sol = solve_ivp(rates, (0.0, 2.0), y0, t_eval=t, rtol=1e-11, atol=1e-12)
    w = sol.y[:3]
    R = sol.y[3:].T.reshape(-1, 3, 3)
    H = R[0] @ (np.diag([I, I, J]) @ w[:, 0])  # fixed in space
    h = H / np.linalg.norm(H)
    e1 = np.cross(h, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(h, e1)
    k = R[:, :, 2]  # the symmetry axis in space
    azimuth = np.unwrap(np.arctan2(k @ e2, k @ e1))
    body_angle = np.unwrap(np.arctan2(w[1], w[0]))
    return float(np.polyfit(t, azimuth, 1)[0]), float(-np.polyfit(t, body_angle, 1)[0])


@pytest.mark.parametrize("theta_deg", [5.0, 30.0])
def test_item6b_disk_with_no_size_against_eulers_equations(write, run, theta_deg):
    """A tossed coin given as `shape: disk` only (no mass, no radius): the precession
    gyro gives for the spin and the angle is the one a numerical integration finds."""
    theta = math.radians(theta_deg)
    phidot, psidot = _integrated_rates(theta, 10.0)
    assert abs(phidot) == pytest.approx(2 * abs(psidot) / math.cos(theta), rel=1e-6)
    result = run("solve", write(f"id: coin\nkind: torque_free\ngiven: {{shape: disk, spin: "
                                f"{psidot!r} rad/s, nutation_angle: {theta_deg} deg}}\n"
                                "find: {precession: rad/s}\n"))
    assert result.exit_code == 0, result.output
    answer = [line for line in result.stdout.splitlines() if "precession" in line][-1]
    got = float(answer.split("=")[1].split()[0])
    assert got == pytest.approx(phidot, rel=1e-3)
    assert "no size given" in result.stdout


def test_item6b_plate_wobbles_twice_per_spin(run, problems_dir):
    """The bundled plate: for a slight wobble, twice as fast as the spin."""
    result = run("check", problems_dir / "tossed_plate_wobble.yaml")
    assert result.exit_code == 0, result.output


@pytest.mark.parametrize("given, find, key", [
    ("shape: disk, angular_momentum: 1 kg m^2/s, nutation_angle: 10 deg", "precession",
     "given.radius"),
    ("shape: disk, mass: 1 kg, angular_momentum: 1 kg m^2/s, nutation_angle: 10 deg",
     "precession", "given.radius"),
    ("shape: disk, radius: 1 cm, angular_momentum: 1 kg m^2/s, nutation_angle: 10 deg",
     "precession", "given.mass"),
    ("shape: disk, spin: -10 rad/s, nutation_angle: 10 deg", "angular_momentum",
     "given.radius"),
    ("shape: disk, spin: -10 rad/s, nutation_angle: 10 deg", "kinetic_energy",
     "given.radius"),
])
def test_item6b_size_needed_is_refused(write, run, given, find, key):
    """Where an answer needs the size (or the mass), one line names the missing key."""
    result = run("solve", write(f"id: x\nkind: torque_free\ngiven: {{{given}}}\n"
                                f"find: [{find}]\n"))
    _one_line_refusal(result, key)


def test_item6b_gravity_needs_the_size(write, run):
    """A top's m g l against I ~ m r^2: the size is needed, and named."""
    result = run("solve", write("id: x\nkind: steady_precession\ngiven: {shape: disk, "
                                "cg_distance: 5 cm, spin: 3000 rpm, theta: 60 deg}\n"
                                "find: [precession]\n"))
    _one_line_refusal(result, "given.radius")


def test_item6b_sizeless_disk_at_its_centre_in_steady_precession(write, run):
    """steady_precession with the fixed point at the centre (torque-free): a disk with
    no size; phidot = -J psidot / ((J - I) cos(theta)) = -2 psidot / cos(theta)."""
    result = run("solve", write("id: x\nkind: steady_precession\ngiven: {shape: disk, "
                                "cg_distance: 0 m, spin: -10 rad/s, theta: 60 deg}\n"
                                "find: {precession: rad/s}\n"))
    assert result.exit_code == 0, result.output
    assert f"{2 * 10 / math.cos(math.radians(60)):.4g}" in result.stdout  # 40 rad/s


def test_item6b_rolling_disk_still_needs_its_radius(write, run):
    """A rolling disk's rates hold g / r: no size is refused, as before, naming it."""
    result = run("solve", write("id: x\nkind: rolling_disk\ngiven: {shape: disk, mass: 1 kg, "
                                "speed: 1 m/s}\nfind: [stability]\n"))
    assert result.exit_code == 2 and "radius or diameter" in result.stderr


# ---- c. a cone by its vertex angle; theta as books measure it ---------------------------

TOP = ("id: t\nkind: steady_precession\ngiven: {{mass: 0.5 kg, k_axial: 30 mm, k_pivot: 60 mm, "
       "cg_distance: 50 mm, spin: 3000 rpm, {angle}}}\nfind: {{precession_slow: rad/s}}\n")


def _answer(result, name: str) -> float:
    assert result.exit_code == 0, result.output
    line = [line for line in result.stdout.splitlines() if line.strip().startswith(name)][-1]
    return float(line.split("=")[-1].split()[0])


def _slow_root(J: float, I: float, mgl: float, psidot: float, theta: float) -> float:
    """The chapter's steady precession, by hand: mgl = phidot (J psidot + (J - I) phidot
    cos(theta)), the smaller root."""
    a, b, c = (J - I) * math.cos(theta), J * psidot, -mgl
    roots = [(-b + s * math.sqrt(b * b - 4 * a * c)) / (2 * a) for s in (1, -1)]
    return min(roots, key=abs)


@pytest.mark.parametrize("angle", ["theta_from_horizontal: 30 deg",
                                   "theta_from_downward_vertical: 120 deg"])
def test_item6c_theta_as_books_measure_it(write, run, angle):
    """30 deg above the horizontal and 120 deg from the downward vertical are both
    theta = 60 deg from the upward vertical: the same slow root, worked by hand."""
    result = run("solve", write(TOP.format(angle=angle)))
    m, l, psidot = 0.5, 0.05, 3000 * math.pi / 30
    expected = _slow_root(m * 0.03 ** 2, m * 0.06 ** 2, m * 9.81 * l, psidot, math.radians(60))
    assert _answer(result, "precession_slow") == pytest.approx(expected, rel=1e-3)
    assert "theta = " in result.stdout and "from the upward vertical" in result.stdout


@pytest.mark.parametrize("angle, key, words", [
    ("theta_from_horizontal: 30 deg, theta: 60 deg", "given.theta_from_horizontal", "one way"),
    ("theta_from_horizontal: 30 deg, theta_from_downward_vertical: 120 deg",
     "given.theta_from_", "one way"),
    ("theta_from_downward_vertical: 190 deg", "given.theta_from_downward_vertical",
     "theta = -10 deg"),
    ("theta_from_horizontal: 30 kg", "given.theta_from_horizontal", "angle"),
    ("theta_from_horizontl: 30 deg", "given.theta_from_horizontl",
     "did you mean 'theta_from_horizontal'"),
])
def test_item6c_theta_bad_input(write, run, angle, key, words):
    result = run("solve", write(TOP.format(angle=angle)))
    _one_line_refusal(result, key)
    assert words in result.stderr


def test_item6c_cone_by_vertex_angle_and_height(run, problems_dir):
    """The bundled cone top: r = h tan(alpha), theta = 90 - 30 deg; the slow root by hand."""
    h, alpha = 0.12, math.radians(30)
    r = h * math.tan(alpha)
    J, I = 0.3 * r * r, 3 * r * r / 20 + 3 * h * h / 80 + (0.75 * h) ** 2  # per kilogram
    expected = _slow_root(J, I, 9.81 * 0.75 * h, 1200 * math.pi / 30, math.radians(60))
    result = run("solve", problems_dir / "cone_top_vertex_angle.yaml")
    assert _answer(result, "precession_slow") == pytest.approx(expected, rel=1e-3)
    assert "r = h tan(alpha)" in result.stdout
    assert run("check", problems_dir / "cone_top_vertex_angle.yaml").exit_code == 0


def test_item6c_cone_by_vertex_angle_and_radius_is_the_same_cone(write, run):
    text = ("id: t\nkind: steady_precession\ngiven: {{shape: cone, mass: 1 kg, {size}, spin: "
            "1200 rpm, theta: 60 deg}}\nfind: {{precession_slow: rad/s}}\n")
    by_radius = run("solve", write(text.format(size="vertex_angle: 60 deg, radius: "
                                               f"{120 * math.tan(math.radians(30))!r} mm"), "a"))
    by_both = run("solve", write(text.format(size="height: 120 mm, radius: "
                                             f"{120 * math.tan(math.radians(30))!r} mm"), "b"))
    assert _answer(by_radius, "precession_slow") == pytest.approx(
        _answer(by_both, "precession_slow"), rel=1e-9)


def test_item6c_free_cone_by_its_vertex_angle_alone(write, run):
    """A free cone needs only J / I_G = (3/10) / (3/20 + 3 / (80 tan^2(alpha))):
    phidot = J psidot / ((I - J) cos(theta))."""
    alpha, theta, psidot = math.radians(30), math.radians(10), -10.0
    ratio = 0.3 / (3 / 20 + 3 / (80 * math.tan(alpha) ** 2))  # J / I_G
    expected = ratio * psidot / ((1 - ratio) * math.cos(theta))
    result = run("solve", write("id: t\nkind: torque_free\ngiven: {shape: cone, vertex_angle: "
                                "60 deg, spin: -10 rad/s, nutation_angle: 10 deg}\n"
                                "find: {precession: rad/s}\n"))
    assert _answer(result, "precession") == pytest.approx(expected, rel=1e-3)


@pytest.mark.parametrize("given, key", [
    ("shape: disk, radius: 5 cm, vertex_angle: 60 deg", "given.vertex_angle"),
    ("shape: cone, radius: 5 cm, height: 10 cm, vertex_angle: 60 deg", "given.vertex_angle"),
    ("shape: cone, height: 10 cm, vertex_angle: 180 deg", "given.vertex_angle"),
    ("shape: cone, height: 10 cm, vertex_angle: 0 deg", "given.vertex_angle"),
    ("shape: cone, vertex_angle: 60 deg", "given.height"),  # gravity needs the size
])
def test_item6c_vertex_angle_bad_input(write, run, given, key):
    result = run("solve", write(f"id: t\nkind: steady_precession\ngiven: {{{given}, mass: 1 kg, "
                                "spin: 3000 rpm, theta: 60 deg}\nfind: [precession_slow]\n"))
    _one_line_refusal(result, key)


# ---- d. US data in inches with no mass: the US textbook g, and a word saying so ----------

US_TOP = ("id: t\nkind: steady_precession\ngiven: {{shape: disk, radius: 2 in, cg_distance: 3 in, "
          "spin: 3000 rpm, theta: 90 deg{more}}}\nfind: {{precession: rad/s}}\n")


def _precession_by_hand(g_ft: float) -> float:
    """phidot = g l / ((r^2 / 2) psidot) at theta = 90 deg, in feet (the mass cancels)."""
    return g_ft * (3 / 12) / ((2 / 12) ** 2 / 2 * (3000 * math.pi / 30))


def test_item6d_inches_and_no_mass_use_the_us_g(write, run):
    result = run("solve", write(US_TOP.format(more="")))
    assert _answer(result, "precession") == pytest.approx(_precession_by_hand(32.2), rel=1e-3)
    warning = [line for line in result.stdout.splitlines() if "no g given" in line]
    assert len(warning) == 1 and "g = 32.2 ft/s^2" in warning[0] and "lengths" in warning[0]


def test_item6d_the_bundled_us_problem(run, problems_dir):
    result = run("check", problems_dir / "us_toy_gyroscope_inches.yaml")
    assert result.exit_code == 0, result.output


@pytest.mark.parametrize("more, g_ft", [(", g: 32.0 ft/s^2", 32.0),
                                        (", mass: 0.2 kg", 9.81 / 0.3048)])
def test_item6d_no_warning_where_g_is_not_the_us_default(write, run, more, g_ft):
    """g given, or a mass in kg (SI data with some lengths in inches): no US default."""
    result = run("solve", write(US_TOP.format(more=more)))
    assert _answer(result, "precession") == pytest.approx(_precession_by_hand(g_ft), rel=1e-3)
    assert "no g given" not in result.stdout


def test_item6d_us_weight_keeps_its_given_line(write, run):
    """A weight in lb was US data before: the same g, said in the Given table as before
    (the warning is for data that are US by their lengths alone)."""
    result = run("solve", write(US_TOP.format(more=", weight: 0.5 lb")))
    assert _answer(result, "precession") == pytest.approx(_precession_by_hand(32.2), rel=1e-3)
    assert "32.2 ft/s^2 (default)" in result.stdout and "no g given" not in result.stdout


def test_item6d_bad_g(write, run):
    result = run("solve", write(US_TOP.format(more=", g: 32.2 ft")))
    _one_line_refusal(result, "given.g")


# ---- the keys stated another way elsewhere: gyro vary, released_top ----------------------

def test_item6a_vary_draws_a_wheel_diameter(write, run, tmp_path, problems_dir):
    """`vary: {wheel_diameter: ...}` draws the diameter; each variant's moment is the
    book's 663 N m scaled by 1.8 m / d (the spin is v / (d / 2))."""
    text = (problems_dir / "khurmi_wheel_drop_diameter.yaml").read_text()
    path = write(text + "vary:\n  wheel_diameter: [0.9, 1.1]\n", "kv.yaml")
    out = tmp_path / "out"
    result = run("vary", "-n", "2", "-s", "1", path, "-o", out)
    assert result.exit_code == 0, result.output
    import yaml

    for variant in sorted(out.glob("*.yaml")):
        data = yaml.safe_load(variant.read_text())
        d = float(data["given"]["wheel_diameter"].split()[0])
        moment = float(str(data["expected"]["moment"]).split()[0])
        v, omega = 95 / 3.6, (0.006 / 2) * (2 * math.pi / 0.1) / 1.5
        assert moment == pytest.approx(180 * v / (d / 2) * omega, rel=2e-3)


def test_item6c_released_top_from_the_downward_vertical(write, run):
    """released_top's theta0 given from the downward vertical: 150 deg from it is 30 deg
    from the upward vertical, the same motion."""
    text = ("id: r\nkind: released_top\ngiven: {{mass: 1 kg, J: 0.002 kg m^2, I_pivot: "
            "0.01 kg m^2, cg_distance: 0.05 m, spin: 2000 rpm, {angle}}}\n"
            "find: {{theta_max: deg}}\n")
    up = run("solve", write(text.format(angle="theta0: 30 deg"), "up.yaml"))
    down = run("solve", write(text.format(angle="theta0_from_downward_vertical: 150 deg"),
                              "down.yaml"))
    assert _answer(down, "theta_max") == _answer(up, "theta_max")
    assert "theta0 = pi - theta0_d" in down.stdout
