"""Issue 38: steps as questions, the dependency graph, errors carried forward (ECF).

Independent references: problem 11/3 (a 3 oz top, k_z 0.84 in, k_O 1.80 in, l 1.5 in,
1800 rpm at 30 deg) worked by hand here: the steady-precession quadratic of Eq. 11.13
(J - I) cos(theta) phidot^2 + J psidot phidot - m g l = 0 and the least spin
2 sqrt((I - J) m g l cos(theta)) / J, with the student's own I put in.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from gyro_cli.checking import grades
from gyro_cli.core.errors import InputError

ROOT = Path(__file__).resolve().parent.parent
PROBLEM_11_3 = (ROOT / "problems" / "11_3.yaml").read_text()
RPM = 2 * math.pi / 60
OZF, INCH = 4.4482216152605 / 16, 0.0254


def hand_11_3(I_factor: float = 1.0, I: float | None = None) -> dict[str, float]:
    """11/3 by hand, with I (about O) scaled or given: I, the roots in rpm, least spin."""
    W, g = 3 * OZF, 32.2 * 0.3048
    m = W / g
    J = m * (0.84 * INCH) ** 2
    I = m * (1.80 * INCH) ** 2 * I_factor if I is None else I
    theta, psidot, mgl = math.radians(30), 1800 * RPM, m * g * 1.5 * INCH
    a, b, c = (J - I) * math.cos(theta), J * psidot, -mgl
    disc = b * b - 4 * a * c
    roots = sorted(abs((-b + s * math.sqrt(disc)) / (2 * a)) for s in (1, -1)) if disc >= 0 \
        else [math.nan, math.nan]
    least = 2 * math.sqrt((I - J) * mgl * math.cos(theta)) / J
    return {"I": I, "slow": roots[0] / RPM, "fast": roots[1] / RPM, "min_spin": least / RPM}


def problem_with(tmp_path: Path, extra: str = "steps: [I]\n", tolerance: str = "1%") -> Path:
    text = PROBLEM_11_3.replace("tolerance: 1%\n", f"tolerance: {tolerance}\n{extra}")
    path = tmp_path / "p11_3.yaml"
    path.write_text(text)
    return path


def sheet(tmp_path: Path, rows: list[tuple[str, str, str]], name: str = "sheet.csv") -> Path:
    path = tmp_path / name
    path.write_text("student,problem,answer,value\n" +
                    "".join(f"{s},11/3,{a},{v}\n" for s, a, v in rows))
    return path


def by_answer(graded: grades.Graded, student: str) -> dict[str, grades.GradeRow]:
    return {r.answer: r for r in graded.rows if r.student == student}


def carl_rows() -> list[tuple[str, str, str]]:
    """A student whose I is 10% high, the rest worked right from it."""
    own = hand_11_3(1.1)
    return [("carl", "I", f"{own['I']:.4g} kg m^2"),
            ("carl", "precession", f"{own['slow']:.4g} rpm; {own['fast']:.4g} rpm"),
            ("carl", "min_spin", f"{own['min_spin']:.4g} rpm")]


# ---- item 1: steps as questions ------------------------------------------------------

def test_item01_steps_are_graded_as_questions(tmp_path):
    right = hand_11_3()
    problem = problem_with(tmp_path)
    graded = grades.grade(str(sheet(tmp_path, [("ann", "I", f"{right['I']:.4g} kg m^2"),
                                               ("ann", "min_spin", f"{right['min_spin']:.4g} rpm")])),
                          [str(problem)])
    rows = by_answer(graded, "ann")
    assert rows["I"].result == "correct" and rows["I"].points == 1
    assert graded.scores["ann"] == (2.0, 2.0)  # the step counts as a question


def test_item01_a_step_not_answered_is_missing(tmp_path):
    right = hand_11_3()
    graded = grades.grade(str(sheet(tmp_path, [("ann", "min_spin", f"{right['min_spin']:.4g} rpm")])),
                          [str(problem_with(tmp_path))])
    assert by_answer(graded, "ann")["I"].result == "missing"
    assert graded.scores["ann"] == (1.0, 2.0)


def test_item01_gyro_check_checks_expected_steps(tmp_path, run):
    right = hand_11_3()
    good = problem_with(tmp_path, f"steps: [I]\n").read_text().replace(
        "  min_spin: 965.4 rpm\n", f"  min_spin: 965.4 rpm\n  I: {right['I']:.4g} kg m^2\n")
    (tmp_path / "good.yaml").write_text(good)
    result = run("check", tmp_path / "good.yaml")
    assert result.exit_code == 0, result.output
    assert "steps.I" in result.output
    (tmp_path / "bad.yaml").write_text(good.replace(f"  I: {right['I']:.4g}", f"  I: {right['I'] * 1.1:.4g}"))
    assert run("check", tmp_path / "bad.yaml").exit_code == 1


def test_item01_unknown_step_symbol_is_one_line_exit_2(tmp_path, run):
    path = problem_with(tmp_path, "steps: [I, Q]\n")
    result = run("check", path)
    assert result.exit_code == 2
    lines = [l for l in result.stderr.splitlines() if l.strip()]
    assert len(lines) == 1
    assert str(path) in lines[0] and "steps" in lines[0] and "'Q'" in lines[0]
    assert "m, J, I, M" in lines[0]  # the symbols there are
    sheet_path = sheet(tmp_path, [("ann", "I", "1 kg m^2")])
    graded = run("check", "--answers", sheet_path, path)
    assert graded.exit_code == 2 and "'Q'" in graded.stderr


def test_item01_sheet_answer_that_is_no_step_is_refused(tmp_path):
    with pytest.raises(InputError, match="steps: I"):
        grades.grade(str(sheet(tmp_path, [("ann", "J", "1 kg m^2")])), [str(problem_with(tmp_path))])


# ---- item 3: the dependency graph -------------------------------------------------------

def test_item03_json_of_a_solve_gives_what_each_step_and_answer_uses(run):
    result = run("solve", "--format", "json", ROOT / "problems" / "11_3.yaml")
    assert result.exit_code == 0
    graph = json.loads(result.output)["graph"]
    assert graph["steps"]["I"]["uses"] == ["m"]
    assert graph["steps"]["psidot_min"]["uses"] == ["m", "J", "I"]
    # the least spin is a closed formula of J and I; m cancels (I, J and m g l all scale with it)
    assert graph["answers"]["min_spin"]["step"] == "psidot_min"
    assert sorted(graph["answers"]["min_spin"]["depends"]) == ["I", "J"]
    # the precession rates are roots of Eq. 11.13: no formula, found by solving again
    assert graph["answers"]["precession"]["step"] is None
    assert sorted(graph["answers"]["precession"]["depends"]) == ["I", "J"]


# ---- acceptance: 11/3 with steps: [I] -------------------------------------------------

def test_acceptance_11_3_carried_I_scores_two_of_three(tmp_path):
    problem, answers = problem_with(tmp_path), sheet(tmp_path, carl_rows())
    graded = grades.grade(str(answers), [str(problem)], credit={"ecf": 1.0})
    rows = by_answer(graded, "carl")
    assert graded.scores["carl"] == (2.0, 3.0)
    assert rows["I"].points == 0  # the wrong value itself earns nothing
    for name in ("precession", "min_spin"):
        assert rows[name].points == 1
        assert f"consistent with your I = {rows['I'].submitted} (ECF)" in rows[name].note
        assert "ECF" in rows[name].feedback
    plain = grades.grade(str(answers), [str(problem)])
    assert plain.scores["carl"] == (0.0, 3.0)


def test_acceptance_precession_7pct_off_with_I_right_gets_no_carried_credit(tmp_path):
    right = hand_11_3()
    rows = [("dora", "I", f"{right['I']:.4g} kg m^2"),
            ("dora", "precession", f"{right['slow'] * 1.07:.4g} rpm; {right['fast'] * 1.07:.4g} rpm"),
            ("dora", "min_spin", f"{right['min_spin']:.4g} rpm")]
    graded = grades.grade(str(sheet(tmp_path, rows)), [str(problem_with(tmp_path))],
                          credit={"ecf": 1.0})
    got = by_answer(graded, "dora")
    assert got["precession"].points == 0 and "ECF" not in got["precession"].note
    assert graded.scores["dora"] == (2.0, 3.0)


def test_item02_share_is_the_teachers(tmp_path):
    graded = grades.grade(str(sheet(tmp_path, carl_rows())), [str(problem_with(tmp_path))],
                          credit={"ecf": 0.5})
    assert graded.scores["carl"] == (1.0, 3.0)
    assert grades.parse_credit("ecf=0.25,sign=0.5") == {"ecf": 0.25, "sign": 0.5}
    with pytest.raises(InputError):
        grades.parse_credit("ecf=2")


def test_item02_a_value_no_earlier_slip_explains_earns_nothing(tmp_path):
    own = hand_11_3(1.1)
    rows = carl_rows()[:2] + [("carl", "min_spin", f"{own['min_spin'] * 1.05:.4g} rpm")]
    graded = grades.grade(str(sheet(tmp_path, rows)), [str(problem_with(tmp_path))],
                          credit={"ecf": 1.0})
    assert by_answer(graded, "carl")["min_spin"].points == 0
    assert graded.scores["carl"] == (1.0, 3.0)


# ---- item 5: fair follow-through ---------------------------------------------------

def test_item05_stock_value_earns_no_follow_through(tmp_path):
    stock = hand_11_3(I=1.0)  # I = 1 kg m^2: the least spin "follows" from it
    rows = [("eve", "I", "1 kg m^2"), ("eve", "min_spin", f"{stock['min_spin']:.4g} rpm")]
    graded = grades.grade(str(sheet(tmp_path, rows)), [str(problem_with(tmp_path))],
                          credit={"ecf": 1.0})
    row = by_answer(graded, "eve")["min_spin"]
    assert row.points == 0 and "stock value" in row.note


def test_item05_value_as_written_and_its_last_digit_widen_the_tolerance(tmp_path):
    # I written to 3 figures; the least spin worked from the unrounded 1.954e-4 differs
    # from the one of 1.95e-4 by more than a 0.1% tolerance, less than the last digit moves it
    unrounded = hand_11_3(I=1.954e-4)["min_spin"]
    assert abs(hand_11_3(I=1.95e-4)["min_spin"] / unrounded - 1) > 0.001
    rows = [("fay", "I", "1.95e-4 kg m^2"), ("fay", "min_spin", f"{unrounded:.5g} rpm")]
    graded = grades.grade(str(sheet(tmp_path, rows)),
                          [str(problem_with(tmp_path, tolerance="0.1%"))], credit={"ecf": 1.0})
    assert by_answer(graded, "fay")["min_spin"].result == "carried"


def test_item05_blank_earlier_part_does_not_block_later_credit(tmp_path):
    own = hand_11_3(1.1)
    rows = [("gus", "I", f"{own['I']:.4g} kg m^2"), ("gus", "min_spin", f"{own['min_spin']:.4g} rpm")]
    graded = grades.grade(str(sheet(tmp_path, rows)),
                          [str(problem_with(tmp_path, "steps: [m, I]\n"))], credit={"ecf": 1.0})
    got = by_answer(graded, "gus")
    assert got["m"].result == "missing"       # m blank: the solver's m is used
    assert got["min_spin"].result == "carried"


def test_item05_named_slip_is_not_penalised_twice(tmp_path):
    slipped = hand_11_3(10.0)  # I a power of ten off, the least spin worked from it
    rows = [("hal", "I", f"{slipped['I']:.4g} kg m^2"),
            ("hal", "min_spin", f"{slipped['min_spin']:.4g} rpm")]
    graded = grades.grade(str(sheet(tmp_path, rows)), [str(problem_with(tmp_path))],
                          credit={"10": 0.5, "ecf": 0.5})
    got = by_answer(graded, "hal")
    assert got["I"].points == 0.5
    assert got["min_spin"].points == 1 and "already marked down" in got["min_spin"].note


def test_item05_no_follow_through_from_a_value_the_answer_barely_depends_on(tmp_path):
    # I 3% high moves the slow precession by under 1%: a slow precession 1.26% off is the
    # student's own error, not one carried from I
    own = hand_11_3(1.03)
    assert abs(own["slow"] / hand_11_3()["slow"] - 1) < 0.01
    rows = [("ian", "I", f"{own['I']:.4g} kg m^2"),
            ("ian", "precession_slow", f"{own['slow'] * 1.009:.4g} rpm")]
    graded = grades.grade(str(sheet(tmp_path, rows)), [str(problem_with(tmp_path))],
                          credit={"ecf": 1.0})
    row = by_answer(graded, "ian")["precession_slow"]
    assert row.points == 0 and "barely" in row.note


def test_item05_without_the_policy_nothing_changes(tmp_path):
    graded = grades.grade(str(sheet(tmp_path, carl_rows())), [str(problem_with(tmp_path))],
                          credit={"sign": 0.5})
    assert all("ECF" not in r.note for r in graded.rows)
    assert graded.scores["carl"] == (0.0, 3.0)
