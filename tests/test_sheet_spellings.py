"""Right answers as students write them on a sheet: a unit written once after several
numbers (``45.13; 533.5 rpm``, the way books print roots) and a leading ≈ or ~ before a
rounded value. Both had been graded ``invalid``, 0 points (found and left open by the
fifth session's adversarial passes). The right values are worked out by hand
(test_i38_ecf.hand_11_3: 11/3's roots 45.13 and 533.5 rpm, its least spin 965.4 rpm)."""

from __future__ import annotations

import json

import pytest
from test_i38_ecf import by_answer, hand_11_3, sheet

from gyro_cli.checking import grades
from gyro_cli.checking.grades import written_values

RIGHT = hand_11_3()
SLOW, FAST, LEAST = (f"{RIGHT[k]:.4g}" for k in ("slow", "fast", "min_spin"))
RAD = 60 / (2 * 3.141592653589793)  # rpm per rad/s


def test_hand_values_are_the_books():
    assert (SLOW, FAST, LEAST) == ("45.13", "533.5", "965.4")


@pytest.mark.parametrize("written", [
    f"{SLOW}; {FAST} rpm", f"{SLOW} rpm; {FAST} rpm", f"{FAST}; {SLOW} rpm",
    f"{float(SLOW) / RAD:.4g}; {float(FAST) / RAD:.4g} rad/s",
    f"≈{SLOW} rpm; ~{FAST} rpm", f"≈ {SLOW}; {FAST} rpm",
])
def test_both_roots_right_however_the_unit_is_written(tmp_path, written):
    graded = grades.grade(str(sheet(tmp_path, [("ann", "precession", written)])),
                          [str(_problem())])
    row = by_answer(graded, "ann")["precession"]
    assert row.result == "correct" and row.points == 1, row


@pytest.mark.parametrize("written", [f"≈{LEAST} rpm", f"~{LEAST} rpm", f"≃ {LEAST} rpm"])
def test_about_sign_before_a_right_value(tmp_path, written):
    graded = grades.grade(str(sheet(tmp_path, [("ann", "min_spin", written)])), [str(_problem())])
    assert by_answer(graded, "ann")["min_spin"].result == "correct"


@pytest.mark.parametrize(("written", "result"), [
    # a unit after the first number only: which unit the second has is not written
    (f"{SLOW} rpm; {FAST}", "invalid"),
    # a wrong root stays wrong with the unit written once
    (f"{SLOW}; {float(FAST) * 1.05:.4g} rpm", "partial"),
    # a number with no unit anywhere is no angular rate
    (f"{SLOW}; {FAST}", "invalid"),
])
def test_what_stays_refused(tmp_path, written, result):
    graded = grades.grade(str(sheet(tmp_path, [("ann", "precession", written)])), [str(_problem())])
    assert by_answer(graded, "ann")["precession"].result == result


def test_written_values_keep_yaml_numbers_and_words():
    assert written_values(["1", "2 rpm"]) == ["1 rpm", "2 rpm"]
    assert written_values([3.0, "2 rpm"]) == ["3.0 rpm", "2 rpm"]
    assert written_values(["2 rpm", 3]) == ["2 rpm", 3]
    assert written_values(["stable", " ", "unstable"]) == ["stable", "unstable"]
    assert written_values(["0.5", "2"]) == ["0.5", "2"]
    assert written_values(["1e-3", "2E+02 N m"]) == ["1e-3 N m", "2E+02 N m"]


def test_a_yaml_sheet_reads_the_unit_once_too(tmp_path):
    path = tmp_path / "s.yaml"
    path.write_text(f'ann:\n  "11/3":\n    precession: [{SLOW}, {FAST} rpm]\n')
    graded = grades.grade(str(path), [str(_problem())])
    assert by_answer(graded, "ann")["precession"].result == "correct"


def _problem():
    from conftest import PROBLEMS

    return PROBLEMS / "11_3.yaml"


# ---- word answers: each side a set of words --------------------------------------------

def _words(truth: list[str], written: str) -> grades.GradeRow:
    from types import SimpleNamespace

    row = grades.GradeRow("ann", "p", "motion", written, "", None, "missing", 0.0)
    return grades._grade_words(row, written.split(";"), SimpleNamespace(si_values=truth))


@pytest.mark.parametrize(("truth", "written", "points", "result"), [
    # the solver's word repeated (both roots stable): one wrong word is half the point
    (["stable", "stable"], "unstable; stable", 0.5, "partial"),
    (["stable", "stable"], "stable; cusps", 0.5, "partial"),
    (["stable", "stable"], "stable", 1.0, "correct"),
    (["stable", "stable"], "Stable; stable.", 1.0, "correct"),
    (["stable", "unstable"], "stable", 0.5, "partial"),
    (["stable", "unstable"], "unstable; stable", 1.0, "correct"),
    (["cusps"], "cusp; cusps", 1.0, "correct"),
    (["cusps"], "loops", 0.0, "wrong"),
])
def test_words_are_sets_on_both_sides(truth, written, points, result):
    row = _words(truth, written)
    assert (row.points, row.result) == (points, result), row


def test_a_wrong_stability_word_is_not_full_marks(tmp_path):
    """11/3-stability: both roots stable. `unstable; stable` had been given 1 of 1 point
    (the solver's two `stable` each matched by the student's one); an adversarial pass."""
    from conftest import PROBLEMS

    path = tmp_path / "w.csv"
    path.write_text("student,problem,answer,value\nann,11/3-stability,stability,unstable; stable\n")
    graded = grades.grade(str(path), [str(PROBLEMS / "11_3_stability.yaml")])
    row = by_answer(graded, "ann")["stability"]
    assert row.points == 0.5 and row.result == "partial", row


# ---- numbers and units as students type them (a second adversarial pass) --------------

J_11_5 = 2.5 * 0.035 ** 2  # 11/5's rotor: m k^2
RPM = 2 * 3.141592653589793 / 60
MOMENT = f"{J_11_5 * (-1725 * RPM) * (48 * RPM):.4g}"  # J psidot Omega = -2.781 N m


def _one(tmp_path, problem: str, answer: str, written: str) -> grades.GradeRow:
    from conftest import PROBLEMS

    path = tmp_path / "one.csv"
    ident = {"11_3.yaml": "11/3", "11_5.yaml": "11/5"}[problem]
    path.write_text(f'student,problem,answer,value\nann,{ident},{answer},"{written}"\n',
                    encoding="utf-8")
    return by_answer(grades.grade(str(path), [str(PROBLEMS / problem)]), "ann")[answer]


@pytest.mark.parametrize("written", [
    f"{SLOW} rpm, {FAST} rpm", f"{SLOW}, {FAST} rpm", f"{SLOW} rpm and {FAST} rpm",
    f"{SLOW} and {FAST} rpm", f"{float(SLOW) * RPM:.4g}; {float(FAST) * RPM:.4g} 1/s",
    f"{SLOW} rpm.; {FAST} RPM.",
])
def test_roots_joined_as_students_join_them(tmp_path, written):
    assert _one(tmp_path, "11_3.yaml", "precession", written).result == "correct"


@pytest.mark.parametrize("written", [
    f"{float(LEAST) / 100:.4g}×10^2 rpm", f"{float(LEAST) / 100:.4g} x 10^2 rpm",
    f"{float(LEAST) / 100:.4g}·10² rpm", f"{float(LEAST) / 100:.4g}*10**2 rpm",
    f"{float(LEAST) * 10:.5g} × 10^(-1) rpm", f"{LEAST} rpm.", f"{LEAST} r.p.m.",
    f"{LEAST} min⁻¹", f"{float(LEAST) * RPM:.4g} rad·s⁻¹", f"{float(LEAST) / 60:.4g} hz",
])
def test_a_least_spin_typed_as_students_type_it(tmp_path, written):
    assert _one(tmp_path, "11_3.yaml", "min_spin", written).result == "correct"


@pytest.mark.parametrize("written", [
    f"{MOMENT} N·m", f"{MOMENT} N⋅m", f"\u2013{MOMENT[1:]} N m",
    f"'{MOMENT} N m", f"{MOMENT} Nm.", f"{MOMENT} kg·m²/s²",
])
def test_a_negative_moment_typed_as_students_type_it(tmp_path, written):
    assert MOMENT == "-2.781"
    assert _one(tmp_path, "11_5.yaml", "moment", written).result == "correct"


@pytest.mark.parametrize(("written", "why"), [
    ("965.4 rpm # least", "a unit is names"),
    ("45.13rpm,533.5 rpm", "separated by ';'"),
    ("3 x 105 rpm", ""),  # no power of ten: not 3e5, not read at all
])
def test_what_a_sheet_still_refuses_says_why_in_a_sheets_words(tmp_path, written, why):
    row = _one(tmp_path, "11_3.yaml", "min_spin", written)
    assert row.result == "invalid" and why in row.feedback, row
    assert "comment needs" not in row.feedback


@pytest.mark.parametrize(("text", "same", "dimension"), [
    ("0.16 kg·m²", "0.16 kg m^2", "inertia"), ("14.08 s⁻¹", "14.08 s^-1", "rate"),
    ("19.47º", "19.47 deg", "angle"), ("19.47˚", "19.47 deg", "angle"),
    ("19.47 DEG", "19.47 deg", "angle"), ("14.24 HZ", "14.24 Hz", "rate"),
    ("2 N·m", "2 N m", "moment"),
])
def test_unit_spellings_read_everywhere(text, same, dimension):
    """SI's ·, superscript powers and other keyboards' degree signs, in a problem file as
    on a sheet (core.units)."""
    from gyro_cli.core import units

    assert units.parse(text, dimension, "k")[0] == units.parse(same, dimension, "k")[0]


def test_percent_is_a_fraction():
    from gyro_cli.core import units

    assert units.parse("83.85%", "dimensionless", "k")[0] == pytest.approx(0.8385)
    assert units.parse("83.85 %", "dimensionless", "k")[0] == pytest.approx(0.8385)


# ---- a value's label, as gyro prints it, or a place in words --------------------------

# 11/5's forces: 49.05 N -+ |M| / 0.2 m
F_A, F_B = (f"{49.05 + s * J_11_5 * (-1725 * RPM) * (48 * RPM) / 0.2:.4g}" for s in (1, -1))


@pytest.mark.parametrize(("answer", "written", "problem"), [
    ("precession", f"{SLOW} rpm (slow); {FAST} rpm (fast)", "11_3.yaml"),
    ("precession", f"{FAST} rpm (fast); {SLOW} rpm (slow)", "11_3.yaml"),
    ("bearing_forces", f"{F_A} N (A); {F_B} N (B)", "11_5.yaml"),
    ("bearing_forces", f"{F_B} N (B); {F_A} N (A)", "11_5.yaml"),
    ("bearing_forces", f"{F_A} N at A; {F_B} N at B", "11_5.yaml"),
    ("bearing_forces", f"{F_B} N up at B; {F_A} N upwards at A", "11_5.yaml"),
    ("bearing_forces", f"{F_A} N (A); {F_B} N", "11_5.yaml"),  # one placed: in order
])
def test_labels_as_gyro_prints_them_and_places_in_words(tmp_path, answer, written, problem):
    """gyro's own printed form (`45.13 rpm (slow)`, `35.15 N (A)`) copied onto a sheet, and
    an answer key's words (`62.95 N up at B`): graded `invalid` before."""
    assert (F_A, F_B) == ("35.15", "62.95")
    assert _one(tmp_path, problem, answer, written).result == "correct"


def test_a_label_at_the_wrong_place_is_the_wrong_place(tmp_path):
    row = _one(tmp_path, "11_5.yaml", "bearing_forces", f"{F_B} N (A); {F_A} N (B)")
    assert row.result == "wrong" and "place" in row.note, row


def test_a_labelled_root_carries_an_error(tmp_path):
    """carl's I 10% high and both roots right for it, written as gyro prints them."""
    from test_i38_ecf import problem_with

    own = hand_11_3(1.1)
    rows = [("carl", "I", f"{own['I']:.4g} kg m^2"),
            ("carl", "precession", f"{own['slow']:.4g} rpm (slow); {own['fast']:.4g} rpm (fast)")]
    graded = grades.grade(str(sheet(tmp_path, rows)), [str(problem_with(tmp_path))],
                          credit={"ecf": 0.5})
    row = by_answer(graded, "carl")["precession"]
    assert row.result == "carried" and row.points == 0.5, row


# ---- a slip on every root (a fresh-clone walk-through) --------------------------------

def test_both_roots_in_rad_s_written_as_rpm_are_named_and_credited(tmp_path):
    """bob works 11/3 in rad/s (4.726 and 55.87 rad/s: the roots / 9.549) and writes rpm.
    His 55.87 is nearer the slow root 45.13 than the fast 533.5 on a log scale, so it was
    paired with the slow root: 'too high', no slip named, 0 points under --credit rpm=0.5.
    Each is now paired with the root a slip explains: both 'too low', both the rpm slip."""
    slow, fast = (float(x) * RPM for x in (SLOW, FAST))
    written = f"{slow:.4g} rpm; {fast:.4g} rpm"
    assert written == "4.726 rpm; 55.87 rpm"
    graded = grades.grade(str(sheet(tmp_path, [("bob", "precession", written)])),
                          [str(_problem())], credit={"rpm": 0.5})
    row = by_answer(graded, "bob")["precession"]
    assert row.points == 0.5 and row.note.count("rpm against rad/s") == 2, row
    assert row.feedback.count("too low") == 2 and "too high" not in row.feedback, row


# ---- the sheet as a spreadsheet writes it -----------------------------------------------

def test_answer_names_as_students_write_them(tmp_path):
    """`Min_Spin`, `min spin`, `min-spin` name min_spin (one such row had stopped the
    grading of a whole class, exit 2); two rows naming one answer two ways are one
    answer, as two rows of one name are."""
    path = tmp_path / "names.csv"
    path.write_text("student,problem,answer,value\n"
                    f"ann,11/3,Min_Spin,{LEAST} rpm\nbob,11/3,min spin,{LEAST} rpm\n"
                    f"cy,11/3,Precession,{SLOW} rpm\ncy,11/3,precession,{FAST} rpm\n")
    graded = grades.grade(str(path), [str(_problem())])
    assert by_answer(graded, "ann")["min_spin"].result == "correct"
    assert by_answer(graded, "bob")["min_spin"].result == "correct"
    assert by_answer(graded, "cy")["precession"].result == "correct"


def test_a_step_symbol_keeps_its_case(tmp_path):
    from gyro_cli.checking.grades import _answer_named
    from gyro_cli.solving.problem import load

    problem = load(str(_problem()))
    assert _answer_named(problem, "MIN SPIN") == "min_spin"
    assert _answer_named(problem, "i") == "i"  # no answer: left for the refusal to name


def test_a_sheet_saved_with_semicolons(tmp_path):
    """A spreadsheet in a language with a decimal comma saves CSV with ';' between cells
    (its cell holding roots quoted): read as such, not refused as one column."""
    path = tmp_path / "semi.csv"
    path.write_text(f'student;problem;answer;value\nann;11/3;min_spin;{LEAST} rpm\n'
                    f'ann;11/3;precession;"{SLOW}; {FAST} rpm"\n')
    rows = by_answer(grades.grade(str(path), [str(_problem())]), "ann")
    assert rows["min_spin"].result == rows["precession"].result == "correct"


# ---- a class that writes a decimal comma (--decimal-comma) -----------------------------

def test_a_decimal_comma_class(tmp_path, run):
    """A class in a language with a decimal comma writes 965,4 rpm and saves its sheet
    with ';': every right answer had been invalid. With --decimal-comma it is read as
    such (1.234,5 groups thousands with dots); without, a comma in a number stays refused
    as ambiguous (1,005: a thousand and five, or one and five thousandths?), and the
    student is told to write a decimal point."""
    path = tmp_path / "dc.csv"
    comma = LEAST.replace(".", ",")
    path.write_text(f'student;problem;answer;value\nann;11/3;min_spin;{comma} rpm\n'
                    f'bob;11/3;precession;"{SLOW.replace(".", ",")}; {FAST.replace(".", ",")} rpm"\n'
                    f'cy;11/3;min_spin;{float(LEAST) * RPM:.4g} rad/s\n'.replace(".", ","))
    rows = grades.grade(str(path), [str(_problem())], decimal_comma=True).rows
    results = {(r.student, r.answer): r.result for r in rows}
    assert results[("ann", "min_spin")] == results[("bob", "precession")] == "correct"
    assert results[("cy", "min_spin")] == "correct"
    plain = by_answer(grades.grade(str(path), [str(_problem())]), "ann")["min_spin"]
    assert plain.result == "invalid" and "decimal point as '.'" in plain.feedback
    done = run("check", "--answers", path, _problem(), "--decimal-comma", "--format", "json")
    assert done.exit_code == 0 and '"correct"' in done.stdout
    assert run("check", _problem(), "--decimal-comma").exit_code == 2


def test_thousands_grouped_with_dots_under_a_decimal_comma():
    assert written_values(["1.234,5 rpm"], decimal_comma=True) == ["1234.5 rpm"]
    assert written_values("-0,5; 2,25 N".split(";"), decimal_comma=True) == ["-0.5 N", "2.25 N"]
    assert written_values(["45,13, 533,5 rpm"], decimal_comma=True) == ["45.13 rpm", "533.5 rpm"]
    assert written_values(["965,4 rpm"]) == ["965,4 rpm"]  # without: as written


def test_roots_ten_apart_are_no_slip_of_the_student():
    """Roots 10 and 100 rad/s (a ratio near a power of ten), a student 5% off each: paired
    with their nearest roots, both 'off', no slip. Paired by slips instead they would be
    two different slips (10x up and 10x down), which is the roots' ratio, not the
    student's slip, and --credit would have paid for it."""
    from types import SimpleNamespace

    from gyro_cli.checking.expected import Expected
    from gyro_cli.checking.matching import compare
    from gyro_cli.checking.tolerance import parse_tolerance

    reported = SimpleNamespace(si_values=[10.0, 100.0], labels=["slow", "fast"],
                               unit="rad/s", si_unit="rad/s")
    values = [Expected(f"{v} rad/s", v, v, "rad/s", 1.0) for v in (10.5, 95.5)]
    lines = compare("precession", values, parse_tolerance("1%", "rate", "t"), reported)
    assert [(line.expected_si, line.got_si) for line in lines] == [(10.5, 10.0), (95.5, 100.0)]
    assert not any(line.slip for line in lines), [line.slip for line in lines]


def test_a_root_given_twice_is_said_so(tmp_path):
    """`45.13 rpm; 45.13 rpm`: the slow root twice. The second had been fed back as 'too
    low' against the fast root (an adversarial pass); it is a root given twice."""
    graded = grades.grade(str(sheet(tmp_path, [("ann", "precession", f"{SLOW} rpm; {SLOW} rpm")])),
                          [str(_problem())])
    row = by_answer(graded, "ann")["precession"]
    assert row.points == 0.5 and "given twice" in row.feedback and "too low" not in row.feedback


# ---- a review of the above (an adversarial pass of this session's reading) --------------

@pytest.mark.parametrize("written", [
    f"{F_A} N at B; {F_B} N", f"{F_A} N up at B; {F_B} N", f"{F_A} N at B, {F_B} N",
    f"{F_A} N (B); {F_B} N",
])
def test_a_place_named_for_one_value_is_kept(tmp_path, written):
    """35.15 N (A's force) put at B: wrong, the other value taking the place left (A).
    The named place had been dropped and the pair graded right in order."""
    row = _one(tmp_path, "11_5.yaml", "bearing_forces", written)
    assert row.points == 0 and row.result == "wrong", row


@pytest.mark.parametrize("written", [f"{F_A}; {F_B} N (B)", f"{F_A}; {F_B} N at B",
                                     f"{F_A} N (A); {F_B}"])
def test_a_unit_written_once_carries_no_label(tmp_path, written):
    """`35.15; 62.95 N (B)`: the unit is the first value's, not its label (which had put
    both at B, 0.33 of a right answer)."""
    row = _one(tmp_path, "11_5.yaml", "bearing_forces", written)
    expected = "invalid" if written.endswith(F_B) else "correct"  # no unit after 62.95
    assert row.result == expected, row


def test_a_long_cell_costs_its_length(tmp_path):
    """A value of `1 (`, 5000 spaces and `x`: the label's regular expression had taken
    time cubic in the length (20 s for 2000 spaces; an autograder a student can stall)."""
    import time

    path = tmp_path / "long.csv"
    path.write_text("student,problem,answer,value\nann,11/3,min_spin,1 (" + " " * 5000 + "x\n")
    start = time.process_time()
    row = by_answer(grades.grade(str(path), [str(_problem())]), "ann")["min_spin"]
    assert row.result == "invalid" and time.process_time() - start < 2.0


def test_dots_group_thousands_under_a_decimal_comma():
    assert written_values(["965.400 rpm"], decimal_comma=True) == ["965400 rpm"]
    assert written_values(["1.234 rpm"], decimal_comma=True) == ["1234 rpm"]
    assert written_values(["45.13 rpm"], decimal_comma=True) == ["45.13 rpm"]
    # YAML has split [45,13 rpm, 533,5 rpm] at its commas: no unit is given to 45 or 533
    assert written_values([45, "13 rpm", 533, "5 rpm"], decimal_comma=True) == \
        [45, "13 rpm", 533, "5 rpm"]


def test_a_bullet_is_no_minus():
    assert written_values(["- 45.13 rpm"]) == ["- 45.13 rpm"]
    assert written_values(["\u201345.13 rpm"]) == ["-45.13 rpm"]


def test_answer_names_two_ways_under_an_assignment(run, tmp_path):
    """`precession` and `Precession` in two rows of an assigned student: one answer, its
    two roots (it had stopped the class: 'answers precession twice, under 11/3 and 11/3')."""
    from conftest import class_set

    assignment = class_set(run, tmp_path, ["ann"])
    path = tmp_path / "two.csv"
    path.write_text("student,problem,answer,value\nann,11/3,precession,50 rpm\n"
                    "ann,11/3,Precession,500 rpm\n")
    done = run("check", "--answers", path, "--assignment", assignment, "--format", "json")
    assert done.exit_code == 0, done.output
    rows = [r for r in json.loads(done.stdout)["rows"] if r["answer"] == "precession"]
    assert len(rows) == 1 and rows[0]["submitted"] == "50 rpm; 500 rpm", rows
