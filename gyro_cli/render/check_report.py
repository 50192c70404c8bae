"""`gyro check` reports: the table and one JSON document (JUnit XML is junit.py)."""

from __future__ import annotations

import math
from typing import Any

from ..checking.results import AnswerCheck, CheckRun
from ..core.errors import terminal_text
from ..core.work import num

# ---- reports ----------------------------------------------------------------

def summary_line(run_: CheckRun) -> str:
    c = run_.counts()
    parts = [f"{c['answers']} answer{'s' * (c['answers'] != 1)} in {c['checked']} problem"
             f"{'s' * (c['checked'] != 1)}: {c['passed']} passed, {c['failed']} failed"]
    if c["no_expected"]:
        parts.append(f"{c['no_expected']} without expected answers (not checked)")
    bad = c["bad_files"] - c["internal_errors"]
    if bad:
        parts.append(f"{bad} bad file{'s' * (bad != 1)}")
    if c["internal_errors"]:
        parts.append(f"{c['internal_errors']} internal error{'s' * (c['internal_errors'] != 1)} "
                     "(a bug in gyro: please report)")
    if c["answers"] == 0 and not c["bad_files"]:
        parts.append("nothing was compared")
    verdict = {0: "OK", 1: "FAILED", 2: "ERROR", 3: "INTERNAL ERROR"}[run_.exit_code]
    return f"{verdict}: " + "; ".join(parts)


def _percent(check: AnswerCheck) -> str:
    if check.relative_error is None:
        return ""
    percent = check.relative_error * 100
    return f"{percent:+.2f}%" if abs(percent) < 1e6 else f"{percent:+.3g}%"


def table(run_: CheckRun) -> str:
    """The terminal report: one line per answer under its file, then the summary."""
    rows: list[tuple[str, ...]] = []
    for p in run_.problems:
        head = f"{p.file}" + (f"  {p.id}" if p.id else "") + (f"  {p.title}" if p.title else "")
        rows.append(("#", head))
        if p.status == "error":
            rows.append(("#", f"  ERROR  {p.error}"))
        elif p.status == "no expected answers":
            rows.append(("#", "  ----   no expected answers (not checked)"))
        for a in p.answers:
            note = a.message if not a.passed or not a.keyed else ""
            if a.slip:
                note += f"; likely slip: {a.slip}"
            tol = (f" (+-{num(a.tolerance_value)} {a.unit or ''})".replace(" )", ")")
                   if a.tolerance_value is not None and a.tolerance_value >= 0 else "")
            rows.append(("PASS" if a.passed and a.keyed else "----" if a.passed else "FAIL",
                         a.label, a.expected or "-",
                         a.got or "-", _percent(a), f"{a.tolerance}{tol}", note))
        rows += [("#", f"  ! {warning}") for warning in p.warnings]
    # file names, ids, titles, answers and messages come from files: one line each, and no
    # terminal escape sequence reaches the terminal raw
    rows = [tuple(terminal_text(cell) for cell in row) for row in rows]
    widths = [0] * 6
    for row in rows:
        if row[0] != "#":
            widths = [max(w, len(c)) for w, c in zip(widths, row[:6])]
    lines = []
    header = ("", "answer", "expected", "got", "error", "tolerance")
    widths = [max(w, len(h)) for w, h in zip(widths, header)]
    lines.append("  " + "  ".join(h.ljust(w) for h, w in zip(header, widths)).rstrip())
    for row in rows:
        if row[0] == "#":
            lines.append(row[1])
            continue
        cells = [c.ljust(w) for c, w in zip(row[:6], widths)]
        cells[4] = row[4].rjust(widths[4])
        line = "  " + "  ".join(cells)
        lines.append((line + ("  " + row[6] if row[6] else "")).rstrip())
    lines.append(summary_line(run_))
    return "\n".join(lines) + "\n"


def as_dict(run_: CheckRun) -> dict[str, Any]:
    """The JSON report: every problem and answer, plus the summary."""
    summary = dict(run_.counts(), exit_code=run_.exit_code, text=summary_line(run_))
    problems = []
    for p in run_.problems:
        problems.append({
            "file": p.file, "id": p.id or None, "title": p.title or None, "kind": p.kind or None,
            "status": p.status, "error": p.error, "internal": p.internal,
            "warnings": list(p.warnings),
            "answers": [{
                "name": a.name, "index": a.index, "passed": a.passed,
                "expected": a.expected, "got": a.got, "unit": a.unit,
                "expected_value": a.expected_value, "got_value": a.got_value,
                "expected_si": a.expected_si, "got_si": a.got_si, "si_unit": a.si_unit,
                "tolerance": a.tolerance, "tolerance_value": a.tolerance_value,
                "relative_error": a.relative_error, "message": a.message or None,
                "slip": a.slip, "keyed": a.keyed} for a in p.answers]})
    return {"summary": summary, "problems": problems}


def _finite(value: Any) -> Any:
    """JSON has no NaN or infinity: such a number (a solver overflow) becomes null."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_finite(v) for v in value]
    return value


def as_json(run_: CheckRun) -> str:
    import json

    return json.dumps(_finite(as_dict(run_)), indent=1, allow_nan=False)
