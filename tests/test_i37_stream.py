"""Issue 37, item 3: `gyro vary --roster` and `gyro export` stream their variants (memory
does not grow with the number of students or variants) and write the same bytes as the
whole-set code did."""

from __future__ import annotations

import json
import tracemalloc
from pathlib import Path

import pytest
import yaml

from gyro_cli.checking.assignment import key_digest, read_key
from gyro_cli.commands import export as export_cmd
from gyro_cli.commands.authoring import variant_yaml
from gyro_cli.render import bank_blackboard, bank_moodle, bank_prairielearn, bank_qti

ROOT = Path(__file__).resolve().parent.parent
TOP = ROOT / "problems" / "11_3.yaml"
FIVE = ROOT / "problems" / "11_5.yaml"


def _peak(run, *args) -> float:
    """The peak of Python's allocations (MB) while the command runs in this process, with
    what it gives back to it printed (pytest -s)."""
    tracemalloc.start()
    try:
        result = run(*args)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert result.exit_code == 0, result.output
    print(args[:2], args[-3:-2], f"{peak / 1e6:.2f} MB")
    return peak / 1e6


def _roster(path: Path, students: int) -> Path:
    path.write_text("student,section\n" + "".join(f"s{k:04d},{k % 3}\n"
                                                  for k in range(students)))
    return path


@pytest.mark.slow  # traced by tracemalloc, threefold slower: a guard of memory
def test_item03_vary_roster_memory_does_not_grow_with_the_students(run, tmp_path):
    # Holding every variant's text and key entry costs about 6 kB a student (2.5 MB more
    # for 400 more students, measured on the code before it streamed); streaming keeps
    # their names and ids (0.9 MB). The bound is 3.75 kB a student, as when the runs
    # were of 100 and 900. A first run imports what the command needs, outside the
    # measure.
    assert run("vary", TOP, "--roster", _roster(tmp_path / "w.csv", 2), "-o",
               tmp_path / "w").exit_code == 0
    small = _peak(run, "vary", TOP, "--roster", _roster(tmp_path / "a.csv", 20), "-o",
                  tmp_path / "a")
    large = _peak(run, "vary", TOP, "--roster", _roster(tmp_path / "b.csv", 420), "-o",
                  tmp_path / "b")
    assert large - small < 1.5, (small, large)
    key, why = read_key(str(tmp_path / "b" / "key.json"))
    assert why == "" and key is not None and len(key["variants"]) == 420


@pytest.mark.slow  # traced by tracemalloc, threefold slower: a guard of memory
def test_item03_export_memory_does_not_grow_with_the_variants(run, tmp_path):
    # A variant's worked answer is tens of kB of MathML: held (the code before it
    # streamed), 60 more variants cost 9 MB; streamed, 0.3 MB. The bound is 12.5 kB a
    # variant, as when the runs were of 40 and 160 variants. A first run imports what the
    # command needs and fills the bounded memo of the worked answers' trees
    # (render/html.py), outside the measure.
    assert run("export", "--to", "moodle", TOP, "--variants", "20", "-o",
               tmp_path / "w.xml").exit_code == 0  # untraced: tracemalloc slows it threefold
    small = _peak(run, "export", "--to", "moodle", TOP, "--variants", "20", "-o",
                  tmp_path / "a.xml")
    large = _peak(run, "export", "--to", "moodle", TOP, "--variants", "80", "-o",
                  tmp_path / "b.xml")
    assert large - small < 0.75, (small, large)
    assert (tmp_path / "b.xml").read_text().count('<question type="cloze">') == 80


def test_item03_streamed_banks_are_the_whole_banks_bytes(run, tmp_path):
    """The streamed file equals the renderers' whole-bank text, a bad file in between
    (refused before its variants: its id is taken) and a problem of one variant included;
    PrairieLearn's directory equals its files."""
    bad = tmp_path / "bad.yaml"
    bad.write_text(TOP.read_text().replace("vary:", "vary:\n  nonsense: [1, 2]\n  # was"))
    files = [str(TOP), str(bad), str(ROOT / "problems" / "11_2_released_top.yaml"), str(FIVE)]
    made, errors = export_cmd.banks(files, 4, 7)
    assert len(made) == 3 and len(errors) == 1
    expected = {"moodle": bank_moodle.xml(made).encode(), "qti": bank_qti.package(made),
                "blackboard": bank_blackboard.text(made).encode("ascii")}
    for fmt, text in expected.items():
        out = tmp_path / f"bank.{fmt}"
        result = run("export", "--to", fmt, *files, "--variants", "4", "--seed", "7",
                     "--no-pictures", "-o", out)
        assert result.exit_code == 2  # the bad file
        assert out.read_bytes() == text, fmt
    result = run("export", "--to", "prairielearn", *files, "--variants", "4", "--seed", "7",
                 "--no-pictures", "-o", tmp_path / "pl")
    assert result.exit_code == 2
    written = {str(p.relative_to(tmp_path / "pl")): p.read_bytes()
               for p in (tmp_path / "pl").rglob("*") if p.is_file()}
    assert written == {rel: text.encode() if isinstance(text, str) else text
                       for rel, text in bank_prairielearn.files(made).items()}


def test_item03_streamed_key_verifies(run, tmp_path):
    roster = tmp_path / "r.csv"
    roster.write_text("student,name\nb,B\na,A\nc-1,C\n")
    result = run("vary", TOP, FIVE, "--roster", roster, "-o", tmp_path / "hw", "--seed", "3")
    assert result.exit_code == 0, result.output
    text = (tmp_path / "hw" / "key.json").read_text()
    data = json.loads(text)
    assert data["digest"] == key_digest(data)
    assert text == json.dumps(data, allow_nan=False)  # as the whole key was written
    assert list(data["variants"]) == ["11/3-b", "11/3-a", "11/3-c-1", "11/5-b", "11/5-a",
                                      "11/5-c-1"]


def test_item03_variant_yaml_is_pyyamls_text():
    data = {"id": "11/3-é \"q\"", "title": "A long title " * 12, "kind": "steady_precession",
            "source": "x: y # z", "statement": "Line one.\n\nLine two: {spin}.\n",
            "given": {"spin": "1200 rpm", "theta": "30.0000000000 deg"},
            "find": {"precession": None}, "expected": {"precession": ["1.23 rpm", "4 rpm"]},
            "tolerance": "1%", "ask": ["precession"], "flag": True, "n": 3, "e": {}}
    shared: dict = {}
    for _ in range(2):  # the second time from what is shared
        assert variant_yaml(data, shared) == yaml.safe_dump(
            data, sort_keys=False, allow_unicode=True, width=100)
    data["given"]["spin"] = "1300 rpm"
    assert "1300 rpm" in variant_yaml(data, shared)
