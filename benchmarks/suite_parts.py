"""Where the test suite's time goes, test by test: each test's CPU seconds in its own
process and in the child processes it waited for, and when each test process was busy.

The suite runs as `make test` runs it (two test processes on this machine, work stealing,
plain asserts), with this module loaded as a pytest plugin in every test process. Each
test's record: its wall time, its process's CPU time (user + system) and the CPU time of
the children it waited for (`RUSAGE_CHILDREN`: a `gyro` subprocess, a build, a hook's
environment; a process reaped later, such as one of Chromium's, lands on the test that
is running when it is reaped, and some of Chromium's are never counted). Then the report:

- the run's wall time, and per test process when its first test started, when its last
  ended, and how long it spent in tests (a process that ends long before the other is
  time a different order of the tests could win back);
- the tests by size: how many take under 50 ms, 0.05-0.2 s, ... and what they add up to;
- the test files that cost most (CPU of the process plus its children), and the tests.

    .venv/bin/python benchmarks/suite_parts.py [--top 25] [--keep DIR] [-- PYTEST ARGS]

A record is also kept as JSON (``--keep``) for other questions. Not a timed test: the
suite itself is `make test`'s, and the figures are this machine's at this hour.
"""

from __future__ import annotations

import argparse
import collections
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
OUT = "SUITE_PARTS_OUT"   # the folder the test processes write their records into

# ---- the plugin, in each test process ------------------------------------------------

_records: list[dict] = []


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):  # type: ignore[no-untyped-def]
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu, wall, start = time.process_time(), time.perf_counter(), time.time()
    yield
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    _records.append({
        "id": item.nodeid, "start": start, "wall": time.perf_counter() - wall,
        "cpu": time.process_time() - cpu,
        "children": (after.ru_utime + after.ru_stime) - (children.ru_utime + children.ru_stime),
    })


def pytest_unconfigure(config):  # type: ignore[no-untyped-def]
    folder = os.environ.get(OUT)
    if folder and _records:
        worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
        Path(folder, f"{worker}.json").write_text(json.dumps(_records), encoding="utf-8")


# ---- the run and its report ----------------------------------------------------------

SIZES = (0.05, 0.2, 1.0, 3.0, float("inf"))


def run(folder: Path, pytest_args: list[str]) -> float:
    """The suite with this plugin in every test process; its wall time."""
    env = dict(os.environ, **{OUT: str(folder)})
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(Path(__file__).parent),
                                                      env.get("PYTHONPATH")]))
    command = [sys.executable, "-m", "pytest", "-q", "-n", "auto", "--dist", "worksteal",
               "--assert=plain", "-p", "suite_parts", *pytest_args]
    start = time.perf_counter()
    subprocess.run(command, cwd=ROOT, env=env, check=False)
    return time.perf_counter() - start


def report(folder: Path, wall: float, start: float, top: int) -> None:
    processes = {p.stem: json.loads(p.read_text(encoding="utf-8"))
                 for p in sorted(folder.glob("*.json"))}
    records = [r for rs in processes.values() for r in rs]
    cpu = sum(r["cpu"] for r in records)
    children = sum(r["children"] for r in records)
    print(f"\n{len(records)} tests in {wall:.1f} s: {cpu:.1f} CPU-s in the test processes, "
          f"{children:.1f} CPU-s in the children they waited for")
    for name, rs in processes.items():
        first = min(r["start"] for r in rs) - start
        last = max(r["start"] + r["wall"] for r in rs) - start
        print(f"  {name}: {len(rs)} tests, first at {first:.1f} s, last ended at {last:.1f} s, "
              f"{sum(r['wall'] for r in rs):.1f} s in tests")
    print("\nby size (wall of one test): tests, wall, CPU, children's CPU")
    low = 0.0
    for high in SIZES:
        rs = [r for r in records if low <= r["wall"] < high]
        print(f"  {low:g}-{high:g} s: {len(rs):5d} {sum(r['wall'] for r in rs):7.1f} "
              f"{sum(r['cpu'] for r in rs):7.1f} {sum(r['children'] for r in rs):7.1f}")
        low = high
    files: dict[str, collections.Counter] = collections.defaultdict(collections.Counter)
    for r in records:
        files[r["id"].split("::")[0]].update({k: r[k] for k in ("wall", "cpu", "children")})
    print(f"\nthe {top} costliest files: wall, CPU, children's CPU")
    for name, c in sorted(files.items(), key=lambda x: -(x[1]["cpu"] + x[1]["children"]))[:top]:
        print(f"  {c['wall']:7.1f} {c['cpu']:7.1f} {c['children']:7.1f}  {name}")
    print(f"\nthe {top} costliest tests: wall, CPU, children's CPU")
    for r in sorted(records, key=lambda r: -(r["cpu"] + r["children"]))[:top]:
        print(f"  {r['wall']:7.1f} {r['cpu']:7.1f} {r['children']:7.1f}  {r['id'][:100]}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--top", type=int, default=25)
    parser.add_argument("--keep", type=Path,
                        help="keep each test process's records in this new or empty folder")
    parser.add_argument("pytest_args", nargs="*", help="after --: pytest's own arguments")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="suite-parts-") as scratch:
        folder = args.keep or Path(scratch)
        if folder.exists() and any(folder.iterdir()):
            parser.error(f"--keep {folder}: not an empty folder (the records are written there)")
        folder.mkdir(parents=True, exist_ok=True)
        start = time.time()
        wall = run(folder, args.pytest_args)
        report(folder, wall, start, args.top)


if __name__ == "__main__":
    main()
