"""Issue 37: `gyro solve` loads only what it needs, and a roster's variants are written
without the work every variant shares (the same bytes as before)."""

from __future__ import annotations

import dataclasses
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from conftest import ROOT, examples
from hypothesis import given, settings
from hypothesis import strategies as st

TOP = ROOT / "problems" / "11_3.yaml"
FIVE = ROOT / "problems" / "11_5.yaml"

# Run as `gyro solve FILE` is run, then name the modules it imported.
_PROBE = """
import sys
from gyro_cli.cli import main
if sys.argv[1] == "--all":  # every command loaded first
    del sys.argv[1]
    for name in main.list_commands(None):
        main.get_command(None, name)
try:
    main()
finally:
    sys.stdout.flush()
    sys.stderr.write("\\nMODULES " + " ".join(sorted(sys.modules)) + " COMMANDS:"
                     + " COMMANDS:".join(sorted(main.commands)) + "\\n")
"""


def _modules(*args: str, tmp_path: Path) -> tuple[set[str], str]:
    """The modules ``gyro ARGS`` imported, and what it printed."""
    env = dict(os.environ, PYTHONPATH=str(ROOT), GYRO_CACHE_DIR=str(tmp_path / "cache"))
    for _ in range(2):  # the first run fills the unit table
        done = subprocess.run([sys.executable, "-c", _PROBE, *args], capture_output=True,
                              text=True, env=env, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    return set(done.stderr.rsplit("MODULES ", 1)[1].split()), done.stdout


@pytest.mark.slow  # fresh interpreters: `make test-slow`
def test_item02_solve_imports_no_other_command(tmp_path):
    loaded, _ = _modules("solve", str(TOP), tmp_path=tmp_path)
    assert "gyro_cli.solving.solve" in loaded
    # the commands built: solve, and check (defined beside it), not their options
    assert {m for m in loaded if m.startswith("COMMANDS:")} == {"COMMANDS:check",
                                                                "COMMANDS:solve"}
    others = {"gyro_cli.commands.others", "gyro_cli.commands.export",
              "gyro_cli.commands.authoring", "gyro_cli.commands.roster",
              "gyro_cli.commands.simulate", "gyro_cli.commands.handout"}
    assert not loaded & others, loaded & others


def test_item02_help_lists_every_command_without_loading_it(tmp_path):
    """`gyro --help` lists each command with its own short help, loading none of the
    commands `gyro solve` does not load."""
    loaded, lazy = _modules("--help", tmp_path=tmp_path)
    assert not {m for m in loaded if m.startswith("gyro_cli.commands.")} - \
        {"gyro_cli.commands", "gyro_cli.commands.exits"}
    assert lazy == _modules("--all", "--help", tmp_path=tmp_path)[1]
    from gyro_cli.cli import main

    for name in main.list_commands(None):  # type: ignore[arg-type]
        main.get_command(None, name)  # type: ignore[arg-type]  # every command loaded
    for name in ("check", "export", "handout", "kinds", "new", "schema", "simulate",
                 "solve", "vary"):
        assert f"\n  {name} " in lazy
    for name, (_, _, text) in type(main).LAZY.items():
        own = main.commands[name].help or ""
        assert " ".join(own.split("\n\n")[0].split()) == text, name


# --- the roster: YAML written without the emitter where its text is known ---------------

_TEXT = st.text(alphabet="aZ09 ()._/+*,:%-'#yn~e", max_size=110)
_WORDS = st.sampled_from(["1.5", "3", "yes", "No", "on", "null", "~", "2001-01-01", "1e3",
                          "0x1f", ".inf", "1:20", "-1", "-.5", "1_000", "3 oz", "-1890 rpm",
                          "35.45 rpm", "-3.504 N m", "--x", "---", "-", "- a", "-a", "a: b",
                          "a:", "a #b", "(s1)", "x" * 98, "x " * 49,
                          "2001-12-14 21:59:43.10 -5", "2001-1-2 1:59", "1-2 3"])
_VALUES = st.one_of(_TEXT, _WORDS)


@settings(max_examples=examples(300), deadline=None, derandomize=True, database=None)
@given(key=st.one_of(st.sampled_from(["id", "given", "yes", "k_axial", "on"]),
                     st.text(alphabet="ab_9", min_size=1, max_size=40)),
       value=st.one_of(_VALUES, st.lists(_VALUES, max_size=3),
                       st.dictionaries(st.sampled_from(["spin", "theta", "null", "b"]),
                                       st.one_of(_VALUES, st.lists(_VALUES, max_size=3)),
                                       max_size=3)))
def test_item03_a_variants_yaml_written_directly_is_pyyamls(key, value):
    from gyro_cli.commands.authoring import _simple_yaml

    fast = _simple_yaml(key, value)
    if fast is None:
        return
    for dumper in (yaml.CSafeDumper, yaml.SafeDumper):
        assert fast == yaml.dump({key: value}, Dumper=dumper, sort_keys=False,
                                 allow_unicode=True, width=100), (key, value)


def test_item03_roster_variants_call_the_emitter_only_for_what_they_share(monkeypatch, tmp_path):
    """The YAML emitter runs for the text the variants share (statement, notes), once a
    problem, not for each student's id, title, numbers and answers; the files are the
    emitter's text all the same."""
    from gyro_cli.commands.roster import roster_variants

    calls = []
    dump = yaml.dump
    monkeypatch.setattr(yaml, "dump", lambda *a, **k: calls.append(a[0]) or dump(*a, **k))
    roster = tmp_path / "roster.csv"
    roster.write_text("student\n" + "".join(f"s{k:02d}\n" for k in range(30)))
    files, _, _ = roster_variants([str(TOP), str(FIVE)], str(roster), 7)
    assert len(files) == 60
    assert len(calls) <= 8, [list(c) for c in calls]
    monkeypatch.setattr(yaml, "dump", dump)
    for _, text in files:
        body = text.split("\n", 1)[1]
        assert body == yaml.safe_dump(yaml.safe_load(body), sort_keys=False,
                                      allow_unicode=True, width=100)


def test_item03_key_answers_are_asdicts(tmp_path):
    from gyro_cli.commands.roster import _answer_entry
    from gyro_cli.solving.solve import solve_file

    for path in sorted((ROOT / "problems").glob("*.yaml"))[:40]:
        try:
            result = solve_file(str(path))
        except Exception:  # noqa: BLE001 - a problem that does not solve alone
            continue
        for answer in result.answers.values():
            made, expected = _answer_entry(answer), dataclasses.asdict(answer)
            assert list(made) == list(expected)
            if answer.symbol_expr is None:  # a tree (copied by asdict) is no plain value
                assert made == expected
                assert json.dumps(made) == json.dumps(expected)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(pytest.main([__file__, "-q"]))
