"""A wheel drop's couple forces lie along the track (the axle tilts about the track, so the
couple is about the vertical): `up`, `down`, `pressed` and `relieved`, the words that sign
a bearing's forces, sign nothing there, and a student who writes them is not given the
point (they had been read as the sign, so "442.2 N up at A" scored as right).

Hand values, Khurmi's locomotive (problems/khurmi_wheel_drop.yaml): psidot = (95 / 3.6) /
0.9 = 29.321 rad/s; the greatest tilt rate Omega = pi h / (T_d L) = pi (0.006) / (0.1 x
1.5) = 0.12566 rad/s; M = J psidot Omega = 180 (29.321)(0.12566) = 663.2 N m; F = M / L =
442.2 N. A rotor in bearings turned about the vertical: M = J psidot Omega = 0.1 (1000)(2)
= 200 N m, F = M / L = 400 N, up at A (pressed) and down at B.
"""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

from gyro_cli import api

ROOT = Path(__file__).resolve().parent.parent
DROP = str(ROOT / "problems" / "khurmi_wheel_drop.yaml")
BEARINGS = """\
id: rotor
title: A rotor turned about the vertical
kind: gyroscopic_torque
given:
  J: 0.1 kg m^2
  spin: 1000 rad/s
  precession: 2 rad/s
  bearing_spacing: 0.5 m
find:
  couple_forces: N
"""


def _graded(folder: Path, problem: str, pid: str, value: str):  # type: ignore[no-untyped-def]
    sheet = folder / "answers.csv"
    with sheet.open("w", newline="") as f:
        csv.writer(f).writerows([("student", "problem", "answer", "value"),
                                 ("ann", pid, "couple_forces", value)])
    [row] = api.grade(str(sheet), [problem]).rows
    return row


def test_the_solver_gives_the_hand_values():
    drop = api.solve(DROP).answers["couple_forces"].si_values
    assert drop == pytest.approx([442.2, -442.2], rel=2e-4)


@pytest.mark.parametrize("value", ["442.2 N up at A; 442.2 N down at B",
                                   "442.2 N pressed at A; 442.2 N relieved at B",
                                   "442.2 N down at B; 442.2 N up at A"])
def test_up_and_down_sign_nothing_along_the_track(tmp_path, value):
    row = _graded(tmp_path, DROP, "Khurmi-locomotive-wheel-drop", value)
    assert row.result == "invalid" and row.points == 0, (row.result, row.note)
    assert "A (place), B (place)" in row.note and "up (+)" not in row.note, row.note


@pytest.mark.parametrize("value", ["442.2 N at A; -442.2 N at B", "442.2 N; -442.2 N"])
def test_signed_values_at_their_places_are_right_along_the_track(tmp_path, value):
    row = _graded(tmp_path, DROP, "Khurmi-locomotive-wheel-drop", value)
    assert row.result == "correct" and row.points == 1, (row.result, row.note)


def test_a_bearings_couple_forces_still_read_up_and_pressed(tmp_path):
    problem = tmp_path / "rotor.yaml"
    problem.write_text(BEARINGS)
    assert api.solve(str(problem)).answers["couple_forces"].si_values == \
        pytest.approx([400.0, -400.0], rel=1e-12)
    for value in ("400 N up at A; 400 N down at B", "400 N pressed at A; 400 N relieved at B"):
        row = _graded(tmp_path, str(problem), "rotor", value)
        assert row.result == "correct", (value, row.result, row.note)
    row = _graded(tmp_path, str(problem), "rotor", "400 N down at A; 400 N up at B")
    assert row.result != "correct" and row.points == 0, (row.result, row.note)


def test_an_answer_key_with_up_for_a_drop_is_bad_input(tmp_path, run):
    text = Path(DROP).read_text().replace(
        "  precession: 0.1257 rad/s\n",
        "  precession: 0.1257 rad/s\n  couple_forces: [442 N up at A, 442 N down at B]\n")
    assert "couple_forces: [442 N up" in text
    (tmp_path / "drop.yaml").write_text(text)
    result = run("check", tmp_path / "drop.yaml")
    assert result.exit_code == 2, result.output
    assert "expected.couple_forces" in result.output and "A (place)" in result.output
    assert "Traceback" not in result.output


def test_a_class_graded_from_its_stored_key_reads_the_drops_words_alike(tmp_path, run):
    import json

    from conftest import class_set

    from gyro_cli.checking import assignment as keys
    from gyro_cli.checking import grades

    drop = tmp_path / "drop.yaml"
    drop.write_text(Path(DROP).read_text() + "vary:\n  speed: [0.8, 1.2]\n")
    assignment = class_set(run, tmp_path, ["ann"], problem=drop)
    key = json.loads((assignment.parent / "key.json").read_text())
    assert keys.read_key(str(assignment.parent / "key.json")) == (key, "")  # it is read
    [entry] = key["variants"].values()
    stored = entry["answers"]["couple_forces"]
    assert stored["signs"] == []                       # the key keeps the drop's own words
    assert entry["answers"]["moment"]["signs"] is None  # the kind's (none for a moment)
    size = f"{abs(stored['values'][0]):.6g} N"
    for value, result in ((f"{size} up at A; {size} down at B", "invalid"),
                          (f"{size} at A; -{size} at B", "correct")):
        sheet = tmp_path / "answers.csv"
        sheet.write_text(f"student,problem,answer,value\nann,{entry['problem']},couple_forces,"
                         f"{value}\n")
        [row] = [r for r in grades.grade(str(sheet), [], assignment=str(assignment)).rows
                 if r.answer == "couple_forces"]
        assert row.result == result, (value, row.result, row.note)
