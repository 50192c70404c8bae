"""Issue 37, item 3: `gyro vary --roster` of a class in seconds. A new folder is written
whole through one hidden folder renamed into place (core/files.py: StagedFolder), with the
same bytes and modes as the set written file by file into an existing folder, and nothing
left behind when the set fails."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from gyro_cli.core.errors import InputError
from gyro_cli.core.files import StagedFolder

ROOT = Path(__file__).resolve().parent.parent
TOP = ROOT / "problems" / "11_3.yaml"
FIVE = ROOT / "problems" / "11_5.yaml"


def _roster(path: Path, students: int) -> Path:
    path.write_text("student,section\n" + "".join(f"s{k:03d},{k % 3}\n"
                                                  for k in range(students)))
    return path


def _tree(folder: Path) -> dict[str, tuple[bytes, int]]:
    """Every file below ``folder``: its bytes and permission bits (folders' bits too)."""
    out = {}
    for path in sorted(folder.rglob("*")):
        mode = stat.S_IMODE(path.stat().st_mode)
        out[str(path.relative_to(folder))] = (path.read_bytes() if path.is_file() else b"",
                                              mode)
    return out


def test_item03_new_folder_same_bytes_and_modes_as_file_by_file(run, tmp_path):
    roster = _roster(tmp_path / "r.csv", 12)
    fresh = tmp_path / "deep" / "new"  # its parent made too
    old = tmp_path / "old"
    old.mkdir()  # an existing folder: the set is staged and placed file by file
    for out in (fresh, old):
        result = run("vary", TOP, FIVE, "--roster", roster, "-o", out)
        assert result.exit_code == 0, result.output
    a, b = _tree(fresh), _tree(old)
    key_a, key_b = a.pop("key.json"), b.pop("key.json")
    assert a == b and len(a) == 2 + 24 + 1
    assert key_a == key_b
    assert stat.S_IMODE(fresh.stat().st_mode) == stat.S_IMODE(old.stat().st_mode)
    assert sorted(os.listdir(fresh.parent)) == ["new"]  # no hidden folder left
    result = run("vary", TOP, "--roster", roster, "-o", fresh)  # exists now: refused
    assert result.exit_code == 2 and "exists; not overwritten" in result.output


def test_item03_failed_new_folder_leaves_nothing(tmp_path):
    target = tmp_path / "made" / "hw"
    with pytest.raises(RuntimeError):
        with StagedFolder(str(target)) as staged:
            staged.add(str(target / "a" / "x.yaml"), "one")
            staged.add(str(target / "key.json"), iter([b"{", "}"]))
            raise RuntimeError("a draw failed")
    assert os.listdir(tmp_path) == []  # the hidden folder and the parent made are gone


def test_item03_new_folder_taken_meanwhile_is_not_replaced(tmp_path):
    target = tmp_path / "hw"
    with pytest.raises(InputError, match="nothing of the set was written"):
        with StagedFolder(str(target)) as staged:
            staged.add(str(target / "x.yaml"), "mine")
            target.mkdir()
            (target / "theirs.txt").write_text("theirs")
            staged.place()
    assert sorted(os.listdir(tmp_path)) == ["hw"]
    assert os.listdir(target) == ["theirs.txt"]


def _answers(result) -> dict:  # type: ignore[no-untyped-def]
    """A result's answers, a symbol written as a tree compared by its text."""
    from gyro_cli.core.prose import text

    out = {}
    for name, answer in result.answers.items():
        fields = dict(answer.__dict__)
        tree = fields.pop("symbol_expr")
        out[name] = (fields, None if tree is None else text(tree))
    return out


def _varied(path: Path):  # type: ignore[no-untyped-def]
    """The problem of ``path`` with a `vary` block scaling each number it gives that
    `gyro vary` can draw (0.5 to 1.5 times: wide, so some draws have no real solution)."""
    from gyro_cli.commands.authoring import parse_vary
    from gyro_cli.solving.problem import load

    problem = load(str(path))
    if problem.vary is not None:
        return problem
    keys = {}
    for key in problem.data["given"]:
        problem.vary = {key: [0.5, 1.5]}
        try:
            parse_vary(problem)
        except Exception:
            continue
        keys[key] = [0.5, 1.5]
    problem.vary = keys or None
    return problem


@pytest.mark.parametrize("path", sorted((ROOT / "problems").glob("*.yaml")),
                         ids=lambda p: p.stem)
def test_item03_a_variant_built_from_the_first_is_built_whole(path):
    # A variant's problem is the first variant's with its given values, id, title and
    # source read again (authoring._variant_problem): every draw, taken or refused, gives
    # the data, `expected` and the solver's answers of the variant built whole.
    import copy
    import random

    from gyro_cli.commands import authoring
    from gyro_cli.commands.authoring import draw_variant, parse_vary

    problem = _varied(path)
    if not problem.vary:
        pytest.skip("no number given that gyro vary can draw")
    ranges = parse_vary(problem)
    base = copy.deepcopy(problem.data)
    base.pop("vary", None)
    keyed = [n for n in problem.expected if problem.kind.answer(n) is not None] \
        or list(problem.find)
    fast, whole = random.Random(7), random.Random(7)
    authoring._TEMPLATE.clear()
    taken = 0
    for n in range(12):
        made: list = []
        again: list = []
        data = draw_variant(problem, base, ranges, fast, keyed, f"v{n}", f"t{n}", "s",
                            solved=made)
        saved = list(authoring._TEMPLATE)
        authoring._TEMPLATE.clear()  # built whole
        expect = draw_variant(problem, base, ranges, whole, keyed, f"v{n}", f"t{n}", "s",
                              solved=again)
        authoring._TEMPLATE[:] = saved
        assert data == expect
        if data is not None:
            taken += 1
            assert _answers(made[0]) == _answers(again[0])
            assert made[0].problem.given.values == again[0].problem.given.values
            assert made[0].problem.quantities == again[0].problem.quantities
            for name in ("id", "title", "source", "find", "us_customary", "units", "ask",
                         "steps", "statement", "notes", "expected", "tolerance"):
                assert getattr(made[0].problem, name) == getattr(again[0].problem, name)
    assert taken or problem.data.get("vary") is None


def test_item03_new_folder_write_error_is_one_line_and_leaves_nothing(tmp_path):
    # The files are written by a thread beside the drawing: its error (here a file where
    # a folder of the set goes) is raised in the command, and nothing is left.
    target = tmp_path / "hw"
    with pytest.raises(InputError, match="cannot write") as err:
        with StagedFolder(str(target)) as staged:
            Path(staged.stage, "a").write_text("in the way")
            for n in range(200):
                staged.add(str(target / "a" / f"{n}.yaml"), "x")
            staged.place()
    assert str(target / "a") in str(err.value.file)
    assert os.listdir(tmp_path) == []
