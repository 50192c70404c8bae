"""Issue 37, item 2: a warm `gyro solve` in text loads what a solve needs and no more, so
that later changes cannot silently grow its start (benchmarks/bench_solve.py measures it).
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import click
import pytest
from conftest import ROOT

from gyro_cli.core import unit_cache

TOP = ROOT / "problems" / "11_3.yaml"

# `gyro solve FILE` as the installed command runs it; then the modules it imported beyond
# the floor (`import yaml, click`), and the regular expressions compiled on the way.
_PROBE = """
import re, sys
import yaml, click
floor = set(sys.modules)
compiled = []
_compile = re._compile
def counting(pattern, flags):
    key = (type(pattern), pattern, flags)
    if key not in re._cache:
        compiled.append(str(pattern))
    return _compile(pattern, flags)
re._compile = counting
from gyro_cli.cli import main
try:
    main()
finally:
    sys.stdout.flush()
    sys.stderr.write("\\nEXTRA " + " ".join(sorted(set(sys.modules) - floor)) + "\\n"
                     + "COMPILED " + repr(compiled) + "\\n")
"""

# What a text solve of a steady_precession file may load beyond yaml and click: gyro's own
# modules on its path (not dataclasses: a record imports it only when its fields are read
# by dataclasses' functions). Not json (the unit table is read by
# Python's parser), locale (click's gettext), signal (its enums) or zlib (the table's stamp).
ALLOWED = {
    "gyro_cli", "gyro_cli.cli", "gyro_cli.api",
    "gyro_cli.commands", "gyro_cli.commands.exits",
    "gyro_cli.core", "gyro_cli.core.alternatives", "gyro_cli.core.body",
    "gyro_cli.core.errors", "gyro_cli.core.expr", "gyro_cli.core.files", "gyro_cli.core.generic",
    "gyro_cli.core.given", "gyro_cli.core.params", "gyro_cli.core.prose",
    "gyro_cli.core.record", "gyro_cli.core.safeyaml", "gyro_cli.core.spec",
    "gyro_cli.core.streams", "gyro_cli.core.unit_cache", "gyro_cli.core.units",
    "gyro_cli.core.work",
    "gyro_cli.kinds", "gyro_cli.kinds.steady_precession",
    "gyro_cli.physics", "gyro_cli.physics.algebra", "gyro_cli.physics.steady",
    "gyro_cli.render", "gyro_cli.render.formats", "gyro_cli.render.report",
    "gyro_cli.solving", "gyro_cli.solving.paths", "gyro_cli.solving.problem",
    "gyro_cli.solving.solve",
    "atexit",  # built in (the table is saved at exit)
    "gc",  # built in: cli.py sets the collector's threshold
}


def _probe(args: list[str], cache: Path) -> tuple[set[str], list[str], str]:
    env = dict(os.environ, PYTHONPATH=str(ROOT), GYRO_CACHE_DIR=str(cache))
    for _ in range(2):  # the first run fills the unit table
        done = subprocess.run([sys.executable, "-c", _PROBE, *args], capture_output=True,
                              text=True, env=env, cwd=ROOT, timeout=300)
    assert done.returncode == 0, done.stderr
    extra = re.search(r"^EXTRA (.*)$", done.stderr, re.M)
    compiled = re.search(r"^COMPILED (.*)$", done.stderr, re.M)
    assert extra and compiled, done.stderr
    return set(extra.group(1).split()), eval(compiled.group(1)), done.stdout  # noqa: S307


@pytest.mark.slow  # fresh interpreters: `make test-slow`
def test_item02_warm_text_solve_loads_only_its_own_modules(tmp_path):
    extra, _, out = _probe(["solve", str(TOP)], tmp_path / "cache")
    assert "Answer" in out
    assert extra <= ALLOWED, sorted(extra - ALLOWED)
    assert not extra & {"json", "locale", "signal", "zlib", "pint", "numpy"}


@pytest.mark.slow  # fresh interpreters: `make test-slow`
def test_item02_warm_text_solve_compiles_only_the_patterns_it_matches(tmp_path):
    """Patterns are compiled when first used, not when their module is imported: a solve
    of 11/3 compiles the few its own input needs (dataclasses, which compiles one, is not
    imported)."""
    from gyro_cli.core import streams, units
    from gyro_cli.solving import solve

    _, compiled, _ = _probe(["solve", str(TOP)], tmp_path / "cache")
    unused = {units._POWER_SUFFIX, solve._NOT_FINITE, streams._SURROGATE}
    assert not unused & set(compiled), compiled
    assert units._NUMBER in compiled  # the probe sees what is compiled
    assert len(compiled) <= 4, compiled


def test_item02_unit_table_read_as_json_reads_it():
    """The unit table is read without json: the same values json reads, for what
    json.dump writes; anything else is refused (then the table is rebuilt)."""
    tables = [{"parse": {"oz\x1fforce\x1f1": [0.2780138509537813, "ozf", True],
                         "x\x1f\"\\\u00e9": [-1.5e-300, "a/b \u00b0", False]},
               "shown": {"rpm\x1frate": "rpm"}, "to": {"rate\x1frpm": 9.549296585513721},
               "stamp": [2, "00a7069fbd588c6ca01b"]},
              {}, {"a": None, "b": [1, -0.0, 1e308, -7]}]
    for table in tables:
        text = json.dumps(table)
        assert unit_cache.from_json(text) == json.loads(text)
        assert repr(unit_cache.from_json(text)) == repr(json.loads(text))  # -0.0, ints
    for bad in ["not json {", "{1: 2}", "f(1)", "[[[[[[[1]]]]]]]", "x", "{**a}", '-"a"',
                "[1, 2] + [3]", "1 if 2 else 3", "\x00"]:
        with pytest.raises((ValueError, SyntaxError)):
            unit_cache.from_json(bad)


def test_item02_help_and_version_say_what_click_says(tmp_path):
    """--help and --version are made without click's gettext, in click's own words."""
    command = click.help_option()(click.Command("probe"))
    theirs = next(p for p in command.params if p.name == "help")
    from gyro_cli.cli import HELP_TEXT, VERSION_TEXT

    assert HELP_TEXT == theirs.help
    version = click.version_option("1", prog_name="p")(click.Command("probe")).params[0]
    assert VERSION_TEXT == version.help
    env = dict(os.environ, PYTHONPATH=str(ROOT), GYRO_CACHE_DIR=str(tmp_path))
    run = [sys.executable, "-m", "gyro_cli"]
    done = subprocess.run([*run, "--version"], capture_output=True, text=True, env=env)
    from gyro_cli import __version__

    assert (done.returncode, done.stdout) == (0, f"gyro, version {__version__}\n")
    done = subprocess.run([*run, "solve", "-h"], capture_output=True, text=True, env=env)
    assert done.returncode == 0 and re.search(r"-h, --help\s+Show this message and exit\.",
                                              done.stdout)
    done = subprocess.run([*run, "solve"], capture_output=True, text=True, env=env)
    assert done.returncode == 2 and "Try 'gyro solve --help' for help." in done.stderr


def test_item02_a_long_unit_table_is_read_by_json_as_from_json_reads_it(tmp_path, monkeypatch):
    """Past AST_MAX characters the table is read by json (ast.parse of a table near
    MAX_BYTES would take hundreds of milliseconds a run): the same tables either way, a
    damaged long table still ignored."""
    monkeypatch.setenv("GYRO_CACHE_DIR", str(tmp_path))
    unit_cache.forget()
    made = unit_cache.stamp()
    assert made is not None
    parse = {f"u{n}\x1flength\x1f0": [1.0 + n / 7, f"u{n}", n % 2 == 0] for n in range(300)}
    text = json.dumps({"parse": parse, "shown": {}, "to": {"rate\x1frpm": 9.5}, "stamp": made})
    assert len(text) > unit_cache.AST_MAX
    assert unit_cache.read_table(text) == unit_cache.from_json(text) == json.loads(text)
    (tmp_path / "units.json").write_text(text)
    try:
        assert unit_cache.get("parse", "u123", "length", 0) == parse["u123\x1flength\x1f0"]
        assert unit_cache.get("to", "rate", "rpm") == 9.5
        unit_cache.forget()
        (tmp_path / "units.json").write_text(text[:-40])  # cut short: not JSON
        assert unit_cache.get("parse", "u123", "length", 0) is None
    finally:
        unit_cache.forget()
