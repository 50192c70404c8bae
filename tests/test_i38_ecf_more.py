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
import re
from pathlib import Path

import numpy as np
import pytest
from test_i38_ecf import PROBLEM_11_3, hand_11_3  # the one hand calculation of 11/3

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


# ---- item 4: a Blackboard download of responses regraded with errors carried forward ----

#: Blackboard's Download Results, long format (By Question and User): its columns
DOWNLOAD_HEADER = ["Username", "Last Name", "First Name", "Question ID", "Question", "Answer",
                   "Possible Points", "Auto Score", "Manual Score"]


def carl_and_dana() -> dict[str, list[str]]:
    """The responses to 11/3 with `steps: [I]` (I, the two roots, the least spin) that the
    platform tests regrade: carl's I 10% high and the rest right for it; dana right but for
    the fast root, left blank."""
    own, right = hand_11_3(1.1), hand_11_3(1.0)
    return {"carl": [f"{own['I']:.4g}", f"{own['slow']:.4g}", f"{own['fast']:.4g}",
                     f"{own['min_spin']:.4g}"],
            "dana": [f"{right['I']:.4g}", f"{right['slow']:.4g}", "",
                     f"{right['min_spin']:.4g}"]}


def download(tmp_path: Path, upload: Path, answers: dict[str, list[str]]) -> Path:
    """A long-format download of the test made from ``upload``: per student one row per
    question (in the upload's order), the question's text as uploaded; the first
    student's rows show it with the tags stripped, as a plain-text view would."""
    import csv

    texts = [line.split("\t")[1] for line in upload.read_text().splitlines()]
    path = tmp_path / "downloadlong.csv"
    with path.open("w", newline="", encoding="utf-8") as out:
        writer = csv.writer(out, quoting=csv.QUOTE_ALL)
        writer.writerow(DOWNLOAD_HEADER)
        for n, (user, typed) in enumerate(answers.items()):
            for k, (text, answer) in enumerate(zip(texts, typed)):
                shown = re.sub(r"<[^>]+>", " ", text) if n == 0 else text
                writer.writerow([user, user.title(), "A", f"_{1000 + k}_1", shown, answer,
                                 "1", "0", ""])
    return path


def test_item04_blackboard_responses_regraded_with_errors_carried_forward(tmp_path, run):
    """11/3 with `steps: [I]` exported to Blackboard; a student whose I is 10% high and whose
    precession roots and least spin are right for it: Blackboard gives 0 for each; regraded
    from the download with --credit ecf=1, 2 of 3 points (the notes naming their I)."""
    import json

    problem = tmp_path / "p11_3.yaml"
    problem.write_text(PROBLEM_11_3.replace("tolerance: 1%\n", "tolerance: 1%\nsteps: [I]\n"))
    upload = tmp_path / "upload.txt"
    made = run("export", "--to", "blackboard", problem, "-o", upload)
    assert made.exit_code == 0, made.output
    assert "--responses blackboard" in made.stderr
    download_path = download(tmp_path, upload, carl_and_dana())
    graded = run("check", "--answers", download_path, "--responses", "blackboard", problem,
                 "--credit", "ecf=1", "--format", "json")
    assert graded.exit_code == 0, graded.output
    rows = {(r["student"], r["answer"]): r for r in json.loads(graded.stdout)["rows"]}
    assert rows["carl", "I"]["points"] == 0
    for name in ("precession", "min_spin"):
        assert rows["carl", name]["result"] == "carried", rows["carl", name]
        assert "consistent with your I = " in rows["carl", name]["note"]
    assert rows["dana", "I"]["points"] == 1 and rows["dana", "min_spin"]["points"] == 1
    assert rows["dana", "precession"]["points"] < 1  # the fast root left blank
    plain = run("check", "--answers", download_path, "--responses", "blackboard", problem,
                "--format", "json")
    carl = [r for r in json.loads(plain.stdout)["rows"] if r["student"] == "carl"]
    assert sum(r["points"] for r in carl) == 0  # without ECF: as Blackboard marked it
    # the same download tab-delimited in UTF-16 (with its byte-order mark)
    import csv

    tabbed = tmp_path / "downloadlong.xls"
    rows = list(csv.reader(download_path.open(newline="")))
    tabbed.write_bytes("".join("\t".join(r) + "\r\n" for r in rows).encode("utf-16"))
    again = run("check", "--answers", tabbed, "--responses", "blackboard", problem,
                "--credit", "ecf=1", "--format", "json")
    assert again.exit_code == 0, again.output
    assert json.loads(again.stdout)["rows"] == json.loads(graded.stdout)["rows"]


def test_item04_a_download_from_another_bank_is_refused(tmp_path, run):
    """A question text no problem file gives: one line naming the file and row, exit 2."""
    import csv

    problem = tmp_path / "p11_3.yaml"
    problem.write_text(PROBLEM_11_3)
    path = tmp_path / "downloadlong.csv"
    with path.open("w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(DOWNLOAD_HEADER)
        writer.writerow(["carl", "C", "A", "_1_1", "What is 2 + 2?", "4", "1", "0", ""])
    graded = run("check", "--answers", path, "--responses", "blackboard", problem)
    assert graded.exit_code == 2
    assert "downloadlong.csv" in graded.output and "line 2" in graded.output
    assert "Traceback" not in graded.output
    wrong = tmp_path / "sheet.csv"
    wrong.write_text("student,problem,answer,value\ncarl,11/3,I,1\n")
    refused = run("check", "--answers", wrong, "--responses", "blackboard", problem)
    assert refused.exit_code == 2 and "Username, Question and Answer" in refused.output
