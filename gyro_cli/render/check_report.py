"""`gyro check` reports: the table and one JSON document (JUnit XML is junit.py)."""

from __future__ import annotations

import math
from typing import Any

from ..checking.results import AnswerCheck, CheckRun, Printed, ProblemCheck, Tally
from ..core.errors import terminal_text
from ..core.work import num

# ---- reports ----------------------------------------------------------------

def summary_line(run_: CheckRun | Tally) -> str:
    """The last line: the counts and the verdict of the exit code."""
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


# The table is printed as each file finishes, so its columns cannot wait for the widest
# cell of the run: each column has a fixed width that fits nearly every answer of the
# bundled problems, and a longer cell pushes only its own row to the right.
_HEADER = ("", "answer", "expected", "got", "error", "tolerance")
_WIDTHS = (4, 16, 14, 18, 8, 24)


def table_head() -> str:
    """The column titles, the table's first line."""
    return "  " + "  ".join(h.ljust(w) for h, w in zip(_HEADER, _WIDTHS)).rstrip() + "\n"


def table_rows(p: ProblemCheck) -> str:
    """One file's lines of the table: its name, id and title, then one line per answer
    (or its error), then its warnings."""
    # file names, ids, titles, answers and messages come from files: one line each, and no
    # terminal escape sequence reaches the terminal raw
    t = terminal_text
    lines = [t(f"{p.file}" + (f"  {p.id}" if p.id else "") + (f"  {p.title}" if p.title else ""))]
    if p.status == "error":
        lines.append(t(f"  ERROR  {p.error}"))
    elif p.status == "no expected answers":
        lines.append("  ----   no expected answers (not checked)")
    for a in p.answers:
        note = a.message if not a.passed or not a.keyed else ""
        if a.slip:
            note += f"; likely slip: {a.slip}"
        tol = (f" (+-{num(a.tolerance_value)} {a.unit or ''})".replace(" )", ")")
               if a.tolerance_value is not None and a.tolerance_value >= 0 else "")
        row = tuple(t(c) for c in (
            "PASS" if a.passed and a.keyed else "----" if a.passed else "FAIL",
            a.label, a.expected or "-", a.got or "-", _percent(a), f"{a.tolerance}{tol}"))
        cells = [c.ljust(w) for c, w in zip(row, _WIDTHS)]
        cells[4] = row[4].rjust(_WIDTHS[4])
        lines.append(("  " + "  ".join(cells) + ("  " + t(note) if note else "")).rstrip())
    lines += [t(f"  ! {warning}") for warning in p.warnings]
    return "\n".join(lines) + "\n"


def table(run_: CheckRun) -> str:
    """The terminal report: one line per answer under its file, then the summary."""
    return table_head() + "".join(table_rows(p) for p in run_.problems) \
        + summary_line(run_) + "\n"


def _summary(run_: CheckRun | Tally, shard: tuple[int, int] | None = None) -> dict[str, Any]:
    summary = dict(run_.counts(), exit_code=run_.exit_code, text=summary_line(run_))
    if shard:
        summary["shard"] = f"{shard[0]}/{shard[1]}"
    return summary


def problem_dict(p: ProblemCheck) -> dict[str, Any]:
    """One problem of the JSON report."""
    return {
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
            "slip": a.slip, "keyed": a.keyed} for a in p.answers]}


def json_line(p: ProblemCheck) -> str:
    """One problem of the JSON report, as its line."""
    return _dumps(problem_dict(p))


def printed(p: ProblemCheck, fmt: str, junit: bool) -> Printed:
    """``p`` as `gyro check` writes it: its JSON line (``fmt`` "json") or table rows, its
    JUnit testsuite if ``junit``, and its counts."""
    from . import junit as junit_xml

    return Printed(p.error, p.status, p.internal, *p.keyed_counts(),
                   json_line(p) if fmt == "json" else table_rows(p),
                   junit_xml.suite_text(p) if junit else None)


def as_dict(run_: CheckRun) -> dict[str, Any]:
    """The JSON report: every problem and answer, plus the summary."""
    return {"summary": _summary(run_), "problems": [problem_dict(p) for p in run_.problems]}


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
    """The JSON report as one document (the same text ``JsonStream`` writes piece by piece)."""
    stream = JsonStream()
    return stream.head() + "".join(stream.problem(p) for p in run_.problems) \
        + stream.tail(run_.tally())


def _dumps(value: Any) -> str:
    """One line of JSON (the C encoder); a NaN or infinity (a solver overflow) as null."""
    import json

    try:
        return json.dumps(value, allow_nan=False)
    except ValueError:
        return json.dumps(_finite(value), allow_nan=False)


class JsonStream:
    """The JSON report written as the files finish: ``{"problems": [`` first, then one
    problem per line as each is known, then the summary once the counts are known::

        {"problems": [
        {"file": "problems/11_1.yaml", ...},
        {"file": "problems/11_2.yaml", ...}
        ],
        "summary": {"files": 2, ...}}

    One ordinary JSON document (``json.load`` reads it), and a line per problem for
    ``grep`` and line-by-line readers."""

    def __init__(self) -> None:
        self._count = 0

    @staticmethod
    def head() -> str:
        return '{"problems": ['

    def problem(self, p: ProblemCheck) -> str:
        return self.line(json_line(p))

    def line(self, text: str) -> str:
        """A problem's line (``json_line``), after the comma that separates it from the
        one before."""
        self._count += 1
        return ("," if self._count > 1 else "") + "\n" + text

    def tail(self, tally: Tally, shard: tuple[int, int] | None = None) -> str:
        """The end: the summary (with ``"shard": "K/N"`` for a shard's report)."""
        return ("\n" if self._count else "") + '],\n"summary": ' \
            + _dumps(_summary(tally, shard)) + "}"
