"""The unit table cached on disk (issue: gyro solve without pint when a unit is known).

pint is the authority: every spelling the docs mention is resolved once by pint
(cold), then again from the cache file with pint made unusable (warm), and the
two must agree exactly. A damaged or foreign file is ignored and rebuilt; whole
runs with an empty and with a warm cache print byte-identical output.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from gyro_cli.core import unit_cache, units

ROOT = Path(__file__).resolve().parents[1]

# (quantity text, dimension, weight key) for every spelling the docs mention.
SPELLINGS = [
    ("1800 rpm", "rate", False), ("1800 RPM", "rate", False), ("1800 rev/min", "rate", False),
    ("1800 r/min", "rate", False), ("30 rps", "rate", False), ("30 rev/s", "rate", False),
    ("30 Hz", "rate", False), ("5 rad/s", "rate", False), ("12 deg/s", "rate", False),
    ("2 rev", "angle", False), ("30 deg", "angle", False), ("0.5 rad", "angle", False),
    ("100 km/h", "speed", False), ("100 km/hr", "speed", False), ("360 kmph", "speed", False),
    ("100 kph", "speed", False), ("20 knot", "speed", False), ("20 kn", "speed", False),
    ("20 kt", "speed", False), ("60 mph", "speed", False), ("10 m/s", "speed", False),
    ("20 t", "mass", False), ("20 tonne", "mass", False), ("3 kg", "mass", False),
    ("2 lb", "mass", False), ("0.2 slug", "mass", False), ("5 kgf", "force", False),
    ("3 oz", "weight", True), ("4 lb", "weight", True), ("20 lb", "force", False),
    ("50 lb ft", "moment", False), ("50 lb-ft", "moment", False), ("50 lb*ft", "moment", False),
    ("50 ft lb", "moment", False), ("50 lb in", "moment", False), ("50 oz in", "moment", False),
    ("2 N m", "moment", False), ("2 N-m", "moment", False), ("2 N.m", "moment", False),
    ("2 N*m", "moment", False), ("2 Nm", "moment", False), ("2 kN m", "moment", False),
    ("2 kNm", "moment", False), ("-0.3 1/s", "inverse_time", False),
    ("150 mm", "length", False), ("1.5 in", "length", False), ("2 ft", "length", False),
    ("32.2 ft/s^2", "acceleration", False), ("0.01 kg m^2", "inertia", False),
    ("0.5 slug ft^2", "inertia", False), ("2 s", "time", False), ("3 h", "time", False),
]
ANSWER_UNITS = [("rate", "rpm"), ("rate", "rev/s"), ("moment", "lb-ft"), ("moment", "N*m"),
                ("speed", "kmph"), ("force", "lb"), ("length", "in"), ("angle", "deg")]


@pytest.fixture
def fresh(tmp_path, monkeypatch):
    """An empty cache directory and empty in-memory tables."""
    monkeypatch.setenv("GYRO_CACHE_DIR", str(tmp_path))
    for table in ("_CHECKED", "_SHOWN", "_TO"):
        monkeypatch.setattr(units, table, {})
    unit_cache.forget()
    yield tmp_path
    unit_cache.forget()


def _no_pint(monkeypatch):
    def refuse():
        raise AssertionError("pint was asked although the unit was cached")

    monkeypatch.setattr(units, "registry", refuse)
    for table in ("_CHECKED", "_SHOWN", "_TO"):
        monkeypatch.setattr(units, table, {})
    unit_cache.forget()


def _resolve_all():
    dim = {"weight": "force"}
    parsed = [units.parse(t, dim.get(d, d), "given.x", weight=w) for t, d, w in SPELLINGS]
    shown = [units.display(t.split(" ", 1)[1], dim.get(d, d)) for t, d, _ in SPELLINGS]
    to = [units.convert(1.0, d, units.check_unit(u, d, "find.x")) for d, u in ANSWER_UNITS]
    return parsed, shown, to


def test_every_documented_spelling_is_the_same_from_the_cache_as_from_pint(fresh, monkeypatch):
    cold = _resolve_all()
    unit_cache.save()
    assert (fresh / "units.json").exists()
    _no_pint(monkeypatch)
    warm = _resolve_all()
    assert warm == cold                      # factors, printed units, US flags: exact
    for (_value, parsed), (text, _, _) in zip(cold[0], SPELLINGS):
        assert parsed.magnitude == float(text.split()[0])


def test_kmph_is_kilometres_per_hour_through_the_cache(fresh, monkeypatch):
    units.parse("1 kmph", "speed", "k")
    unit_cache.save()
    _no_pint(monkeypatch)
    assert units.parse("360 kmph", "speed", "k")[0] == pytest.approx(100.0, rel=1e-15)


@pytest.mark.parametrize("content", [b"not json {", b"\x00\xff" * 10, b"[]", b'{"stamp": 1}',
                                     b'{"stamp": [1, "0.0.0", "/elsewhere/pint", 0], '
                                     b'"parse": {"rpm\\u001frate\\u001f0": [1e9, "rpm", false]}}'])
def test_a_damaged_or_foreign_cache_is_ignored_and_rebuilt(fresh, content):
    (fresh / "units.json").write_bytes(content)
    value, _ = units.parse("60 rpm", "rate", "k")     # pint's answer, not the file's 1e9
    assert value == pytest.approx(2 * 3.141592653589793, rel=1e-15)
    unit_cache.save()
    data = json.loads((fresh / "units.json").read_text())
    assert data["stamp"] == unit_cache.stamp()
    assert data["parse"]["rpm\x1frate\x1f0"][0] == pytest.approx(2 * 3.141592653589793 / 60)
    assert not [p for p in fresh.iterdir() if p.suffix == ".tmp"]


def test_cache_switched_off_writes_nothing(tmp_path, monkeypatch):
    monkeypatch.setenv("GYRO_CACHE_DIR", "")
    monkeypatch.setattr(units, "_CHECKED", {})
    unit_cache.forget()
    units.parse("3 furlong", "length", "k")
    unit_cache.save()
    assert unit_cache.path() is None
    unit_cache.forget()


def _gyro(args, cache, code="from gyro_cli.cli import main; main()"):
    env = dict(os.environ, GYRO_CACHE_DIR=str(cache))
    return subprocess.run([sys.executable, "-c", code, *args], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=300)


@pytest.mark.slow  # fresh interpreters: `make test-slow`
def test_empty_and_warm_cache_print_byte_identical_output(tmp_path):
    files = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "problems").glob("*.yaml"))
    runs = []
    for _ in range(2):                       # the first fills the cache, the second reads it
        text = _gyro(["solve", *files], tmp_path)
        js = _gyro(["solve", "--format", "json", *files], tmp_path)
        runs.append((text.returncode, text.stdout, text.stderr, js.stdout))
    assert (tmp_path / "units.json").exists()
    assert runs[0] == runs[1]


@pytest.mark.slow  # fresh interpreters: `make test-slow`
def test_warm_solve_kinds_and_help_import_neither_pint_nor_numpy(tmp_path):
    probe = ("import sys\nfrom gyro_cli.cli import main\ntry:\n    main()\nexcept SystemExit:\n"
             "    pass\nprint(sorted(m for m in ('pint', 'numpy', 'scipy', 'matplotlib') "
             "if m in sys.modules), file=sys.stderr)")
    _gyro(["solve", "problems/11_3.yaml"], tmp_path)            # fills the cache
    for args in (["solve", "problems/11_3.yaml"], ["kinds"], ["--help"]):
        run = _gyro(args, tmp_path, probe)
        assert run.stderr.strip().splitlines()[-1] == "[]", (args, run.stderr)


@pytest.mark.slow  # fresh interpreters: `make test-slow`
def test_warm_bicycle_solve_imports_no_numpy(tmp_path):
    """The bicycle's eigenvalues and speeds are pure Python: a warm solve loads no numpy."""
    probe = ("import sys\nfrom gyro_cli.cli import main\ntry:\n    main()\nexcept SystemExit:\n"
             "    pass\nprint(sorted(m for m in ('pint', 'numpy', 'scipy', 'matplotlib') "
             "if m in sys.modules), file=sys.stderr)")
    args = ["solve", "problems/bicycle_benchmark.yaml"]
    first = _gyro(args, tmp_path, probe)                      # fills the cache
    assert first.returncode == 0, first.stderr
    run = _gyro(args, tmp_path, probe)
    assert run.returncode == 0, run.stderr
    assert "v_w" in run.stdout and "motion" in run.stdout
    assert run.stderr.strip().splitlines()[-1] == "[]", run.stderr


def test_the_test_runs_own_cache_is_removed_when_its_process_ends():
    """tests/conftest.py's cache folder goes with the process that made it (every `make
    test` left three behind), and not with a child forked by a test, which ends first."""
    script = """
import os, sys
sys.path.insert(0, "tests")
import conftest
child = os.fork()
if child == 0:
    sys.exit(0)  # the child's exit handlers run, with the parent's cleanup among them
os.waitpid(child, 0)
print(conftest.TEST_CACHE, os.path.isdir(conftest.TEST_CACHE))
"""
    done = subprocess.run([sys.executable, "-c", script], cwd=ROOT, capture_output=True,
                          text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    cache, there = done.stdout.split()
    assert there == "True"  # kept while the process that made it runs
    assert Path(cache).name.startswith("gyro-test-cache-") and not Path(cache).exists()
