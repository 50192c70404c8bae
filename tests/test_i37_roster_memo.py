"""Issue 37, item 3, second pass: what a roster's variants share is read and written once.
A given line written as a string (solving/solve.py: `_WRITTEN`) and a given string of the
variants of one problem (solving/problem.py: `parse_given`'s memo) are remembered; these
tests hold what is remembered to what is made afresh, and its size bounded."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

from gyro_cli.commands import authoring
from gyro_cli.commands.roster import roster_variants
from gyro_cli.core.expr import formula
from gyro_cli.solving import problem as problem_module
from gyro_cli.solving import solve as solve_module
from gyro_cli.solving.problem import load, parse_given
from gyro_cli.solving.solve import solve

ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = sorted((ROOT / "problems").glob("*.yaml"))


def _given(path: Path) -> list[dict]:
    """The given lines of a solve, their trees as printed (a tree is compared by identity)."""
    lines = [dataclasses.asdict(line) for line in solve(load(str(path))).solution.given]
    for line in lines:
        tree = line["symbol_expr"]
        line["symbol_expr"] = None if tree is None else formula(tree)
        prose = line["note_prose"]
        line["note_prose"] = None if prose is None else prose.text
    return lines


@pytest.mark.parametrize("path", PROBLEMS, ids=lambda p: p.stem)
def test_item03_remembered_given_lines_equal_fresh(path: Path) -> None:
    """Every bundled problem's given lines (weights in lb, defaults, keys stated another
    way) are the same made afresh, remembered, and made afresh again."""
    solve_module._WRITTEN.clear()
    fresh = _given(path)
    remembered = _given(path)
    solve_module._WRITTEN.clear()
    assert remembered == fresh == _given(path)


def test_item03_a_kind_editing_its_given_line_leaves_the_next_solve_alone() -> None:
    """torque_free writes a note into its spin's given line: a solve after it reads the
    line as written, not as the last solve left it."""
    path = ROOT / "problems" / "torque_free_curtis_10_18.yaml"
    solve_module._WRITTEN.clear()
    first = solve(load(str(path))).solution.given
    for line in first:
        line.note = "edited"
    assert all(line.note != "edited" for line in solve(load(str(path))).solution.given)


def test_item03_remembered_strings_are_bounded() -> None:
    """A memo of a roster's given strings keeps at most _MEMO_MAX (the varied values are
    each met once) and gives what parse_given gives without it."""
    kind = load(str(ROOT / "problems" / "11_3.yaml")).kind
    memo: dict = {}
    for n in range(problem_module._MEMO_MAX + 300):
        raw = {"weight": "30 N", "k_axial": "50 mm", "k_pivot": "60 mm",
               "cg_distance": "40 mm", "spin": f"{1000 + n / 10:.1f} rpm",
               "theta": "30 deg"}
        with_memo, without = parse_given(kind, raw, memo), parse_given(kind, raw)
        assert with_memo[0].values == without[0].values
        assert with_memo[1:] == without[1:]
    assert len(memo) <= problem_module._MEMO_MAX


def test_item03_refused_string_is_not_remembered() -> None:
    """A string refused is refused again, not taken from the memo."""
    from gyro_cli.core.errors import InputError

    kind = load(str(ROOT / "problems" / "11_3.yaml")).kind
    memo: dict = {}
    raw = {"weight": "30 N", "k_axial": "50 mm", "k_pivot": "60 mm", "cg_distance": "40 mm",
           "spin": "-5 furlongs", "theta": "30 deg"}
    for _ in range(2):
        with pytest.raises(InputError):
            parse_given(kind, raw, memo)
    assert ("spin", "-5 furlongs") not in memo


def test_item03_roster_same_with_memos_cleared_between_variants(tmp_path, monkeypatch) -> None:
    """A set drawn with the memos in use is the set drawn with every variant read afresh
    (each variant's problem built whole, no given line remembered)."""
    roster = tmp_path / "r.csv"
    roster.write_text("student\n" + "".join(f"s{k}\n" for k in range(25)))
    paths = [str(ROOT / "problems" / "11_3.yaml"), str(ROOT / "problems" / "11_5.yaml")]
    fast = roster_variants(paths, str(roster), 7)
    made = authoring._variant_problem

    def whole(path, base, keyed, data):  # type: ignore[no-untyped-def]
        authoring._TEMPLATE.clear()
        solve_module._WRITTEN.clear()
        return made(path, base, keyed, data)

    monkeypatch.setattr(authoring, "_variant_problem", whole)
    slow = roster_variants(paths, str(roster), 7)
    assert fast[0] == slow[0] and fast[1] == slow[1]
    assert fast[2].split('"variants"')[1] == slow[2].split('"variants"')[1]
