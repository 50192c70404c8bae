"""`gyro check` on a large bank: streamed reports, --jobs, --timeout, --shard and --merge.

Independent references: the in-process run of one job is the reference for any
number of workers (the outputs must be the same bytes); the whole run is the
reference for its shards (each file in exactly one shard, the merged reports the
same bytes as the whole); the JSON stream is compared with ``json.dumps`` of the
whole document; a crash and a hang are injected into one file of a batch.
"""

from __future__ import annotations

import faulthandler
import json
import os
import shutil
import signal
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from conftest import PROBLEMS
from test_check import GYRO_PRECESSION, gyro_file, put

from gyro_cli.checking import check
from gyro_cli.checking.results import CheckRun
from gyro_cli.core.errors import InputError
from gyro_cli.render import check_report, junit


@pytest.fixture(scope="module")
def bank(tmp_path_factory) -> Path:
    """Every bundled problem twice, in two folders, plus a failing answer, a bad file
    and a problem without expected answers: every kind of entry a report has."""
    root = tmp_path_factory.mktemp("bank")
    for copy in ("a", "b"):
        shutil.copytree(PROBLEMS, root / copy)
    put(root, "a/wrong.yaml", gyro_file(f"precession: {GYRO_PRECESSION * 10:.6g} rad/s\n"))
    put(root, "b/bad.yaml", gyro_file("precession: 3 m\n"))
    put(root, "b/unkeyed.yaml", gyro_file())
    return root


def _outputs(run, bank: Path, tmp: Path, *options: str) -> tuple:
    """(exit code, table, stderr, JSON, JUnit bytes) of one configuration."""
    name = "-".join(o.replace("/", "of") for o in options) or "plain"
    table = run("check", bank, "--junit", tmp / f"{name}.xml", *options)
    document = run("check", bank, "--format", "json", *options)
    assert document.exit_code == table.exit_code
    return (table.exit_code, table.stdout, table.stderr, document.stdout,
            (tmp / f"{name}.xml").read_bytes())


def test_jobs_1_and_jobs_4_write_the_same_table_json_and_junit(run, bank, tmp_path):
    one = _outputs(run, bank, tmp_path, "--jobs", "1")
    four = _outputs(run, bank, tmp_path, "--jobs", "4")
    assert one[0] == 2  # the bad file
    assert one == four
    files = [p["file"] for p in json.loads(one[3])["problems"]]
    assert files == sorted(files) and len(files) == 2 * len(list(PROBLEMS.glob("*.yaml"))) + 3
    assert one[2].splitlines() == [line for line in one[2].splitlines() if "bad.yaml" in line]


def test_shards_cover_the_whole_once_and_merge_back_to_it(run, bank, tmp_path):
    whole = _outputs(run, bank, tmp_path, "--jobs", "2")
    reports, seen = [], []
    for k in (1, 2, 3):
        shard = run("check", bank, "--format", "json", "--shard", f"{k}/3")
        assert shard.exit_code in (0, 1, 2)
        document = json.loads(shard.stdout)
        assert document["summary"]["shard"] == f"{k}/3"
        seen += [p["file"] for p in document["problems"]]
        reports.append(tmp_path / f"shard{k}.json")
        reports[-1].write_text(shard.stdout)
    whole_files = [p["file"] for p in json.loads(whole[3])["problems"]]
    assert sorted(seen) == whole_files  # each file in exactly one shard
    assert all(len(json.loads(r.read_text())["problems"]) > 10 for r in reports)  # spread
    merged_table = run("check", "--merge", *reports, "--junit", tmp_path / "merged.xml")
    merged_json = run("check", "--merge", *reports, "--format", "json")
    assert merged_table.exit_code == merged_json.exit_code == whole[0]
    assert merged_table.stdout == whole[1]
    assert merged_json.stdout == whole[3]
    assert (tmp_path / "merged.xml").read_bytes() == whole[4]
    # the shard of a path is a property of the path alone
    assert check.shard_of("sets/a/11_3.yaml", 3) == check.shard_of("./sets/a/11_3.yaml", 3)


def test_merge_refuses_an_incomplete_set_of_shards_and_other_files(run, bank, tmp_path):
    shard = run("check", bank, "--format", "json", "--shard", "2/3")
    report = tmp_path / "shard2.json"
    report.write_text(shard.stdout)
    missing = run("check", "--merge", report)
    assert missing.exit_code == 2
    assert missing.stderr.splitlines() == [
        "gyro: the reports are shards 2/3; expected each shard K/N of one N exactly once "
        "(1/3, 2/3, 3/3)"]
    not_json = run("check", "--merge", PROBLEMS / "11_3.yaml")
    assert not_json.exit_code == 2 and len(not_json.stderr.splitlines()) == 1
    assert "is not a JSON report of `gyro check --format json`" in not_json.stderr
    assert "Traceback" not in not_json.output


@pytest.mark.parametrize("shard", ["0/3", "4/3", "x", "1/0", "2"])
def test_a_malformed_shard_is_one_line_and_exit_2(run, shard):
    result = run("check", PROBLEMS, "--shard", shard)
    assert result.exit_code == 2
    assert result.stderr.splitlines() == [
        f"gyro: --shard {shard!r}: expected K/N with 1 <= K <= N, e.g. 2/4"]
    assert result.stdout == ""


def test_the_json_stream_is_one_document_with_a_line_per_problem(bank):
    files, missing = check.collect([str(bank), str(bank / "nothing-here" / "*.yaml")])
    assert missing  # a pattern that matches nothing is an entry too
    run_ = CheckRun(missing + [check.check_file(f) for f in files])
    text = check_report.as_json(run_)
    document = check_report.as_dict(run_)
    assert json.loads(text) == json.loads(json.dumps(check_report._finite(document)))
    lines = text.splitlines()
    assert len(lines) == 1 + len(run_.problems) + 2  # head, problems, "]," and the summary
    assert [json.loads(line.rstrip(","))["file"] for line in lines[1:-2]] \
        == [p.file for p in run_.problems]
    assert json.loads(lines[-1].removeprefix('"summary": ')[:-1]) == document["summary"]
    empty = json.loads(check_report.as_json(CheckRun([])))
    assert empty["problems"] == [] and empty["summary"]["exit_code"] == 1


def test_results_are_handed_on_before_the_last_file_is_checked(monkeypatch, bank):
    """Streaming: the first result is out while later files are still to be checked."""
    files = check.collect([str(bank / "a")])[0][:6]
    started: list[str] = []
    real = check.check_file

    def logged(path, strict=False):
        started.append(path)
        return real(path, strict)

    monkeypatch.setattr(check, "check_file", logged)
    stream = check.checks(files, jobs=1)
    first = next(stream)
    assert first.file == files[0] and started == files[:1]
    assert [p.file for p in stream] == files[1:]


def _steady_bank(tmp_path: Path, count: int) -> list[str]:
    """``count`` copies of problem 11/3 (a steady precession: no scipy, milliseconds)."""
    for i in range(count):
        shutil.copy(PROBLEMS / "11_3.yaml", tmp_path / f"p{i:02d}.yaml")
    return check.collect([str(tmp_path)])[0]


def test_a_file_that_kills_its_worker_costs_only_that_file(monkeypatch, tmp_path, run):
    files = _steady_bank(tmp_path, 7)
    real = check.check_file

    def crashing(path, strict=False):
        if path.endswith("p03.yaml"):
            faulthandler.disable()  # pytest's dump of the stack: not needed here
            os.kill(os.getpid(), signal.SIGSEGV)  # what a crash in compiled code does
        return real(path, strict)

    monkeypatch.setattr(check, "check_file", crashing)
    result = run("check", tmp_path, "--jobs", "3", "--format", "json")
    assert result.exit_code == 3
    problems = json.loads(result.stdout)["problems"]
    assert [p["file"] for p in problems] == files
    assert [p["status"] for p in problems] == ["pass"] * 3 + ["error"] + ["pass"] * 3
    assert problems[3]["internal"] is True
    line = (f"gyro: {files[3]}: internal error: the worker process checking it died "
            "(killed by signal 11) (please report)")
    assert result.stderr.splitlines() == [line]


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_file_that_hangs_is_stopped_at_the_time_limit(monkeypatch, tmp_path, run, jobs):
    files = _steady_bank(tmp_path, 4)
    real = check.check_file
    real(files[0])  # warm (units, kinds): the limit then times the files, not a cold start

    def hanging(path, strict=False):
        if path.endswith("p01.yaml"):
            time.sleep(120)
        return real(path, strict)

    monkeypatch.setattr(check, "check_file", hanging)
    start = time.monotonic()
    result = run("check", tmp_path, "--jobs", jobs, "--timeout", "1", "--junit",
                 tmp_path / "out.xml")
    assert time.monotonic() - start < 60
    assert result.exit_code == 3
    assert result.stderr.splitlines() == [
        f"gyro: {files[1]}: internal error: took longer than the time limit of 1 s per file "
        "(--timeout); stopped (please report)"]
    assert result.stdout.count("  PASS  ") == 3 * 3  # the other files: two roots, min_spin
    root = ET.parse(tmp_path / "out.xml").getroot()
    assert [e.get("type") for e in root.iter("error")] == ["InternalError"]


@pytest.mark.parametrize("how", ["crash", "hang"])
def test_the_failed_file_is_found_inside_a_batch(monkeypatch, tmp_path, how):
    """Workers reply once per batch (pool.BATCH files): a crash or a hang in the middle
    of a batch is still laid at its own file, the files before it in the batch (checked,
    their reply lost with the worker) and after it are checked again, each once in the
    output, in order."""
    files = _steady_bank(tmp_path, 40)  # 2 jobs: batches of 10 files
    bad = files[13]  # the fourth file of the second batch
    real = check.check_file
    real(files[0])  # warm (units, kinds): the limit then times the files, not a cold start

    def failing(path, strict=False):
        if path == bad:
            if how == "crash":
                faulthandler.disable()
                os.kill(os.getpid(), signal.SIGSEGV)
            time.sleep(120)
        return real(path, strict)

    monkeypatch.setattr(check, "check_file", failing)
    results = list(check.checks(files, jobs=2, timeout=1 if how == "hang" else 60))
    assert [p.file for p in results] == files
    assert [p.file for p in results if p.status != "pass"] == [bad]
    assert results[13].internal
    assert ("died (killed by signal 11)" if how == "crash" else "time limit of 1 s") \
        in results[13].error


def test_junit_spool_is_the_document_of_the_whole_run(bank):
    """The spooled JUnit parses, and its totals are the sums over its suites."""
    files = check.collect([str(bank / "b")])[0]
    text = junit.xml(CheckRun([check.check_file(f) for f in files]))
    root = ET.fromstring(text.encode("utf-8"))
    suites = root.findall("testsuite")
    assert len(suites) == len(files)
    for key in ("tests", "failures", "errors", "skipped"):
        assert int(root.get(key)) == sum(int(s.get(key)) for s in suites)
    assert root.get("errors") == "1" and root.get("skipped") == "1"


# ---- less per file: the loader composes first when no anchor can expand ------

def _both_ways(monkeypatch, text: str):
    """(outcome with the event prescan, outcome composing first): data or the message."""
    import yaml

    from gyro_cli.core import safeyaml

    outcomes = []
    for compose_first in (False, True):
        monkeypatch.setattr(safeyaml, "_COMPOSE_FIRST", compose_first)
        try:
            data, node = safeyaml.load(text)
            outcomes.append(("data", data, node.start_mark.line if node is not None else None))
        except (InputError, yaml.YAMLError) as err:
            outcomes.append(("error", type(err).__name__, str(err)))
    return outcomes


#: the limit of values the refusals below are tried at (safeyaml.MAX_NODES, 100,000, lowered:
#: both ways read it where they compare, and lists of 100,000 values took seconds to parse)
LIMIT = 1_000

HOSTILE = {
    "deep flow": "a: " + "[" * 65 + "]" * 65 + "\n",
    "deep flow past libyaml's limit": "a: " + "[" * 5000 + "]" * 5000 + "\n",
    "deep block": "".join("  " * i + f"k{i}:\n" for i in range(70)) + "  " * 70 + "x: 1\n",
    "at the limit": "a: " + "[" * 63 + "]" * 63 + "\n",
    "too many values": "a: [" + ", ".join(["1"] * (LIMIT + 1)) + "]\n",
    "just enough values": "a: [" + ", ".join(["1"] * (LIMIT - 3)) + "]\n",
    "deep and long": "b: [" + ", ".join(["1"] * (LIMIT + 500)) + "]\na: " + "[" * 70 + "]" * 70,
    "undefined alias": "a: *x\n",
    "malformed": "a: [1, 2\nb: c\n",
    "empty": "",
    "a scalar": "just words\n",
    "an ampersand in prose": "source: Meijaard, Papadopoulos, Ruina & Schwab (2007)\nb: [a &]\n",
    "an anchor without a name": "b: [&]\n",
    "an anchor after prose": "source: Ruina & Schwab\nb: &x [1, 2]\nc: *x\n",
    "a cycle": "x: &a [1, *a]\n",
}


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_composing_first_refuses_what_the_event_walk_refuses(monkeypatch, name):
    from gyro_cli.core import safeyaml

    monkeypatch.setattr(safeyaml, "MAX_NODES", LIMIT)
    with_prescan, composed = _both_ways(monkeypatch, HOSTILE[name])
    assert with_prescan == composed
    refused = {"deep flow", "deep flow past libyaml's limit", "deep block", "too many values",
               "deep and long", "undefined alias", "malformed", "a cycle",
               "an anchor without a name"}
    assert (composed[0] == "error") == (name in refused), composed


def test_composing_first_reads_every_bundled_problem_alike(monkeypatch):
    from gyro_cli.core import safeyaml

    assert safeyaml._nests_itself()  # the installed libyaml bounds nesting (0.2.6+)
    for path in sorted(PROBLEMS.glob("*.yaml")):
        with_prescan, composed = _both_ways(monkeypatch, path.read_text())
        assert with_prescan == composed and with_prescan[0] == "data", path


@pytest.mark.slow  # fresh interpreters: `make test-slow`
def test_a_warm_check_of_every_bundled_problem_imports_no_pint(tmp_path):
    """A unit of three names (`kg m^2/s`, in find and expected) was asked of pint name by
    name on every run, so each process (each worker) paid pint's import for it."""
    import subprocess
    import sys

    probe = ("import sys\nfrom gyro_cli.cli import main\ntry:\n    main()\nexcept SystemExit:\n"
             "    pass\nprint('pint' in sys.modules, file=sys.stderr)")
    env = dict(os.environ, GYRO_CACHE_DIR=str(tmp_path))
    runs = [subprocess.run([sys.executable, "-c", probe, "check", "--jobs", "1", str(PROBLEMS)],
                           env=env, capture_output=True, text=True, timeout=300)
            for _ in range(2)]  # the first fills the unit table, the second reads it
    assert [r.returncode for r in runs] == [0, 0], runs[0].stderr
    assert runs[0].stdout == runs[1].stdout
    assert runs[1].stderr.splitlines()[-1] == "False"


def _scan_as_it_was(m, g, r, J, I, speed, path_radius):
    """free_from_speed_and_path before it was made faster: free_residual called at every
    point of the grid (the reference for 'the same answers, bit for bit'). Each tilt found
    is refined as the module refines it (`_bisected`, `_tiny_tilt`): the scan is what is
    compared."""
    import math

    from gyro_cli.kinds.rolling_disk import _bisected, _tiny_tilt, free_residual, free_state

    top = math.pi / 2 if path_radius >= r else math.asin(path_radius / r)

    def f(tilt):
        return free_residual(m, g, r, J, I, tilt, path_radius - r * math.sin(tilt), speed)

    n = 4000
    fine = [top / n * 10 ** (-k / 8) for k in range(96, 0, -1)]
    grid = fine + [top * i / n for i in range(1, n)]
    roots = []
    values = [f(t) for t in grid]
    if f(0.0) < 0 < values[0]:
        roots.append(_tiny_tilt(f, grid[0]))
    for (t0, f0), (t1, f1) in zip(zip(grid, values), zip(grid[1:], values[1:])):
        if f0 == 0:
            roots.append(t0)
        elif f0 * f1 < 0:
            roots.append(_bisected(f, t0, t1, f0))
    return [free_state(m, r, t, path_radius - r * math.sin(t), speed) for t in roots]


def test_the_rolling_disks_faster_scan_finds_the_same_tilts_bit_for_bit():
    import random

    from gyro_cli.kinds.rolling_disk import free_from_speed_and_path

    rng = random.Random(26)
    found = set()
    for _ in range(60):
        m, r = 10 ** rng.uniform(-2, 2), 10 ** rng.uniform(-2, 0.5)
        J = m * r * r * rng.uniform(0.2, 1.0)
        I = J * rng.uniform(0.3, 1.0)
        speed, path = 10 ** rng.uniform(-2, 1.5), r * 10 ** rng.uniform(-1, 3)
        states = free_from_speed_and_path(m, 9.81, r, J, I, speed, path)
        assert states == _scan_as_it_was(m, 9.81, r, J, I, speed, path)
        found.add(len(states))
    assert found >= {0, 1, 2}  # no tilt, one, and two (a slow and a fast one)


@pytest.mark.slow  # fresh interpreters: `make test-slow`
def test_a_checks_workers_import_nothing_after_warming_and_never_numpy(tmp_path):
    """What checking needs is loaded once, before the workers are forked (check.warm), and
    it is the standard library alone: checking every bundled problem (every kind, every
    arrangement) and writing its reports imports no module of gyro's after that, and
    numpy (about 45 ms of start-up, a twentieth of a bank's check) not at all. Once the
    unit cache is warm: a first run, on a cache of its own, fills it (the test does not
    lean on what tests before it left in the run's cache)."""
    import subprocess
    import sys

    probe = """
import glob, sys
from gyro_cli.checking import check
from gyro_cli.render import check_report, junit  # as the command imports them
check.warm()
before = set(sys.modules)
for path in sorted(glob.glob(sys.argv[1] + '/**/*.yaml', recursive=True)):
    check_report.printed(check.check_file(path), 'json', True)
    check_report.printed(check.check_file(path), 'table', False)
new = sorted(set(sys.modules) - before)
print(' '.join(m for m in new if m.startswith(('gyro_cli', 'numpy', 'scipy', 'pint'))))
"""
    env = dict(os.environ, GYRO_CACHE_DIR=str(tmp_path / "cache"))
    for _ in range(2):  # the first run fills the unit cache
        run = subprocess.run([sys.executable, "-c", probe, str(PROBLEMS)], capture_output=True,
                             text=True, timeout=300, env=env)
        assert run.returncode == 0, run.stderr
    assert run.stdout.split() == []


def _root_counts_change(m, r, J, I, path, slow, fast):
    """A speed between ``slow`` and ``fast`` (different numbers of tilts) where the number
    of tilts changes, found by halving: there two tilts meet (the residual touches 0)."""
    from gyro_cli.kinds.rolling_disk import free_from_speed_and_path

    count = len(free_from_speed_and_path(m, 9.81, r, J, I, slow, path))
    for _ in range(60):
        mid = (slow * fast) ** 0.5
        if len(free_from_speed_and_path(m, 9.81, r, J, I, mid, path)) == count:
            slow = mid
        else:
            fast = mid
    return slow, fast


@pytest.mark.property  # `make props`: ten times the cases
def test_the_scan_finds_the_same_tilts_where_two_tilts_meet_and_where_it_halves_most():
    """Where the scan gains most (it skips stretches of the grid on which the residual
    cannot reach 0), it is tried hardest: at speeds where two tilts meet (the residual
    touches 0 between two points of the grid, or on one), bracketed to the last bits of
    the speed, and with the contact circle as large as the disk (the residual is nearly 0
    over a wide range of tilts). The tilts are those of evaluating every point."""
    import math
    import random

    from conftest import examples

    from gyro_cli.kinds import rolling_disk as rd

    rng = random.Random(2611)
    cases = 0
    while cases < examples(20):  # 40 before the suite's budget was cut (issue 37)
        m, r = 10 ** rng.uniform(-2, 2), 10 ** rng.uniform(-2, 0.5)
        J = m * r * r * rng.uniform(0.2, 1.0)
        I = J * rng.uniform(0.3, 1.0)
        path = r * (rng.uniform(0.98, 1.02) if cases % 4 == 0 else 10 ** rng.uniform(-1, 3))
        speeds = [10 ** (k / 4) for k in range(-12, 7)]
        counts = [len(rd.free_from_speed_and_path(m, 9.81, r, J, I, v, path)) for v in speeds]
        changes = [k for k in range(len(speeds) - 1) if counts[k] != counts[k + 1]]
        if not changes:
            continue
        cases += 1
        k = rng.choice(changes)
        slow, fast = _root_counts_change(m, r, J, I, path, speeds[k], speeds[k + 1])
        for speed in (slow, fast, math.nextafter(slow, 0), math.nextafter(fast, math.inf),
                      speeds[k], speeds[k + 1]):
            assert rd.free_from_speed_and_path(m, 9.81, r, J, I, speed, path) == \
                _scan_as_it_was(m, 9.81, r, J, I, speed, path), (m, r, J, I, speed, path)


def test_the_scan_evaluates_a_few_points_for_a_book_disk():
    """The point of the halving: for a coin rolling on a circle of a metre at a few metres
    per second the residual is far from 0 except near its one root, and the scan evaluates
    it at some tens of points of the 4095 (the vectorised scan evaluated them all)."""
    import math

    from gyro_cli.kinds import rolling_disk as rd

    calls = []

    def counted(grid, f, slope, slack):  # type: ignore[no-untyped-def]
        return rd_sign_changes(grid, lambda t: calls.append(t) or f(t), slope, slack)

    rd_sign_changes = rd._sign_changes
    m, r = 0.0081, 0.0121  # a coin: 8.1 g, 24.2 mm across
    J = m * r * r / 2
    try:
        rd._sign_changes = counted
        states = rd.free_from_speed_and_path(m, 9.81, r, J, J / 2, 1.5, 1.0)
    finally:
        rd._sign_changes = rd_sign_changes
    assert len(states) == 1 and 0 < len(calls) <= 60, len(calls)
    # tan(beta) ~ 3 v^2 / (2 g rho) for a thin disk on a large circle (the module's note)
    assert math.tan(states[0].tilt) == pytest.approx(3 * 1.5 ** 2 / (2 * 9.81 * 1.0), rel=0.02)


def test_the_spooled_junit_is_what_elementtree_writes_for_awkward_text():
    """The spool writes each suite itself; ElementTree's own serializer is the reference."""
    from gyro_cli.checking.results import AnswerCheck, ProblemCheck

    awkward = 'a&b <c> "d" \'e\' \r\n\tf ü 中 ]]> \x01'
    problems = [
        ProblemCheck(f"dir/{awkward}.yaml", awkward, awkward, "steady_precession", status="fail",
                     answers=[AnswerCheck("precession", 1, awkward, awkward, False,
                                          message=f"expected {awkward}; off by", slip=awkward),
                              AnswerCheck("moment", None, "1 N m", "1 N m", True)]),
        ProblemCheck("bad.yaml", status="error", error=awkward, internal=True),
        ProblemCheck("none.yaml", "x", status="no expected answers"),
    ]
    spool = junit.Spool()
    for problem in problems:
        spool.add(problem)
    text = b"".join(spool.chunks()).decode("utf-8")
    root = ET.Element("testsuites", name="gyro check")
    for key, value in (("tests", "4"), ("failures", "1"), ("errors", "1"), ("skipped", "1"),
                       ("time", "0")):
        root.set(key, value)
    for problem in problems:
        root.append(junit.suite(problem))
    ET.indent(root)
    assert text == ('<?xml version="1.0" encoding="UTF-8"?>\n'
                    + ET.tostring(root, encoding="unicode") + "\n")
    assert ET.fromstring(text.encode("utf-8")).find(".//failure").get("message").startswith(
        "expected a&b <c>")


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_report_that_fails_to_print_costs_only_its_file(monkeypatch, tmp_path, run, jobs):
    """The report text is made where a file is checked (a worker): a bug there is that
    file's internal error, in one line, and the others are reported."""
    from gyro_cli.render import check_report

    files = _steady_bank(tmp_path, 3)
    real = check_report.json_line

    def failing(problem):
        if problem.file.endswith("p01.yaml") and problem.status == "pass":
            raise RuntimeError("no report")
        return real(problem)

    monkeypatch.setattr(check_report, "json_line", failing)
    result = run("check", tmp_path, "--jobs", jobs, "--format", "json")
    assert result.exit_code == 3
    problems = json.loads(result.stdout)["problems"]
    assert [p["status"] for p in problems] == ["pass", "error", "pass"]
    assert result.stderr.splitlines() == [
        f"gyro: {files[1]}: internal error: RuntimeError: no report (please report)"]


@pytest.mark.parametrize("timeout", [60.0, None])
def test_one_job_flushes_each_report_before_checking_the_next_file(monkeypatch, timeout):
    """In one process the caller's ``idle`` (which flushes the report so far) runs before
    each file but the first, so a file's line is out before the next file is checked (and
    before a hang there runs out its time limit); and the alarm's handler is the caller's
    again once the run ends."""
    import signal

    files = [str(p) for p in sorted(PROBLEMS.glob("11_*.yaml"))[:4]]
    flushes, seen = [], []
    real = check.check_file
    monkeypatch.setattr(check, "check_file",
                        lambda path, strict=False: seen.append(len(flushes)) or real(path, strict))
    before = signal.getsignal(signal.SIGALRM)
    results = list(check.checks(files, jobs=1, timeout=timeout,
                                idle=lambda: flushes.append(1)))
    assert [r.file for r in results] == files
    assert seen == [0, 1, 2, 3]
    assert signal.getsignal(signal.SIGALRM) is before
