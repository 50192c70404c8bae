"""Rendering every bundled problem in each output format, in one process: the work a
`gyro check`, a handout, a bank and most of the test suite repeat.

Each format's pass renders the worked answer of every file in `problems/` from a fresh
solve (solving is its own row), and is timed in the process's CPU seconds, the best of
``--passes`` (a machine shared with other work slows a pass; it never speeds one). With
``--old DIR`` the same passes run in a checkout of other code (a `git worktree`), the two
interleaved, so that a change is read against the code before it in one call.

``--instructions``: each format's pass over every ``--every``-th bundled problem counted
in instructions by valgrind (callgrind), the same on a machine shared with other work,
where CPU seconds vary by a third from one run to the next. A process that solves the
files and renders them in one format, less one that only solves them (both after a
first pass of every format), is that format's pass.

    .venv/bin/python benchmarks/bench_render.py [--passes 7] [--rounds 3] [--old DIR]
    .venv/bin/python benchmarks/bench_render.py --instructions [--every 4] [--old DIR]
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FORMATS = ("solve", "text", "markdown", "latex", "json", "html")
RENDERED = FORMATS[1:]


def _render(results: list, fmt: str) -> None:
    for r in results:
        r.html(picture=False) if fmt == "html" else r.render(fmt)


def _paths(every: int = 1) -> list[str]:
    """The bundled problems of the checkout in the working directory, whose code this
    process imported (`python -c` puts the working directory first)."""
    import glob

    import gyro_cli

    assert Path(gyro_cli.__file__).resolve().is_relative_to(Path.cwd().resolve()), \
        f"gyro_cli from {gyro_cli.__file__}, not the checkout in {Path.cwd()}"
    return sorted(glob.glob("problems/*.yaml"))[::every]


def count_pass(fmt: str, every: int) -> int:
    """What `--instructions` counts under valgrind: a first pass of every format, then
    the files solved, then rendered in ``fmt`` (or not: "none"); the number of files."""
    from gyro_cli import api

    paths = _paths(every)
    for f in RENDERED:
        _render([api.solve_file(p) for p in paths], f)
    results = [api.solve_file(p) for p in paths]
    if fmt != "none":
        _render(results, fmt)
    return len(paths)


def measure(passes: int) -> dict[str, float]:
    """Each format's best pass over every bundled problem, CPU seconds of this process."""
    from gyro_cli import api

    paths = _paths()

    def one(fmt: str) -> float:
        results = [api.solve_file(p) for p in paths]
        start = time.process_time()
        if fmt == "solve":
            for p in paths:
                api.solve_file(p)
        else:
            _render(results, fmt)
        return time.process_time() - start

    for fmt in FORMATS:  # a first pass of each, not timed: imports, the unit table
        one(fmt)
    return {fmt: min(one(fmt) for _ in range(passes)) / len(paths) for fmt in FORMATS}


def _this_script_in(tree: Path, *args: str, env: dict[str, str] | None = None,
                    tool: tuple[str, ...] = ()) -> subprocess.CompletedProcess[str]:
    """This script run with ``args`` in another checkout, importing that checkout's code."""
    code = (f"import runpy, sys; sys.argv = [{str(Path(__file__))!r}, *{list(args)!r}]; "
            "runpy.run_path(sys.argv[0], run_name='__main__')")
    return subprocess.run([*tool, sys.executable, "-c", code], cwd=tree, check=True,
                          capture_output=True, text=True, env=env)


def run_in(tree: Path, passes: int) -> dict[str, float]:
    """`measure` in a checkout."""
    return json.loads(_this_script_in(tree, "--measure", "--passes", str(passes)).stdout)  # type: ignore[no-any-return]


def counted(tree: Path, fmt: str, every: int, env: dict[str, str],
            valgrind: bool = True) -> tuple[int, int]:
    """Instructions of a `count_pass` process in ``tree`` and the number of files it read."""
    tool = ("valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null") if valgrind else ()
    done = _this_script_in(tree, "--count", fmt, "--every", str(every), env=env, tool=tool)
    if not valgrind:
        return 0, int(done.stdout)
    return int(done.stderr.rsplit("Collected : ", 1)[1].split()[0]), int(done.stdout)


def instructions(trees: list[tuple[str, Path]], every: int) -> None:
    """Each format's pass in instructions per file, each tree (see the module's doc)."""
    import os
    import shutil
    import tempfile

    print("M instructions a problem" + " " * 16 + "  ".join(f"{f:>8}" for f in RENDERED))
    rows = {}
    for name, tree in trees:
        # each tree its own unit table, filled by a run not counted: a run that met a unit
        # first (pint imported, the table written) would count far more than the others
        env = dict(os.environ, GYRO_CACHE_DIR=tempfile.mkdtemp(prefix="gyro-bench-render-"))
        counted(tree, RENDERED[-1], every, env, valgrind=False)
        base, files = counted(tree, "none", every, env)
        rows[name] = {f: (counted(tree, f, every, env)[0] - base) / files / 1e6
                      for f in RENDERED}
        shutil.rmtree(env["GYRO_CACHE_DIR"], ignore_errors=True)
        print(f"{name:40}" + "  ".join(f"{rows[name][f]:8.2f}" for f in RENDERED))
    if len(trees) > 1:
        print(f"{'this / old':40}" + "  ".join(
            f"{rows['this'][f] / rows['old'][f]:7.3f}x" for f in RENDERED))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--passes", type=int, default=7)
    parser.add_argument("--rounds", type=int, default=3, help="with --old: each code's runs")
    parser.add_argument("--old", type=Path, help="a checkout of the code to compare with")
    parser.add_argument("--instructions", action="store_true",
                        help="count instructions (valgrind) instead of timing")
    parser.add_argument("--every", type=int, default=4,
                        help="with --instructions: every Nth bundled problem")
    parser.add_argument("--measure", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--count", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.count:
        print(count_pass(args.count, args.every))
        return
    if args.measure:
        print(json.dumps(measure(args.passes)))
        return
    trees = [("this", ROOT)] + ([("old", args.old.resolve())] if args.old else [])
    if args.instructions:
        instructions(trees, args.every)
        return
    runs: dict[str, list[dict[str, float]]] = {name: [] for name, _ in trees}
    for k in range(args.rounds if args.old else 1):
        for name, tree in trees if k % 2 == 0 else trees[::-1]:  # ABBA
            runs[name].append(run_in(tree, args.passes))
    print("ms a problem (CPU, best pass, best run)  " + "  ".join(f"{f:>8}" for f in FORMATS))
    best = {name: {f: min(r[f] for r in rs) * 1000 for f in FORMATS} for name, rs in runs.items()}
    for name, row in best.items():
        print(f"{name:40}  " + "  ".join(f"{row[f]:8.2f}" for f in FORMATS))
    if args.old:
        print(f"{'this / old':40}  " + "  ".join(
            f"{best['this'][f] / best['old'][f]:7.2f}x" for f in FORMATS))


if __name__ == "__main__":
    main()
