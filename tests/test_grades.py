"""Grading answer sheets: `gyro check --answers SHEET PROBLEMS --out grades.csv`.

Independent references: the students' answers are hand-worked values (the
roots of the top's theta equation and the gyroscope limit, see test_check) or
those values with a deliberate slip; the grades CSV is read back with the csv
module and the points and scores are counted here by hand.
"""

from __future__ import annotations

import csv
import math
import os
from pathlib import Path

import pytest
from test_check import FAST, GYRO_PRECESSION, RPM, SLOW, gyro_file, put, top_file

from gyro_cli.core.errors import InputError
from gyro_cli.core.files import write_atomic

SHEET = f"""student,problem,answer,value
ann,top-60,precession,{SLOW:.4g} rad/s; {FAST / RPM:.4g} rpm
ann,gyro-90,precession,{GYRO_PRECESSION / RPM:.4g} rpm
bob,top-60,precession,{SLOW:.4g} rad/s
bob,gyro-90,precession,{GYRO_PRECESSION * 10:.4g} rad/s
cy,top-60,precession,{SLOW:.4g} m
"""


@pytest.fixture
def problems(tmp_path: Path) -> Path:
    d = tmp_path / "problems"
    put(d, "top.yaml", top_file(f"precession: [{SLOW} rad/s, {FAST} rad/s]\n"))
    put(d, "gyro.yaml", gyro_file())
    return d


def read_back(path: Path) -> tuple[dict, dict]:
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    items = {(r["student"], r["problem"]): r for r in rows if r["result"] != "score"}
    scores = {r["student"]: (float(r["points"]), float(r["max_points"]), r["note"])
              for r in rows if r["result"] == "score"}
    return items, scores


def test_csv_sheet_round_trip(run, tmp_path, problems):
    sheet = put(tmp_path, "sheet.csv", SHEET)
    out = tmp_path / "grades.csv"
    result = run("check", "--answers", sheet, problems, "--out", out)
    assert result.exit_code == 0, result.output
    items, scores = read_back(out)
    assert len(items) == 6  # 3 students x 2 questions
    assert items[("ann", "top-60")]["result"] == "correct"
    assert items[("ann", "gyro-90")]["result"] == "correct"  # rpm against rad/s converted
    assert items[("bob", "top-60")]["result"] == "partial"   # one of two roots
    assert float(items[("bob", "top-60")]["points"]) == 0.5
    assert "missing root" in items[("bob", "top-60")]["note"]
    assert items[("bob", "gyro-90")]["result"] == "wrong"
    assert "power of ten" in items[("bob", "gyro-90")]["note"]
    assert float(items[("bob", "gyro-90")]["relative_error"]) == pytest.approx(9.0, rel=1e-3)
    assert items[("cy", "top-60")]["result"] == "invalid"     # a length for a rate
    assert items[("cy", "gyro-90")]["result"] == "missing"
    assert scores == {"ann": (2.0, 2.0, "100.0%"), "bob": (0.5, 2.0, "25.0%"),
                      "cy": (0.0, 2.0, "0.0%")}


def test_yaml_sheet_grades_like_the_csv(run, tmp_path, problems):
    csv_out, yaml_out = tmp_path / "a.csv", tmp_path / "b.csv"
    run("check", "--answers", put(tmp_path, "sheet.csv", SHEET), problems, "--out", csv_out)
    sheet = put(tmp_path, "sheet.yaml", f"""\
ann:
  top-60:
    precession: [{SLOW:.4g} rad/s, {FAST / RPM:.4g} rpm]
  gyro-90:
    precession: {GYRO_PRECESSION / RPM:.4g} rpm
bob:
  top-60: {{precession: {SLOW:.4g} rad/s}}
  gyro-90: {{precession: {GYRO_PRECESSION * 10:.4g} rad/s}}
cy:
  top-60: {{precession: {SLOW:.4g} m}}
""")
    result = run("check", "--answers", sheet, problems, "--out", yaml_out)
    assert result.exit_code == 0, result.output
    assert read_back(yaml_out) == read_back(csv_out)


def test_out_is_never_overwritten_without_force(run, tmp_path, problems):
    sheet = put(tmp_path, "sheet.csv", SHEET)
    out = put(tmp_path, "grades.csv", "precious\n")
    refused = run("check", "--answers", sheet, problems, "--out", out)
    assert refused.exit_code == 2 and "--force" in refused.stderr
    assert out.read_text() == "precious\n"
    assert run("check", "--answers", sheet, problems, "--out", out, "--force").exit_code == 0
    assert out.read_text().startswith("student,problem,answer")
    assert sorted(os.listdir(tmp_path)) == ["grades.csv", "problems", "sheet.csv"]


@pytest.mark.parametrize("sheet, message", [
    ("student,problem,answer,value\nann,nope,precession,1 rad/s\n", "not among the problem"),
    ("student,problem,answer,value\nann,top-60,precesion,1 rad/s\n", "has no answer"),
    ("student,problem,answer,value\nann,top-60,precession\n", "expected 4 columns"),
    ("who,what\n", "expected 4 columns"),
])
def test_bad_sheet_is_exit_2_and_writes_nothing(run, tmp_path, problems, sheet, message):
    path = put(tmp_path, "sheet.csv", sheet)
    out = tmp_path / "grades.csv"
    result = run("check", "--answers", path, problems, "--out", out)
    assert result.exit_code == 2
    assert message in result.stderr
    assert not out.exists()


def test_headerless_csv_and_formula_cells_are_neutralised(run, tmp_path, problems):
    sheet = put(tmp_path, "sheet.csv", f"=cmd(),gyro-90,precession,{GYRO_PRECESSION} rad/s\n")
    out = tmp_path / "g.csv"
    assert run("check", "--answers", sheet, problems, "--out", out).exit_code == 0
    items, _ = read_back(out)
    assert ("'=cmd()", "gyro-90") in items


def test_write_atomic(tmp_path):
    target = tmp_path / "x.txt"
    write_atomic(target, "one")
    with pytest.raises(InputError, match="--force"):
        write_atomic(target, "two")
    assert target.read_text() == "one"
    write_atomic(target, "two", force=True)
    assert target.read_text() == "two"
    with pytest.raises(InputError, match="no such directory"):
        write_atomic(tmp_path / "missing" / "y.txt", "x")
    with pytest.raises(InputError, match="directory"):
        write_atomic(tmp_path, "x", force=True)
    assert os.listdir(tmp_path) == ["x.txt"]  # no temporary files left
    assert math.isclose(os.stat(target).st_mode & 0o777, 0o666 & ~_umask())


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def test_round_trip_through_the_installed_command(tmp_path, problems):
    import subprocess

    from test_check import gyro_exe

    sheet = put(tmp_path, "sheet.csv", SHEET)
    out = tmp_path / "grades.csv"
    done = subprocess.run([gyro_exe(), "check", "--answers", str(sheet), str(problems),
                           "--out", str(out)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    _, scores = read_back(out)
    assert scores["bob"] == (0.5, 2.0, "25.0%")
