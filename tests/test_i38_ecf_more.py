"""Issue 38, errors carried forward: the bicycle carries a student's wrong step into its
eigenvalues, weave and capsize speeds.

Independent references: the benchmark's matrices M, C1, K0, K2 as Meijaard, Papadopoulos,
Ruina & Schwab (2007) print them (Section 6 of the paper, the values of
problems/bicycle_benchmark.yaml's `expected`), changed here by hand where the student's
wrong step enters them (Eqs. A 20-A 23), and the speeds found from them with numpy (the
eigenvalues of the 4x4 state matrix) or in closed form (det(g K0 + v^2 K2) = 0).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from gyro_cli.checking import grades

ROOT = Path(__file__).resolve().parent.parent
BENCHMARK = (ROOT / "problems" / "bicycle_benchmark.yaml").read_text()
G = 9.81
LAMBDA, W, C = math.pi / 10, 1.02, 0.08  # Table 1: steer axis tilt, wheel base, trail
MU = C * math.cos(LAMBDA) / W             # trail ratio (Eq. A 15)
# the paper's printed benchmark matrices, rows and columns (phi, delta)
M = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
C1 = np.array([[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0 = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2 = np.array([[0.0, 76.59734589573222], [0.0, 2.65431523794604]])
S_F = 0.28 / 0.35                         # I_Fyy / r_F, kg m (Eq. A 16)


def spectrum(m, c1, k0, k2, v: float) -> np.ndarray:
    """The eigenvalues of M q'' + v C1 q' + (g K0 + v^2 K2) q = 0 at speed v."""
    inv = np.linalg.inv(m)
    state = np.block([[np.zeros((2, 2)), np.eye(2)],
                      [-inv @ (G * k0 + v * v * k2), -inv @ (v * c1)]])
    return np.linalg.eigvals(state)


def weave_speed(m, c1, k0, k2, lo: float = 1.0, hi: float = 6.0) -> float:
    """Where the complex pair's real part crosses zero, by bisection."""
    def growth(v: float) -> float:
        return max(e.real for e in spectrum(m, c1, k0, k2, v) if abs(e.imag) > 1e-9)

    assert growth(lo) > 0 > growth(hi)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if growth(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)


def capsize_speed(k0, k2) -> float:
    """det(g K0 + v^2 K2) = 0 (a real eigenvalue at 0), K2's first column being zero:
    g^2 det K0 + g v^2 (K0_pp K2_dd - K0_dp K2_pd) = 0."""
    return math.sqrt(-G * np.linalg.det(k0) / (k0[0, 0] * k2[1, 1] - k0[1, 0] * k2[0, 1]))


def asking(tmp_path: Path, steps: str) -> Path:
    path = tmp_path / "bicycle.yaml"
    path.write_text(BENCHMARK.replace("tolerance: 12 sig\n",
                                      f"tolerance: 12 sig\nsteps: [{steps}]\n"))
    return path


def graded_rows(tmp_path: Path, problem: Path, rows: list[tuple[str, str]],
                credit: dict[str, float] | None) -> dict[str, grades.GradeRow]:
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("student,problem,answer,value\n" +
                     "".join(f"bea,bicycle-benchmark,{a},{v}\n" for a, v in rows))
    graded = grades.grade(str(sheet), [str(problem)], credit=credit)
    return {r.answer: r for r in graded.rows if r.student == "bea"}


def test_references_reproduce_the_paper():
    """The independent references give the paper's Table 2 speeds for its own matrices."""
    assert weave_speed(M, C1, K0, K2) == pytest.approx(4.29238253634111, rel=1e-9)
    assert capsize_speed(K0, K2) == pytest.approx(6.02426201538837, rel=1e-9)


def test_item02_bicycle_carries_a_wrong_mass_matrix_entry_into_the_weave_speed(tmp_path):
    """A student whose I_Txx (= M_pp, Eq. A 20) is 90 kg m^2, not 80.82, and whose weave
    speed is right for that mass matrix, earns the share for the weave speed."""
    wrong = M.copy()
    wrong[0, 0] = 90.0
    own = weave_speed(wrong, C1, K0, K2)
    assert abs(own / 4.29238253634111 - 1) > 0.05  # the wrong entry moves it
    problem = asking(tmp_path, "I_Txx")
    rows = [("I_Txx", "90 kg m^2"), ("weave_speed", f"{own:.6g} m/s")]
    carried = graded_rows(tmp_path, problem, rows, {"ecf": 0.5})
    assert carried["I_Txx"].points == 0
    assert carried["weave_speed"].result == "carried"
    assert carried["weave_speed"].points == 0.5
    assert "consistent with your I_Txx = 90 kg m^2 (ECF)" in carried["weave_speed"].note
    assert graded_rows(tmp_path, problem, rows, None)["weave_speed"].points == 0
    off = [rows[0], ("weave_speed", f"{own * 1.03:.6g} m/s")]  # no slip explains it
    assert graded_rows(tmp_path, problem, off, {"ecf": 0.5})["weave_speed"].points == 0


def test_item02_bicycle_carries_a_wrong_spin_term_into_capsize_speed_and_eigenvalues(tmp_path):
    """A student whose front wheel's S_F = I_Fyy / r_F is 1.2 kg m, not 0.8: S_T = S_R + S_F
    follows it, and so do C1 and K2 (Eqs. A 21, A 23); the capsize speed (closed form) and
    the eigenvalues at 5 m/s (numpy) worked from those earn the share."""
    d = 1.2 - S_F
    c1, k2 = C1.copy(), K2.copy()
    c1[0, 1] += (MU + math.cos(LAMBDA)) * d      # mu S_T + S_F cos(lambda) + ...
    c1[1, 0] -= (MU + math.cos(LAMBDA)) * d      # -(mu S_T + S_F cos(lambda))
    k2[0, 1] += d * math.cos(LAMBDA) / W         # (S_T - m_T z_T) cos(lambda) / w
    k2[1, 1] += d * math.sin(LAMBDA) * math.cos(LAMBDA) / W  # (S_A + S_F sin) cos / w
    capsize = capsize_speed(K0, k2)
    assert abs(capsize / 6.02426201538837 - 1) > 0.02
    ev = sorted(spectrum(M, c1, K0, k2, 5.0), key=lambda e: (round(e.real, 9), e.imag))
    problem = asking(tmp_path, "S_F")
    rows = [("S_F", "1.2 kg m"), ("capsize_speed", f"{capsize:.6g} m/s"),
            ("eigenvalues_real", "; ".join(f"{e.real:.6g} 1/s" for e in ev))]
    carried = graded_rows(tmp_path, problem, rows, {"ecf": 0.5})
    assert carried["S_F"].points == 0
    for name in ("capsize_speed", "eigenvalues_real"):
        assert carried[name].points == 0.5, carried[name]
        assert "consistent with your S_F = 1.2 kg m (ECF)" in carried[name].note
    plain = graded_rows(tmp_path, problem, rows, None)
    assert plain["capsize_speed"].points == 0 and plain["eigenvalues_real"].points < 0.5


def test_item02_bicycle_total_mass_cancels_as_the_working_shows(tmp_path):
    """m_T enters the matrices only as m_T x_T and m_T z_T, and the working divides by it to
    find x_T and z_T: a wrong m_T alone moves no answer, so nothing is carried from it
    (as 11/3's m cancels from the least spin)."""
    from gyro_cli.solving.deps import graph
    from gyro_cli.solving.problem import load
    from gyro_cli.solving.solve import solve

    problem = load(str(asking(tmp_path, "m_T")))
    again = solve(problem, {"m_T": 120.0}).answers["weave_speed"].si_values[0]
    assert again == pytest.approx(4.29238253634111, rel=1e-12)
    g = graph(problem)
    assert "m_T" not in g.answer_depends("weave_speed")
    assert {"I_Txx", "S_F", "z_T"} <= set(g.answer_depends("weave_speed"))


def test_item02_bicycle_without_overrides_unchanged():
    """Solved with no student's values, the bicycle's matrices are the paper's (the steps'
    values are used only when a value is carried)."""
    from gyro_cli.solving.problem import load
    from gyro_cli.solving.solve import solve

    result = solve(load(str(ROOT / "problems" / "bicycle_benchmark.yaml")))
    assert result.answers["weave_speed"].si_values[0] == pytest.approx(4.29238253634111,
                                                                       rel=1e-12)
    same = solve(result.problem, {"I_Txx": 80.81722}).answers["weave_speed"].si_values[0]
    assert same == pytest.approx(4.29238253634111, rel=1e-12)
