"""The full equations of motion (Euler + quaternion, simulate.py) against
independent references:

* Lagrange's reduced equation 11.15 with Eq. 11.16 for phi, integrated here in
  Euler angles with its own solve_ivp (a different formulation and state);
* the chapter's closed forms for the released top (Eq. 11.25, cusps at u2) and
  for steady precession (the quadratic of kind steady_precession);
* conservation laws written in Euler angles (Eqs. 11.10, 11.11, 11.14) on the
  output series, not on the integrator's state;
* the analytic module nutation.py (elliptic/quadrature path), for 20 random tops.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from gyro_cli.physics.simulate import Params, initial_state, motion_of, simulate

G = 9.81
# Problem 11/3: 3 ozf top, k_z = 0.84 in, k_O = 1.80 in, l = 1.5 in, 1800 rpm, 30 deg
M_11_3 = 3 * 0.27801385 / (32.2 * 0.3048)
TOP_11_3 = dict(I=M_11_3 * (1.80 * 0.0254) ** 2, J=M_11_3 * (0.84 * 0.0254) ** 2,
                mgl=M_11_3 * 32.2 * 0.3048 * 1.5 * 0.0254)


def top(theta0_deg: float, spin: float, precession0: float = 0.0, theta_rate0: float = 0.0,
        **body) -> Params:
    body = body or TOP_11_3
    return Params(theta0=math.radians(theta0_deg), spin=spin, precession0=precession0,
                  theta_rate0=theta_rate0, **body)


def lagrange(p: Params, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """theta, phi, phidot from Eqs. 11.14-11.16 integrated in Euler angles."""
    c0, s0 = math.cos(p.theta0), math.sin(p.theta0)
    P2 = p.J * (p.spin + p.precession0 * c0)                     # Eq. 11.14
    P1 = p.I * p.precession0 * s0 ** 2 + P2 * c0

    def rhs(_, y):
        th, thd, _phi = y
        c, s = math.cos(th), math.sin(th)
        thdd = ((P1 - P2 * c) * (P1 * c - P2) / (p.I * s ** 3) + p.mgl * s) / p.I   # Eq. 11.15
        return [thd, thdd, (P1 - P2 * c) / (p.I * s * s)]                           # Eq. 11.16

    sol = solve_ivp(rhs, (0, t[-1]), [p.theta0, p.theta_rate0, 0.0], method="DOP853",
                    rtol=1e-13, atol=1e-14, t_eval=t)
    theta, phi = sol.y[0], sol.y[2]
    return theta, phi, (P1 - P2 * np.cos(theta)) / (p.I * np.sin(theta) ** 2)


def euler_energy(p: Params, sim) -> np.ndarray:
    """T + V from the output Euler angles and rates, Eqs. 11.10 and 11.11."""
    th = sim.theta
    return 0.5 * (p.I * (sim.theta_rate ** 2 + sim.phidot ** 2 * np.sin(th) ** 2)
                  + p.J * (sim.psidot + sim.phidot * np.cos(th)) ** 2) + p.mgl * np.cos(th)


CASES = {
    "cusps (released, problem 11/3 top)": top(30, 188.5),
    "loops (phidot0 < 0)": top(60, 150.0, precession0=-3.0),
    "waves (phidot0 > 0)": top(45, 150.0, precession0=6.0),
    "hanging, thetadot0 != 0": top(120, 90.0, precession0=1.0, theta_rate0=0.7),
}


@pytest.mark.parametrize("name", list(CASES))
def test_theta_and_phi_match_lagrange_eq_11_15(name):
    p = CASES[name]
    sim = simulate(p, p, t_end=1.0, samples=801)
    theta, phi, phidot = lagrange(p, sim.t)
    assert np.max(np.abs(sim.theta - theta)) < 1e-8
    assert np.max(np.abs(sim.phi - phi)) < 1e-7
    assert np.max(np.abs(sim.phidot - phidot)) < 1e-6 * np.max(np.abs(phidot))


def test_initial_state_is_eq_11_8():
    """Body omega at t = 0 by hand (psi = 0): (thetadot, phidot sin th, psidot + phidot cos th)."""
    p = top(40, 100.0, precession0=2.0, theta_rate0=-0.5)
    w, x, y, z, ox, oy, oz = initial_state(p)
    assert (ox, oy) == (-0.5, pytest.approx(2.0 * math.sin(math.radians(40))))
    assert oz == pytest.approx(100.0 + 2.0 * math.cos(math.radians(40)))
    assert w * w + x * x + y * y + z * z == pytest.approx(1.0)
    # body z axis seen from the fixed frame: cos(theta) = 1 - 2 (x^2 + y^2)
    assert 1 - 2 * (x * x + y * y) == pytest.approx(math.cos(math.radians(40)))


def test_released_top_falls_to_eq_11_25_and_has_cusps():
    """theta oscillates between theta2 (release) and theta1 of Eq. 11.25 (as corrected);
    phidot = 0 at theta2 (cusps, Eq. 11.26) and the path repeats."""
    p = top(30, 188.5)
    sim = simulate(p, p, t_end=1.0, samples=401)
    a = 2 * p.mgl / p.I
    gamma = p.J * p.spin / p.I
    u2 = math.cos(p.theta0)
    u1 = gamma ** 2 / (2 * a) - math.sqrt(gamma ** 4 / (4 * a * a) - gamma ** 2 / a * u2 + 1)
    assert sim.theta_min == pytest.approx(p.theta0, rel=1e-10)
    assert sim.theta_max == pytest.approx(math.acos(u1), rel=1e-9)
    assert np.all(np.abs(sim.phidot_at_min) < 1e-7 * np.max(np.abs(sim.phidot_at_max)))
    assert motion_of(sim) == "cusps"


def test_energy_and_momenta_drift_over_100_periods():
    """Energy (Eqs. 11.10-11.11) and P1, P2 (Eq. 11.14) from the output Euler angles stay at
    their values computed by hand from the initial conditions, over 100 nutation periods."""
    p = top(60, 150.0, precession0=-3.0)
    short = simulate(p, p, t_end=1.0, samples=3)
    sim = simulate(p, p, t_end=100 * short.nutation_period, samples=20001)
    assert len(sim.t_theta_max) >= 99
    c0, s0 = math.cos(p.theta0), math.sin(p.theta0)
    omega_z = p.spin + p.precession0 * c0
    E0 = 0.5 * (p.I * p.precession0 ** 2 * s0 ** 2 + p.J * omega_z ** 2) + p.mgl * c0
    P2 = p.J * omega_z
    P1 = p.I * p.precession0 * s0 ** 2 + P2 * c0
    scale_E = 0.5 * (p.I * p.precession0 ** 2 * s0 ** 2 + p.J * omega_z ** 2) + p.mgl
    H = math.hypot(p.I * p.precession0 * s0, P2)
    th = sim.theta
    energy = euler_energy(p, sim)
    p2 = p.J * (sim.psidot + sim.phidot * np.cos(th))
    p1 = p.I * sim.phidot * np.sin(th) ** 2 + p2 * np.cos(th)
    assert np.max(np.abs(energy - E0)) / scale_E < 1e-10
    assert np.max(np.abs(p1 - P1)) / H < 1e-10
    assert np.max(np.abs(p2 - P2)) / H < 1e-10
    # and the integrator's own bookkeeping agrees
    assert sim.energy0 == pytest.approx(E0, rel=1e-14)
    assert max(sim.energy_drift, sim.P1_drift, sim.P2_drift) < 1e-10
    assert sim.norm_drift < 1e-10


@pytest.mark.parametrize("which", [0, 1])
def test_steady_precession_keeps_theta(which):
    """Started at a root of the steady-precession quadratic (kind steady_precession, Eq. 11.13
    with thetaddot = 0), theta stays put and phi advances at that root."""
    from gyro_cli.kinds.steady_precession import precession_from_spin

    p0 = top(30, 188.5)
    roots = precession_from_spin(p0.I, p0.J, p0.theta0, p0.spin, p0.mgl)
    phidot = sorted(roots, key=abs)[which]
    p = top(30, 188.5, precession0=phidot)
    sim = simulate(p, p, t_end=5 * 2 * math.pi / abs(phidot), samples=2001)
    assert np.max(np.abs(sim.theta - p.theta0)) < 1e-9
    assert sim.mean_precession == pytest.approx(phidot, rel=1e-10)
    assert motion_of(sim) == "steady"
    assert sim.nutation_period is None


def test_sleeping_top_at_theta_zero():
    """theta0 = 0 is gimbal lock for Euler angles; the quaternion state integrates it, the axis
    stays vertical and the body spins at omega_z (psi + phi advance at the spin)."""
    p = top(0, 188.5)
    sim = simulate(p, p, t_end=2.0, samples=201)
    assert np.all(np.isfinite(sim.theta)) and np.max(sim.theta) < 1e-12
    assert sim.energy_drift < 1e-12
    assert motion_of(sim) == "sleeping"


def test_axis_through_the_vertical():
    """With P1 = P2 (Eq. 11.14) u = 1 is a root of f(u) (Eq. 11.19: f(1) = -(beta - gamma)^2);
    pushed up hard enough that f > 0 on (u0, 1) (thetadot0^2 + phidot0^2 sin^2 th0 > a (1 - u0),
    f(u)/(1 - u) is concave), the axis passes through theta = 0, where Eq. 11.15 is singular.
    The quaternion integration goes through, conserving energy and P1."""
    th0 = math.radians(20)
    body = TOP_11_3
    P2 = body["J"] * 120.0
    # phidot0 with I phidot sin^2 + P2 cos = P2 and spin such that J(psidot + phidot cos) = P2
    phidot0 = P2 * (1 - math.cos(th0)) / (body["I"] * math.sin(th0) ** 2)
    p = top(20, 120.0 - phidot0 * math.cos(th0), precession0=phidot0, theta_rate0=-30.0)
    a = 2 * body["mgl"] / body["I"]
    assert p.theta_rate0 ** 2 + (phidot0 * math.sin(th0)) ** 2 > a * (1 - math.cos(th0))
    sim = simulate(p, p, t_end=0.5, samples=4001)
    assert sim.theta_min < 1e-6
    assert sim.energy_drift < 1e-11 and sim.P1_drift < 1e-11
    assert np.all(np.isfinite(sim.theta))
    # phidot = gamma (1 - u) / (1 - u^2) = gamma / (1 + u) (Eq. 11.16 with beta = gamma): one sign
    assert motion_of(sim) == "waves"
    assert any("through the vertical" in note for note in sim.notes)


def test_unstable_sleeping_top_falls_and_stable_one_stays():
    """Near theta = 0 the sleeping top is stable iff J^2 omega_z^2 > 4 I m g l (Eq. 11.21 at
    theta0 = 0)."""
    body = TOP_11_3
    critical = 2 * math.sqrt(body["I"] * body["mgl"]) / body["J"]
    stable = top(0.01, 1.5 * critical)
    unstable = top(0.01, 0.5 * critical)
    sim_s = simulate(stable, stable, t_end=2.0, samples=401)
    sim_u = simulate(unstable, unstable, t_end=2.0, samples=401)
    assert sim_s.theta_max < math.radians(0.1)
    assert sim_u.theta_max > math.radians(30)


def test_bad_parameters_raise():
    with pytest.raises(ValueError):
        simulate(top(30, 10.0, I=-1.0, J=1.0, mgl=1.0), top(30, 10.0), t_end=1.0)
    with pytest.raises(ValueError):
        p = top(30, 10.0)
        simulate(p, p, t_end=0.0)


# ---- the command line -----------------------------------------------------------

STEADY_FILE = """\
    id: t1
    kind: steady_precession
    given:
      mass: 0.5 kg
      J: 2.0e-4 kg*m^2
      I_pivot: 1.2e-3 kg*m^2
      cg_distance: 40 mm
      spin: 3000 rpm
      theta: 50 deg
    find:
      precession: rpm
"""


def test_cli_steady_precession_json(run, write):
    """The slow root of the steady-precession quadratic, worked by hand here:
    (J - I) cos th phidot^2 + J psidot phidot - m g l = 0."""
    import json

    result = run("simulate", write(STEADY_FILE), "--periods", "3", "--format", "json")
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    I, J, mgl, th, spin = 1.2e-3, 2.0e-4, 0.5 * 9.81 * 0.040, math.radians(50), 100 * math.pi
    a, b, c = (J - I) * math.cos(th), J * spin, -mgl
    slow = min(((-b + s * math.sqrt(b * b - 4 * a * c)) / (2 * a) for s in (1, -1)), key=abs)
    assert report["analytic"]["mean_precession"] == pytest.approx(slow, rel=1e-12)
    assert report["simulated"]["mean_precession"] == pytest.approx(slow, rel=1e-9)
    assert report["simulated"]["motion"] == "steady"
    assert report["theta_range"] < 1e-9
    assert report["t_end"] == pytest.approx(3 * 2 * math.pi / slow, rel=1e-12)
    assert max(report["drift"].values()) < 1e-10


def test_cli_text_report_names_the_equations(run, problems_dir):
    result = run("simulate", problems_dir / "11_3.yaml", "--periods", "1")
    assert result.exit_code == 0, result.output
    for text in ("analytic", "simulated", "Eq. 11.14", "energy T + V", "45.13444", "steady"):
        assert text in result.stdout


@pytest.mark.parametrize("args,message", [
    (["nope.yaml"], "no such file"),
    (["{steady}", "--periods", "0"], "periods"),
    (["{moment}"], "applied moment"),
    (["{steady}", "--plot", "{tmp}/x.gif"], "png"),
    (["{steady}", "--csv", "{tmp}/no/dir/x.csv"], "no such directory"),
])
def test_cli_bad_input_is_one_line_exit_2(run, write, tmp_path, args, message):
    steady = write(STEADY_FILE, "steady.yaml")
    moment = write(STEADY_FILE.replace("cg_distance: 40 mm", "moment: 0.2 N*m"), "moment.yaml")
    args = [a.format(steady=steady, moment=moment, tmp=tmp_path) for a in args]
    result = run("simulate", *args)
    assert result.exit_code == 2
    assert message in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1 or "Usage" in result.stderr
    assert "Traceback" not in result.output


def test_progress_bar_only_on_a_terminal():
    import io

    from gyro_cli.commands.simulate import terminal_progress

    class Tty(io.StringIO):
        def isatty(self):
            return True

    assert terminal_progress(io.StringIO()) is None
    stream = Tty()
    show = terminal_progress(stream)
    show(0.01)
    assert stream.getvalue() == ""                # short runs show nothing
    import time as _time
    _time.sleep(0.55)
    show(0.5)
    show(1.0)
    assert "simulating" in stream.getvalue() and "50.0%" in stream.getvalue()
    assert stream.getvalue().endswith("\r")       # the bar is wiped at the end


# ---- random tops: the integration against quadratures of Eq. 11.19 and nutation.py -------

def quadrature(p: Params) -> dict:
    """theta limits, nutation period and mean precession by quadrature of Eq. 11.19, written
    here: f(u) = (1 - u^2)(alpha - a u) - (beta - gamma u)^2 = a (u - u1)(u - u2)(u - u3);
    u = u1 + (u2 - u1) sin^2 s makes dt = du / sqrt(f) = 2 ds / sqrt(a (u3 - u)), smooth."""
    from scipy.integrate import quad

    c0, s0 = math.cos(p.theta0), math.sin(p.theta0)
    a = 2 * p.mgl / p.I
    gamma = p.J * (p.spin + p.precession0 * c0) / p.I
    beta = p.precession0 * s0 ** 2 + gamma * c0
    alpha = p.theta_rate0 ** 2 + (p.precession0 * s0) ** 2 + a * c0
    # f(u) = a u^3 - (alpha + gamma^2) u^2 + (2 beta gamma - a) u + alpha - beta^2
    coeffs = [a, -(alpha + gamma ** 2), 2 * beta * gamma - a, alpha - beta ** 2]
    roots = np.sort(np.roots(coeffs).real)
    for _ in range(3):                                   # polish by Newton
        roots = roots - np.polyval(coeffs, roots) / np.polyval(np.polyder(coeffs), roots)
    u1, u2, u3 = np.sort(roots)

    def u_of(s):
        return u1 + (u2 - u1) * math.sin(s) ** 2

    def dt(s):
        return 2 / math.sqrt(a * (u3 - u_of(s)))

    def dphi(s):
        u = u_of(s)
        return (beta - gamma * u) / (1 - u * u) * dt(s)

    period = 2 * quad(dt, 0, math.pi / 2, epsabs=0, epsrel=1e-13, limit=200)[0]
    advance = 2 * quad(dphi, 0, math.pi / 2, epsabs=0, epsrel=1e-13, limit=200)[0]
    phidot_ends = [(beta - gamma * u) / (1 - u * u) for u in (u1, u2)]
    return {"theta_min": math.acos(min(u2, 1.0)), "theta_max": math.acos(max(u1, -1.0)),
            "nutation_period": period, "mean_precession": advance / period,
            "phidot_scale": max(map(abs, phidot_ends))}


def random_tops(n: int = 20, seed: int = 11) -> list[Params]:
    """Seeded tops spanning slow and fast spin, upright and hanging, released and thrown;
    tops whose axis comes within 5 deg of the vertical are redrawn (phi is ill-defined there)."""
    rng = np.random.default_rng(seed)
    tops = []
    while len(tops) < n:
        I = 10 ** rng.uniform(-4, -2)
        J = I * rng.uniform(0.2, 1.8)
        mgl = I * rng.uniform(5, 50)
        a = 2 * mgl / I
        theta0 = math.radians(rng.uniform(15, 150))
        gamma = math.sqrt(a) * rng.uniform(0.7, 4.0)
        precession0 = rng.choice([0.0, rng.uniform(-1, 1) * math.sqrt(a)])
        theta_rate0 = rng.choice([0.0, 0.0, rng.uniform(-0.5, 0.5) * math.sqrt(a)])
        spin = gamma * I / J - precession0 * math.cos(theta0)
        p = Params(I=I, J=J, mgl=mgl, theta0=theta0, spin=spin, precession0=precession0,
                   theta_rate0=theta_rate0)
        q = quadrature(p)
        if q["theta_min"] > math.radians(5) and q["theta_max"] < math.radians(175) and \
                q["theta_max"] - q["theta_min"] > 1e-4:
            tops.append(p)
    return tops


TOPS = random_tops()


@pytest.fixture(scope="module")
def simulated():
    """Each random top integrated over 5 nutation periods (period from the quadrature; a
    duration only: everything measured comes from the integration)."""
    out = []
    for p in TOPS:
        q = quadrature(p)
        out.append((p, q, simulate(p, p, t_end=5 * q["nutation_period"] * (1 + 1e-3),
                                   samples=1001)))
    return out


def test_random_tops_match_quadrature_of_eq_11_19(simulated):
    for p, q, sim in simulated:
        assert sim.theta_min == pytest.approx(q["theta_min"], rel=1e-7), p
        assert sim.theta_max == pytest.approx(q["theta_max"], rel=1e-7), p
        assert sim.nutation_period == pytest.approx(q["nutation_period"], rel=1e-7), p
        assert sim.mean_precession == pytest.approx(
            q["mean_precession"], rel=1e-7, abs=1e-9 * q["phidot_scale"]), p
        assert len(sim.t_theta_max) + len(sim.t_theta_min) >= 10


@pytest.fixture(scope="module")
def nutation():
    import gyro_cli.physics.nutation

    return gyro_cli.physics.nutation


def _top_start(nutation, p: Params):
    return (nutation.Top(I=p.I, J=p.J, mgl=p.mgl),
            nutation.Start(theta0=p.theta0, spin=p.spin, precession0=p.precession0,
                           theta_rate0=p.theta_rate0))


def test_random_tops_match_nutation_analyse(nutation, simulated):
    """The analytic module against the integration: theta limits, period, mean precession to
    1e-7 relative; its motion word against phidot's signs in the simulated series."""
    for p, q, sim in simulated:
        nut = nutation.analyse(*_top_start(nutation, p))
        assert nut.theta_min == pytest.approx(sim.theta_min, rel=1e-7), p
        assert nut.theta_max == pytest.approx(sim.theta_max, rel=1e-7), p
        assert nut.nutation_period == pytest.approx(sim.nutation_period, rel=1e-7), p
        assert nut.mean_precession == pytest.approx(
            sim.mean_precession, rel=1e-7, abs=1e-9 * q["phidot_scale"]), p
        series = sim.phidot
        scale = np.max(np.abs(series))
        if nut.motion == "loops":
            assert series.min() < -1e-6 * scale and series.max() > 1e-6 * scale, p
        elif nut.motion == "waves":
            assert np.all(series > 0) or np.all(series < 0), p
        elif nut.motion == "cusps":
            ends = np.concatenate([sim.phidot_at_min, sim.phidot_at_max])
            assert np.min(np.abs(ends)) < 1e-7 * scale, p
            assert np.all(series >= -1e-7 * scale) or np.all(series <= 1e-7 * scale), p
        assert nut.motion == motion_of(sim), p


def test_exact_theta_of_t_matches_integration(nutation, simulated):
    """theta(t) of the analytic module against the integrated theta, 5 nutation periods."""
    from gyro_cli.physics.motion import theta_of_t

    for p, _, sim in simulated:
        exact = np.asarray(theta_of_t(*_top_start(nutation, p), sim.t))
        assert np.max(np.abs(exact - sim.theta)) < 1e-8, p


# ---- gyro simulate on released_top files ------------------------------------------------

RELEASED_FILE = """\
    id: r1
    title: Problem 11/3's top released at 30 deg
    kind: released_top
    given:
      weight: 3 oz
      k_axial: 0.84 in
      k_pivot: 1.80 in
      cg_distance: 1.5 in
      spin: 1800 rpm
      theta0: {theta0}
    find:
      theta_max: deg
      nutation_period: s
      motion: null
"""


@pytest.fixture
def released(write):
    return lambda theta0="30 deg": write(RELEASED_FILE.format(theta0=theta0), "released.yaml")


def test_cli_released_top_analytic_beside_simulated(run, released):
    import json

    result = run("simulate", released(), "--periods", "4", "--format", "json")
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    for key in ("theta_min", "theta_max", "nutation_period", "mean_precession"):
        assert abs(report["difference"][key]["relative"]) < 1e-7, key
    assert report["analytic"]["motion"] == report["simulated"]["motion"] == "cusps"
    assert max(report["drift"].values()) < 1e-10
    # Eq. 11.25 (as corrected) by hand: the axis falls from 30 deg to theta_1
    p = TOP_11_3
    a, gamma, u2 = 2 * p["mgl"] / p["I"], p["J"] * 60 * math.pi / p["I"], math.cos(math.pi / 6)
    u1 = gamma ** 2 / (2 * a) - math.sqrt(gamma ** 4 / (4 * a * a) - gamma ** 2 / a * u2 + 1)
    assert report["simulated"]["theta_max"] == pytest.approx(math.acos(u1), rel=1e-9)
    assert report["t_end"] == pytest.approx(4 * report["analytic"]["nutation_period"])


def test_cli_released_top_text_and_plot(run, released, tmp_path):
    png = tmp_path / "r.png"
    result = run("simulate", released(), "--plot", png)
    assert result.exit_code == 0, result.output
    assert "cusps" in result.stdout and "nutation period (s)" in result.stdout
    assert png.read_bytes().startswith(b"\x89PNG")


def test_cli_sleeping_released_top(run, released):
    import json

    result = run("simulate", released("0 deg"), "--periods", "2", "--format", "json")
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["simulated"]["motion"] == "sleeping"
    assert report["simulated"]["theta_max"] < 1e-12
    assert max(report["drift"].values()) < 1e-10


def test_gyro_solve_plot_released_top(run, released, tmp_path):
    png = tmp_path / "solve.png"
    result = run("solve", released(), "--plot", png)
    assert result.exit_code == 0, result.output
    assert png.read_bytes().startswith(b"\x89PNG")
    again = run("solve", released(), "--plot", png)
    assert again.exit_code == 2 and "exists" in again.stderr


def test_a_run_too_long_is_refused_at_once(run, tmp_path):
    """A needle-like top (I/J = 1e6) at 1e6 rpm would take hours: refused before integrating."""
    import time

    path = tmp_path / "needle.yaml"
    path.write_text("id: needle\nkind: released_top\ngiven: {mass: 1 kg, J: 1e-7 kg m^2, "
                    "I_pivot: 0.1 kg m^2, cg_distance: 0.1 m, theta0: 30 deg, spin: 1e6 rpm}\n"
                    "find: {theta_max: deg}\n")
    start = time.perf_counter()
    out = run("simulate", path)
    assert out.exit_code == 2 and "--periods" in out.stderr and out.stderr.count("\n") == 1
    assert time.perf_counter() - start < 5
