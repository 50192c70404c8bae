"""Issue 22, items 4 and 11: nothing silently wrong, nothing injected, in grading.

Each test is named after its item and fails on the code before the fix: a
verbatim duplicate row halved the point, `cusps; cusps` was worth 0.5, a
duplicate answer key in a YAML sheet kept the last value, a repeated header
column graded by the second one, and a cell `-2+3+cmd|' /C calc'!A0` reached
the grades CSV as a formula.
"""

from __future__ import annotations

import csv
from pathlib import Path

from test_check import FAST, SLOW, put, top_file

ROOT = Path(__file__).resolve().parent.parent
RELEASED = ROOT / "problems" / "11_2_released_top.yaml"


def problems(tmp_path: Path) -> Path:
    return put(tmp_path / "p", "top.yaml", top_file(f"precession: [{SLOW} rad/s, {FAST} rad/s]\n"))


def test_i22_04_duplicate_csv_row(run, tmp_path):
    row = f"ann,top-60,precession,{SLOW:.4g} rad/s\n"
    sheet = put(tmp_path, "s.csv", "student,problem,answer,value\n" + row + row)
    result = run("check", "--answers", sheet, problems(tmp_path))
    assert result.exit_code == 2, result.output
    assert "s.csv" in result.stderr and "line 3" in result.stderr
    assert "repeats line 2" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    # two different rows for the two roots are still one answer, graded whole
    two = put(tmp_path, "t.csv", row + f"ann,top-60,precession,{FAST:.4g} rad/s\n")
    result = run("check", "--answers", two, problems(tmp_path), "--format", "json")
    assert result.exit_code == 0 and '"result": "correct"' in result.stdout


def test_i22_04_duplicated_word_answer(run, tmp_path):
    for value in ("cusps; cusps", "cusp; Cusps."):
        sheet = put(tmp_path, "w.csv", f'ann,11.2-released,motion,"{value}"\n')
        out = tmp_path / "g.csv"
        result = run("check", "--answers", sheet, RELEASED, "--out", out, "--force")
        assert result.exit_code == 0, result.output
        with open(out, newline="") as handle:
            row = next(csv.DictReader(handle))
        assert (row["result"], row["points"]) == ("correct", "1"), (value, row)
    # a second, different word still costs its share
    sheet = put(tmp_path, "w.csv", 'ann,11.2-released,motion,"cusps; loops"\n')
    result = run("check", "--answers", sheet, RELEASED, "--format", "json")
    assert '"result": "partial"' in result.stdout and '"points": 0.5' in result.stdout


def test_i22_04_duplicate_yaml_key(run, tmp_path):
    sheet = put(tmp_path, "s.yaml", f"""ann:
  top-60:
    precession: {SLOW:.4g} rad/s
    precession: 999 rad/s
""")
    result = run("check", "--answers", sheet, problems(tmp_path))
    assert result.exit_code == 2, result.output
    assert "written twice (lines 3 and 4)" in result.stderr and "precession" in result.stderr


def test_i22_04_duplicate_header_column(run, tmp_path):
    sheet = put(tmp_path, "h.csv", "student,student,problem,answer,value\n"
                                   f"ann,bob,top-60,precession,{SLOW:.4g} rad/s\n")
    result = run("check", "--answers", sheet, problems(tmp_path))
    assert result.exit_code == 2, result.output
    assert "two student columns" in result.stderr and "line 1" in result.stderr


ATTACKS = ["=1+1", "+1+1", "-2+3+cmd|' /C calc'!A0", "@SUM(A1)", "\t=1", "\r=1",
           "-1+cmd|' /C calc'!A0", "\uff1dHYPERLINK(1)", "45 rpm;=HYPERLINK(\"x\")",
           "1 rpm, -2+cmd|x!A0"]


def _runs_as_formula(cell: str) -> bool:
    """Would a spreadsheet run this cell, or a part of it after a field separator?
    (OWASP: a start of =, +, -, @, tab or CR, unless the part is a plain number.)"""
    import re

    number = re.compile(r"[-+]?(\d+(\.\d*)?|\.\d+)([eE][-+]?\d+)?%?\Z")
    parts = [cell] + [p.lstrip(" ") for p in re.split(r"[,;\t\r\n|]", cell)[1:]]
    return any(p[:1] in ("=", "+", "-", "@", "\t", "\r", "\uff1d") and not number.match(p.strip())
               for p in parts)


def test_i22_11_csv_injection(run, tmp_path):
    # end to end: the student's cell as the attack, read back as text, not a formula
    lines = "".join(f'ann{k},top-60,precession,"{a}"\n' for k, a in enumerate(ATTACKS[:4]))
    sheet = put(tmp_path, "a.csv", lines + 'ann9,top-60,precession,"-1 rpm"\n')
    out = tmp_path / "g.csv"
    result = run("check", "--answers", sheet, problems(tmp_path), "--out", out)
    assert result.exit_code == 0, result.output
    with open(out, newline="") as handle:
        cells = [c for row in csv.reader(handle) for c in row]
    assert not [c for c in cells if _runs_as_formula(c)]
    assert "'-2+3+cmd|' /C calc'!A0" in cells
    # every attack, cell by cell; plain numbers (negative ones too) stay numbers
    from gyro_cli.core.csvsafe import plain_cell, safe_cell

    for attack in ATTACKS:
        assert _runs_as_formula(attack)
        assert not _runs_as_formula(safe_cell(attack)), (attack, safe_cell(attack))
        assert plain_cell(safe_cell(attack)) == attack
    for number in ("-0.00136857", "-12", "45", "1e-05", "-3.5E+2", "+7", "50.0%"):
        assert safe_cell(number) == number
