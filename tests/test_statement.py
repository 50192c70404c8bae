"""Problem statements (issue 25.1): `statement:` with {key} filled from `given` as written.

The filled texts are written out here by hand from the files' given values.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from gyro_cli.core.statement import fill_statement, placeholders
from gyro_cli.solving.problem import load

ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = sorted((ROOT / "problems").glob("*.yaml"))

TOP = """\
id: t
kind: steady_precession
statement: >-
  A top of weight {weight} spins at {spin} with its axis at {theta}
  from the vertical ({{k}} is a brace). Find the precession.
given:
  weight: 3 oz
  k_axial: 0.84 in
  k_pivot: 1.80 in
  cg_distance: 1.5 in
  spin: 1800   rpm
  theta: 30 deg
find: {precession: rpm}
"""


def test_placeholders_are_filled_from_given_as_written(tmp_path):
    path = tmp_path / "t.yaml"
    path.write_text(TOP)
    assert load(str(path)).statement_text() == (
        "A top of weight 3 oz spins at 1800 rpm with its axis at 30 deg from the vertical "
        "({k} is a brace). Find the precession.")
    assert fill_statement("{gear_ratio} to 1", {"gear_ratio": 5}) == "5 to 1"
    assert placeholders("{a} {{b}} {c}") == ["a", "c"]


@pytest.mark.parametrize("text, message", [
    ("at {speed}", "{speed} is not a key of `given` (given keys: weight, k_axial"),
    ("at {spin.__class__}", "{spin.__class__} is not a given key's name"),
    ("a lone { brace", "a lone '{'"),
    ("a lone } brace", "a lone '}'"),
])
def test_a_bad_placeholder_is_one_line_naming_the_key(run, tmp_path, text, message):
    path = tmp_path / "t.yaml"
    data = yaml.safe_load(TOP)
    data["statement"] = text
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    result = run("solve", path)
    assert result.exit_code == 2
    line = result.stderr.strip()
    assert len(line.splitlines()) == 1 and "statement (line 3)" in line and message in line, line


@pytest.mark.parametrize("path", PROBLEMS, ids=[p.stem for p in PROBLEMS])
def test_every_bundled_problem_has_a_statement_with_its_numbers(path):
    problem = load(str(path))
    text = problem.statement_text()
    assert text and "{" not in text and "}" not in text
    names = placeholders(problem.statement)
    assert names, "a statement states the problem's data"
    for name in names:
        assert " ".join(str(problem.data["given"][name]).split()) in text


def test_gyro_new_writes_a_statement_that_fills(run, tmp_path):
    out = tmp_path / "n.yaml"
    assert run("new", "steady_precession", "-o", out).exit_code == 0
    text = load(str(out)).statement_text()
    assert "3 oz" in text and "1800 rpm" in text and "30 deg" in text


def test_a_students_variant_states_their_own_numbers(run, tmp_path):
    roster = tmp_path / "r.csv"
    roster.write_text("student\nann\n")
    result = run("vary", ROOT / "problems" / "11_3.yaml", "--roster", roster, "-o", tmp_path / "hw")
    assert result.exit_code == 0, result.output
    variant = load(str(tmp_path / "hw" / "11_3" / "ann.yaml"))
    given = variant.data["given"]
    text = variant.statement_text()
    assert f"spins at {given['spin']} with its axis at {given['theta']}" in text
    assert given["spin"] != "1800 rpm"
