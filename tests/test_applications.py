"""The chapter's applications (section 11.3): earth_precession, gyrocompass, rate_gyro.

Independent references, none of which uses the kinds' formulas:

- the precession of the equinoxes: the Newtonian torque of a point mass on an
  equatorial ring (the oblate part of a planet), summed over the ring's
  elements and averaged by quadrature over a Kepler orbit (and over the turning
  node of an inclined orbit); rate = <T> / (C omega sin(eps)). No multipole
  expansion, no averaging formula. And the published IAU 2006 figure.
- the gyrocompass: Lagrange's equations of a rotor in a gimbal free about the
  local vertical on the rotating Earth, built numerically from the kinetic
  energy (inertia tensors and angular velocities only; derivatives by complex
  step), integrated with solve_ivp; period, moment and settling measured.
- the rate gyro: the gimbal equation I_g thetaddot + c thetadot + k theta =
  H Omega integrated in time; deflection, gimbal rate, natural frequency,
  damping ratio (logarithmic decrement) and time constant measured. And the
  gimbal equation itself: Lagrange's equation of a driven rotor in a gimbal in
  a turning case, from its kinetic energy, integrated to its steady deflection.

Each bundled problem is also worked by hand, and bad input exits 2 with one line.
"""

from __future__ import annotations

import cmath
import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from gyro_cli.physics.earth_precession import ARCSEC, JULIAN_YEAR

G = 6.67430e-11
DEG = math.pi / 180
EARTH_RATE = 7.292115e-5


def answers(run, path):
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    return {k: v["si_values"] for k, v in json.loads(result.stdout)["answers"].items()}


# ---- earth_precession: the ring's torque by quadrature -----------------------

def kepler_positions(a, e, samples):
    """Positions (x, y) in the orbit plane at equal steps of mean anomaly (equal times)."""
    M = 2 * np.pi * (np.arange(samples) + 0.5) / samples
    E = M.copy()
    for _ in range(50):
        E = E - (E - e * np.sin(E) - M) / (1 - e * np.cos(E))
    return a * (np.cos(E) - e), a * math.sqrt(1 - e * e) * np.sin(E)


def ring_torque(gm_body, a, e, inclination, ring_mass, R, obliquity, orbit_samples=240,
                ring_elements=48, nodes=12):
    """Mean torque of a point mass on a ring about its centre (ecliptic frame, n = z).

    Spin axis s = (0, sin eps, cos eps); the ring lies in the plane normal to s.
    Summed element by element from Newton's law, averaged over equal times on
    the orbit and over equally spaced longitudes of the node.
    """
    s = np.array([0.0, math.sin(obliquity), math.cos(obliquity)])
    e1 = np.array([1.0, 0.0, 0.0])
    e2 = np.cross(s, e1)
    phi = 2 * np.pi * np.arange(ring_elements) / ring_elements
    ring = R * (np.cos(phi)[:, None] * e1 + np.sin(phi)[:, None] * e2)   # (K, 3)
    dm = ring_mass / ring_elements
    x, y = kepler_positions(a, e, orbit_samples)
    total = np.zeros(3)
    node_list = [0.0] if inclination == 0 else 2 * np.pi * np.arange(nodes) / nodes
    for node in node_list:
        line = np.array([math.cos(node), math.sin(node), 0.0])
        normal = np.array([math.sin(inclination) * math.sin(node),
                           -math.sin(inclination) * math.cos(node), math.cos(inclination)])
        other = np.cross(normal, line)
        body = x[:, None] * line + y[:, None] * other                       # (N, 3)
        d = body[:, None, :] - ring[None, :, :]                              # (N, K, 3)
        force = gm_body * dm * d / np.linalg.norm(d, axis=2)[..., None] ** 3
        torque = np.cross(ring[None, :, :], force).sum(axis=1)               # (N, 3)
        total += torque.mean(axis=0)
    return total / len(node_list), s


def quadrature_rate(gm_body, a, e, inclination, ring_mass, R, C, omega, obliquity, **kw):
    """Precession rate (retrograde positive) from the ring's mean torque: T / (C omega sin eps)."""
    T, s = ring_torque(gm_body, a, e, inclination, ring_mass, R, obliquity, **kw)
    n = np.array([0.0, 0.0, 1.0])
    westward = -np.cross(n, s) / np.linalg.norm(np.cross(n, s))
    # the mean torque lies along -(n x s): nothing across it
    assert abs(T @ s) < 1e-9 * np.linalg.norm(T)
    assert abs(T @ np.cross(s, westward)) < 1e-6 * np.linalg.norm(T)
    return (T @ westward) / (C * omega * math.sin(obliquity))


PLANET = """
id: ring
kind: earth_precession
given:
  dynamical_ellipticity: {H}
  obliquity: {eps} deg
  rotation_rate: {omega} rad/s
  sun_mass: {mass} kg
  sun_distance: {a} m
  sun_eccentricity: {e}
  sun_inclination: {i} deg
find: [precession_rate]
"""


@pytest.mark.parametrize("e, inclination_deg, eps_deg, R_over_a", [
    (0.0, 0.0, 23.44, 1e-3),
    (0.3, 0.0, 40.0, 1e-3),
    (0.0549, 5.145, 23.44, 1e-3),     # the Moon's orbit, node averaged
    (0.2, 30.0, 10.0, 1e-3),          # a steep orbit: (1 - 3/2 sin^2 i) = 0.625
    (0.0549, 5.145, 23.44, 1 / 60.3),  # the Moon's real distance: higher multipoles 3e-4
])
def test_precession_matches_the_ring_torque_by_quadrature(run, write, e, inclination_deg,
                                                          eps_deg, R_over_a):
    gm_body, a = 4.9e12, 3.84e8
    R = R_over_a * a
    ring_mass = 1e22
    C = 0.33 * 6e24 * R * R + ring_mass * R * R   # a sphere plus the ring
    H = ring_mass * R * R / 2 / C                 # ring: C - A = m R^2 / 2
    omega = 7.29e-5
    expected = quadrature_rate(gm_body, a, e, inclination_deg * DEG, ring_mass, R, C, omega,
                               eps_deg * DEG)
    path = write(PLANET.format(H=H, eps=eps_deg, omega=omega, mass=gm_body / G, a=a, e=e,
                               i=inclination_deg))
    got = answers(run, path)["precession_rate"][0]
    tolerance = 2e-6 if R_over_a < 0.01 else 1e-3
    assert got == pytest.approx(expected, rel=tolerance)


def test_earth_preset_gives_the_iau_2006_lunisolar_precession(run, problems_dir):
    # IAU 2006 (P03): psi_A = 5038.481507 arcsec per Julian century.
    iau = 5038.481507 / 100
    got = answers(run, problems_dir / "11_3_equinoxes.yaml")
    rate = got["precession_rate"][0] / ARCSEC * JULIAN_YEAR
    assert rate == pytest.approx(iau, rel=0.005)
    # the shares add up, and the Moon's is about twice the Sun's
    assert got["sun_rate"][0] + got["moon_rate"][0] == pytest.approx(got["precession_rate"][0])
    assert 2.0 < got["moon_rate"][0] / got["sun_rate"][0] < 2.3
    # the chapter's 26,000 years, and the errata's 72 years a degree (not 80)
    years = got["precession_period"][0] / JULIAN_YEAR
    assert years == pytest.approx(26000, rel=0.02)
    per_degree = got["years_per_degree"][0] * DEG / JULIAN_YEAR
    assert per_degree == pytest.approx(years / 360) and abs(per_degree - 72) < 1


def test_earth_preset_by_hand(run, write):
    # The Moon's share, worked out here from G, the masses and Kepler's law a^3 = G (M + m) / n^2
    # rather than from the mass ratio: GM_E = 3.986004418e14, mu = 0.0123000371,
    # P = 27.321661 d, e = 0.0549, i = 5.145 deg; H = 0.003273795, eps = 84381.406 arcsec,
    # omega = 2 pi / 86164.0905 s.
    gm_e = 3.986004418e14
    gm_m = 0.0123000371 * gm_e
    n = 2 * math.pi / (27.321661 * 86400)
    a = ((gm_e + gm_m) / n ** 2) ** (1 / 3)
    assert a == pytest.approx(3.844e8, rel=1e-3)  # the Moon's mean distance
    eps = 84381.406 / 3600 * DEG
    omega = 2 * math.pi / 86164.0905
    i = 5.145 * DEG
    torque_per_C = 1.5 * gm_m / a ** 3 / (1 - 0.0549 ** 2) ** 1.5 * 0.003273795 * \
        math.cos(eps) * math.sin(eps) * (1 - 1.5 * math.sin(i) ** 2)
    moon = torque_per_C / (omega * math.sin(eps))
    path = write(f"""
        id: moon
        kind: earth_precession
        given:
          preset: earth
          moon_mass: {gm_m / G} kg
          moon_distance: {a} m
        find: [moon_rate, sun_rate]
        """)
    got = answers(run, path)
    assert got["moon_rate"][0] == pytest.approx(moon, rel=1e-9)
    assert got["moon_rate"][0] / ARCSEC * JULIAN_YEAR == pytest.approx(34.36, abs=0.01)
    assert got["sun_rate"][0] / ARCSEC * JULIAN_YEAR == pytest.approx(15.95, abs=0.01)


def test_mars_against_the_pathfinder_measurement(run, problems_dir):
    # Folkner et al. 1997: -7576 +- 35 mas/yr (westward).
    got = answers(run, problems_dir / "mars_precession.yaml")["precession_rate"][0]
    assert got / ARCSEC * JULIAN_YEAR == pytest.approx(7.576, abs=0.035)


def test_worked_answer_shows_the_shares_and_the_errata(run, problems_dir):
    out = run("solve", problems_dir / "11_3_equinoxes.yaml").stdout
    assert "the Sun's share" in out and "the Moon's share" in out
    assert "misprint" in out and "72" in out
    assert "(1 - (3/2) sin^2(i))" in out


EARTH_BAD = """
id: bad
kind: earth_precession
given:
  {extra}
find: [precession_rate]
"""


@pytest.mark.parametrize("extra, reason", [
    ("preset: earth\n  obliquity: 95 deg", "expected 0 deg <= obliquity < 90 deg"),
    ("preset: earth\n  dynamical_ellipticity: -0.003",
     "expected 0 < dynamical_ellipticity < 1"),
    ("preset: earth\n  moon_eccentricity: 1", "expected 0 <= moon_eccentricity < 1"),
    ("dynamical_ellipticity: 0.003\n  obliquity: 20 deg\n  rotation_period: 1 day\n"
     "  rotation_rate: 7e-5 rad/s\n  sun_mass_ratio: 3e5\n  sun_orbital_period: 1 yr",
     "not both"),
    ("preset: earth\n  J2: 1e-3", "give polar_moment_factor too"),
    ("preset: earth\n  J2: 1e-3\n  polar_moment_factor: 0.33\n  dynamical_ellipticity: 0.003",
     "not both"),
    ("J2: 1e-3\n  obliquity: 20 deg\n  rotation_period: 1 day\n  sun_mass_ratio: 3e5\n"
     "  sun_orbital_period: 1 yr", "give polar_moment_factor too"),
    ("dynamical_ellipticity: 0.003\n  obliquity: 20 deg\n  rotation_period: 1 day",
     "no torquing body"),
    ("dynamical_ellipticity: 0.003\n  obliquity: 20 deg\n  rotation_period: 1 day\n"
     "  sun_mass_ratio: 3e5", "needs its orbital_period"),
    ("dynamical_ellipticity: 0.003\n  obliquity: 20 deg\n  rotation_period: 1 day\n"
     "  sun_mass: 2e30 kg\n  sun_orbital_period: 1 yr", "planet_mass"),
    ("preset: earth\n  sun_distance: 1 au\n  sun_orbital_period: 1 yr", "not both"),
    ("preset: earth\n  obliquity: 90 deg", "expected 0 deg <= obliquity < 90 deg"),
    ("preset: earth\n  J2: 0.5\n  polar_moment_factor: 0.4", "between 0 and 1"),
])
def test_earth_bad_input_exits_2_with_one_line(run, write, extra, reason):
    result = run("solve", write(EARTH_BAD.format(extra=extra)))
    assert result.exit_code == 2, result.output
    assert reason in result.stderr and "Traceback" not in result.output
    assert len(result.stderr.strip().splitlines()) == 1


# ---- gyrocompass: Lagrange's equations built from the kinetic energy ----------

def compass_model(J, I_t, I_gv, I_gh, Omega, lat, damping=0.0):
    """Right-hand side for y = (alpha, alphadot, psidot) from T(alpha, alphadot, psidot).

    ENU axes fixed in the Earth: U = z, N = y, E = x. The rotor's axis s = (sin a, cos a, 0)
    (azimuth a east of north); rotor inertia J s s^T + I_t (1 - s s^T); gimbal inertia
    I_gv about U and I_gh about horizontal axes. Angular velocities in inertial space,
    written in Earth axes: rotor Omega_E - alphadot U + psidot s, gimbal Omega_E - alphadot U.
    The kinetic energy T = w.I.w / 2 of both is all the model knows; Lagrange's equations
    are formed from it numerically (psi is cyclic, alpha is not).
    """
    W = (0.0, Omega * math.cos(lat), Omega * math.sin(lat))

    def T(alpha, ad, pd):
        s = (cmath.sin(alpha), cmath.cos(alpha), 0.0)
        w_r = (W[0] + pd * s[0], W[1] + pd * s[1], W[2] - ad)
        along = sum(w * e for w, e in zip(w_r, s))
        rotor = J * along * along + I_t * (sum(w * w for w in w_r) - along * along)
        w_g = (W[0], W[1], W[2] - ad)
        gimbal = I_gv * w_g[2] ** 2 + I_gh * (w_g[0] ** 2 + w_g[1] ** 2)
        return 0.5 * (rotor + gimbal)

    def parts(alpha):
        """M, b, T0 of T = v^T M v / 2 + b . v + T0 (polarisation at unit velocities), and
        their derivatives in alpha (complex step: alpha + i h, h = 1e-30)."""
        h = 1e-30
        a = alpha + 1j * h
        T0, Tp0, Tm0 = T(a, 0, 0), T(a, 1, 0), T(a, -1, 0)
        Tp1, Tm1, T01 = T(a, 0, 1), T(a, 0, -1), T(a, 1, 1)
        b = np.array([(Tp0 - Tm0) / 2, (Tp1 - Tm1) / 2])
        M00, M11 = Tp0 + Tm0 - 2 * T0, Tp1 + Tm1 - 2 * T0
        M01 = T01 - T0 - b[0] - b[1] - M00 / 2 - M11 / 2
        M = np.array([[M00, M01], [M01, M11]])
        return M.real, b.real, M.imag / h, b.imag / h, T0.imag / h

    def rhs(t, y):
        alpha, ad, pd = y
        v = np.array([ad, pd])
        M, b, Ma, ba, T0a = parts(alpha)
        dT_dalpha = 0.5 * v @ Ma @ v + ba @ v + T0a
        generalised = np.array([dT_dalpha - damping * ad, 0.0])
        acc = np.linalg.solve(M, generalised - ad * (Ma @ v + ba))
        return [ad, acc[0], acc[1]]

    return rhs


def measured_period(rhs, alpha0, spin, t_end):
    sol = solve_ivp(rhs, (0, t_end), [alpha0, 0.0, spin], method="DOP853", rtol=1e-10,
                    atol=1e-12, dense_output=True)
    t = np.linspace(0, t_end, 20001)
    a = sol.sol(t)[0]
    crossings = []
    for k in np.nonzero(np.diff(np.sign(a)) != 0)[0]:
        lo, hi = t[k], t[k + 1]
        for _ in range(50):
            mid = (lo + hi) / 2
            if np.sign(sol.sol(mid)[0]) == np.sign(a[k]):
                lo = mid
            else:
                hi = mid
        crossings.append((lo + hi) / 2)
    return 2 * np.mean(np.diff(crossings))


COMPASS = """
id: c
kind: gyrocompass
given:
  J: {J} kg m^2
  I_cg: {I_t} kg m^2
  spin: {spin} rad/s
  I_vertical: {I_v} kg m^2
  latitude: {lat} deg
  deviation: {dev} deg
find: [period, swing_period, moment, directive_moment, settles]
"""


@pytest.mark.parametrize("J, I_t, I_gv, spin, lat_deg", [
    (0.002, 0.001, 0.003, 2000.0, 30.0),
    (0.01, 0.006, 0.0, 1500.0, 60.0),     # no gimbal: the rotor alone
    (0.002, 0.001, 0.003, 2000.0, -45.0),  # southern hemisphere: also north
])
def test_compass_period_and_moment_match_lagrange(run, write, J, I_t, I_gv, spin, lat_deg):
    lat = lat_deg * DEG
    rhs = compass_model(J, I_t, I_gv, 0.004, EARTH_RATE, lat)
    I_v = I_t + I_gv
    path = write(COMPASS.format(J=J, I_t=I_t, spin=spin, I_v=I_v, lat=lat_deg, dev=60))
    got = answers(run, path)
    guess = 2 * math.pi * math.sqrt(I_v / (J * spin * EARTH_RATE * math.cos(lat)))
    small = measured_period(rhs, 1 * DEG, spin, 3.2 * guess)
    assert got["period"][0] == pytest.approx(small, rel=1e-4)
    large = measured_period(rhs, 60 * DEG, spin, 3.2 * guess * 1.1)
    assert got["swing_period"][0] == pytest.approx(large, rel=1e-5)
    # the moment about the vertical at 60 deg east: I_v alphaddot, turning the axis back west
    alphaddot = rhs(0, [60 * DEG, 0, spin])[1]
    assert got["moment"][0] == pytest.approx(-I_v * alphaddot, rel=1e-5)
    assert got["directive_moment"][0] == pytest.approx(got["moment"][0] / math.sin(60 * DEG))
    assert got["settles"] == ["north"]


@pytest.mark.parametrize("spin, settles_at", [(2000.0, 0.0), (-2000.0, math.pi)])
def test_damped_compass_settles_with_its_spin_vector_north(spin, settles_at):
    # started 120 deg east of north; a little damping about the vertical
    J, I_t, I_gv, lat = 0.002, 0.001, 0.003, 40 * DEG
    rhs = compass_model(J, I_t, I_gv, 0.004, EARTH_RATE, lat, damping=1e-3)
    sol = solve_ivp(rhs, (0, 300), [120 * DEG, 0, spin], method="DOP853", rtol=1e-9,
                    atol=1e-12)
    alpha = sol.y[0, -1]
    assert math.remainder(alpha - settles_at, 2 * math.pi) == pytest.approx(0, abs=1e-3)


def test_at_the_pole_there_is_no_north_seeking_moment(run, write):
    # the model: at latitude 90 deg the axis feels nothing about the vertical
    pole = compass_model(0.002, 0.001, 0.003, 0.004, EARTH_RATE, math.pi / 2)
    equator = compass_model(0.002, 0.001, 0.003, 0.004, EARTH_RATE, 0.0)
    state = [60 * DEG, 0, 2000.0]
    assert abs(pole(0, state)[1]) < 1e-8 * abs(equator(0, state)[1])
    result = run("solve", write(COMPASS.format(J=0.002, I_t=0.001, spin=2000, I_v=0.004,
                                               lat=90, dev=10)))
    assert result.exit_code == 2
    assert "cannot settle" in result.stderr and "no horizontal component" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def test_compass_problems_by_hand(run, problems_dir):
    # Kibble & Berkshire 9.15: flat disc, I_v / J = 1/2, 6000 rpm, 30 deg N.
    w = 6000 * 2 * math.pi / 60
    T = 2 * math.pi * math.sqrt(0.5 / (w * EARTH_RATE * math.cos(30 * DEG)))
    assert answers(run, problems_dir / "gyrocompass_disc.yaml")["period"][0] == \
        pytest.approx(T, rel=1e-12)
    assert T == pytest.approx(22.30, abs=0.005)
    # the ship's compass: H = 2.5 (0.06)^2 (20000 rpm)
    H = 2.5 * 0.06 ** 2 * 20000 * 2 * math.pi / 60
    D = H * EARTH_RATE * 0.5
    got = answers(run, problems_dir / "gyrocompass_ship.yaml")
    assert got["moment"][0] == pytest.approx(D * math.sin(5 * DEG), rel=1e-12)
    assert got["period"][0] == pytest.approx(2 * math.pi * math.sqrt(0.03 / D), rel=1e-12)


COMPASS_BAD = """
id: bad
kind: gyrocompass
given:
  J: 0.002 kg m^2
  {extra}
find: [period]
"""


@pytest.mark.parametrize("extra, reason", [
    ("spin: 2000 rad/s\n  I_vertical: 0.01 kg m^2\n  latitude: -90 deg", "cannot settle"),
    ("spin: 2000 rad/s\n  I_vertical: 0.01 kg m^2\n  latitude: 100 deg",
     "expected -90 deg <= latitude <= 90 deg"),
    ("spin: 0 rad/s\n  I_vertical: 0.01 kg m^2\n  latitude: 30 deg", "must spin"),
    ("spin: 2000 rad/s\n  latitude: 30 deg", "needs I_vertical"),
    ("I_vertical: 0.01 kg m^2\n  latitude: 30 deg", "give the rotor's spin"),
    ("spin: 2000 rad/s\n  I_vertical: -0.01 kg m^2\n  latitude: 30 deg",
     "expected I_vertical > 0 kg m^2"),
    ("spin: 2000 rad/s\n  I_vertical: 0.01 kg m^2\n  latitude: 30 deg\n  earth_rate: 0 rad/s",
     "expected earth_rate > 0 rad/s"),
])
def test_compass_bad_input_exits_2_with_one_line(run, write, extra, reason):
    result = run("solve", write(COMPASS_BAD.format(extra=extra)))
    assert result.exit_code == 2, result.output
    assert reason in result.stderr and "Traceback" not in result.output
    assert len(result.stderr.strip().splitlines()) == 1


# ---- rate_gyro: the gimbal equation in time --------------------------------------

def gimbal(I_g, c, k, H, rate, t_end, cos_term=False):
    """theta(t) from I_g thetaddot + c thetadot + k theta = H Omega(t), from rest."""
    def rhs(t, y):
        drive = H * rate(t) * (math.cos(y[0]) if cos_term else 1.0)
        return [y[1], (drive - c * y[1] - k * y[0]) / I_g]
    return solve_ivp(rhs, (0, t_end), [0.0, 0.0], method="DOP853", rtol=1e-11, atol=1e-14,
                     dense_output=True)


GYRO = """
id: g
kind: rate_gyro
given:
  angular_momentum: {H} kg m^2/s
  {extra}
find: [{find}]
"""


def test_spring_gyro_deflection_frequency_and_damping_match_the_integration(run, write):
    H, k, c, I_g, rate = 0.5, 0.8, 0.004, 1e-4, 3 * DEG
    got = answers(run, write(GYRO.format(
        H=H, extra=f"stiffness: {k} N m/rad\n  damping: {c} N m s/rad\n  gimbal_inertia: "
                   f"{I_g} kg m^2\n  rate: 3 deg/s",
        find="deflection, sensitivity, natural_frequency, damping_ratio, moment")))
    sol = gimbal(I_g, c, k, H, lambda t: rate, 2.0)
    theta_end = sol.sol(2.0)[0]
    assert got["deflection"][0] == pytest.approx(theta_end, rel=1e-8)
    assert got["sensitivity"][0] == pytest.approx(theta_end / rate, rel=1e-8)
    assert got["moment"][0] == pytest.approx(k * theta_end, rel=1e-8)
    # ringing about the steady value: peaks give the damped period and the decrement
    t = np.linspace(0, 0.3, 300001)
    x = sol.sol(t)[0] - theta_end
    peaks = [i for i in range(1, len(t) - 1) if x[i] > x[i - 1] and x[i] >= x[i + 1]
             and x[i] > 0]
    Td = np.mean(np.diff(t[peaks[:5]]))
    delta = math.log(x[peaks[0]] / x[peaks[1]])
    zeta = delta / math.sqrt(4 * math.pi ** 2 + delta ** 2)
    wn = 2 * math.pi / Td / math.sqrt(1 - zeta ** 2)
    assert got["damping_ratio"][0] == pytest.approx(zeta, rel=1e-4)
    assert got["natural_frequency"][0] == pytest.approx(wn, rel=1e-4)


def test_rate_integrating_gyro_integrates_the_input(run, write):
    H, c, I_g = 0.1, 0.05, 2e-4
    got = answers(run, write(GYRO.format(
        H=H, extra=f"damping: {c} N m s/rad\n  gimbal_inertia: {I_g} kg m^2\n  rate: 2 deg/s",
        find="gimbal_rate, gain, time_constant")))
    sol = gimbal(I_g, c, 0.0, H, lambda t: 2 * DEG, 0.2)
    assert got["gimbal_rate"][0] == pytest.approx(sol.sol(0.2)[1], rel=1e-8)
    tau = got["time_constant"][0]
    assert sol.sol(tau)[1] == pytest.approx(got["gimbal_rate"][0] * (1 - math.exp(-1)),
                                            rel=1e-6)
    # a varying input (slow against tau): the gimbal angle is gain times the angle turned
    def rate(t):
        return 5 * DEG * math.sin(2 * t)
    sol = gimbal(I_g, c, 0.0, H, rate, 1.0)
    turned = 5 * DEG * (1 - math.cos(2.0)) / 2
    assert sol.sol(1.0)[0] == pytest.approx(got["gain"][0] * turned, rel=2e-2)
    angle = answers(run, write(GYRO.format(
        H=H, extra=f"damping: {c} N m s/rad\n  input_angle: {turned} rad", find="deflection")))
    assert angle["deflection"][0] == pytest.approx(sol.sol(1.0)[0], rel=2e-2)


def test_large_deflection_warns_with_the_exact_steady_state(run, write):
    H, k, c, I_g = 0.5, 0.2, 0.01, 1e-4
    path = write(GYRO.format(H=H, extra=f"stiffness: {k} N m/rad\n  rate: 20 deg/s",
                             find="deflection"))
    out = run("solve", path).stdout
    sol = gimbal(I_g, c, k, H, lambda t: 20 * DEG, 3.0, cos_term=True)
    exact_deg = sol.sol(3.0)[0] / DEG
    assert "is not small" in out
    assert f"gives {exact_deg:.4g} deg" in out


def test_rate_gyro_problems_by_hand(run, problems_dir):
    H = 2.0e-4 * 24000 * 2 * math.pi / 60
    got = answers(run, problems_dir / "rate_gyro_turn.yaml")
    assert got["deflection"][0] == pytest.approx(H * 3 * DEG / 0.8, rel=1e-12)
    assert got["natural_frequency"][0] == pytest.approx(math.sqrt(0.8 / 1e-4))
    assert got["damping_ratio"][0] == pytest.approx(0.015 / (2 * math.sqrt(0.8e-4)))
    got = answers(run, problems_dir / "rate_gyro_reading.yaml")
    assert got["rate"][0] == pytest.approx(0.4 * 4 * DEG / 0.25, rel=1e-12)
    got = answers(run, problems_dir / "rate_integrating_gyro.yaml")
    assert got["gimbal_rate"][0] == pytest.approx(0.1 * 2 * DEG / 0.05, rel=1e-12)
    assert got["gain"][0] == pytest.approx(2.0) and got["time_constant"][0] == pytest.approx(4e-3)
    got = answers(run, problems_dir / "11_3_bearing_moment.yaml")
    assert got["rate"][0] == pytest.approx(0.05 / (1.5e-3 * 12000 * 2 * math.pi / 60),
                                           rel=1e-12)


@pytest.mark.parametrize("extra, find, reason", [
    ("stiffness: 0.5 N m/rad\n  rate: 1 deg/s\n  deflection: 2 deg", "rate", "give one input"),
    ("rate: 1 deg/s", "deflection", "deflection needs stiffness"),
    ("deflection: 2 deg", "rate", "needs a restraining spring"),
    ("stiffness: -0.5 N m/rad\n  rate: 1 deg/s", "deflection", "expected stiffness > 0"),
    ("stiffness: 0.5 N m/rad\n  gimbal_rate: 1 deg/s", "rate", "belongs to a rate-integrating"),
    ("stiffness: 0.5 N m/rad\n  rate: 1 deg/s", "natural_frequency",
     "natural_frequency needs stiffness and gimbal_inertia"),
    ("damping: 0.05 N m s/rad\n  deflection: 2 deg", "rate", "input_angle"),
    ("stiffness: 0.5 N m/rad\n  rate: 1 deg/s\n  spin: 100 rad/s", "rate", "not both"),
])
def test_rate_gyro_bad_input_exits_2_with_one_line(run, write, extra, find, reason):
    result = run("solve", write(GYRO.format(H=0.1, extra=extra, find=find)))
    assert result.exit_code == 2, result.output
    assert reason in result.stderr and "Traceback" not in result.output
    assert len(result.stderr.strip().splitlines()) == 1


# ---- the three kinds in the authoring tools --------------------------------------

@pytest.mark.parametrize("name", ["earth_precession", "gyrocompass", "rate_gyro"])
def test_new_kinds_are_listed_and_their_templates_check(run, tmp_path, name):
    assert name in run("kinds").stdout
    out = tmp_path / f"{name}.yaml"
    assert run("new", name, "-o", out).exit_code == 0
    assert "expected:" in out.read_text()
    assert run("check", out).exit_code == 0
    schema = json.loads(run("schema").stdout)
    assert name in schema["properties"]["kind"]["enum"]


def test_compass_refuses_what_cannot_be(run, write):
    # a sensitive element lighter than its own rotor
    result = run("solve", write(COMPASS.format(J=0.002, I_t=0.001, spin=2000, I_v=0.0005,
                                               lat=30, dev=10)))
    assert result.exit_code == 2 and "includes the rotor" in result.stderr
    # released at rest pointing south: unstable equilibrium, no swing period
    result = run("solve", write(COMPASS.format(J=0.002, I_t=0.001, spin=2000, I_v=0.004,
                                               lat=30, dev=180)))
    assert result.exit_code == 2 and "unstable equilibrium" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def gimbal_rigid_body(J, I_t, A, B, C, k, c, p, Omega):
    """Right-hand side for y = (theta, thetadot) of a rotor driven at p in a gimbal, case turning.

    Case axes (turning at Omega about Z, the input axis): X the gimbal (output) axis, Y the
    spin axis at theta = 0. The gimbal turns by theta about X, so the spin axis is
    s = cos(theta) Y + sin(theta) Z, and t = X x s. Rotor inertia J s s^T + I_t (1 - s s^T);
    gimbal inertia A, B, C about X, s, t. Angular velocities: gimbal Omega Z + thetadot X,
    rotor that plus p s. Lagrange's equation for theta, from T alone (complex step), with a
    spring k theta and a damper c thetadot; the drive holds p, so psi is not free.
    """
    def T(theta, td):
        s = (0.0, cmath.cos(theta), cmath.sin(theta))
        t = (0.0, -cmath.sin(theta), cmath.cos(theta))
        w_g = (td, 0.0, Omega)
        w_r = (td, p * s[1], Omega + p * s[2])
        dot = lambda u, v: sum(a * b for a, b in zip(u, v))  # noqa: E731
        rotor = J * dot(w_r, s) ** 2 + I_t * (dot(w_r, w_r) - dot(w_r, s) ** 2)
        gimbal = A * w_g[0] ** 2 + B * dot(w_g, s) ** 2 + C * dot(w_g, t) ** 2
        return 0.5 * (rotor + gimbal)

    def rhs(_, y):
        theta, td = y
        h = 1e-30
        z = theta + 1j * h
        v = 100.0  # polarise at a rate that lifts M's share above the spin energy's rounding
        T0, Tp, Tm = T(z, 0.0), T(z, v), T(z, -v)
        M, M_theta = (Tp + Tm - 2 * T0).real / v ** 2, (Tp + Tm - 2 * T0).imag / h / v ** 2
        T0_theta = T0.imag / h
        return [td, (T0_theta - 0.5 * M_theta * td * td - k * theta - c * td) / M]

    return rhs


@pytest.mark.parametrize("rate_deg", [3.0, 20.0])
def test_gimbal_equation_from_the_rigid_body(run, write, rate_deg):
    # rotor J = 2e-4 at 2500 rad/s (H = 0.5); spring, damper; gimbal inertias
    J, I_t, p = 2e-4, 1.1e-4, 2500.0
    k, c = 0.8 if rate_deg < 10 else 0.2, 0.01
    rhs = gimbal_rigid_body(J, I_t, 2e-5, 3e-5, 4e-5, k, c, p, rate_deg * DEG)
    sol = solve_ivp(rhs, (0, 1.0), [0.0, 0.0], method="DOP853", rtol=1e-10, atol=1e-10)
    steady = sol.y[0, -1]
    path = write(GYRO.format(H=J * p, extra=f"stiffness: {k} N m/rad\n  gimbal_inertia: "
                             f"{I_t + 2e-5} kg m^2\n  rate: {rate_deg} deg/s",
                             find="deflection, natural_frequency"))
    got = answers(run, path)
    if rate_deg < 10:
        # small angle: theta = H Omega / k, to the neglected cos(theta) (5e-4 here)
        assert got["deflection"][0] == pytest.approx(steady, rel=1e-3)
    else:
        # 28 deg: the warning's k theta = H Omega cos(theta) is the rigid body's steady state
        out = run("solve", path).stdout
        exact = float(out.split("gives ")[1].split(" deg")[0])
        assert exact == pytest.approx(steady / DEG, rel=1e-3)
        assert got["deflection"][0] > 1.05 * steady
    # the free gimbal (no damper) rings at sqrt(k / I_g), I_g = I_t + A about the gimbal axis
    free = gimbal_rigid_body(J, I_t, 2e-5, 3e-5, 4e-5, k, 0.0, p, 0.0)
    sol = solve_ivp(free, (0, 1.0), [1e-3, 0.0], method="DOP853", rtol=1e-10, atol=1e-13,
                    dense_output=True)
    t = np.linspace(0, 1.0, 100001)
    theta = sol.sol(t)[0]
    ups = t[1:][(theta[:-1] < 0) & (theta[1:] >= 0)]
    assert got["natural_frequency"][0] == pytest.approx(2 * math.pi / np.mean(np.diff(ups)),
                                                        rel=1e-4)


def test_rate_gyro_refuses_a_gimbal_past_90_deg(run, write):
    result = run("solve", write(GYRO.format(H=0.5, extra="stiffness: 0.1 N m/rad\n  deflection: "
                                            "95 deg", find="rate")))
    assert result.exit_code == 2 and "expected -90 deg < deflection < 90 deg" in result.stderr
    # a rate far beyond the range: refused, with the exact steady state as the limit
    result = run("solve", write(GYRO.format(H=0.5, extra="stiffness: 0.1 N m/rad\n  rate: "
                                            "100 rad/s", find="deflection")))
    H, k, rate = 0.5, 0.1, 100.0
    lo, hi = 0.0, math.pi / 2  # k theta = H rate cos(theta), by bisection here
    for _ in range(100):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if k * mid < H * rate * math.cos(mid) else (lo, mid)
    assert result.exit_code == 2 and f"{lo / DEG:.4g} deg" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def test_earth_with_no_torque_gives_zero_and_no_period(run, write):
    path = write(EARTH_BAD.format(extra="preset: earth\n  sun_mass_ratio: 0\n  moon_mass_ratio: 0"))
    assert answers(run, path)["precession_rate"] == [0.0]
    result = run("solve", write(EARTH_BAD.format(
        extra="preset: earth\n  sun_mass_ratio: 0\n  moon_mass_ratio: 0").replace(
        "[precession_rate]", "[precession_period]")))
    assert result.exit_code == 2 and "Traceback" not in result.output
