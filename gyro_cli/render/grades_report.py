"""`gyro check --answers` reports: the grades as CSV, a table, or JSON."""

from __future__ import annotations

import csv
import dataclasses
import io
import json
from typing import Any

from ..checking.grades import OUT_COLUMNS, Graded
from ..core.errors import terminal_text

# ---- output -----------------------------------------------------------------

def _cell(value: Any) -> str:
    """A CSV cell a spreadsheet will not run as a formula (=, +, @, -letters)."""
    text = "" if value is None else str(value)
    if text[:1] in ("=", "+", "@", "\t", "\r") or (text[:1] == "-" and not
                                                   text[1:2].replace(".", "").isdigit()):
        return "'" + text
    return text


def csv_text(graded: Graded) -> str:
    """The grades: one row per student and answer, then a score row per student."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(OUT_COLUMNS)
    for row in graded.rows:
        rel = "" if row.relative_error is None else f"{row.relative_error:.6g}"
        writer.writerow([_cell(row.student), _cell(row.problem), _cell(row.answer),
                         _cell(row.submitted), _cell(row.correct), rel, row.result,
                         f"{row.points:g}", f"{row.max_points:g}", _cell(row.note)])
    for student, (points, total) in graded.scores.items():
        percent = 100 * points / total if total else 0.0
        writer.writerow([_cell(student), "", "", "", "", "", "score", f"{points:g}",
                         f"{total:g}", f"{percent:.1f}%"])
    return out.getvalue()


def table(graded: Graded) -> str:
    """The grades as a table with a header row, columns as wide as their longest cell."""
    widths = [max([len(head)] + [len(str(getattr(row, name))) for row in graded.rows])
              for head, name in (("student", "student"), ("problem", "problem"),
                                 ("answer", "answer"), ("result", "result"))]
    lines = [f"{'student':<{widths[0]}} {'problem':<{widths[1]}} {'answer':<{widths[2]}} "
             f"{'result':<{widths[3]}} {'points':>6}  submitted  [solver: correct answer]"]
    for row in graded.rows:
        lines.append(f"{row.student:<{widths[0]}} {row.problem:<{widths[1]}} "
                     f"{row.answer:<{widths[2]}} {row.result:<{widths[3]}} "
                     f"{row.points:>6g}  {row.submitted or '-'}  [solver: {row.correct}]"
                     + (f"  {row.note}" if row.note and row.result != "correct" else ""))
    lines.append("")
    for student, (points, total) in graded.scores.items():
        percent = 100 * points / total if total else 0.0
        lines.append(f"{student:<12} score {points:g} / {total:g} ({percent:.1f}%)")
    # names and answers come from the sheet: no escape sequence reaches the terminal raw
    return "\n".join(terminal_text(line) for line in lines) + "\n"


def as_json(graded: Graded) -> str:
    return json.dumps({"rows": [dataclasses.asdict(r) for r in graded.rows],
                       "scores": {s: {"points": p, "max_points": t}
                                  for s, (p, t) in graded.scores.items()}}, allow_nan=False)
