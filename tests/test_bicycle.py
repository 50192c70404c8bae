"""bicycle checked against the benchmark paper and against independent computations.

(a) the matrices, eigenvalues and speeds against the numbers printed by
    Meijaard, Papadopoulos, Ruina & Schwab, Proc. R. Soc. A 463 (2007) 1955
    (written out here, not computed by gyro);
(b) by hand from the published matrices: the eigenvalues at rest (a quadratic
    in s^2) and the capsize speed (det(g K0 + v^2 K2) = 0 is linear in v^2);
(c) the equations of motion M q'' + v C1 q' + (g K0 + v^2 K2) q = 0, written
    here with the published matrices, integrated in time by solve_ivp: a small
    lean disturbance dies out inside the stable range and grows outside, at the
    rate of gyro's largest eigenvalue;
(d) the gyroscopic share: `gyroscopic: false` is exactly I_Ryy = I_Fyy = 0;
(e) the command line, the problem file, the plot, and bad input (exit 2, one line).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from gyro_cli.physics import bicycle as bike

G = 9.81
# The paper's printed values for the benchmark (section on the benchmark results, Table 2).
M_PUB = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
C1_PUB = np.array([[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0_PUB = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2_PUB = np.array([[0.0, 76.59734589573222], [0.0, 2.65431523794604]])
WEAVE, CAPSIZE = 4.29238253634111, 6.02426201538837
EIG_5 = [-14.0783896927982, -0.775341882195845 - 4.46486771378823j,
         -0.775341882195845 + 4.46486771378823j, -0.322866429004087]
EIG_0 = [-5.53094371765393, -3.13164324790656, 3.13164324790656, 5.53094371765393]
EIG_4 = [-12.15861426576447, -1.42944427361326, 0.41325331521125 - 3.07910818603206j,
         0.41325331521125 + 3.07910818603206j]
EIG_10 = [-24.62459635017404, -3.72016840437287 - 10.90681139476287j,
          -3.72016840437287 + 10.90681139476287j, 0.16105338653172]


# ---- (a) the paper's numbers --------------------------------------------------

def test_matrices_equal_the_published_values():
    m = bike.matrices(bike.BENCHMARK)
    for got, want in ((m.M, M_PUB), (m.C1, C1_PUB), (m.K0, K0_PUB), (m.K2, K2_PUB)):
        assert np.allclose(got, want, rtol=1e-13, atol=1e-13), (got, want)


def test_eigenvalues_at_5_and_0_m_per_s_equal_the_published_values():
    m = bike.matrices(bike.BENCHMARK)
    got = bike.eigenvalues(m, 5.0, G)
    assert np.allclose(got, EIG_5, rtol=1e-13, atol=1e-13)
    assert list(got.real) == sorted(got.real)        # ascending real part, then imaginary
    assert got[1].imag < 0 < got[2].imag
    assert np.allclose(bike.eigenvalues(m, 0.0, G), EIG_0, rtol=1e-13)
    assert np.allclose(bike.eigenvalues(m, 4.0, G), EIG_4, rtol=1e-12)
    assert np.allclose(bike.eigenvalues(m, 10.0, G), EIG_10, rtol=1e-12)


def test_weave_and_capsize_speeds_equal_the_published_values():
    stab = bike.stability(bike.matrices(bike.BENCHMARK), G)
    assert stab.weave == [pytest.approx(WEAVE, rel=1e-12)]
    assert stab.capsize == [pytest.approx(CAPSIZE, rel=1e-12)]
    assert stab.stable == [(stab.weave[0], stab.capsize[0])]
    assert abs(stab.weave[0] / WEAVE - 1) < 1e-6 and abs(stab.capsize[0] / CAPSIZE - 1) < 1e-6


def test_froude_scaling():
    """Dimensional analysis, independent of the formulas: a bicycle scaled by L in every
    length and by k in every mass (inertias by k L^2) has its speeds scaled by sqrt(L)
    and its eigenvalues by 1/sqrt(L) (same g)."""
    lengths = ("w", "c", "rR", "rF", "xB", "zB", "xH", "zH")
    for L, k in ((0.01, 1e-3), (3.0, 2.0), (100.0, 1e3)):
        p = {key: (v * L if key in lengths else v * k if key.startswith("m") else
                   v * k * L * L if key.startswith("I") else v)
             for key, v in bike.BENCHMARK.items()}
        stab = bike.stability(bike.matrices(p), G)
        assert stab.weave == [pytest.approx(WEAVE * math.sqrt(L), rel=1e-12)]
        assert stab.capsize == [pytest.approx(CAPSIZE * math.sqrt(L), rel=1e-12)]
        got = bike.eigenvalues(bike.matrices(p), 5.0 * math.sqrt(L), G)
        assert np.allclose(got * math.sqrt(L), EIG_5, rtol=1e-11)


# ---- (b) by hand from the published matrices -----------------------------------

def test_eigenvalues_at_rest_by_hand():
    """v = 0: det(M s^2 + g K0) = 0 is a quadratic in s^2 (an inverted double pendulum)."""
    a = M_PUB[0, 0] * M_PUB[1, 1] - M_PUB[0, 1] ** 2
    b = G * (M_PUB[0, 0] * K0_PUB[1, 1] + K0_PUB[0, 0] * M_PUB[1, 1]
             - 2 * M_PUB[0, 1] * K0_PUB[0, 1])
    c = G * G * (K0_PUB[0, 0] * K0_PUB[1, 1] - K0_PUB[0, 1] ** 2)
    s2 = [(-b + sign * math.sqrt(b * b - 4 * a * c)) / (2 * a) for sign in (1, -1)]
    assert all(x > 0 for x in s2)                    # both real pairs: it falls at rest
    by_hand = sorted([r for x in s2 for r in (math.sqrt(x), -math.sqrt(x))])
    assert by_hand == pytest.approx(EIG_0, rel=1e-12)


def test_capsize_speed_by_hand():
    """a0 = det(g K0 + v^2 K2); K2's first column is zero, so a0 is linear in v^2."""
    det_k0 = K0_PUB[0, 0] * K0_PUB[1, 1] - K0_PUB[0, 1] ** 2
    slope = K0_PUB[0, 0] * K2_PUB[1, 1] - K0_PUB[1, 0] * K2_PUB[0, 1]
    assert math.sqrt(-G * det_k0 / slope) == pytest.approx(CAPSIZE, rel=1e-12)


def test_total_mass_centre_and_lean_inertia_by_hand():
    """Table 1 by hand: the centre of mass of the whole bicycle and I_Txx (parallel axes)."""
    t = bike.totals(bike.BENCHMARK)
    assert t.mT == 2 + 85 + 4 + 3
    assert t.zT == pytest.approx((-0.3 * 2 - 0.9 * 85 - 0.7 * 4 - 0.35 * 3) / 94)
    assert t.xT == pytest.approx((0.3 * 85 + 0.9 * 4 + 1.02 * 3) / 94)
    assert t.ITxx == pytest.approx(0.0603 + 9.2 + 0.05892 + 0.1405 + 2 * 0.3 ** 2
                                   + 85 * 0.9 ** 2 + 4 * 0.7 ** 2 + 3 * 0.35 ** 2)
    # lean stiffness at rest is gravity's: d^2(m_T g h cos phi)/dphi^2 = -m_T g h, h = -z_T
    assert G * t.mT * t.zT == pytest.approx(G * K0_PUB[0, 0])


# ---- (c) the equations of motion integrated in time -----------------------------

def integrate(v: float, t_end: float, lean0: float = 0.01):
    """M q'' + v C1 q' + (g K0 + v^2 K2) q = 0 with the published matrices (solve_ivp)."""
    from scipy.integrate import solve_ivp

    inv = np.linalg.inv(M_PUB)
    stiffness = G * K0_PUB + v * v * K2_PUB

    def rhs(_t, y):
        q, qd = y[:2], y[2:]
        return np.concatenate([qd, -inv @ (v * C1_PUB @ qd + stiffness @ q)])

    t = np.linspace(0.0, t_end, 4001)
    sol = solve_ivp(rhs, (0.0, t_end), [lean0, 0.0, 0.0, 0.0], t_eval=t, rtol=1e-10,
                    atol=1e-13, method="DOP853")
    assert sol.success
    return sol.t, sol.y


def growth_rate(t, y) -> float:
    """Slope of log of the state's size over the last half (the slowest/fastest mode)."""
    size = np.log(np.linalg.norm(y, axis=0))
    half = len(t) // 2
    # the peaks of an oscillation: fit the upper envelope by the maxima in windows
    windows = np.array_split(np.arange(half, len(t)), 20)
    tt = np.array([t[w][np.argmax(size[w])] for w in windows])
    ss = np.array([np.max(size[w]) for w in windows])
    return float(np.polyfit(tt, ss, 1)[0])


@pytest.mark.parametrize("v, verdict", [(5.0, "stable"), (3.0, "weave"), (4.0, "weave"),
                                        (7.0, "capsize"), (10.0, "capsize")])
def test_lean_disturbance_decays_inside_and_grows_outside(v, verdict, run, write):
    t, y = integrate(v, t_end=25.0)
    lean = np.abs(y[0])
    rate = growth_rate(t, y)
    ev = bike.eigenvalues(bike.matrices(bike.BENCHMARK), v, G)
    assert rate == pytest.approx(float(np.max(ev.real)), abs=0.02)
    if verdict == "stable":
        assert lean[-1] < 1e-3 * lean[0]
    else:
        assert np.max(lean[-400:]) > 10 * lean[0]
    if verdict == "weave":      # oscillates: the lean changes sign again and again
        assert np.count_nonzero(np.diff(np.sign(y[0][len(t) // 2:]))) > 4
    if verdict == "capsize":    # falls one way without oscillating, late on
        assert np.all(np.sign(y[0][-1000:]) == np.sign(y[0][-1]))
    path = write(f"""
        id: v{v}
        kind: bicycle
        given: {{preset: benchmark, speed: {v} m/s}}
        find: {{motion: null, eigenvalues_real: s^-1}}
    """)
    out = run("solve", path, "--format", "json")
    assert out.exit_code == 0, out.output
    answers = json.loads(out.stdout)["answers"]
    assert answers["motion"]["values"] == [verdict]


def no_spin_by_hand():
    """The published C1 and K2 with the wheels' spin terms taken out by hand (Appendix A):
    S_R = I_Ryy / r_R = 0.4 kg m, S_F = I_Fyy / r_F = 0.8 kg m, S_T = 1.2 kg m."""
    lam, w, c = math.pi / 10, 1.02, 0.08
    mu, SF, ST = c * math.cos(lam) / w, 0.28 / 0.35, 0.12 / 0.3 + 0.28 / 0.35
    C1 = C1_PUB.copy()
    C1[0, 1] -= mu * ST + SF * math.cos(lam)
    C1[1, 0] += mu * ST + SF * math.cos(lam)
    K2 = K2_PUB.copy()
    K2[0, 1] -= ST * math.cos(lam) / w
    K2[1, 1] -= SF * math.sin(lam) * math.cos(lam) / w
    return C1, K2


def test_no_spin_problem_against_the_published_matrices_edited_by_hand(run, problems_dir):
    from scipy.integrate import solve_ivp

    C1, K2 = no_spin_by_hand()
    assert abs(C1[1, 0]) < 1e-13      # C1_deltaphi is wholly gyroscopic
    v = 5.0
    inv = np.linalg.inv(M_PUB)
    A = np.block([[np.zeros((2, 2)), np.eye(2)],
                  [-inv @ (G * K0_PUB + v * v * K2), -inv @ (v * C1)]])
    want = np.linalg.eigvals(A)
    out = run("solve", problems_dir / "bicycle_no_spin.yaml", "--format", "json")
    assert out.exit_code == 0, out.output
    answers = json.loads(out.stdout)["answers"]
    got = np.array(answers["eigenvalues_real"]["si_values"]) + \
        1j * np.array(answers["eigenvalues_imag"]["si_values"])
    assert np.allclose(np.sort_complex(got), np.sort_complex(want), rtol=1e-12)
    assert answers["motion"]["values"] == ["weave"]
    # in time: the lean oscillates with a growing amplitude
    sol = solve_ivp(lambda _t, y: A @ y, (0, 6), [0.01, 0, 0, 0], rtol=1e-10, atol=1e-13,
                    t_eval=np.linspace(0, 6, 601))
    lean = sol.y[0]
    assert np.max(np.abs(lean[-100:])) > 100 * 0.01
    assert np.count_nonzero(np.diff(np.sign(lean))) >= 2


@pytest.mark.parametrize("name, speed, published", [
    ("bicycle_benchmark_slow.yaml", 4.0, EIG_4), ("bicycle_benchmark_fast.yaml", 10.0, EIG_10),
    ("bicycle_benchmark.yaml", 5.0, EIG_5)])
def test_bundled_problems_by_hand(run, problems_dir, name, speed, published):
    """The km/h problems: the speed converts to the published one, the eigenvalues are Table 2's,
    and the doubling time and period in the notes follow from them by hand."""
    out = run("solve", problems_dir / name, "--format", "json")
    assert out.exit_code == 0, out.output
    answers = json.loads(out.stdout)["answers"]
    got = np.array(answers["eigenvalues_real"]["si_values"]) + \
        1j * np.array(answers["eigenvalues_imag"]["si_values"])
    assert np.allclose(got, published, rtol=1e-12, atol=1e-12)
    worst = max(published, key=lambda e: e.real)
    if speed == 4.0:
        assert math.log(2) / worst.real == pytest.approx(1.68, abs=0.005)
        assert 2 * math.pi / abs(worst.imag) == pytest.approx(2.04, abs=0.005)
        assert answers["weave_speed"]["values"] == [pytest.approx(WEAVE * 3.6, rel=1e-12)]
    if speed == 10.0:
        assert math.log(2) / worst.real == pytest.approx(4.3, abs=0.05)
        assert answers["capsize_speed"]["values"] == [pytest.approx(CAPSIZE * 3.6, rel=1e-12)]


def test_docs_trail_table():
    """docs/bicycle.md: the stable range for trail 0, 0.04, 0.08, 0.12 m, with and without spin."""
    table = {0.0: (2.933, 3.129), 0.04: (3.753, 4.767), 0.08: (4.292, 6.024),
             0.12: (4.696, 7.115)}
    for c, (lo, hi) in table.items():
        p = dict(bike.BENCHMARK, c=c)
        (got_lo, got_hi), = bike.stability(bike.matrices(p), G).stable
        assert (round(got_lo, 3), round(got_hi, 3)) == (lo, hi)
        assert bike.stability(bike.matrices(p, gyroscopic=False), G).stable == []
        # just outside the range unstable, inside stable
        m = bike.matrices(p)
        for v, stable in ((0.5 * (lo + hi), True), (lo - 0.05, False), (hi + 0.05, False)):
            assert (max(bike.eigenvalues(m, v, G).real) < 0) == stable


# ---- (d) the gyroscopic share ---------------------------------------------------

def test_gyroscopic_false_is_exactly_no_wheel_spin():
    no_spin = dict(bike.BENCHMARK, IRyy=0.0, IFyy=0.0)
    a = bike.matrices(bike.BENCHMARK, gyroscopic=False)
    b = bike.matrices(no_spin)
    for x, y in ((a.M, b.M), (a.C1, b.C1), (a.K0, b.K0), (a.K2, b.K2)):
        assert np.array_equal(x, y)
    full = bike.matrices(bike.BENCHMARK)
    assert np.array_equal(full.M, a.M) and np.array_equal(full.K0, a.K0)
    # C1_deltaphi is purely gyroscopic: -(mu S_T + S_F cos(lambda)); K2 loses S_T, S_F terms
    assert a.C1[1, 0] == 0 and full.C1[1, 0] == pytest.approx(C1_PUB[1, 0])
    t = bike.totals(bike.BENCHMARK)
    lam = math.pi / 10
    assert full.K2[0, 1] - a.K2[0, 1] == pytest.approx((0.12 / 0.3 + 0.28 / 0.35)
                                                       * math.cos(lam) / 1.02)
    assert full.K2[1, 1] - a.K2[1, 1] == pytest.approx(0.8 * math.sin(lam) * math.cos(lam)
                                                       / 1.02)
    assert full.C1[0, 1] - a.C1[0, 1] == pytest.approx(t.mu * 1.2 + 0.8 * math.cos(lam))


def test_without_wheel_spin_the_benchmark_has_no_stable_speed(run, write):
    stab = bike.stability(bike.matrices(bike.BENCHMARK, gyroscopic=False), G)
    assert stab.stable == [] and stab.weave == [] and stab.capsize == []
    m = bike.matrices(bike.BENCHMARK, gyroscopic=False)
    for v in np.linspace(0.5, 30, 60):       # unstable at every speed; the weave above ~1 m/s
        assert bike.motion(bike.eigenvalues(m, v, G)) != "stable"
        if v > 1.5:
            assert "weave" in bike.motion(bike.eigenvalues(m, v, G))
    path = write("""
        id: nospin
        kind: bicycle
        given: {preset: benchmark, speed: 5 m/s, gyroscopic: false}
        find: {motion: null, stable_speeds: m/s}
    """)
    out = run("solve", path)
    assert out.exit_code == 0, out.output
    assert "motion = weave" in out.stdout and "stable_speeds  v = none" in out.stdout


def test_normal_answer_states_the_share(run, problems_dir):
    out = run("solve", problems_dir / "bicycle_benchmark.yaml")
    assert out.exit_code == 0, out.output
    assert "without it (gyroscopic: false): no self-stable speed" in out.stdout
    assert "with the wheels' spin angular momentum: 4.292383 m/s < v < 6.024262 m/s" in out.stdout


# ---- (e) command line, problem file, plot, bad input ----------------------------

def test_problem_file_checks(run, problems_dir):
    out = run("check", problems_dir / "bicycle_benchmark.yaml")
    assert out.exit_code == 0, out.output
    assert "29 passed, 0 failed" in out.stdout


def test_json_carries_the_matrices_and_preset_keys_override(run, write):
    path = write("""
        id: j
        kind: bicycle
        given: {preset: benchmark, speed: 5 m/s, c: 0.08 m, mB: 85000 g}
        find: [M, C1, K0, K2, weave_speed]
    """)
    out = run("solve", path, "--format", "json")
    assert out.exit_code == 0, out.output
    answers = json.loads(out.stdout)["answers"]
    assert answers["M"]["si_values"] == pytest.approx(M_PUB.ravel().tolist(), rel=1e-13)
    assert answers["C1"]["si_unit"] == "kg m" and answers["K2"]["si_unit"] == "kg"
    assert answers["K0"]["labels"] == ["phi,phi", "phi,delta", "delta,phi", "delta,delta"]
    assert answers["weave_speed"]["values"] == [pytest.approx(WEAVE, rel=1e-12)]
    # a key beside the preset overrides it: a longer trail moves the weave speed
    longer = write("""
        id: j2
        kind: bicycle
        given: {preset: benchmark, c: 0.1 m}
        find: [weave_speed]
    """, name="j2.yaml")
    out = run("solve", longer, "--format", "json")
    assert out.exit_code == 0, out.output
    assert json.loads(out.stdout)["answers"]["weave_speed"]["values"][0] != \
        pytest.approx(WEAVE, rel=1e-3)


def test_every_key_without_preset_equals_the_preset(run, write):
    lines = "\n".join(f"  {k}: {v!r} {'rad' if k == 'lambda' else unit}"
                      for k, v, unit in ((k, v, _unit(k)) for k, v in bike.BENCHMARK.items()))
    path = write("id: all\nkind: bicycle\ngiven:\n" + lines +
                 "\n  speed: 5 m/s\nfind: [eigenvalues_real, capsize_speed]\n")
    out = run("solve", path, "--format", "json")
    assert out.exit_code == 0, out.output
    answers = json.loads(out.stdout)["answers"]
    assert answers["eigenvalues_real"]["si_values"] == pytest.approx(
        [e.real for e in EIG_5], rel=1e-12)
    assert answers["capsize_speed"]["si_values"] == [pytest.approx(CAPSIZE, rel=1e-12)]


def _unit(key: str) -> str:
    if key == "g":
        return "m/s^2"
    if key.startswith("I"):
        return "kg m^2"
    if key.startswith("m"):
        return "kg"
    return "m"


def test_plot_draws_a_png(run, problems_dir, tmp_path):
    png = tmp_path / "eig.png"
    out = run("solve", problems_dir / "bicycle_benchmark.yaml", "--plot", png)
    assert out.exit_code == 0, out.output
    assert png.read_bytes().startswith(b"\x89PNG")
    again = run("solve", problems_dir / "bicycle_benchmark.yaml", "--plot", png)
    assert again.exit_code == 2 and "exists" in again.stderr


def test_plot_curves_are_the_eigenvalues():
    from gyro_cli.render.plot_bicycle import eigenvalue_curves

    speeds, ev = eigenvalue_curves(bike.BENCHMARK, True, 10.0, n=101)
    i = int(np.argmin(abs(speeds - 5.0)))
    assert speeds[i] == pytest.approx(5.0)
    assert np.allclose(ev[i], EIG_5, rtol=1e-12)


BAD = [
    ("mB: -85 kg", "given.mB", "expected mB > 0 kg"),
    ("speed: 5 m", "given.speed", "expected a speed"),
    ("IBxz: 6 kg m^2", "given.IBxz", "not positive definite"),
    ("IHxx: -0.05 kg m^2", "given.IHxx", "expected IHxx > 0 kg m^2"),
    ("IRyy: 0.2 kg m^2", "given.IRyy", "at most twice"),
    ("IByy: 20 kg m^2", "given.IByy", "triangle inequality"),
    ("zB: 0.9 m", "given.zB", "expected zB < 0 m"),
    ("lambda: 95 deg", "given.lambda", "expected -90 deg < lambda < 90 deg"),
    ("w: 0 m", "given.w", "expected w > 0 m"),
    ("gyroscopic: maybe", "given.gyroscopic", "expected one of true, false"),
]


@pytest.mark.parametrize("line, key, words", BAD)
def test_bad_input_exits_2_with_one_line(run, write, line, key, words):
    speed = "" if line.startswith("speed") else "speed: 5 m/s"
    path = write(f"""
        id: bad
        kind: bicycle
        given:
          preset: benchmark
          {speed or line}
          {line if speed else ""}
        find: [weave_speed]
    """)
    out = run("solve", path)
    assert out.exit_code == 2
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1, out.stderr
    assert key in lines[0] and words in lines[0], lines[0]
    assert "Traceback" not in out.output


def test_missing_key_without_preset_and_speed_for_eigenvalues(run, write):
    path = write("""
        id: bad
        kind: bicycle
        given: {w: 1.02 m, speed: 5 m/s}
        find: [weave_speed]
    """)
    out = run("solve", path)
    assert out.exit_code == 2 and "given.c" in out.stderr and "preset: benchmark" in out.stderr
    path = write("""
        id: bad
        kind: bicycle
        given: {preset: benchmark}
        find: [eigenvalues_real]
    """, name="q.yaml")
    out = run("solve", path)
    assert out.exit_code == 2 and "given.speed" in out.stderr
    assert len(out.stderr.strip().splitlines()) == 1


def test_s_a_and_the_wheels_share_are_said_as_they_enter_the_matrices(run, problems_dir):
    # S_A = m_A u_A + mu m_T x_T (Meijaard et al. 2007, Appendix A): the steering
    # assembly's own static moment and the trail's share (mu = (c / w) cos(lambda)) of the
    # whole bicycle's m_T x_T, so not the steering assembly's alone; S_R and S_F enter C1
    # and K2 with the trail and the tilt, so the spin moves the range as well as opening it
    out = run("solve", problems_dir / "bicycle_benchmark_fast.yaml").stdout
    assert "static moment of the steering assembly" not in out
    assert "S_A = m_A u_A + mu m_T x_T" in out and "lean-steer static moment" in out
    assert "the rest of the design" not in out
    slow = (problems_dir / "bicycle_benchmark_slow.yaml").read_text()
    assert "riderless" not in slow and "rigid rider" in slow  # m_B = 85 kg holds the rider
