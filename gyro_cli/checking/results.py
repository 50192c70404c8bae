"""What `gyro check` finds, as data: one AnswerCheck per value, one ProblemCheck
per file, one CheckRun per command; the reports in render/ print them."""

from __future__ import annotations

from dataclasses import dataclass, field


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


@dataclass
class CheckRun:
    problems: list[ProblemCheck]
    strict: bool = False

    def counts(self) -> dict[str, int]:
        answers = [a for p in self.problems for a in p.answers if a.keyed]
        return {
            "files": len(self.problems),
            "checked": sum(p.status in ("pass", "fail") for p in self.problems),
            "answers": len(answers),
            "passed": sum(a.passed for a in answers),
            "failed": sum(not a.passed for a in answers),
            "bad_files": sum(p.status == "error" for p in self.problems),
            "internal_errors": sum(p.internal for p in self.problems),
            "no_expected": sum(p.status == "no expected answers" for p in self.problems),
        }

    @property
    def exit_code(self) -> int:
        """3 if gyro failed on a file (a bug); else 2 if a file is bad; else 1 if an answer
        failed or nothing was compared; else 0."""
        c = self.counts()
        if c["internal_errors"]:
            return 3
        if c["bad_files"]:
            return 2
        if c["failed"] or c["answers"] == 0 or (self.strict and c["no_expected"]):
            return 1
        return 0
