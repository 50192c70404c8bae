"""`gyro check` of a whole problem bank against merely reading it with PyYAML's C loader.

Makes a bank of N files by copying the bundled problems (problems/*.yaml, every
kind) into numbered folders, then times, in the same run and interleaved so
machine noise hits both alike:

- reading: one Python process that reads and parses every file with
  ``yaml.load(..., Loader=yaml.CSafeLoader)`` (nothing checked);
- checking: ``gyro check BANK --format json --junit FILE`` (every report
  streamed; stdout to /dev/null), with ``--jobs`` as given (default: gyro's own
  default, the CPUs available).

For each it prints the wall time, the CPU time (user + system, workers
included), files per second and the peak resident set size of the largest
process (from wait4), then the ratio checking / reading. Targets (issue 26):
checking 60 copies (3,600 files) in at most 2x the reading time on a 2-core
machine, and peak RSS at 36,000 files within 30 MB of the peak at 3,600. The
check must pass on every file, so the figure is not flattered by skipped work.

    .venv/bin/python benchmarks/bench_bank.py [--files 3600 36000] [--runs 3] [--jobs N]
                                              [--variants]

``--variants`` makes the bank with ``gyro vary`` instead (every bundled problem that
has a ``vary:`` block, the same number of variants of each): no two files alike, as
in a real bank, so nothing is flattered by texts that repeat from copy to copy.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

READ = """\
import os, sys, yaml
for root, dirs, names in os.walk(sys.argv[1]):
    dirs.sort()
    for name in sorted(names):
        if name.endswith((".yaml", ".yml")):
            with open(os.path.join(root, name), "rb") as handle:
                yaml.load(handle, Loader=yaml.CSafeLoader)
"""


def make_bank(directory: Path, count: int) -> int:
    """``count`` files (rounded up to whole copies of problems/): folder cNNNN per copy."""
    sources = sorted((ROOT / "problems").glob("*.yaml"))
    copies = -(-count // len(sources))
    for i in range(copies):
        folder = directory / f"c{i:04d}"
        folder.mkdir(parents=True)
        for source in sources:
            shutil.copyfile(source, folder / source.name)
    return copies * len(sources)


def make_variant_bank(directory: Path, count: int) -> int:
    """``count`` files (rounded up) of distinct numbers: ``gyro vary`` of each bundled
    problem that has a ``vary:`` block, as a real bank is made (no two files alike)."""
    sources = [p for p in sorted((ROOT / "problems").glob("*.yaml"))
               if any(line.startswith("vary:") for line in p.read_text().splitlines())]
    each = -(-count // len(sources))
    for source in sources:
        subprocess.run(gyro_cmd() + ["vary", str(source), "-n", str(each), "-o",
                                     str(directory / source.stem)],
                       check=True, cwd=ROOT, stdout=subprocess.DEVNULL)
    return each * len(sources)


def measure(cmd: list[str], out: Path | None = None) -> tuple[float, float, int]:
    """(wall s, CPU s of the process and its children, peak RSS in bytes of the largest).

    stdout goes to ``out`` (or nowhere). This process stays small (it never holds a
    report): on Linux a child's peak RSS starts from its parent's at exec.
    """
    sink = open(out, "wb") if out else open(os.devnull, "wb")
    with sink:
        start = time.perf_counter()
        process = subprocess.Popen(cmd, stdout=sink, stderr=subprocess.PIPE, cwd=ROOT)
        err = process.stderr.read().decode() if process.stderr else ""
        _, status, usage = os.wait4(process.pid, 0)
        wall = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} exited {process.returncode}: {err[:2000]}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss * 1024


def summary_of(report: Path) -> dict:
    """The summary of a JSON report: its last line (``"summary": {...}}``), read alone."""
    with open(report, "rb") as handle:
        handle.seek(max(0, os.path.getsize(report) - 4096))
        last = handle.read().decode().splitlines()[-1]
    return json.loads(last.removeprefix('"summary": ')[:-1])


def gyro_cmd() -> list[str]:
    gyro = Path(sys.executable).with_name("gyro")
    return [str(gyro)] if gyro.exists() else [sys.executable, "-m", "gyro_cli"]


def bench(count: int, runs: int, jobs: int | None, variants: bool = False) -> dict:
    with tempfile.TemporaryDirectory(prefix="gyro-bank-") as tmp:
        bank = Path(tmp) / "bank"
        files = (make_variant_bank if variants else make_bank)(bank, count)
        junit, report = Path(tmp) / "report.xml", Path(tmp) / "report.json"
        check = gyro_cmd() + ["check", str(bank), "--format", "json", "--junit", str(junit)]
        if jobs:
            check += ["--jobs", str(jobs)]
        read = [sys.executable, "-c", READ, str(bank)]
        # Untimed: the OS's file cache and gyro's unit table.
        measure(read)
        measure(gyro_cmd() + ["check", str(ROOT / "problems")])
        reads, checks = [], []
        for _ in range(runs):
            reads.append(measure(read))
            checks.append(measure(check, report))
            summary = summary_of(report)
            if summary["exit_code"] != 0 or summary["checked"] != files:
                raise SystemExit(f"the check did not pass on every file: {summary}")
    return {"files": files, "answers": summary["answers"], "read": reads, "check": checks}


def _median(samples: list[tuple[float, float, int]], i: int) -> float:
    return statistics.median(s[i] for s in samples)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--files", type=int, nargs="+", default=[3600, 36000])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--jobs", type=int, default=None,
                        help="gyro check --jobs (default: gyro's, the CPUs available)")
    parser.add_argument("--variants", action="store_true",
                        help="a bank of distinct variants (gyro vary of every problem with a "
                             "vary: block) instead of copies of the bundled problems")
    args = parser.parse_args()
    cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    print(f"{cpus} CPUs available, load average {os.getloadavg()[0]:.1f}; "
          f"median of {args.runs} runs; --jobs {args.jobs or 'default'}; "
          f"{'distinct variants' if args.variants else 'copies of problems/'}")
    peaks = {}
    for count in args.files:
        result = bench(count, args.runs, args.jobs, args.variants)
        n = result["files"]
        for name, samples in (("read (C loader)", result["read"]),
                              ("gyro check", result["check"])):
            wall, cpu, rss = (_median(samples, i) for i in range(3))
            print(f"{n:6d} files  {name:16s} wall {wall:7.2f} s  cpu {cpu:7.2f} s  "
                  f"{n / wall:8.0f} files/s  peak RSS {rss / 2**20:6.1f} MB")
        ratio = _median(result["check"], 0) / _median(result["read"], 0)
        cpu_ratio = _median(result["check"], 1) / _median(result["read"], 1)
        peaks[n] = _median(result["check"], 2)
        print(f"{n:6d} files  ratio check/read: wall {ratio:.2f}x (target <= 2.00x), "
              f"cpu {cpu_ratio:.2f}x; {result['answers']} answers, all passed")
    if len(peaks) > 1:
        small, large = min(peaks), max(peaks)
        growth = (peaks[large] - peaks[small]) / 2**20
        print(f"peak RSS growth {small} -> {large} files: {growth:+.1f} MB (target <= 30 MB)")


if __name__ == "__main__":
    main()
