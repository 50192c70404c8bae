"""The test suite on fresh clones: `make test` (with --ci, `CI=true bash .ci/run`: `make
test`, `make test-slow`, then `gyro check problems/`) of two or more revisions, side by side.

Each revision is cloned once into its own folder and set up with `make demo` (the
virtual environment, the install; not timed). Every timed run starts from that fresh
clone's state: `git clean -fdx -e .venv` first removes what a run before it left (mypy's
and pytest's caches, bytecode of the tests), and the package is byte-compiled again as
the install left it. The runs go in turn, ABBA... for two
revisions, so that a machine that slows or speeds up over the runs moves both alike.
Each run's wall time, its CPU seconds (user + system of the whole process tree:
`os.wait4` of bash, which waits for everything below it, Chromium included), pytest's own
time and its count of tests are printed, then each revision's median.

    .venv/bin/python benchmarks/bench_suite.py 846166c HEAD [--repeat 2] [--source .] [--ci]

The issue's row: `make test` on a fresh clone, install not counted (goal <= 150 s). A run
of one revision takes 3 to 4 minutes on the 2-core machine, the setup of each 1 to 2.
"""

from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def clone(source: str, rev: str, into: Path) -> Path:
    """A fresh clone of ``source`` at ``rev`` in ``into``, set up by `make demo`."""
    subprocess.run(["git", "clone", "-q", source, str(into)], check=True)
    subprocess.run(["git", "-C", str(into), "checkout", "-q", rev], check=True)
    with (into.parent / f"{into.name}-demo.log").open("w") as log:
        subprocess.run(["make", "-C", str(into), "demo"], check=True, stdout=log,
                       stderr=subprocess.STDOUT)
    return into


def run(folder: Path, log: Path, ci: bool = False) -> dict[str, float | str]:
    """One timed `make test` (``ci``: `CI=true bash .ci/run`) in ``folder``, from the fresh
    clone's state; pytest's time and count are its last run's."""
    subprocess.run(["git", "-C", str(folder), "clean", "-q", "-fdx", "-e", ".venv"], check=True)
    # the package's bytecode, as the install left it (the clean took it)
    subprocess.run([str(folder / ".venv" / "bin" / "python"), "-m", "compileall", "-q",
                    "gyro_cli"], cwd=folder, check=True)
    start = time.perf_counter()
    with log.open("w") as out:
        child = subprocess.Popen(["bash", ".ci/run"] if ci else ["make", "test"], cwd=folder,
                                 stdout=out, stderr=subprocess.STDOUT,
                                 env=dict(os.environ, CI="true", PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD="1"))
        _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    text = log.read_text(errors="replace")
    found = re.findall(r"^(\d+) passed.* in ([\d.]+)s", text, re.MULTILINE)
    tests, pytest_s = found[-1] if found else ("?", "nan")
    return {"exit": child.returncode, "wall": wall, "cpu": usage.ru_utime + usage.ru_stime,
            "pytest": float(pytest_s), "tests": tests}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("revs", nargs="+", help="revisions to compare, e.g. 846166c HEAD")
    ap.add_argument("--repeat", type=int, default=2, help="timed runs of each revision")
    ap.add_argument("--source", default=str(ROOT), help="the repository to clone")
    ap.add_argument("--ci", action="store_true",
                    help="time CI's whole run (.ci/run), not the issue's `make test`")
    args = ap.parse_args()

    work = Path(tempfile.mkdtemp(prefix="gyro-bench-suite-"))
    folders = {rev: clone(args.source, rev, work / f"r{i}") for i, rev in enumerate(args.revs)}
    order: list[str] = []
    for k in range(args.repeat):  # ABBA...: each round in the other order
        order += args.revs if k % 2 == 0 else args.revs[::-1]
    rows: dict[str, list[dict[str, float | str]]] = {rev: [] for rev in args.revs}
    print(f"{'revision':<12} {'exit':>4} {'wall s':>7} {'CPU s':>7} {'pytest s':>8} tests  load")
    for n, rev in enumerate(order):
        row = run(folders[rev], work / f"run{n}-{rev}.log", ci=args.ci)
        rows[rev].append(row)
        load = os.getloadavg()[0]
        print(f"{rev:<12} {row['exit']:>4} {row['wall']:>7.1f} {row['cpu']:>7.1f} "
              f"{row['pytest']:>8.1f} {row['tests']:>5}  {load:.1f}", flush=True)
    print("medians:")
    for rev, runs in rows.items():
        med = {k: statistics.median(float(r[k]) for r in runs) for k in ("wall", "cpu", "pytest")}
        print(f"{rev:<12} wall {med['wall']:.1f} s, CPU {med['cpu']:.1f} s, "
              f"pytest {med['pytest']:.1f} s over {len(runs)} runs")
    print(f"clones and logs in {work}")


if __name__ == "__main__":
    main()
