"""`gyro check`: solve problem files and compare with their `expected` answers.

Pure parts (tolerances, root matching, slip diagnosis) are small functions on
SI floats; the runner loads and solves every file in this one process (one
unit registry) and collects a CheckRun that the reports render: a table, one
JSON document, or JUnit XML (``junit.py``).

Rules (see docs/check.md):
- dimensions are checked before magnitudes: an expected value in the wrong
  dimension is an error in the file (exit 2), not a failed answer;
- tolerance ``"1%"`` relative, ``"3 sig"`` significant figures of the expected
  value as written, or a quantity (``"0.01 rad/s"``) absolute; one for the file
  or a mapping answer -> tolerance (``default:`` for the rest); default 1%;
- roots match as sets: each expected value to its nearest computed root, none
  used twice; a computed root no expected value claims fails, and so does an
  expected value left without a root.
"""

from __future__ import annotations

import dataclasses
import math
import os
import re
from dataclasses import dataclass, field
from typing import Any

from ..core import units
from ..core.errors import InputError, shown
from ..core.work import num

DEFAULT_TOLERANCE = "1%"
_SIG = re.compile(r"\s*(\d{1,2})\s*(?:sig|sf|s\.f\.|sig\s*figs?|significant\s+figures?)\s*",
                  re.I)
_PERCENT = re.compile(r"\s*((?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d{1,3})?)\s*"
                      r"(?:%|percent|per\s*cent|pct)\s*", re.I)
_MAGNITUDE = re.compile(r"\s*,?\s*\b(?:magnitudes?|abs)\b\s*,?\s*", re.I)


# ---- tolerances -------------------------------------------------------------

@dataclass(frozen=True)
class Tolerance:
    """How close is close enough: relative fraction, significant figures, or absolute SI."""

    form: str   # "relative" | "sig" | "absolute"
    value: float  # fraction (0.01), digits (3), or SI half-width
    text: str
    magnitude: bool = False  # compare absolute values (books that quote magnitudes)

    def half_width(self, expected_si: float, expected_number: float) -> float:
        """The allowed |got - expected| in SI for one expected value.

        ``expected_number`` is the value as written (in its own unit); significant
        figures count on it: 3 sig of 45.1 rpm allows 0.05 rpm.
        """
        if self.form == "relative":
            return self.value * abs(expected_si)
        if self.form == "absolute":
            return self.value
        if expected_number == 0 or expected_si == 0:
            return 0.0
        exponent = math.floor(math.log10(abs(expected_number)))
        half_unit = 0.5 * 10.0 ** (exponent - int(self.value) + 1)
        return half_unit * abs(expected_si / expected_number)


def parse_tolerance(raw: Any, dimension: str | None, key: str = "tolerance") -> Tolerance:
    """One tolerance: ``"1%"``, ``"3 sig"`` or a quantity in the answer's dimension."""
    if isinstance(raw, bool) or not isinstance(raw, (str, int, float)):
        raise InputError(f"expected a tolerance such as '1%', '3 sig' or '0.01 rad/s', got "
                         f"{shown(raw)}", key=key)
    if isinstance(raw, (int, float)):
        raise InputError(f"a bare number {shown(raw)} is ambiguous as a tolerance: write '{raw}%' "
                         "(relative), '3 sig' (significant figures) or a quantity with a unit "
                         "(absolute)", key=key)
    text = raw.strip()
    if len(text) <= units.MAX_TEXT and _MAGNITUDE.search(text):
        rest = _MAGNITUDE.sub(" ", text).strip()
        one = parse_tolerance(rest or DEFAULT_TOLERANCE, dimension, key)
        return dataclasses.replace(one, magnitude=True, text=text)
    match = _PERCENT.fullmatch(text)
    if match:
        fraction = float(match.group(1)) / 100
        if not 0 <= fraction <= 1:
            raise InputError(f"a relative tolerance lies between 0% and 100%, got {text!r}",
                             key=key)
        return Tolerance("relative", fraction, text)
    match = _SIG.fullmatch(text)
    if match:
        digits = int(match.group(1))
        if not 1 <= digits <= 15:
            raise InputError(f"significant figures run from 1 to 15, got {text!r}", key=key)
        return Tolerance("sig", digits, text)
    if dimension is None:
        # A word answer: compared exactly, but the text must still be a tolerance.
        _guarded(lambda t, d, k: units._split(t, k), text, dimension, key)
        return Tolerance("absolute", 0.0, text)
    value, _ = _guarded(units.parse, text, dimension, key)
    if value < 0:
        raise InputError(f"a tolerance cannot be negative, got {text!r}", key=key)
    return Tolerance("absolute", value, text)


def tolerance_for(spec: Any, name: str, dimension: str | None, answer_names: list[str]) -> Tolerance:
    """The tolerance of answer ``name`` from the file's ``tolerance`` (None, one, or a mapping)."""
    if spec is None:
        return parse_tolerance(DEFAULT_TOLERANCE, dimension)
    if isinstance(spec, dict):
        for entry in spec:
            if entry != "default" and entry not in answer_names:
                from ..solving.problem import suggest

                raise InputError(f"unknown answer {entry!r}{suggest(str(entry), answer_names)} "
                                 f"(answers: {', '.join(answer_names)}; or `default`)",
                                 key=f"tolerance.{entry}")
        if name in spec:
            return parse_tolerance(spec[name], dimension, f"tolerance.{name}")
        if "default" in spec:
            return parse_tolerance(spec["default"], dimension, "tolerance.default")
        return parse_tolerance(DEFAULT_TOLERANCE, dimension)
    return parse_tolerance(spec, dimension, "tolerance")


def validate_tolerance(spec: Any, kind: Any) -> None:
    """Check every entry of a file's `tolerance`, used or not (InputError if malformed)."""
    names = [a.name for a in kind.answers]
    if spec is None:
        return
    if not isinstance(spec, dict):
        # The form here; an absolute value's dimension against each answer when it is used.
        parse_tolerance(spec, None, "tolerance")
        return
    tolerance_for(spec, "", None, names)  # unknown answer names
    for name, value in spec.items():
        answer = kind.answer(name)
        parse_tolerance(value, answer.dimension if answer else None,
                        f"tolerance.{name}")


# ---- expected values --------------------------------------------------------

@dataclass(frozen=True)
class Expected:
    """One expected value: as written, in SI, and the written number and unit."""

    text: str
    si: float | str  # a word for word answers
    number: float = 0.0
    unit: str = ""
    factor: float = 1.0  # SI per written unit (linear units only)


_FACTORS: dict[tuple[str, str], float] = {}


def parse_value(raw: Any, dimension: str | None, key: str) -> Expected:
    """One expected value in the answer's dimension; a word for word answers.

    The SI factor of each unit is cached, so checking many files asks pint
    once per unit, not once per value.
    """
    if dimension is None:
        if not isinstance(raw, str) or not raw.strip():
            raise InputError(f"expected a word, got {shown(raw)}", key=key)
        return Expected(str(raw).strip(), str(raw).strip())
    if isinstance(raw, (dict, list)):
        raise InputError(f"expected a quantity such as '45.1 rpm', got a "
                         f"{'mapping' if isinstance(raw, dict) else 'nested list'}", key=key)
    number, unit = _guarded(lambda t, d, k: units._split(t, k), raw, dimension, key)
    factor = _FACTORS.get((unit, dimension))
    if factor is None:
        _guarded(units.parse, raw, dimension, key)  # every check, with the text as written
        factor, _ = _guarded(units.parse, f"1 {unit}" if unit else 1, dimension, key)
        _FACTORS[(unit, dimension)] = factor
    si = number * factor
    if not math.isfinite(si):
        raise InputError(f"{shown(raw)} is not a finite number", key=key)
    text = " ".join(raw.split()) if isinstance(raw, str) else f"{raw:g}"
    return Expected(text, si, number, units.display(unit, dimension, key), factor)


def _guarded(parse: Any, text: Any, dimension: str | None, key: str) -> Any:
    from ..solving.problem import guarded

    return guarded(parse, text, dimension, key)


def parse_expected(raw: Any, dimension: str | None, key: str) -> list[Expected]:
    """`expected.<name>`: one value or a non-empty list of them (roots in any order)."""
    values = raw if isinstance(raw, list) else [raw]
    if not values:
        raise InputError("expected at least one value, got an empty list", key=key)
    return [parse_value(v, dimension, key) for v in values]


# ---- matching and diagnosis -------------------------------------------------

def distance(expected: float, got: float) -> float:
    """How far apart two values are for matching: |ln(|got| / |expected|)|.

    On a log scale a slip (10x, 2 pi, the sign) stays nearest to the root it
    spoils; a differing sign adds a hair so like signs pair first. A zero pairs
    only by absolute difference, after every non-zero pair.
    """
    if expected == 0 or got == 0:
        return 0.0 if expected == got else 1e6 + abs(got - expected)
    # log|got| - log|expected|, not log(|got| / |expected|): the ratio of 1e-300 and
    # 1e300 underflows to 0.
    return abs(math.log(abs(got)) - math.log(abs(expected))) + \
        (1e-9 if (got < 0) != (expected < 0) else 0)


def match_roots(expected: list[float], computed: list[float],
                passes: Any = None) -> list[tuple[int | None, int | None]]:
    """Pairs (expected index, computed index): nearest first, none used twice.

    ``passes(i, j)`` (optional) says whether the pair is within tolerance; such
    pairs are taken before any other. Unpaired expected values come as
    (i, None), unclaimed roots as (None, j); the list is in the order of the
    expected values, then the extra roots.
    """
    pairs = sorted((not passes(i, j) if passes else False, distance(e, c), i, j)
                   for i, e in enumerate(expected) for j, c in enumerate(computed))
    of_expected: dict[int, int] = {}
    used: set[int] = set()
    for _, _, i, j in pairs:
        if i not in of_expected and j not in used:
            of_expected[i] = j
            used.add(j)
    out: list[tuple[int | None, int | None]] = [(i, of_expected.get(i))
                                                for i in range(len(expected))]
    out += [(None, j) for j in range(len(computed)) if j not in used]
    return out


# (factor, what it suggests); both directions are tried, and each with the sign.
SLIPS: tuple[tuple[float, str], ...] = (
    (2 * math.pi, "a factor of 2 pi: rad/s against rev/s (Hz)"),
    (60 / (2 * math.pi), "a factor of 60/(2 pi) = 9.549: rpm against rad/s"),
    (60.0, "a factor of 60: rpm against rev/s (Hz), or minutes against seconds"),
    (9.81, "a factor of g = 9.81 m/s^2: mass against weight"),
    (32.174, "a factor of g = 32.2 ft/s^2: mass against weight (lbm against slug or lbf)"),
    (180 / math.pi, "a factor of 180/pi = 57.30: degrees against radians"),
)


def diagnose(expected: float, got: float, half_width: float,
             other_roots: list[float] | None = None) -> str | None:
    """The likely slip that turns ``expected`` into ``got``, or None.

    Tried in order: another computed root of the same answer, the sign, a power
    of ten, then the factors in SLIPS. A factor counts when got is within the
    answer's relative tolerance (at least 0.5%, at most 2%) of expected times it.
    """
    for root in other_roots or []:
        if abs(root - expected) <= half_width:
            return f"the other root: expected matches the computed root {num(root)} (SI)"
    if expected == 0 or got == 0 or not math.isfinite(got):
        return None
    window = min(max(half_width / abs(expected), 0.005), 0.02)
    ratio = got / expected
    if not math.isfinite(ratio) or ratio == 0 or not math.isfinite(window):
        return None  # a denormal expected value: no slip to name
    if abs(ratio + 1) <= window:
        return "the sign: got is minus the expected value"
    sign = " and the sign" if ratio < 0 else ""
    size = abs(ratio)
    power = round(math.log10(size))
    if power and abs(size / 10.0 ** power - 1) <= window:
        times = f"10^{power}" if abs(power) > 1 else ("10" if power == 1 else "1/10")
        return f"a power of ten{sign}: got is {times} times expected (a unit prefix or a " \
               "decimal point?)"
    best: tuple[float, str] | None = None
    for factor, what in SLIPS:
        for f, direction in ((factor, "got is larger"), (1 / factor, "got is smaller")):
            miss = abs(size / f - 1)
            if miss <= window and (best is None or miss < best[0]):
                best = (miss, f"{what} ({direction}){sign}")
    return best[1] if best else None


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


# ---- the runner -------------------------------------------------------------

def collect(paths: list[str] | tuple[str, ...]) -> tuple[list[str], list[ProblemCheck]]:
    """Problem files from files, directories and globs (solving.paths), with each path
    that names nothing as an error entry."""
    from ..solving.paths import problem_files

    files, missing = problem_files(paths)
    return files, [ProblemCheck(path, status="error", error=message) for path, message in missing]


def check_problem(problem: Any, strict: bool = False) -> ProblemCheck:
    """Solve one loaded problem and compare every expected answer; InputError if bad.

    ``strict``: every computed root must be keyed (else a root the key does not
    quote is reported as not keyed and does not fail).
    """
    from ..solving.solve import solve

    kind = problem.kind
    result = ProblemCheck(problem.file, problem.id, problem.title, kind.name)
    answer_names = [a.name for a in kind.answers]
    # Validate everything in the file before solving: a bad key is exit 2 either way.
    validate_tolerance(problem.tolerance, kind)
    wanted: dict[str, tuple[list[Expected], Tolerance]] = {}
    for name, raw in problem.expected.items():
        dimension = kind.answer(name).dimension
        values = parse_expected(raw, dimension, f"expected.{name}")
        wanted[name] = (values, tolerance_for(problem.tolerance, name, dimension, answer_names))
    find = dict(problem.find)
    for name in wanted:
        find.setdefault(name, None)
    # Solved even without expected answers: a file that cannot be solved is a bad file.
    solved = solve(dataclasses.replace(problem, find=find))
    result.warnings = list(solved.solution.warnings)
    if not wanted:
        result.status = "no expected answers"
        return result
    for name, (values, tolerance) in wanted.items():
        result.answers += compare(name, values, tolerance, solved.answers[name], strict=strict)
    result.status = "pass" if all(a.passed for a in result.answers) else "fail"
    return result


def compare(name: str, values: list[Expected], tolerance: Tolerance, reported: Any,
            strict: bool = True) -> list[AnswerCheck]:
    """Compare the expected values of one answer with its computed roots (as sets).

    With ``strict`` False a computed root that no expected value claims, where
    every expected value found its root, is "not keyed": listed, not failed
    (a book quotes the slow precession and not the fast one).
    """
    computed = list(reported.si_values)
    if tolerance.magnitude and reported.si_unit is not None:
        computed = [abs(c) for c in computed]
        values = [dataclasses.replace(v, si=abs(float(v.si)), number=abs(v.number))
                  for v in values]
    labels = list(reported.labels)
    out: list[AnswerCheck] = []
    if reported.unit is None and reported.si_unit is None:  # a word answer
        got = [str(v) for v in computed]
        several = len(values) > 1
        for i, value in enumerate(values):
            ok = str(value.si).lower() in (g.lower() for g in got)
            out.append(AnswerCheck(name, i + 1 if several else None, value.text, ", ".join(got),
                                   ok, expected_value=value.text, got_value=", ".join(got),
                                   expected_si=value.si, got_si=", ".join(got),
                                   tolerance="exact", message="" if ok else
                                   f"expected {value.text}, got {', '.join(got)}"))
        return out
    widths_si = [tolerance.half_width(float(v.si), v.number) for v in values]

    def within(i: int, j: int) -> bool:
        return abs(computed[j] - float(values[i].si)) <= widths_si[i] * (1 + 1e-12) + 1e-300

    pairs = match_roots([float(v.si) for v in values], computed, within)
    # A root equal to one an expected value already matched (the moment, the
    # same for both precession rates) is covered by it, not a missing value.
    pairs = [(i, j) for i, j in pairs
             if i is not None or not any(within(k, j) for k in range(len(values)))]
    all_found = all(j is not None and within(i, j) for i, j in pairs if i is not None)
    several = len(values) > 1 or len(pairs) > 1
    for position, (i, j) in enumerate(pairs):
        index = position + 1 if several else None
        label = f" ({labels[j]})" if j is not None and j < len(labels) and labels[j] else ""
        if i is None:  # a computed root that no expected value claims
            unit, factor = values[0].unit or reported.unit or "", values[0].factor
            got_value = computed[j] / factor
            if not strict and all_found:
                out.append(AnswerCheck(
                    name, index, None, f"{num(got_value)} {unit}".rstrip() + label, True,
                    unit=unit, got_value=got_value, got_si=computed[j],
                    si_unit=reported.si_unit, tolerance=tolerance.text, keyed=False,
                    message="not keyed: the key quotes no value for this root "
                            "(gyro check --strict fails it)"))
                continue
            out.append(AnswerCheck(
                name, index, None, f"{num(got_value)} {unit}".rstrip() + label, False,
                unit=unit, got_value=got_value, got_si=computed[j],
                si_unit=reported.si_unit, tolerance=tolerance.text,
                message=f"computed root {num(got_value)} {unit}{label} has no expected "
                        f"value ({len(values)} expected, {len(computed)} computed)"))
            continue
        value = values[i]
        unit = value.unit or reported.unit or ""
        width_si = widths_si[i]
        width = width_si / value.factor
        check = AnswerCheck(name, index, value.text, None, False, unit=unit,
                            expected_value=value.number, expected_si=value.si,
                            si_unit=reported.si_unit, tolerance=tolerance.text,
                            tolerance_value=width)
        if j is None:
            check.message = (f"expected {value.text} +- {num(width)} {unit}, got no root "
                             f"({len(values)} expected, {len(computed)} computed)").replace(" ,", ",")
            check.slip = diagnose(float(value.si), math.nan, width_si, computed)
            if check.slip:
                check.slip = _other_root(value, computed, width_si, unit)
            out.append(check)
            continue
        got_si = computed[j]
        got = got_si / value.factor
        check.got_si, check.got_value = got_si, got
        check.got = f"{num(got)} {unit}".rstrip() + label
        if not math.isfinite(got):  # finite in SI, too large for the expected value's unit
            check.got_value = None
            check.got = f"{num(got_si)} {reported.si_unit or ''}".rstrip() + label
        relative = (got_si - value.si) / abs(value.si) if value.si else None
        check.relative_error = relative if relative is not None and abs(relative) < 1e300 \
            else None  # in percent it would overflow
        check.passed = within(i, j)
        if not check.passed:
            off = ("expected is 0" if not value.si else "more than 1e308 times the expected value" if
                   check.relative_error is None else f"{check.relative_error * 100:+.3g}%")
            check.message = (f"expected {value.text} +- {num(width)} {unit}, got "
                             f"{num(got)} {unit}; off by {num(got - value.number)} {unit} "
                             f"({off})").replace("  ", " ")
            if not math.isfinite(got):
                check.message = (f"expected {value.text}, got {check.got}: too large to "
                                 f"express in {unit}")
            others = [c for k, c in enumerate(computed) if k != j]
            check.slip = diagnose(float(value.si), got_si, width_si, others)
            if check.slip and check.slip.startswith("the other root"):
                check.slip = _other_root(value, others, width_si, unit)
        out.append(check)
    return out


def _other_root(value: Expected, roots: list[float], width_si: float, unit: str) -> str:
    root = next(c for c in roots if abs(c - float(value.si)) <= width_si)
    return (f"the other root: {value.text} is the computed root {num(root / value.factor)} "
            f"{unit}, which another expected value took")


def check_file(path: str, strict: bool = False) -> ProblemCheck:
    """Load, solve and compare one file; a bad file comes back with status error."""
    from ..solving.problem import load

    problem = None
    try:
        problem = load(path)
        return check_problem(problem, strict=strict)
    except InputError as err:
        if problem is not None:
            err.located(file=problem.file, line=problem.line(err.key))
        error = str(err)
        internal = False
    except Exception as err:  # a bug in gyro: this file is an error, the next goes on
        from ..core.errors import internal_message

        if os.environ.get("GYRO_DEBUG"):
            import traceback

            traceback.print_exception(err)
        error = internal_message(path, err)
        internal = True
    if problem is None:
        return ProblemCheck(path, status="error", error=error, internal=internal)
    return ProblemCheck(path, str(problem.id), str(problem.title), problem.kind.name,
                        status="error", error=error, internal=internal)


def run(paths: list[str] | tuple[str, ...], strict: bool = False) -> CheckRun:
    """Check every problem file under ``paths``, all in this process."""
    files, errors = collect(paths)
    return CheckRun(errors + [check_file(f, strict) for f in files], strict=strict)


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
