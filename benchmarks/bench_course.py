"""Per-student homework at course scale: `gyro vary --roster` and grading by assignment.

Makes a roster of N students (default 10,000), writes one variant of
problems/11_3.yaml per student with `gyro vary --roster`, an answer sheet in
which every student answers their own variant (from the variant's answer key),
and times `gyro check --answers SHEET --assignment DIR/assignment.csv`. It
asserts that the grades hold N x 2 rows and that every student scored 2 of 2,
and runs the grading at N/10 students as well, so the growth with N is shown
(linear: about 10x the time for 10x the students, not 100x).

    .venv/bin/python benchmarks/bench_course.py [--students 10000]
"""

from __future__ import annotations

import argparse
import csv
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent
TOP = ROOT / "problems" / "11_3.yaml"


def gyro_cmd() -> list[str]:
    gyro = Path(sys.executable).with_name("gyro")
    return [str(gyro)] if gyro.exists() else [sys.executable, "-m", "gyro_cli"]


def timed(cmd: list[str]) -> float:
    start = time.perf_counter()
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    took = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"{' '.join(cmd)} exited {done.returncode}: {done.stderr.decode()[-500:]}")
    return took


def course(work: Path, students: int) -> tuple[float, float]:
    """(seconds to write the variants, seconds to grade) for ``students`` students."""
    work.mkdir()
    roster = work / "roster.csv"
    roster.write_text("student,section\n" + "".join(f"s{k:05d},{k % 12}\n"
                                                    for k in range(students)))
    out = work / "hw"
    vary = timed(gyro_cmd() + ["vary", str(TOP), "--roster", str(roster), "-o", str(out)])
    with open(out / "assignment.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    lines = ["student,problem,answer,value"]
    for r in rows:
        expected = yaml.safe_load((out / r["file"]).read_text())["expected"]
        lines.append(f"{r['student']},11/3,precession,{'; '.join(expected['precession'])}")
        lines.append(f"{r['student']},11/3,min_spin,{expected['min_spin']}")
    sheet = work / "sheet.csv"
    sheet.write_text("\n".join(lines) + "\n")
    grades = work / "grades.csv"
    grade = timed(gyro_cmd() + ["check", "--answers", str(sheet), "--assignment",
                                str(out / "assignment.csv"), "--out", str(grades)])
    with open(grades, newline="") as handle:
        graded = list(csv.DictReader(handle))
    items = [g for g in graded if g["result"] != "score"]
    scores = [g for g in graded if g["result"] == "score"]
    assert len(items) == 2 * students, len(items)
    assert all(g["points"] == "2" and g["max_points"] == "2" for g in scores)
    return vary, grade


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--students", type=int, default=10_000)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="gyro-bench-course-") as tmp:
        small = max(1, args.students // 10)
        vary_small, grade_small = course(Path(tmp) / "small", small)
        vary_big, grade_big = course(Path(tmp) / "big", args.students)
    print("students  vary --roster  check --answers --assignment  grade rows")
    print(f"{small:>8}  {vary_small:>11.2f} s  {grade_small:>27.2f} s  {2 * small:>10}")
    print(f"{args.students:>8}  {vary_big:>11.2f} s  {grade_big:>27.2f} s  "
          f"{2 * args.students:>10}")
    print(f"grading time ratio for {args.students // small}x the students: "
          f"{grade_big / grade_small:.1f}x")


if __name__ == "__main__":
    main()
