"""`gyro check`, the runner: solve problem files and compare with their `expected` answers.

The pure parts live beside it: tolerances (``tolerance.py``), expected values
(``expected.py``), root matching and slip diagnosis (``matching.py``), the
results as data (``results.py``). ``check_file`` loads, solves and compares one
file; ``checks`` hands on each file's ProblemCheck in order as soon as it is
known, from this process or from forked workers (``pool.py``), so the command
streams its reports (render/: ``check_report.py`` table and JSON, ``junit.py``)
and keeps only a Tally; ``shard_of`` and ``merged`` split a bank over CI jobs
and join their JSON reports. ``run`` keeps every result (the Python API).

Rules (see docs/check.md):
- dimensions are checked before magnitudes: an expected value in the wrong
  dimension is an error in the file (exit 2), not a failed answer;
- tolerance ``"1%"`` relative, ``"3 sig"`` significant figures of the expected
  value as written, or a quantity (``"0.01 rad/s"``) absolute; one for the file
  or a mapping answer -> tolerance (``default:`` for the rest); default 1%;
- roots match as sets: each expected value to its nearest computed root, none
  used twice; a computed root no expected value claims fails, and so does an
  expected value left without a root.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Generator, Iterator
from typing import Any

from ..core.errors import InputError
from .expected import Expected, answer_signs, parse_expected
from .matching import compare
from .results import CheckRun, ProblemCheck
from .tolerance import Tolerance, tolerance_for, validate_tolerance

# ---- the runner -------------------------------------------------------------

def collect(paths: list[str] | tuple[str, ...],
            found: tuple[list[str], list[tuple[str, str]]] | None = None,
            ) -> tuple[list[str], list[ProblemCheck]]:
    """Problem files from files, directories and globs (solving.paths), with each path
    that names nothing as an error entry. ``found``: ``problem_files(paths)`` if the
    caller has it already."""
    from ..solving.paths import problem_files

    files, missing = found if found is not None else problem_files(paths)
    return files, [ProblemCheck(path, status="error", error=message) for path, message in missing]


def check_problem(problem: Any, strict: bool = False) -> ProblemCheck:
    """Solve one loaded problem and compare every expected answer; InputError if bad.

    ``strict``: every computed root must be keyed (else a root the key does not
    quote is reported as not keyed and does not fail).
    """
    from ..solving.solve import solve_asking

    kind = problem.kind
    result = ProblemCheck(problem.file, problem.id, problem.title, kind.name)
    answer_names = [a.name for a in kind.answers]
    # Validate everything in the file before solving: a bad key is exit 2 either way.
    validate_tolerance(problem.tolerance, kind)
    wanted: dict[str, tuple[list[Expected], Tolerance]] = {}
    step_values: dict[str, Any] = {}
    for name, raw in problem.expected.items():
        if name == "steps" and kind.answer("steps") is None:
            step_values = step_values | raw
            continue
        if kind.answer(name) is None and name in problem.steps:  # a step asked (`steps:`)
            step_values = step_values | {name: raw}
            continue
        spec = kind.answer(name)
        dimension = spec.dimension
        values = parse_expected(raw, dimension, f"expected.{name}", spec.sides, spec.signs)
        wanted[name] = (values, tolerance_for(problem.tolerance, name, dimension, answer_names))
    # Solved even without expected answers: a file that cannot be solved is a bad file.
    solved = solve_asking(problem, wanted)  # each expected answer asked for too, in SI
    if problem.steps:  # steps asked (`steps:`): each a step of the worked answer
        from .ecf import check_steps

        check_steps(problem, solved)
    result.warnings = list(solved.solution.warnings)
    if not wanted and not step_values:
        result.status = "no expected answers"
        return result
    for name, (values, tolerance) in wanted.items():
        spec, reported = kind.answer(name), solved.answers[name]
        signs = answer_signs(spec, reported)
        if signs != spec.signs:  # words the kind reads that sign nothing in this problem
            values = parse_expected(problem.expected[name], spec.dimension, f"expected.{name}",
                                    spec.sides, signs)
        result.answers += compare(name, values, tolerance, reported, strict=strict,
                                  convention=spec.doc, signs=signs)
    for symbol, raw in step_values.items():
        result.answers += _compare_step(str(symbol), raw, problem, solved.solution, answer_names)
    result.status = "pass" if all(a.passed for a in result.answers) else "fail"
    return result


def _compare_step(symbol: str, raw: Any, problem: Any, solution: Any,
                  answer_names: list[str]) -> list:
    """`expected.steps.<symbol>`: an intermediate value of the worked answer, graded as an
    answer is (the file's tolerance, or its `default:`)."""
    from types import SimpleNamespace

    key = f"expected.steps.{symbol}"
    from ..solving.deps import graded_steps

    steps = graded_steps(solution)
    if symbol not in steps:
        from ..solving.problem import suggest

        raise InputError(f"no step of the worked answer gives {symbol!r} in SI"
                         f"{suggest(symbol, list(steps))} (steps: {', '.join(steps)})", key=key)
    value, unit, dimension = steps[symbol]
    values = parse_expected(raw, dimension, key)
    spec = problem.tolerance
    if isinstance(spec, dict):
        spec = spec.get("default")
    tolerance = tolerance_for(spec, symbol, dimension, answer_names)
    reported = SimpleNamespace(si_values=[value], si_unit=unit, unit=unit, labels=[])
    return compare(f"steps.{symbol}", values, tolerance, reported, strict=True)


def check_file(path: str, strict: bool = False) -> ProblemCheck:
    """Load, solve and compare one file; a bad file comes back with status error."""
    from ..solving.problem import load

    problem = None
    try:
        problem = load(path)
        return check_problem(problem, strict=strict)
    except InputError as err:
        if problem is not None:
            err.located(file=problem.file, line=problem.line(err.key))
        error = str(err)
        internal = False
    except Exception as err:  # a bug in gyro: this file is an error, the next goes on
        from ..core.errors import internal_message

        if os.environ.get("GYRO_DEBUG"):
            import traceback

            traceback.print_exception(err)
        error = internal_message(path, err)
        internal = True
    if problem is None:
        return ProblemCheck(path, status="error", error=error, internal=internal)
    return ProblemCheck(path, str(problem.id), str(problem.title), problem.kind.name,
                        status="error", error=error, internal=internal)


def run(paths: list[str] | tuple[str, ...], strict: bool = False) -> CheckRun:
    """Check every problem file under ``paths``, all in this process."""
    files, errors = collect(paths)
    return CheckRun(errors + list(checks(files, strict, timeout=None)), strict=strict)


# ---- sharding: a stable part of the files for one job of a CI matrix --------

def shard_of(path: str, count: int) -> int:
    """Which of ``count`` shards (1..count) a path belongs to: CRC-32 of the path as
    written (normalised, with forward slashes), the same on every machine and run."""
    import zlib

    key = os.path.normpath(path).replace(os.sep, "/")
    return zlib.crc32(key.encode("utf-8", "surrogateescape")) % count + 1


def parse_shard(text: str) -> tuple[int, int]:
    """``"K/N"`` -> (K, N) with 1 <= K <= N; InputError otherwise."""
    k, _, n = text.partition("/")
    try:
        shard, count = int(k), int(n)
    except ValueError:
        shard = count = 0
    if not (1 <= shard <= count):
        raise InputError(f"--shard {text!r}: expected K/N with 1 <= K <= N, e.g. 2/4")
    return shard, count


def merged(reports: list[str] | tuple[str, ...], strict: bool = False) -> Iterator[ProblemCheck]:
    """The problems of several JSON reports (``--format json``, one per shard) as one run,
    in path order. InputError for a file that is not such a report, or for shards that
    do not make a whole (each K of N exactly once)."""
    import json

    from ..core.safeyaml import read_text
    from .results import ProblemCheck

    problems: list[ProblemCheck] = []
    shards: list[str] = []
    for path in reports:
        text = read_text(path, 1 << 31, "a JSON report of gyro check")
        try:
            document = json.loads(text)
            summary = document["summary"]
            problems += [ProblemCheck.from_dict(p) for p in document["problems"]]
        except (ValueError, KeyError, TypeError) as err:
            raise InputError("is not a JSON report of `gyro check --format json` "
                             f"({type(err).__name__}: {err})", file=path) from None
        if isinstance(summary, dict) and summary.get("shard"):
            shards.append(str(summary["shard"]))
    if shards:
        counts = {s.partition("/")[2] for s in shards}
        whole = [f"{k}/{n}" for n in counts for k in range(1, int(n) + 1)] \
            if len(counts) == 1 and next(iter(counts)).isdigit() else []
        if len(shards) != len(reports) or sorted(shards) != sorted(whole):
            raise InputError(f"the reports are shards {', '.join(sorted(shards)) or 'none'}; "
                             "expected each shard K/N of one N exactly once "
                             f"({', '.join(whole) or 'K/N'})")
    problems.sort(key=lambda p: p.file)
    return iter(problems)


# ---- the run, file by file, in order ---------------------------------------

TIMEOUT = 60.0  # seconds per file; a file takes milliseconds


def timed_out(path: str, timeout: float) -> ProblemCheck:
    """The entry of a file stopped at the time limit (a solver that does not end is a bug)."""
    return ProblemCheck(path, status="error", internal=True,
                        error=f"{path}: internal error: took longer than the time limit of "
                              f"{timeout:g} s per file (--timeout); stopped (please report)")


def crashed(path: str, exitcode: int | None) -> ProblemCheck:
    """The entry of a file whose worker process died (a crash in compiled code)."""
    how = f"killed by signal {-exitcode}" if exitcode and exitcode < 0 else \
        f"exit status {exitcode}"
    return ProblemCheck(path, status="error", internal=True,
                        error=f"{path}: internal error: the worker process checking it died "
                              f"({how}) (please report)")


def checks(files: list[str], strict: bool = False, jobs: int = 1,
           timeout: float | None = TIMEOUT,
           then: Callable[[ProblemCheck], Any] | None = None,
           idle: Callable[[], Any] | None = None) -> Generator[Any, None, None]:
    """Each file's ProblemCheck, in the order of ``files``, as soon as it is known; or,
    given ``then``, ``then`` of it, applied where the file was checked (so a worker
    hands back what the caller makes of a result, e.g. its report text). ``idle()`` is
    called when the next result is not ready yet (the caller flushes its output).

    ``jobs`` > 1 spreads the files over that many worker processes (checking/pool.py);
    then a file that crashes its worker or outlasts ``timeout`` costs only that file.
    With one job the files are checked in this process, the time limit by an alarm signal.
    """
    def finish(problem: ProblemCheck) -> Any:
        if then is None:
            return problem
        try:
            return then(problem)
        except Exception as err:  # a bug in what the caller makes of it: this file's error
            from ..core.errors import internal_message

            return then(ProblemCheck(problem.file, status="error", internal=True,
                                     error=internal_message(problem.file, err)))

    if min(jobs, len(files)) > 1:
        from . import pool  # forked workers, only for a pool

        if pool.forks():
            warm()
            yield from pool.pooled(
                files, lambda path: finish(check_file(path, strict)), min(jobs, len(files)),
                timeout, lambda path, limit: finish(timed_out(path, limit)),
                lambda path, code: finish(crashed(path, code)), idle)
            return
    for problem in _in_time(files, strict, timeout, idle):
        yield finish(problem)


def warm() -> None:
    """Load, once, what checking a file needs: the kinds and the physics they import on
    first use (the standard library alone: no numpy), the YAML loader and the unit table.
    Called before the workers are forked, so each starts with it (shared, copy-on-write)
    instead of loading it again; the objects made so far are then left out of the
    collector's passes (gc.freeze), so a worker's collections do not touch, and copy, the
    pages it shares."""
    import gc

    from ..core import safeyaml, unit_cache
    from ..kinds import preload
    from ..solving import solve  # noqa: F401 -- imported for the workers

    preload()
    safeyaml.loader_class()
    unit_cache.get("parse", "")
    gc.freeze()


class _Alarm(BaseException):
    """The time limit of one file, raised by SIGALRM (a BaseException, so a kind's own
    ``except Exception`` does not swallow it)."""


def _in_time(files: list[str], strict: bool, timeout: float | None,
             idle: Callable[[], Any] | None = None) -> Iterator[ProblemCheck]:
    """check_file of each file, each under the time limit where this process can set an
    alarm (Unix, main thread); elsewhere without one. ``idle()`` is called before each
    file but the first (the caller flushes what it wrote of the one before).

    The alarm's handler is set once for the run, not once per file (setting it was a
    twentieth of a file's time), and the alarm runs only while a file is checked:
    between files (the caller writing its report) there is none."""
    import signal
    import threading

    def ready(i: int) -> None:
        if i and idle is not None:
            idle()

    if not timeout or not hasattr(signal, "setitimer") \
            or threading.current_thread() is not threading.main_thread():
        for i, path in enumerate(files):
            ready(i)
            yield check_file(path, strict)
        return

    def ring(signum: int, frame: Any) -> None:
        raise _Alarm()

    previous = signal.signal(signal.SIGALRM, ring)
    try:
        for i, path in enumerate(files):
            ready(i)
            try:
                signal.setitimer(signal.ITIMER_REAL, timeout)
                try:
                    problem = check_file(path, strict)
                finally:
                    signal.setitimer(signal.ITIMER_REAL, 0)
            except _Alarm:
                problem = timed_out(path, timeout)
            yield problem
    finally:
        signal.signal(signal.SIGALRM, previous)
