"""`gyro check --answers` reports: the grades as CSV, a table, or JSON."""

from __future__ import annotations

import csv
import dataclasses
import io
import json
from typing import Any

from ..checking.grades import OUT_COLUMNS, Graded
from ..core.csvsafe import safe_cell as _cell

# ---- output -----------------------------------------------------------------


def csv_text(graded: Graded) -> str:
    """The grades: one row per student and answer, then a score row per student."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    by_assignment = graded.assignment is not None  # then a last column: the variant
    writer.writerow(OUT_COLUMNS + (("variant",) if by_assignment else ()))
    for row in graded.rows:
        rel = "" if row.relative_error is None else f"{row.relative_error:.6g}"
        writer.writerow([_cell(row.student), _cell(row.problem), _cell(row.answer),
                         _cell(row.submitted), _cell(row.correct), rel, row.result,
                         f"{row.points:g}", f"{row.max_points:g}", _cell(row.note)]
                        + ([_cell(row.variant)] if by_assignment else []))
    for student, (points, total) in graded.scores.items():
        percent = 100 * points / total if total else 0.0
        writer.writerow([_cell(student), "", "", "", "", "", "score", f"{points:g}",
                         f"{total:g}", f"{percent:.1f}%"] + ([""] if by_assignment else []))
    return out.getvalue()


def table(graded: Graded) -> str:
    lines = []
    for row in graded.rows:
        lines.append(f"{row.student:<12} {row.problem:<8} {row.answer:<12} {row.result:<8} "
                     f"{row.points:>4g}  {row.submitted or '-'}  [solver: {row.correct}]"
                     + (f"  {row.note}" if row.note and row.result != "correct" else ""))
    lines.append("")
    for student, (points, total) in graded.scores.items():
        percent = 100 * points / total if total else 0.0
        lines.append(f"{student:<12} score {points:g} / {total:g} ({percent:.1f}%)")
    return "\n".join(lines) + "\n"


def as_json(graded: Graded) -> str:
    return json.dumps({"rows": [_row_json(r, graded) for r in graded.rows],
                       "scores": {s: {"points": p, "max_points": t}
                                  for s, (p, t) in graded.scores.items()}}, allow_nan=False)


def _row_json(row: Any, graded: Graded) -> dict[str, Any]:
    data = dataclasses.asdict(row)
    if graded.assignment is None:
        data.pop("variant", None)
    return data
