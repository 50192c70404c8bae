"""Variants and banks streamed: time and peak memory of `gyro vary --roster` and
`gyro export --to FORMAT --variants N`, this code against another checkout, interleaved.

Each command runs in its own process; its peak resident memory is that process's
``ru_maxrss`` (os.wait4, the rusage of that one child: the largest of it and the workers
it forks), and the peak proportional set size of all its processes together is sampled
from /proc every 0.1 s (a roster drawn by workers: the memory they take beside it). With ``--old DIR`` each run of
this checkout is followed by the same command run with ``PYTHONPATH=DIR`` (an older
checkout, e.g. one made by ``git worktree add /tmp/old 1438cdf``), so a loaded machine
slows both alike; the load average is printed before and after. Medians of ``--repeat``
runs.

    .venv/bin/python benchmarks/bench_stream.py --students 10000 --variants 2000 \\
        --variants 10000 --old /tmp/old [--repeat 3] [--format moodle]

The issue's rows: `gyro vary problems/11_3.yaml problems/11_5.yaml --roster` of 10,000
students (goal <= 15 s, <= 80 MB) and `gyro export --to moodle problems/11_3.yaml
--variants 2000` (and 10,000; goal: memory flat, <= 100 MB at any count).
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = ROOT / "problems"
SUFFIX = {"moodle": ".xml", "qti": ".zip", "blackboard": ".txt", "prairielearn": ""}


CPU: dict[str, list[float]] = {}  # CPU seconds (user + system) of each run, by command and code


#: each checkout's own unit table (GYRO_CACHE_DIR), warmed before it is timed: the table is
#: stamped with the code's unit sources, so checkouts sharing one would rebuild it in turn
CACHES: dict[Path, str] = {}


def cache_for(code: Path) -> str:
    if code not in CACHES:
        CACHES[code] = tempfile.mkdtemp(prefix="gyro-bench-units-")
        subprocess.run([sys.executable, "-m", "gyro_cli", "solve", *sorted(
            str(p) for p in PROBLEMS.glob("*.yaml"))], cwd=code, stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL, env=dict(os.environ, PYTHONPATH=str(code),
                                                GYRO_CACHE_DIR=CACHES[code]))
    return CACHES[code]


def _tree(pid: int) -> list[int]:
    """``pid`` and every process below it (Linux's /proc; just ``pid`` elsewhere)."""
    found, i = [pid], 0
    while i < len(found):
        try:
            for task in os.listdir(f"/proc/{found[i]}/task"):
                with open(f"/proc/{found[i]}/task/{task}/children") as children:
                    found += [int(c) for c in children.read().split()]
        except OSError:
            pass
        i += 1
    return found


def _pss_mb(pids: list[int]) -> float:
    """The processes' proportional set size together (a page shared by two forks counts
    half in each), in MB; NaN where /proc has no smaps_rollup."""
    total = 0
    for pid in pids:
        try:
            with open(f"/proc/{pid}/smaps_rollup") as rollup:
                total += next(int(line.split()[1]) for line in rollup if line.startswith("Pss:"))
        except (OSError, StopIteration, ValueError):
            if pid == pids[0]:
                return float("nan")
    return total / 1024


def _sample_pss(pid: int, peak: list[float], done: threading.Event) -> None:
    while not done.wait(0.1):
        peak[0] = max(peak[0], _pss_mb(_tree(pid)))


def run(cmd: list[str], code: Path) -> tuple[float, float, float]:
    """(seconds, peak RSS in MB, peak PSS of its processes together in MB) of ``cmd`` run
    with ``code`` first on the path and its own warm unit table; its CPU seconds (user +
    system, steadier than the wall on a shared machine; its workers' included) go to CPU.
    The RSS is the largest one process had (the command's or a worker's); the PSS, sampled
    every 0.1 s, counts every process of the command, workers included."""
    env = dict(os.environ, PYTHONPATH=str(code), GYRO_CACHE_DIR=cache_for(code))
    start = time.perf_counter()
    # Run from the checkout: ``python -m`` puts the working directory first on the path.
    child = subprocess.Popen(cmd, env=env, cwd=code, stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE)
    assert child.stderr is not None
    peak, done = [0.0], threading.Event()
    sampler = threading.Thread(target=_sample_pss, args=(child.pid, peak, done), daemon=True)
    sampler.start()
    err = child.stderr.read()
    done.set()
    sampler.join()
    _, status, usage = os.wait4(child.pid, 0)
    took = time.perf_counter() - start
    CPU.setdefault(f"{cmd[3]} {code}", []).append(usage.ru_utime + usage.ru_stime)
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != 0:  # an old checkout may not read today's problem files
        lines = err.decode().strip().splitlines() or [""]
        print(f"  {code}: exited {child.returncode}: {lines[-1][:300]}", flush=True)
        return float("nan"), float("nan"), float("nan")
    return took, usage.ru_maxrss / 1024, peak[0]  # kB on Linux


def commands(work: Path, students: int, counts: list[int], fmt: str
             ) -> list[tuple[str, list[str], Path]]:
    """(row name, command, what it writes) of each benchmark."""
    gyro = [sys.executable, "-m", "gyro_cli"]
    roster = work / "roster.csv"
    roster.write_text("student,section\n" + "".join(f"s{k:05d},{k % 12}\n"
                                                    for k in range(students)))
    out = [(f"vary --roster, {students} students x 2 problems",
            gyro + ["vary", str(PROBLEMS / "11_3.yaml"), str(PROBLEMS / "11_5.yaml"),
                    "--roster", str(roster), "-o", str(work / "hw")], work / "hw")]
    for count in counts:
        target = work / f"bank{SUFFIX[fmt]}"
        out.append((f"export --to {fmt} 11_3.yaml --variants {count}",
                    gyro + ["export", "--to", fmt, str(PROBLEMS / "11_3.yaml"), "--variants",
                            str(count), "-o", str(target)], target))
    return out


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--students", type=int, default=10_000)
    parser.add_argument("--variants", type=int, action="append",
                        help="variants of the export (repeatable; default 2000)")
    parser.add_argument("--format", default="moodle", choices=sorted(SUFFIX))
    parser.add_argument("--old", type=Path, action="append", default=[],
                        help="an older checkout to measure beside (repeatable)")
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--only", help="run only the rows whose name contains this")
    parser.add_argument("--alone", type=int, action="append", default=[],
                        help="export variants measured with this code only (the old may "
                             "need gigabytes)")
    args = parser.parse_args()
    codes = [("now", ROOT)] + [(f"old {path.name}", path.resolve()) for path in args.old]
    code_of = dict(codes)
    print(f"load average before: {load()} ({os.cpu_count()} cores)")
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        rows = commands(work, args.students, (args.variants or [2000]) + args.alone,
                        args.format)
        for name, cmd, target in rows:
            if args.only and args.only not in name:
                continue
            measured: dict[str, list[tuple[float, float, float]]] = {
                label: [] for label, _ in codes}
            alone = any(name.endswith(f" {n}") and "export" in name for n in args.alone)
            for _ in range(args.repeat):
                for label, code in codes[:1] if alone else codes:
                    measured[label].append(run(cmd, code))
                    if target.is_dir():
                        shutil.rmtree(target)
                    elif target.exists():
                        target.unlink()
                    # the deletion's writes to the disk before the next run, not during it
                    # (20,000 files deleted then slowed the next set's creation two to
                    # eightfold, whichever code ran next)
                    os.sync()
            for label, _ in codes[:1] if alone else codes:
                seconds = statistics.median(t for t, _, _ in measured[label])
                peak = statistics.median(m for _, m, _ in measured[label])
                pss = statistics.median(p for _, _, p in measured[label])
                runs = CPU[f"{cmd[3]} {code_of[label]}"][-len(measured[label]):]
                cpu = statistics.median(runs)
                print(f"{name:<48} {label}: {seconds:7.1f} s  {cpu:7.1f} CPU-s  {peak:7.1f} MB peak "
                      f"RSS  {pss:7.1f} MB peak PSS of all its processes (runs: "
                      f"{', '.join(f'{t:.1f} s/{m:.0f}/{p:.0f} MB' for t, m, p in measured[label])})",
                      flush=True)
    print(f"load average after: {load()}")
    for folder in CACHES.values():
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
