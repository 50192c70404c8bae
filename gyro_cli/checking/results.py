"""What `gyro check` finds, as data: one AnswerCheck per value, one ProblemCheck
per file, one CheckRun per command; the reports in render/ print them."""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import NamedTuple

# ---- results ----------------------------------------------------------------

@dataclass
class AnswerCheck:
    """One compared value: an expected value and its root, or an unclaimed root."""

    name: str
    index: int | None  # 1-based position among several expected values, else None
    expected: str | None  # as written; None for a root no expected value claimed
    got: str | None  # in the expected value's unit (or the find unit for extra roots)
    passed: bool
    unit: str | None = None
    expected_value: float | str | None = None  # in ``unit``
    got_value: float | str | None = None
    expected_si: float | str | None = None
    got_si: float | str | None = None
    si_unit: str | None = None
    tolerance: str = ""
    tolerance_value: float | None = None  # in ``unit``
    relative_error: float | None = None
    message: str = ""
    slip: str | None = None
    keyed: bool = True  # False: a computed root the key does not quote (passes unless --strict)

    @property
    def label(self) -> str:
        return f"{self.name}[{self.index}]" if self.index else self.name


@dataclass
class ProblemCheck:
    file: str
    id: str = ""
    title: str = ""
    kind: str = ""
    status: str = "pass"  # pass | fail | no expected answers | error
    error: str | None = None
    internal: bool = False  # the error is a bug in gyro (exit 3), not a bad file
    answers: list[AnswerCheck] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)

    def keyed_counts(self) -> tuple[int, int]:
        """(passed, failed) among the answers the key quotes (what the summary counts)."""
        passed = sum(1 for a in self.answers if a.keyed and a.passed)
        return passed, sum(1 for a in self.answers if a.keyed) - passed

    @classmethod
    def from_dict(cls, data: dict) -> ProblemCheck:
        """A problem of a JSON report (``gyro check --format json``), for ``--merge``."""
        answers = [AnswerCheck(**{k: v for k, v in a.items() if k in _ANSWER_FIELDS}
                               | {"message": a.get("message") or ""})
                   for a in data.get("answers") or []]
        return cls(str(data["file"]), data.get("id") or "", data.get("title") or "",
                   data.get("kind") or "", status=str(data["status"]), error=data.get("error"),
                   internal=bool(data.get("internal")), answers=answers,
                   warnings=list(data.get("warnings") or []))


_ANSWER_FIELDS = {f.name for f in fields(AnswerCheck)}


class Printed(NamedTuple):
    """One problem as the command writes it, made where it was checked (a worker): its
    report text (the table's rows or the JSON line), its JUnit ``<testsuite>`` and
    counts, and what the summary counts of it. The parent writes and counts it without
    the ProblemCheck, so the reports' text is made in parallel and only text crosses
    the pipe."""

    error: str | None
    status: str
    internal: bool
    passed: int  # keyed answers that passed
    failed: int  # keyed answers that failed
    report: str
    junit: tuple[str, tuple[int, int, int, int]] | None


class Tally:
    """The counts of a run, added to one problem at a time: what the summary line and the
    exit code need, without keeping the problems (a run of any size in constant memory)."""

    def __init__(self, strict: bool = False) -> None:
        self.strict = strict
        self._counts = dict.fromkeys(("files", "checked", "answers", "passed", "failed",
                                      "bad_files", "internal_errors", "no_expected"), 0)

    def add(self, problem: ProblemCheck) -> None:
        self.count(problem.status, problem.internal, *problem.keyed_counts())

    def count(self, status: str, internal: bool, passed: int, failed: int) -> None:
        """One problem, by what the counts need of it: its status, whether its error is
        gyro's own, and its keyed answers that passed and failed."""
        c = self._counts
        c["files"] += 1
        c["checked"] += status in ("pass", "fail")
        c["bad_files"] += status == "error"
        c["internal_errors"] += internal
        c["no_expected"] += status == "no expected answers"
        c["answers"] += passed + failed
        c["passed"] += passed
        c["failed"] += failed

    def counts(self) -> dict[str, int]:
        return dict(self._counts)

    @property
    def exit_code(self) -> int:
        """3 if gyro failed on a file (a bug); else 2 if a file is bad; else 1 if an answer
        failed or nothing was compared; else 0."""
        c = self._counts
        if c["internal_errors"]:
            return 3
        if c["bad_files"]:
            return 2
        if c["failed"] or c["answers"] == 0 or (self.strict and c["no_expected"]):
            return 1
        return 0


@dataclass
class CheckRun:
    """Every problem of a run, kept (the API's CheckReport, the HTML page); the command
    itself streams them through a Tally."""

    problems: list[ProblemCheck]
    strict: bool = False

    def tally(self) -> Tally:
        tally = Tally(self.strict)
        for problem in self.problems:
            tally.add(problem)
        return tally

    def counts(self) -> dict[str, int]:
        return self.tally().counts()

    @property
    def exit_code(self) -> int:
        return self.tally().exit_code
