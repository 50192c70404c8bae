"""A Markdown job summary of a `gyro check --junit` report (the GitHub Action's last step).

    python ci/junit_summary.py REPORT.xml [--title TEXT] >> "$GITHUB_STEP_SUMMARY"

A table of the problem files (answers, passed, failed, errors), then a table of
what failed. Only the standard library: it runs with any Python. A missing or
unreadable report is said in the summary (the check's own exit code is what
fails the job).
"""

from __future__ import annotations

import argparse
import html
import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

MAX_FAILURE_ROWS = 100  # GitHub keeps 1 MiB of summary per step


@dataclass
class FileResult:
    """One problem file of the report (a JUnit testsuite)."""

    name: str
    answers: int = 0
    failed: int = 0
    errors: int = 0
    failures: list[tuple[str, str]] = field(default_factory=list)

    @property
    def passed(self) -> int:
        return self.answers - self.failed - self.errors


def cell(text: str) -> str:
    """Text safe inside a Markdown table cell: no markup, no pipe, one line."""
    one_line = " ".join(text.split())
    return html.escape(one_line, quote=False).replace("|", "\\|").replace("`", "&#96;")


def read_report(path: str) -> list[FileResult]:
    """The problem files of a JUnit report written by gyro check."""
    files = []
    for suite in ET.parse(path).getroot().iter("testsuite"):
        result = FileResult(suite.get("name", "?"))
        for case in suite.iter("testcase"):
            result.answers += 1
            for tag in ("failure", "error"):
                bad = case.find(tag)
                if bad is not None:
                    if tag == "failure":
                        result.failed += 1
                    else:
                        result.errors += 1
                    message = bad.get("message") or (bad.text or "")
                    result.failures.append((case.get("name", "?"), message))
        files.append(result)
    return files


def summary(files: list[FileResult], title: str) -> str:
    """The Markdown summary: one row per file and a total, then the failures."""
    total = FileResult("total", sum(f.answers for f in files), sum(f.failed for f in files),
                       sum(f.errors for f in files))
    verdict = "all answers match" if not (total.failed or total.errors) else "some answers do not match"
    lines = [f"### {cell(title)}: {verdict}", "",
             "| problem file | answers | passed | failed | errors |", "| --- | ---: | ---: | ---: | ---: |"]
    for f in files:
        lines.append(f"| {cell(f.name)} | {f.answers} | {f.passed} | {f.failed} | {f.errors} |")
    lines.append(f"| **{len(files)} files** | **{total.answers}** | **{total.passed}** "
                 f"| **{total.failed}** | **{total.errors}** |")
    failures = [(f.name, answer, message) for f in files for answer, message in f.failures]
    if failures:
        lines += ["", "| problem file | answer | what was wrong |", "| --- | --- | --- |"]
        lines += [f"| {cell(name)} | {cell(answer)} | {cell(message)} |"
                  for name, answer, message in failures[:MAX_FAILURE_ROWS]]
        if len(failures) > MAX_FAILURE_ROWS:
            lines.append(f"\n{len(failures) - MAX_FAILURE_ROWS} more in the JUnit report.")
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("report", help="the JUnit XML written by gyro check --junit")
    parser.add_argument("--title", default="gyro check")
    args = parser.parse_args(argv)
    try:
        files = read_report(args.report)
    except (OSError, ET.ParseError) as exc:
        sys.stdout.write(f"### {cell(args.title)}: no report\n\n"
                         f"{cell(args.report)} could not be read ({cell(str(exc))}).\n")
        return 0
    sys.stdout.write(summary(files, args.title))
    return 0


if __name__ == "__main__":
    sys.exit(main())
